// Crease families: roofs of 20..175 deg, a cube and a capped cylinder (90 deg), noise
// 0..20 % of l_ave along the normals, two seeds pooled.
//   "f1":   crease precision / recall / F1 per vertex (crease or corner class, or a vertex of a
//           selected edge), every method with its crease angle at half the crease's
//           normal-angle: this project's sign-aware rule at k = 1, 3, 5 (phi = alpha / 2),
//           MeshLab's "Select Crease Edges" and CGAL's detect_sharp_edges (dihedral bound
//           alpha / 2);
//   "near": surface vertices 0.5..3 l_ave from a crease: normal error (deg), curvature error
//           100 |kappa - kappa_true| l_ave (%) over kappa1 and kappa2, and on the capped
//           cylinder's side the direction of the smaller curvature (deg).
#include <cstdio>
#include <string>
#include <vector>

#include "crease_shapes.h"
#include "estimators.h"
#include "report.h"
#include "sections.h"

namespace nvv_bench {

std::vector<Estimator> SmoothEstimators(bool torus);
void CalibrateSigns(std::vector<Estimator>& ests);

namespace {

std::vector<char> NvvFeatures(const TMesh& m, double k, double phi, bool thin = true, bool ridgeFit = true,
                              bool autoK = false) {
  nvv::Params p = nvv_test::WithK(k);
  p.autoK = autoK;
  p.thinCreases = thin;
  p.ridgeFit = ridgeFit;
  p.creaseAngleDeg = std::max(1.0, std::min(89.0, phi));
  const nvv_test::NvvRun r = nvv_test::RunNvv(m, p);
  std::vector<char> f(m.vert.size(), 0);
  for (std::size_t i = 0; i < r.res.size(); ++i)
    f[i] = r.res[i].cls == nvv::VertexClass::Crease || r.res[i].cls == nvv::VertexClass::Corner;
  return f;
}

std::vector<CreaseShape> Shapes(bool all) {
  std::vector<CreaseShape> v;
  const std::vector<double> roofs = all ? std::vector<double>{20, 40, 60, 90, 120, 150, 175}
                                        : std::vector<double>{60, 90, 120};
  for (double a : roofs) v.push_back({"roof " + std::to_string(int(a)) + "°", a, 0});
  v.push_back({"cube", 90, 1});
  v.push_back({"capped cylinder", 90, 2});
  return v;
}

int RunF1(const std::string& outDir) {
  const std::vector<double> noises = {0, 0.01, 0.05, 0.10, 0.20};
  Csv csv(outDir, "creases_f1.csv", "shape,alpha,noise,method,precision,recall,f1");
  std::printf("| shape | noise | NVV k=1 | NVV k=3 | NVV k=5 | NVV k=3 strength thinning | NVV k=3 paper band | MeshLab dihedral | CGAL sharp edges | NVV auto k |\n"
              "|---|---|---|---|---|---|---|---|---|---|\n");
  const char* names[] = {"NVV k=1", "NVV k=3", "NVV k=5", "NVV k=3 strength thinning", "NVV k=3 paper band",
                         "MeshLab dihedral", "CGAL sharp edges", "NVV auto k"};
  const int methods = int(sizeof(names) / sizeof(names[0]));
  for (const CreaseShape& s : Shapes(true))
    for (double noise : noises) {
      std::vector<char> truthAll, useAll;
      std::vector<std::vector<char>> foundAll(methods);
      for (unsigned seed = 1; seed <= 2; ++seed) {
        TMesh m;
        BuildCreaseShape(s, m);
        std::vector<char> truth(m.vert.size()), use(m.vert.size());
        for (std::size_t i = 0; i < m.vert.size(); ++i) {
          const VertexTruth t = CreaseTruthAt(s, m.vert[i].cP());
          truth[i] = t.feature;
          use[i] = t.use;
        }
        NoiseAlongNormals(m, noise * nvv_shapes::MeanEdge(m), 77 * seed + unsigned(1000 * noise));
        const double phi = s.alphaDeg / 2;
        Context c(m);
        std::vector<std::vector<char>> found = {NvvFeatures(m, 1, phi), NvvFeatures(m, 3, phi), NvvFeatures(m, 5, phi),
                                                NvvFeatures(m, 3, phi, true, false), NvvFeatures(m, 3, phi, false),
                                                DihedralCreaseVertices(m, phi), CgalSharpVertices(c.plain, phi),
                                                NvvFeatures(m, 3, phi, true, true, true)};
        truthAll.insert(truthAll.end(), truth.begin(), truth.end());
        useAll.insert(useAll.end(), use.begin(), use.end());
        for (int j = 0; j < methods; ++j) foundAll[j].insert(foundAll[j].end(), found[j].begin(), found[j].end());
      }
      std::printf("| %s | %g %% |", s.name.c_str(), noise * 100);
      for (int j = 0; j < methods; ++j) {
        const F1 f = ScoreFeatures(foundAll[j], truthAll, useAll);
        std::printf(" %.2f (%.2f / %.2f) |", f.f1, f.precision, f.recall);
        std::fprintf(csv.f(), "%s,%g,%g,%s,%g,%g,%g\n", s.name.c_str(), s.alphaDeg, noise * 100, names[j], f.precision,
                     f.recall, f.f1);
      }
      std::printf("\n");
      std::fflush(stdout);
    }
  return 0;
}

int RunNear(const std::string& outDir) {
  const std::vector<double> noises = {0, 0.01, 0.05, 0.10, 0.20};
  std::vector<Estimator> all = SmoothEstimators(false), ests;
  for (auto& e : all)
    if (e.k != 1 && e.name.find("Euler") == std::string::npos && e.name.find("diag") == std::string::npos)
      ests.push_back(e);
  CalibrateSigns(ests);
  Csv csv(outDir, "creases_near.csv",
          "shape,noise,estimator,kind,k,normal_med,normal_p90,normal_mean,dir_med,dir_p90,dir_mean,curv_med,curv_p90,curv_mean");
  for (const CreaseShape& s : Shapes(false)) {
    std::printf("\n#### %s (crease angle %g° for this project)\n\n", s.name.c_str(), s.alphaDeg / 2);
    const bool dir = s.kind == 2;
    std::printf("| noise | estimator | normal (deg) |%s curvature (%% of 1/l_ave) |\n|---|---|---|%s---|\n",
                dir ? " min. direction (deg) |" : "", dir ? "---|" : "");
    for (double noise : noises)
      for (auto& e : ests) {
        std::vector<double> en, ed, ek;
        for (unsigned seed = 1; seed <= 2; ++seed) {
          TMesh m;
          BuildCreaseShape(s, m);
          std::vector<VertexTruth> truth(m.vert.size());
          for (std::size_t i = 0; i < m.vert.size(); ++i) truth[i] = CreaseTruthAt(s, m.vert[i].cP());
          const double lave = nvv_shapes::MeanEdge(m);
          NoiseAlongNormals(m, noise * lave, 77 * seed + unsigned(1000 * noise));
          Context c(m);
          std::vector<Estimate> out;
          if (e.kind <= 1) {  // this project: crease angle at half the crease's normal-angle
            nvv::Params p = e.params;
            p.creaseAngleDeg = s.alphaDeg / 2;
            std::vector<nvv::VertexResult> res;
            nvv::Summary sum;
            nvv::RunNormalVectorVoting(c.graph, p, res, sum);
            FromNvv(res, out);
          } else {
            e.fn(c, out);
            ApplySign(e.sign, out);
          }
          for (std::size_t i = 0; i < m.vert.size(); ++i) {
            const VertexTruth& t = truth[i];
            if (!t.use || t.feature || t.dist < 0.5 * lave - 1e-9 || t.dist > 3 * lave + 1e-9) continue;
            en.push_back(nvv_test::AngleDeg(out[i].n, t.n));
            if (t.hasDir) ed.push_back(nvv_test::AngleDeg(out[i].t2, t.t2));
            ek.push_back(100 * std::abs(out[i].k1 - t.k1) * lave);
            ek.push_back(100 * std::abs(out[i].k2 - t.k2) * lave);
          }
        }
        const Stat3 n = Stats(en), d = Stats(ed), k = Stats(ek);
        std::printf("| %g %% | %s | %s |%s%s %s |\n", noise * 100, e.name.c_str(), Cell(n).c_str(), dir ? " " : "",
                    dir ? (Cell(d) + " |").c_str() : "", Cell(k).c_str());
        std::fprintf(csv.f(), "%s,%g,%s,%d,%g,%g,%g,%g,%g,%g,%g,%g,%g,%g\n", s.name.c_str(), noise * 100, e.name.c_str(),
                     e.kind, e.k, n.median, n.p90, n.mean, d.median, d.p90, d.mean, k.median, k.p90, k.mean);
      }
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace

int RunCreases(const std::string& outDir, const std::string& which) {
  return which == "f1" ? RunF1(outDir) : RunNear(outDir);
}

}  // namespace nvv_bench

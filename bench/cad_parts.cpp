// "cad": parts made by a real CAD kernel (gmsh's OpenCASCADE, bench/cad/make_cad_parts.py),
// meshed as STL exporters write them (slivers, fans), coarse, default and fine, with truth
// from the CAD model (vertices on sharp model curves, the curves' dihedral angles, analytic
// normals and curvatures inside faces); plus ../shared/meshes/real/abc_00000006.obj with its
// .fea feature edges. Noise 0, 1, 5, 10, 20 % of l_ave along the clean mesh's normals.
//   Crease vertices: this filter with its defaults (k = 3, crease angle 60 deg) and at crease
//   angles 20 / 30 / 45 / 60 deg; MeshLab's "Select Crease Edges" and CGAL's
//   detect_sharp_edges at 20 / 30 / 45 / 60 deg (the table shows the best angle per mesh and
//   noise level, the lowest on ties: an oracle choice the defaults do not get). Strict F1 (a vertex is
//   right or wrong) and +-1-edge F1: a marked vertex counts as right when it or one of its
//   one-ring neighbours is a true crease vertex, a true crease vertex as found when it or one
//   of its neighbours is marked.
//   Surfaces next to creases: vertices inside faces whose distance along mesh edges to the
//   nearest sharp-curve vertex is 1..3 l_ave: normal error (deg) and curvature error
//   100 |kappa - kappa_true| l_ave (%, over kappa1 and kappa2) of this filter (defaults; only
//   vertices it classes as surface), MeshLab's Quadric Fitting and CGAL's jet (r = 3 l_ave).
// Usage: nvv_bench_accuracy cad OUTDIR PARTSDIR (PARTSDIR: make_cad_parts.py's output).
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <queue>
#include <sstream>
#include <string>
#include <vector>

#include "crease_shapes.h"
#include "estimators.h"
#include "mesh_files.h"
#include "report.h"
#include "sections.h"

#ifndef NVV_SHARED_MESHES
#define NVV_SHARED_MESHES "../shared/meshes"
#endif

namespace nvv_bench {

void CalibrateSigns(std::vector<Estimator>& ests);

namespace {

struct PointTruth {
  bool known = false;  // inside a face: normal and curvatures defined
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  double k1 = 0, k2 = 0;
};

struct CadMesh {
  std::string name;        // "<part>_<size>" or the ABC file's name
  TMesh clean;
  std::vector<char> sharp;  // on a sharp model curve
  std::vector<PointTruth> point;
  std::vector<double> curveAngles;  // normal-angles of the sharp curves (deg), for the table
};

// make_cad_parts.py's .truth file (its format is described there).
bool LoadTruth(const std::string& path, CadMesh& c) {
  std::ifstream in(path);
  std::string word;
  std::size_t n = 0;
  while (in >> word && word != "vertices") {}
  if (!(in >> n) || n != c.clean.vert.size()) return false;
  c.sharp.assign(n, 0);
  c.point.assign(n, PointTruth());
  for (std::size_t i = 0; i < n; ++i) {
    int sharp, dim, entity, known;
    PointTruth& t = c.point[i];
    in >> sharp >> dim >> entity >> known >> t.n[0] >> t.n[1] >> t.n[2] >> t.k1 >> t.k2;
    c.sharp[i] = char(sharp);
    t.known = known != 0;
  }
  std::size_t edges = 0, curves = 0;
  in >> word >> edges;
  for (std::size_t i = 0; i < edges; ++i) {
    int a, b, convex;
    double angle;
    in >> a >> b >> angle >> convex;
  }
  in >> word >> curves;
  for (std::size_t i = 0; i < curves; ++i) {
    int tag, convex, sharp, nodes;
    double med, lo, hi;
    in >> tag >> med >> lo >> hi >> convex >> sharp >> nodes;
    if (sharp) c.curveAngles.push_back(med);
  }
  return bool(in);
}

std::vector<std::vector<int>> OneRings(const PlainMesh& m) {
  std::vector<std::vector<int>> r(m.pos.size());
  for (const auto& f : m.face)
    for (int j = 0; j < 3; ++j) {
      r[f[j]].push_back(f[(j + 1) % 3]);
      r[f[(j + 1) % 3]].push_back(f[j]);
    }
  for (auto& x : r) {
    std::sort(x.begin(), x.end());
    x.erase(std::unique(x.begin(), x.end()), x.end());
  }
  return r;
}

// Distance along mesh edges from every vertex to the nearest marked one.
std::vector<double> EdgeDistance(const PlainMesh& m, const std::vector<std::vector<int>>& ring,
                                 const std::vector<char>& from) {
  std::vector<double> d(m.pos.size(), 1e300);
  typedef std::pair<double, int> Item;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
  for (std::size_t i = 0; i < from.size(); ++i)
    if (from[i]) { d[i] = 0; q.push({0, int(i)}); }
  while (!q.empty()) {
    const Item it = q.top();
    q.pop();
    if (it.first > d[it.second]) continue;
    for (int w : ring[it.second]) {
      const double nd = it.first + (m.pos[w] - m.pos[it.second]).norm();
      if (nd < d[w]) { d[w] = nd; q.push({nd, w}); }
    }
  }
  return d;
}

struct Score {
  F1 strict, near;
};
// Strict and +-1-edge precision / recall / F1 over every vertex.
Score ScoreBoth(const std::vector<char>& found, const std::vector<char>& truth,
                const std::vector<std::vector<int>>& ring) {
  Score s;
  s.strict = ScoreFeatures(found, truth, std::vector<char>(found.size(), 1));
  auto touches = [&](const std::vector<char>& mark, std::size_t v) {
    if (mark[v]) return true;
    for (int w : ring[v]) if (mark[w]) return true;
    return false;
  };
  double marked = 0, marked_ok = 0, real = 0, real_found = 0;
  for (std::size_t v = 0; v < found.size(); ++v) {
    if (found[v]) { ++marked; marked_ok += touches(truth, v); }
    if (truth[v]) { ++real; real_found += touches(found, v); }
  }
  F1& f = s.near;
  f.precision = marked > 0 ? marked_ok / marked : 1;
  f.recall = real > 0 ? real_found / real : 1;
  f.f1 = f.precision + f.recall > 0 ? 2 * f.precision * f.recall / (f.precision + f.recall) : 0;
  return s;
}

// The share of triangles (%) whose longest edge is over 10 times their height on it, and the
// largest number of triangles at a vertex.
std::pair<double, int> Shape(const PlainMesh& m) {
  int slivers = 0;
  std::vector<int> valence(m.pos.size(), 0);
  for (const auto& f : m.face) {
    double longest = 0;
    for (int j = 0; j < 3; ++j) {
      ++valence[f[j]];
      longest = std::max(longest, (m.pos[f[(j + 1) % 3]] - m.pos[f[j]]).norm());
    }
    const double area2 = (m.pos[f[1]] - m.pos[f[0]]).cross(m.pos[f[2]] - m.pos[f[0]]).norm();
    if (longest * longest > 10 * area2) ++slivers;
  }
  return {100.0 * slivers / std::max<std::size_t>(1, m.face.size()), *std::max_element(valence.begin(), valence.end())};
}

std::string Angles(const std::vector<double>& a) {
  std::vector<int> r;
  for (double x : a) r.push_back(int(std::lround(x)));
  std::sort(r.begin(), r.end());
  r.erase(std::unique(r.begin(), r.end()), r.end());
  std::string s;
  for (int x : r) s += (s.empty() ? "" : ", ") + std::to_string(x);
  return s.empty() ? "–" : s + "°";
}

}  // namespace

int RunCad(const std::string& outDir, const std::string& partsDir) {
  const std::vector<double> noises = {0, 0.01, 0.05, 0.10, 0.20};
  const std::vector<double> angles = {20, 30, 45, 60};
  std::vector<std::unique_ptr<CadMesh>> meshes;  // TMesh cannot be copied or moved
  {
    std::ifstream list(partsDir + "/parts.txt");
    std::string name;
    while (list >> name) {
      meshes.emplace_back(new CadMesh);
      CadMesh& c = *meshes.back();
      c.name = name;
      if (!LoadMesh(partsDir + "/" + name + ".obj", c.clean) || !LoadTruth(partsDir + "/" + name + ".truth", c)) {
        std::fprintf(stderr, "cad: cannot read %s/%s.obj / .truth\n", partsDir.c_str(), name.c_str());
        return 2;
      }
    }
    if (meshes.empty()) {
      std::fprintf(stderr, "cad: no parts in %s/parts.txt (run bench/cad/make_cad_parts.py first)\n", partsDir.c_str());
      return 2;
    }
    const std::string abc = std::string(NVV_SHARED_MESHES) + "/real/abc_00000006";
    std::unique_ptr<CadMesh> c(new CadMesh);
    c->name = "abc_00000006";
    if (LoadMesh(abc + ".obj", c->clean)) {
      c->sharp = TruthFromFea(abc + ".fea", c->clean.vert.size());
      c->point.assign(c->clean.vert.size(), PointTruth());
      meshes.push_back(std::move(c));
    } else {
      std::printf("<!-- abc_00000006.obj not found under ../shared/meshes/real: left out -->\n");
    }
  }

  std::vector<Estimator> ests = {Nvv(3, nvv::CurvatureFit::SheetQuadric), Vcg("MeshLab Quadric Fitting", VcgMethod::QuadricFitting),
                                 Jet(3)};
  ests[0].name = "NVV defaults";
  CalibrateSigns(ests);

  Csv csv(outDir, "cad_f1.csv", "mesh,noise,method,angle,precision,recall,f1,near_precision,near_recall,near_f1");
  Csv ccsv(outDir, "cad_curvature.csv",
           "mesh,noise,estimator,vertices,normal_med,normal_p90,normal_mean,curv_med,curv_p90,curv_mean");
  Csv ncsv(outDir, "cad_noise.csv", "mesh,noise,noise_estimate,k_auto");
  Csv mcsv(outDir, "cad_meshes.csv", "mesh,vertices,triangles,l_ave,slivers_pct,max_valence,sharp_vertices,crease_angles");
  std::ostringstream curvTable, meshTable, infoTable;
  curvTable << "| mesh | noise | vertices | " << ests[0].name << " | " << ests[1].name << " | " << ests[2].name
            << " |\n|---|---|---|---|---|---|\n";
  meshTable << "| mesh | noise | NVV defaults | NVV votes only | NVV best φ | MeshLab dihedral, best angle | CGAL sharp edges, best angle |\n"
               "|---|---|---|---|---|---|---|\n";
  infoTable << "| mesh | vertices | l_ave (mm) | slivers | max. valence | sharp-curve vertices | crease angles |\n"
               "|---|---|---|---|---|---|---|\n";
  // pooled strict / near F1 per size and noise, for the summary: [size][noise][method]
  std::map<std::string, std::map<double, std::vector<std::vector<double>>>> pooled;

  for (const auto& cmp : meshes) {
    const CadMesh& cm = *cmp;
    const std::string size = cm.name == "abc_00000006" ? "ABC" : cm.name.substr(cm.name.rfind('_') + 1);
    const double lave = nvv_shapes::MeanEdge(cm.clean);
    Context c0(cm.clean);
    const std::vector<std::vector<int>> ring = OneRings(c0.plain);
    const std::vector<double> dist = EdgeDistance(c0.plain, ring, cm.sharp);
    const std::pair<double, int> shape = Shape(c0.plain);
    {
      const int nsharp = int(std::count(cm.sharp.begin(), cm.sharp.end(), 1));
      char b[256];
      std::snprintf(b, sizeof b, "| %s | %zu | %s | %.0f %% | %d | %d | %s |\n", cm.name.c_str(), cm.clean.vert.size(),
                    Num(lave).c_str(), shape.first, shape.second, nsharp, Angles(cm.curveAngles).c_str());
      infoTable << b;
      std::string angles = Angles(cm.curveAngles);
      if (angles.size() > 2 && angles.compare(angles.size() - 2, 2, "°") == 0) angles.erase(angles.size() - 2);
      std::fprintf(mcsv.f(), "%s,%zu,%zu,%g,%g,%d,%d,\"%s\"\n", cm.name.c_str(), cm.clean.vert.size(), c0.plain.face.size(), lave,
                   shape.first, shape.second, nsharp, angles == "–" ? "" : angles.c_str());
    }
    for (double noise : noises) {
      TMesh m;
      vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, const_cast<TMesh&>(cm.clean));
      NoiseAlongNormals(m, noise * lave, 11 + unsigned(10000 * noise));
      Context c(m);
      auto row = [&](const std::string& method, double angle, const Score& s) {
        std::fprintf(csv.f(), "%s,%g,%s,%g,%g,%g,%g,%g,%g,%g\n", cm.name.c_str(), noise * 100, method.c_str(), angle,
                     s.strict.precision, s.strict.recall, s.strict.f1, s.near.precision, s.near.recall, s.near.f1);
      };
      auto cell = [](const Score& s, double angle) {
        char b[96];
        if (angle > 0) std::snprintf(b, sizeof b, "%.2f / %.2f at %g°", s.strict.f1, s.near.f1, angle);
        else std::snprintf(b, sizeof b, "%.2f / %.2f", s.strict.f1, s.near.f1);
        return std::string(b);
      };
      // this filter with its defaults: classes and estimates from one run
      std::vector<nvv::VertexResult> res;
      {
        nvv::Summary sum;
        nvv::RunNormalVectorVoting(c.graph, ests[0].params, res, sum);
      }
      auto featuresOf = [](const std::vector<nvv::VertexResult>& r) {
        std::vector<char> f(r.size(), 0);
        for (std::size_t i = 0; i < r.size(); ++i)
          f[i] = r[i].cls == nvv::VertexClass::Crease || r[i].cls == nvv::VertexClass::Corner;
        return f;
      };
      const Score nvvDef = ScoreBoth(featuresOf(res), cm.sharp, ring);
      row("NVV defaults", nvv::Params().creaseAngleDeg, nvvDef);
      // automatic k (Params::autoK): its classes, the noise it estimated and the k it chose
      std::vector<nvv::VertexResult> resAuto;
      {
        nvv::Params p = ests[0].params;
        p.autoK = true;
        nvv::Summary sum;
        nvv::RunNormalVectorVoting(c.graph, p, resAuto, sum);
        row("NVV auto k", p.creaseAngleDeg, ScoreBoth(featuresOf(resAuto), cm.sharp, ring));
        std::fprintf(ncsv.f(), "%s,%g,%g,%g\n", cm.name.c_str(), noise * 100, 100 * sum.noiseOverEdge, sum.k);
      }
      // the votes alone, as in the paper (no sharp edges of clean meshes, sharp_edges.h)
      Score votesOnly;
      {
        nvv::Params p = ests[0].params;
        p.sharpEdgeAngleDeg = 0;
        std::vector<nvv::VertexResult> r;
        nvv::Summary sum;
        nvv::RunNormalVectorVoting(c.graph, p, r, sum);
        votesOnly = ScoreBoth(featuresOf(r), cm.sharp, ring);
        row("NVV votes only", p.creaseAngleDeg, votesOnly);
      }
      // the pictures' data (docs/images/accuracy_cad_parts.png): a coarse and a fine part, clean and
      // at 10 %: positions, truth, the defaults' classes, the votes' alone, MeshLab's dihedral test at 30 deg
      if ((cm.name == "bracket_coarse" || cm.name == "bracket_fine") && (noise == 0 || noise == 0.10)) {
        std::vector<nvv::VertexResult> r;
        nvv::Summary sum;
        nvv::Params p = ests[0].params;
        p.sharpEdgeAngleDeg = 0;
        nvv::RunNormalVectorVoting(c.graph, p, r, sum);
        const std::vector<char> dihedral = DihedralCreaseVertices(m, 30);
        Csv pts(outDir, "cadpic_" + cm.name + "_" + (noise == 0 ? "clean" : "noise10") + "_vertices.csv",
                "x,y,z,truth,nvv,votes,dihedral30");
        for (std::size_t i = 0; i < m.vert.size(); ++i)
          std::fprintf(pts.f(), "%g,%g,%g,%d,%d,%d,%d\n", m.vert[i].cP()[0], m.vert[i].cP()[1], m.vert[i].cP()[2],
                       int(cm.sharp[i]), int(res[i].cls), int(r[i].cls), int(dihedral[i]));
        Csv fs(outDir, "cadpic_" + cm.name + "_faces.csv", "a,b,c");
        for (const auto& f : c.plain.face) std::fprintf(fs.f(), "%d,%d,%d\n", f[0], f[1], f[2]);
      }
      // the filter and the peers at each angle; the best strict F1 of each
      Score best[3];
      double bestAngle[3] = {0, 0, 0};
      for (double a : angles) {
        nvv::Params p = ests[0].params;
        p.creaseAngleDeg = a;
        std::vector<nvv::VertexResult> r;
        nvv::Summary sum;
        nvv::RunNormalVectorVoting(c.graph, p, r, sum);
        const Score s[3] = {ScoreBoth(featuresOf(r), cm.sharp, ring), ScoreBoth(DihedralCreaseVertices(m, a), cm.sharp, ring),
                            ScoreBoth(CgalSharpVertices(c.plain, a), cm.sharp, ring)};
        const char* names[3] = {"NVV phi", "MeshLab dihedral", "CGAL sharp edges"};
        for (int j = 0; j < 3; ++j) {
          row(names[j], a, s[j]);
          if (bestAngle[j] == 0 || s[j].strict.f1 > best[j].strict.f1) { best[j] = s[j]; bestAngle[j] = a; }
        }
      }
      meshTable << "| " << cm.name << " | " << noise * 100 << " % | " << cell(nvvDef, 0) << " | " << cell(votesOnly, 0)
                << " | " << cell(best[0], bestAngle[0])
                << " | " << cell(best[1], bestAngle[1]) << " | " << cell(best[2], bestAngle[2]) << " |\n";
      std::fprintf(stderr, "cad: %s %g %%\n", cm.name.c_str(), noise * 100);
      auto& pool = pooled[size][noise];
      pool.push_back({nvvDef.strict.f1, votesOnly.strict.f1, best[0].strict.f1, best[1].strict.f1, best[2].strict.f1,
                      nvvDef.near.f1, votesOnly.near.f1, best[0].near.f1, best[1].near.f1, best[2].near.f1});

      // surfaces next to creases (the CAD parts only: the ABC file has no surface truth)
      std::vector<std::size_t> near;
      for (std::size_t i = 0; i < m.vert.size(); ++i)
        if (cm.point[i].known && dist[i] >= lave - 1e-9 && dist[i] <= 3 * lave + 1e-9) near.push_back(i);
      if (near.empty()) continue;
      curvTable << "| " << cm.name << " | " << noise * 100 << " % | " << near.size();
      for (std::size_t e = 0; e < ests.size(); ++e) {
        std::vector<Estimate> out;
        if (e == 0) FromNvv(res, out);
        else { ests[e].fn(c, out); ApplySign(ests[e].sign, out); }
        std::vector<double> en, ek;
        for (std::size_t i : near) {
          if (e == 0 && res[i].cls != nvv::VertexClass::Surface) continue;
          const PointTruth& t = cm.point[i];
          en.push_back(nvv_test::AngleDeg(out[i].n, t.n));
          ek.push_back(100 * std::abs(out[i].k1 - t.k1) * lave);
          ek.push_back(100 * std::abs(out[i].k2 - t.k2) * lave);
        }
        const Stat3 n = Stats(en), k = Stats(ek);
        curvTable << " | " << Num(n.median) << " / " << Num(n.p90) << "°; " << Num(k.median) << " / " << Num(k.p90) << " %"
                  << (e == 0 && en.size() < near.size() ? " (" + std::to_string(en.size()) + ")" : "");
        std::fprintf(ccsv.f(), "%s,%g,%s,%zu,%g,%g,%g,%g,%g,%g\n", cm.name.c_str(), noise * 100, ests[e].name.c_str(),
                     en.size(), n.median, n.p90, n.mean, k.median, k.p90, k.mean);
      }
      curvTable << " |\n";
      {  // automatic k, for the CSV only
        std::vector<double> en, ek;
        for (std::size_t i : near) {
          if (resAuto[i].cls != nvv::VertexClass::Surface) continue;
          const PointTruth& t = cm.point[i];
          en.push_back(nvv_test::AngleDeg(nvv_test::E(resAuto[i].normal), t.n));
          ek.push_back(100 * std::abs(resAuto[i].k1 - t.k1) * lave);
          ek.push_back(100 * std::abs(resAuto[i].k2 - t.k2) * lave);
        }
        const Stat3 n = Stats(en), k = Stats(ek);
        std::fprintf(ccsv.f(), "%s,%g,%s,%zu,%g,%g,%g,%g,%g,%g\n", cm.name.c_str(), noise * 100, "NVV auto k", en.size(),
                     n.median, n.p90, n.mean, k.median, k.p90, k.mean);
      }
    }
  }

  std::printf("#### Mean F1 over the meshes of each size\n\n"
              "Strict F1 / ±1-edge F1, averaged over the five parts (the ABC model alone).\n\n"
              "| meshes | noise | NVV defaults | NVV votes only | NVV best φ | MeshLab dihedral, best angle | CGAL sharp edges, best angle |\n"
              "|---|---|---|---|---|---|---|\n");
  Csv scsv(outDir, "cad_summary.csv", "meshes,noise,method,f1,near_f1");
  const int kPooled = 5;
  const char* pooledNames[kPooled] = {"NVV defaults", "NVV votes only", "NVV best phi", "MeshLab dihedral best",
                                      "CGAL sharp edges best"};
  for (const char* size : {"export", "coarse", "default", "fine", "ABC"}) {
    if (!pooled.count(size)) continue;
    for (const auto& kv : pooled[size]) {
      std::printf("| %s | %g %% |", size, kv.first * 100);
      for (int j = 0; j < kPooled; ++j) {
        double s = 0, t = 0;
        for (const auto& r : kv.second) { s += r[j]; t += r[j + kPooled]; }
        s /= kv.second.size();
        t /= kv.second.size();
        std::printf(" %.2f / %.2f |", s, t);
        std::fprintf(scsv.f(), "%s,%g,%s,%g,%g\n", size, kv.first * 100, pooledNames[j], s, t);
      }
      std::printf("\n");
    }
  }
  std::printf("\n#### Every mesh\n\nStrict F1 / ±1-edge F1; \"at\": the angle of the best strict F1 among 20, 30, 45 and "
              "60°.\n\n%s\n#### The meshes\n\nSlivers: triangles whose longest edge is over 10 times their height on it. "
              "Crease angles: the sharp model curves' normal-angles.\n\n%s",
              meshTable.str().c_str(), infoTable.str().c_str());
  std::printf("\n#### Surfaces next to creases\n\nVertices inside faces 1–3 l_ave (along mesh edges) from a sharp curve: "
              "normal error (deg) and curvature error (%% of 1/l_ave), median / p90; in brackets, how many of them "
              "this filter classes as surface where that is not all (the rest get no curvatures and are not scored).\n\n%s",
              curvTable.str().c_str());
  return 0;
}

}  // namespace nvv_bench

// Smooth surfaces with known geometry: the paper's 32x32 grids (plane, sphere and cylinder,
// R = 31 mm, noise along z as in the paper), the same sphere and cylinder on an irregular
// triangulation and at twice the resolution, and a torus (unequal curvatures, negative Gaussian
// curvature inside; noise along the normal). Noise: sigma = 0..20 % of l_ave.
// Metrics over interior vertices, three seeds pooled, median / p90 / mean:
//   normal: angle to the true normal (deg); the paper's Eq. 18 is 100 (1 - cos angle) %;
//   direction: angle between the direction of the smaller curvature and the truth (deg), where
//     the principal directions are defined (cylinder: the axis; torus);
//   curvature: 100 |kappa - kappa_true| R over kappa1 and kappa2 (%), R = 31 mm on the grids and
//     the tube radius on the torus; on the sphere this is the paper's Eq. 19.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "estimators.h"
#include "report.h"
#include "sections.h"

namespace nvv_bench {
namespace {

const double kR = 31;
const double kTorusA = 24, kTorusB = 8;

struct Truth {
  Eigen::Vector3d n, t2;
  double k1, k2;
  bool hasDir, use;
};

struct ShapeSet {
  const char* name;
  enum { Plane, Sphere, Cylinder, Torus } kind;
  int n;            // grid vertices per side
  double irregular;
  bool paperGrid;   // noise along z and interior |x|, |y| <= 10 mm
};

void Build(const ShapeSet& s, unsigned seed, TMesh& m) {
  if (s.kind == ShapeSet::Torus) {
    nvv_shapes::Torus(m, kTorusA, kTorusB, 150, 50, s.irregular, seed);
    return;
  }
  const int n = s.n;
  nvv_shapes::ParametricGrid(m, n, n, [&](double u, double v) {
    const double x = 31 * u - 15.5, y = 31 * v - 15.5;
    const double z = s.kind == ShapeSet::Plane ? 0 : s.kind == ShapeSet::Sphere ? std::sqrt(kR * kR - x * x - y * y)
                                                                               : std::sqrt(kR * kR - x * x);
    return vcg::Point3d(x, y, z);
  }, s.irregular, seed);
}

Truth TruthAt(const ShapeSet& s, const vcg::Point3d& q) {
  const Eigen::Vector3d p(q[0], q[1], q[2]);
  Truth t;
  t.hasDir = false;
  t.use = !s.paperGrid || (std::abs(p.x()) <= 10 && std::abs(p.y()) <= 10);
  switch (s.kind) {
    case ShapeSet::Plane: t.n = Eigen::Vector3d::UnitZ(); t.k1 = t.k2 = 0; break;
    case ShapeSet::Sphere: t.n = p.normalized(); t.k1 = t.k2 = 1 / kR; break;
    case ShapeSet::Cylinder:
      t.n = Eigen::Vector3d(p.x(), 0, p.z()).normalized();
      t.k1 = 1 / kR;
      t.k2 = 0;
      t.t2 = Eigen::Vector3d::UnitY();
      t.hasDir = true;
      break;
    case ShapeSet::Torus: {
      const double th = std::atan2(p.y(), p.x()), rho = std::hypot(p.x(), p.y());
      const double ph = std::atan2(p.z(), rho - kTorusA);
      t.n = Eigen::Vector3d(std::cos(ph) * std::cos(th), std::cos(ph) * std::sin(th), std::sin(ph));
      t.k1 = 1 / kTorusB;
      t.k2 = std::cos(ph) / (kTorusA + kTorusB * std::cos(ph));
      t.t2 = Eigen::Vector3d(-std::sin(th), std::cos(th), 0);
      t.hasDir = true;
      break;
    }
  }
  return t;
}
double CurvScale(const ShapeSet& s) { return s.kind == ShapeSet::Torus ? kTorusB : kR; }

struct Errors {
  std::vector<double> normal, dir, curv;
};

// The clean mesh of one seed (where the truth is evaluated) and its noisy copy (what the
// estimators see).
void BuildNoisy(const ShapeSet& s, double noise, unsigned seed, TMesh& clean, TMesh& m) {
  Build(s, seed, clean);
  Build(s, seed, m);
  const double sigma = noise * nvv_shapes::MeanEdge(m);
  const unsigned noiseSeed = 1000 * seed + unsigned(noise * 1000);
  if (s.paperGrid) nvv_shapes::AddNoise(m, sigma, noiseSeed, nvv_shapes::AlongZ);
  else NoiseAlongNormals(m, sigma, noiseSeed);
}

void MeasureOne(const ShapeSet& s, double noise, Estimator& est, Errors& acc, std::vector<Estimate>* keep = nullptr) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    TMesh clean, m;
    BuildNoisy(s, noise, seed, clean, m);
    Context c(m);
    std::vector<Estimate> e;
    est.fn(c, e);
    ApplySign(est.sign, e);
    for (std::size_t i = 0; i < m.vert.size(); ++i) {
      const Truth t = TruthAt(s, clean.vert[i].cP());
      if (!t.use) continue;
      acc.normal.push_back(nvv_test::AngleDeg(e[i].n, t.n));
      if (t.hasDir) acc.dir.push_back(nvv_test::AngleDeg(e[i].t2, t.t2));
      acc.curv.push_back(100 * std::abs(e[i].k1 - t.k1) * CurvScale(s));
      acc.curv.push_back(100 * std::abs(e[i].k2 - t.k2) * CurvScale(s));
    }
    if (keep && seed == 1) *keep = e;
  }
}

// The shapes and noise levels of the "grids" and "variants" sections (RunSmooth measures them,
// ExportSmooth writes them out for bench/python_peers.py).
std::vector<ShapeSet> SmoothSets(bool paper) {
  if (paper)
    return {
        {"plane", ShapeSet::Plane, 32, 0, true},
        {"sphere", ShapeSet::Sphere, 32, 0, true},
        {"cylinder", ShapeSet::Cylinder, 32, 0, true},
    };
  return {
      {"sphere irregular", ShapeSet::Sphere, 32, 0.6, true},
      {"cylinder irregular", ShapeSet::Cylinder, 32, 0.6, true},
      {"sphere 64x64 (0.5 mm)", ShapeSet::Sphere, 63, 0, true},
      {"torus a=24 b=8", ShapeSet::Torus, 0, 0, false},
  };
}
std::vector<double> SmoothNoises(bool paper) {
  return paper ? std::vector<double>{0, 0.01, 0.02, 0.05, 0.10, 0.20} : std::vector<double>{0, 0.05, 0.20};
}

}  // namespace

// Sign of each peer's curvature: positive mean curvature on the clean outward sphere.
void CalibrateSigns(std::vector<Estimator>& ests) {
  const ShapeSet sphere = {"sphere", ShapeSet::Sphere, 32, 0, true};
  TMesh m;
  Build(sphere, 1, m);
  Context c(m);
  for (auto& e : ests) {
    std::vector<Estimate> out;
    e.fn(c, out);
    double sum = 0;
    for (std::size_t i = 0; i < out.size(); ++i)
      if (TruthAt(sphere, m.vert[i].cP()).use && std::isfinite(out[i].k1 + out[i].k2)) sum += out[i].k1 + out[i].k2;
    e.sign = sum < 0 ? -1 : 1;
  }
}

std::vector<Estimator> SmoothEstimators(bool torus) {
  std::vector<Estimator> v;
  const std::vector<double> ks = torus ? std::vector<double>{1, 3, 5, 8} : std::vector<double>{1, 3, 5};
  for (double k : ks) v.push_back(Nvv(k, nvv::CurvatureFit::SheetQuadric));
  v.push_back(NvvAutoK());
  for (double k : ks) v.push_back(Nvv(k, nvv::CurvatureFit::SheetQuadric, 1));
  for (double k : ks) v.push_back(Nvv(k, nvv::CurvatureFit::PaperTaubin));
  for (double k : ks) v.push_back(Nvv(k, nvv::CurvatureFit::EulerLeastSquares));
  v.push_back(Vcg("MeshLab Taubin one-ring", VcgMethod::Taubin));
  v.push_back(Vcg("MeshLab PCA r=diag/20", VcgMethod::PCA));
  for (double k : ks)
    if (k > 1) {
      char b[64];
      std::snprintf(b, sizeof b, "MeshLab PCA r=%g l_ave", k);
      Estimator e = Vcg("", VcgMethod::PCA, k);
      e.name = b;
      v.push_back(e);
    }
  v.push_back(Vcg("MeshLab Normal Cycles", VcgMethod::NormalCycle));
  v.push_back(Vcg("MeshLab Quadric Fitting", VcgMethod::QuadricFitting));
  for (double k : ks) v.push_back(Jet(k));
  v.push_back(Jet(3, 2));
  v.push_back(Jet(5, 2));
  return v;
}

int RunSmooth(const std::string& outDir, const std::string& which) {
  const bool paper = which == "grids";
  const std::vector<ShapeSet> sets = SmoothSets(paper);
  const std::vector<double> noises = SmoothNoises(paper);
  std::vector<Estimator> ests = SmoothEstimators(!paper);
  CalibrateSigns(ests);
  std::printf("<!-- curvature signs calibrated on the clean sphere:");
  for (const auto& e : ests) if (e.sign < 0) std::printf(" [%s] -1", e.name.c_str());
  std::printf(" -->\n");

  Csv csv(outDir, "smooth_" + which + ".csv",
          "shape,noise,estimator,kind,k,normal_med,normal_p90,normal_mean,dir_med,dir_p90,dir_mean,curv_med,curv_p90,curv_mean");
  std::unique_ptr<Csv> hist;  // the histograms (paper's sphere, 5 % noise) come from "grids" only
  if (paper) hist.reset(new Csv(outDir, "smooth_hist.csv", "estimator,normal_deg,curv_pct"));
  for (const ShapeSet& s : sets) {
    std::printf("\n#### %s\n\n", s.name);
    const bool dir = s.kind == ShapeSet::Cylinder || s.kind == ShapeSet::Torus;
    std::printf("| noise | estimator | normal (deg) |%s curvature (%%) |\n|---|---|---|%s---|\n",
                dir ? " min. direction (deg) |" : "", dir ? "---|" : "");
    for (double noise : noises)
      for (auto& e : ests) {
        if (s.kind == ShapeSet::Torus && e.k == 1 && e.kind != 3) continue;
        Errors acc;
        MeasureOne(s, noise, e, acc);
        const Stat3 n = Stats(acc.normal), d = Stats(acc.dir), k = Stats(acc.curv);
        std::printf("| %g %% | %s | %s |%s%s %s |\n", noise * 100, e.name.c_str(), Cell(n).c_str(), dir ? " " : "",
                    dir ? (Cell(d) + " |").c_str() : "", Cell(k).c_str());
        std::fprintf(csv.f(), "%s,%g,%s,%d,%g,%g,%g,%g,%g,%g,%g,%g,%g,%g\n", s.name, noise * 100, e.name.c_str(), e.kind,
                     e.k, n.median, n.p90, n.mean, d.median, d.p90, d.mean, k.median, k.p90, k.mean);
        if (paper && s.kind == ShapeSet::Sphere && noise == 0.05)
          for (std::size_t i = 0; i < acc.normal.size(); ++i)
            std::fprintf(hist->f(), "%s,%g,%g\n", e.name.c_str(), acc.normal[i], acc.curv[2 * i]);
      }
    std::fflush(stdout);
  }
  return 0;
}

// Writes every mesh the "grids" and "variants" sections score (same shapes, seeds and noise) as
// binary PLY into outDir, with the truth and this project's default estimates at k = 3 and 5 as
// vertex properties, and lists them in outDir/meshes.csv. bench/python_peers.py runs the Python
// libraries' estimators on these files and scores everyone with the metrics of MeasureOne.
// Per vertex (double unless noted): x y z, the noisy position; true_n{x,y,z}, true_t2{x,y,z}
// (direction of the smaller curvature, zero where undefined), true_k1, true_k2; scored and
// has_dir (uchar); nvv{3,5}_n{x,y,z}, nvv{3,5}_t2{x,y,z}, nvv{3,5}_k1, nvv{3,5}_k2.
// Header comments: l_ave (as the core computes it), curvature_scale (R or the tube radius).
int ExportSmooth(const std::string& outDir) {
  std::vector<Estimator> ests = {Nvv(3, nvv::CurvatureFit::SheetQuadric), Nvv(5, nvv::CurvatureFit::SheetQuadric)};
  CalibrateSigns(ests);
  Csv list(outDir, "meshes.csv", "section,shape,noise,seed,file,vertices,curvature_scale");
  int count = 0;
  for (const char* section : {"grids", "variants"}) {
    const bool paper = std::string(section) == "grids";
    for (const ShapeSet& s : SmoothSets(paper))
      for (double noise : SmoothNoises(paper))
        for (unsigned seed = 1; seed <= 3; ++seed) {
          TMesh clean, m;
          BuildNoisy(s, noise, seed, clean, m);
          Context c(m);
          std::vector<std::vector<Estimate>> e(ests.size());
          for (std::size_t j = 0; j < ests.size(); ++j) {
            ests[j].fn(c, e[j]);
            ApplySign(ests[j].sign, e[j]);
          }
          char file[64];
          std::snprintf(file, sizeof file, "%s_%02d_%03g_%u.ply", section, ++count, noise * 100, seed);
          FILE* f = std::fopen((outDir + "/" + file).c_str(), "wb");
          if (!f) {
            std::fprintf(stderr, "cannot write %s/%s\n", outDir.c_str(), file);
            return 2;
          }
          std::fprintf(f, "ply\nformat binary_little_endian 1.0\n");
          std::fprintf(f, "comment shape %s\ncomment noise %g\ncomment seed %u\n", s.name, noise * 100, seed);
          std::fprintf(f, "comment l_ave %.17g\ncomment curvature_scale %.17g\n", c.lave, CurvScale(s));
          std::fprintf(f, "element vertex %zu\n", m.vert.size());
          const char* axes[] = {"x", "y", "z"};
          for (const char* a : axes) std::fprintf(f, "property double %s\n", a);
          for (const char* v : {"true_n", "true_t2"})
            for (const char* a : axes) std::fprintf(f, "property double %s%s\n", v, a);
          std::fprintf(f, "property double true_k1\nproperty double true_k2\n");
          std::fprintf(f, "property uchar scored\nproperty uchar has_dir\n");
          for (const auto& est : ests) {
            const int k = int(est.k);
            for (const char* v : {"n", "t2"})
              for (const char* a : axes) std::fprintf(f, "property double nvv%d_%s%s\n", k, v, a);
            std::fprintf(f, "property double nvv%d_k1\nproperty double nvv%d_k2\n", k, k);
          }
          std::fprintf(f, "element face %zu\nproperty list uchar int vertex_indices\nend_header\n", c.plain.face.size());
          auto put3 = [f](const Eigen::Vector3d& v) { std::fwrite(v.data(), sizeof(double), 3, f); };
          auto put = [f](double x) { std::fwrite(&x, sizeof x, 1, f); };
          for (std::size_t i = 0; i < m.vert.size(); ++i) {
            const Truth t = TruthAt(s, clean.vert[i].cP());
            put3(c.plain.pos[i]);
            put3(t.n);
            put3(t.hasDir ? t.t2 : Eigen::Vector3d::Zero());
            put(t.k1);
            put(t.k2);
            const unsigned char flags[2] = {t.use, t.hasDir};
            std::fwrite(flags, 1, 2, f);
            for (const auto& ej : e) {
              put3(ej[i].n);
              put3(ej[i].t2);
              put(ej[i].k1);
              put(ej[i].k2);
            }
          }
          for (const auto& fc : c.plain.face) {
            const unsigned char three = 3;
            std::fwrite(&three, 1, 1, f);
            std::fwrite(fc.data(), sizeof(int), 3, f);
          }
          std::fclose(f);
          std::fprintf(list.f(), "%s,%s,%g,%u,%s,%zu,%g\n", section, s.name, noise * 100, seed, file, m.vert.size(),
                       CurvScale(s));
        }
  }
  std::printf("wrote %d meshes to %s\n", count, outDir.c_str());
  return 0;
}

}  // namespace nvv_bench

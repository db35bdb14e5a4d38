// nvv_bench_paper_grids: the paper's experiment (par. 8) on its 32x32 plane / sphere / cylinder
// grids (1 mm spacing, R = 31 mm, Gaussian noise on z with sigma = 1 / 5 / 10 % of l_ave), interior
// vertices (|x|, |y| <= 10 mm), three noise seeds pooled. Prints, per estimator: normal error
// (deg) median / p90, the cylinder's minimum-direction error (deg, against the axis) median / p90,
// and the sphere's principal-curvature error |kappa R - 1| (%) median / p90; then the
// single-thread time per vertex of each pass at k = 3 on a 131,072-vertex sphere.
//
// Estimators: this project's default (crease-aware quadric fit) and the paper's Taubin form at
// k = 3 and 5, and vcglib's one-ring estimators (angle-weighted normals, Taubin's
// tri::UpdateCurvature::PrincipalDirections) that MeshLab uses.
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "test_support.h"

using namespace nvv_test;

namespace {

enum Shape { kPlane, kSphere, kCylinder };
const char* kShapeName[] = {"plane", "sphere", "cylinder"};
const double R = 31;

void Make(TMesh& m, Shape s, double noise, unsigned seed, int n = 32) {
  const double half = (n - 1) / 2.0;
  nvv_shapes::ParametricGrid(m, n, n, [&](double u, double v) {
    const double x = (n - 1) * u - half, y = (n - 1) * v - half;
    const double z = s == kPlane ? 0 : s == kSphere ? std::sqrt(R * R - x * x - y * y) : std::sqrt(R * R - x * x);
    return vcg::Point3d(x, y, z);
  });
  nvv_shapes::AddNoise(m, noise * nvv_shapes::MeanEdge(m), seed, nvv_shapes::AlongZ);
}
Eigen::Vector3d TrueNormal(Shape s, const vcg::Point3d& p) {
  if (s == kPlane) return Eigen::Vector3d(0, 0, 1);
  if (s == kSphere) return Eigen::Vector3d(p[0], p[1], std::sqrt(R * R - p[0] * p[0] - p[1] * p[1])) / R;
  return Eigen::Vector3d(p[0], 0, std::sqrt(R * R - p[0] * p[0])) / R;
}

struct Sample {
  std::vector<double> normalDeg, minDirDeg, curvPct;
};

// Per-vertex estimate: normal, (k1 >= k2), direction of k2.
struct Estimate {
  Eigen::Vector3d n, t2;
  double k1, k2;
};
typedef std::function<void(TMesh&, std::vector<Estimate>&)> Estimator;

Estimator Nvv(double k, nvv::CurvatureFit fit) {
  return [k, fit](TMesh& m, std::vector<Estimate>& out) {
    const NvvRun r = RunNvv(m, WithK(k, fit));
    out.resize(m.vert.size());
    for (std::size_t i = 0; i < m.vert.size(); ++i)
      out[i] = {E(r.res[i].normal), E(r.res[i].t2), r.res[i].k1, r.res[i].k2};
  };
}
void OneRing(TMesh& m, std::vector<Estimate>& out) {
  OneRingNormals(m);
  OneRingTaubin(m);
  out.resize(m.vert.size());
  for (std::size_t i = 0; i < m.vert.size(); ++i) {
    const auto& v = m.vert[i];
    // vcglib's sign and order vary: compare magnitudes, take the direction of the smaller one.
    double a = std::abs(v.cK1()), b = std::abs(v.cK2());
    Eigen::Vector3d t2 = b <= a ? E(v.cPD2()) : E(v.cPD1());
    out[i] = {E(v.cN()), t2, std::max(a, b), std::min(a, b)};
  }
}

void Measure(Shape s, double noise, const Estimator& est, Sample& acc) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    TMesh m;
    Make(m, s, noise, 100 * seed + unsigned(noise * 1000));
    std::vector<Estimate> e;
    est(m, e);
    for (std::size_t i = 0; i < m.vert.size(); ++i) {
      const auto& p = m.vert[i].cP();
      if (!Interior(p, 10.0)) continue;
      acc.normalDeg.push_back(AngleDeg(e[i].n, TrueNormal(s, p)));
      if (s == kCylinder) acc.minDirDeg.push_back(AngleDeg(e[i].t2, Eigen::Vector3d::UnitY()));
      if (s == kSphere) {
        acc.curvPct.push_back(100 * std::abs(std::abs(e[i].k1) * R - 1));
        acc.curvPct.push_back(100 * std::abs(std::abs(e[i].k2) * R - 1));
      }
    }
  }
}

}  // namespace

int main() {
  struct Named {
    const char* name;
    Estimator est;
  };
  const std::vector<Named> estimators = {
      {"NVV quadric k=3 (default)", Nvv(3, nvv::CurvatureFit::SheetQuadric)},
      {"NVV quadric k=5", Nvv(5, nvv::CurvatureFit::SheetQuadric)},
      {"NVV paper Taubin k=3", Nvv(3, nvv::CurvatureFit::PaperTaubin)},
      {"NVV paper Taubin k=5", Nvv(5, nvv::CurvatureFit::PaperTaubin)},
      {"vcglib one-ring (MeshLab)", OneRing},
  };
  std::printf("Paper's 32x32 grids, interior vertices, 3 seeds; median / p90\n\n");
  std::printf("| noise | estimator | plane normal (deg) | sphere normal (deg) | cylinder normal (deg) | "
              "cylinder min. dir. (deg) | sphere curvature (%%) |\n|---|---|---|---|---|---|---|\n");
  for (double noise : {0.0, 0.01, 0.05, 0.10})
    for (const auto& e : estimators) {
      Sample plane, sphere, cyl;
      Measure(kPlane, noise, e.est, plane);
      Measure(kSphere, noise, e.est, sphere);
      Measure(kCylinder, noise, e.est, cyl);
      auto f = [](const std::vector<double>& v) {
        const Stats s = StatsOf(v);
        char b[64];
        std::snprintf(b, sizeof b, "%.2f / %.2f", s.median, s.p90);
        return std::string(b);
      };
      std::printf("| %g %% | %s | %s | %s | %s | %s | %s |\n", noise * 100, e.name, f(plane.normalDeg).c_str(),
                  f(sphere.normalDeg).c_str(), f(cyl.normalDeg).c_str(), f(cyl.minDirDeg).c_str(),
                  f(sphere.curvPct).c_str());
    }
  // Time per vertex, one thread, k = 3, on a larger sphere with 5 % noise along the normals.
  TMesh big;
  nvv_shapes::UVSphere(big, R, 512, 256);
  nvv_shapes::AddNoise(big, 0.05 * nvv_shapes::MeanEdge(big), 9,
                       [](const vcg::Point3d& p) { return p / p.Norm(); });
  std::printf("\nSingle-thread time per vertex, UV sphere (%zu vertices, 5 %% noise), k = 3:\n", big.vert.size());
  for (auto fit : {nvv::CurvatureFit::SheetQuadric, nvv::CurvatureFit::PaperTaubin}) {
    nvv::Params p = WithK(3, fit);
    p.threads = 1;
    const NvvRun r = RunNvv(big, p);
    std::printf("  %-14s pass 1 %.1f us/vertex, pass 2 %.1f us/vertex\n",
                fit == nvv::CurvatureFit::SheetQuadric ? "quadric fit" : "paper Taubin",
                1e6 * r.sum.secondsPass1 / big.vert.size(), 1e6 * r.sum.secondsPass2 / big.vert.size());
  }
  return 0;
}

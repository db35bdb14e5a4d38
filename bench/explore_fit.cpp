// nvv_bench_explore_fit: the crease-aware quadric fit (sheet_fit.h) with its levers varied, on
// the paper's sphere and cylinder grids (interior, three seeds). Pass 1 comes from the core
// unchanged; pass 2 is re-run here with the lever set as given on the command line:
//   nvv_bench_explore_fit K NOISE_PERCENT SLOPE_WEIGHT(l_ave) [FITS]
// FITS = 2 fits again with the first fit's normals in the slope rows (re-voting with refined
// normals).
// Prints a markdown row: normal (deg, both grids), cylinder min. direction (deg), sphere
// curvature (%), median / p90.
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "report.h"
#include "test_support.h"
#include "core/ball_flood.h"
#include "core/sheet_fit.h"
#include "core/tangent_frame.h"

using namespace nvv_test;

namespace {
const double R = 31;
void Make(TMesh& m, bool sphere, double noise, unsigned seed) {
  nvv_shapes::ParametricGrid(m, 32, 32, [&](double u, double v) {
    const double x = 31 * u - 15.5, y = 31 * v - 15.5;
    return vcg::Point3d(x, y, sphere ? std::sqrt(R * R - x * x - y * y) : std::sqrt(R * R - x * x));
  });
  nvv_shapes::AddNoise(m, noise * nvv_shapes::MeanEdge(m), 1000 * seed + unsigned(noise * 1000), nvv_shapes::AlongZ);
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) return 2;
  const double k = std::atof(argv[1]), noise = std::atof(argv[2]) / 100, sw = std::atof(argv[3]);
  const int fits = argc > 4 ? std::atoi(argv[4]) : 1;
  std::vector<double> nerr, derr, kerr;
  for (int sphere = 0; sphere <= 1; ++sphere)
    for (unsigned seed = 1; seed <= 3; ++seed) {
      TMesh m;
      Make(m, sphere, noise, seed);
      nvv::SurfaceGraph g;
      nvv::BuildSurfaceGraph(m, g);
      nvv::Params p = WithK(k, nvv::CurvatureFit::PaperTaubin);  // keeps the voted normals
      std::vector<nvv::VertexResult> res;
      nvv::Summary sum;
      nvv::RunNormalVectorVoting(g, p, res, sum);
      nvv::BallFlood flood(g);  // the neighbourhood pass 2 of the core uses
      std::vector<nvv::SheetSample> samples;
      std::vector<Eigen::Vector3d> normal(g.VertexCount());
      for (int v = 0; v < g.VertexCount(); ++v) normal[v] = nvv::ToVec(res[v].normal).normalized();
      std::vector<nvv::PrincipalCurvatures> fit(g.VertexCount());
      for (int pass = 0; pass < fits; ++pass) {
        for (int v = 0; v < g.VertexCount(); ++v) {
          if (res[v].cls != nvv::VertexClass::Surface) continue;
          flood.Run(v, sum.radius, 1 << 20, [&](int x) { return res[x].cls != nvv::VertexClass::Surface; });
          samples.clear();
          for (int x : flood.Reached())
            if (res[x].cls == nvv::VertexClass::Surface) samples.push_back({g.pos[x] - g.pos[v], normal[x]});
          fit[v] = nvv::SheetQuadricFit(nvv::TangentFrame(normal[v]), samples, sum.radius, sw * g.meanEdge,
                                        std::cos(nvv::DegToRad(60)));
        }
        for (int v = 0; v < g.VertexCount(); ++v)
          if (fit[v].ok) normal[v] = fit[v].normal;
      }
      for (int v = 0; v < g.VertexCount(); ++v) {
        const auto& q = m.vert[v].cP();
        const nvv::PrincipalCurvatures& pc = fit[v];
        if (!Interior(q, 10) || !pc.ok) continue;
        const Eigen::Vector3d tn = sphere ? Eigen::Vector3d(q[0], q[1], q[2]) / R
                                          : Eigen::Vector3d(q[0], 0, q[2]).normalized();
        nerr.push_back(AngleDeg(pc.normal, tn));
        if (!sphere) derr.push_back(AngleDeg(pc.t2, Eigen::Vector3d::UnitY()));
        else {
          kerr.push_back(100 * std::abs(pc.k1 * R - 1));
          kerr.push_back(100 * std::abs(pc.k2 * R - 1));
        }
      }
    }
  const auto n = nvv_bench::Stats(nerr), d = nvv_bench::Stats(derr), c = nvv_bench::Stats(kerr);
  // One markdown row: k | noise | slope weight | fits | normal | direction | curvature.
  std::printf("| %g | %g %% | %g l_ave | %d | %.2f / %.2f | %.2f / %.2f | %.2f / %.2f |\n", k, noise * 100, sw, fits,
              n.median, n.p90, d.median, d.p90, c.median, c.p90);
  return 0;
}

// The estimators of the accuracy benchmark, all run in-process on the same mesh: this
// project's three pass-2 fits at k = 1, 3, 5 (8), MeshLab's four principal-direction methods
// (vcglib, peers_vcg.h), and CGAL's degree-2 jet fitting on the vertices within the same
// geodesic radius (peers_cgal.cpp). Every estimator's answer is mapped onto this project's
// convention (k1 >= k2, outward sphere +1/R) by a sign calibrated once on the clean sphere.
#ifndef NVV_BENCH_ESTIMATORS_H
#define NVV_BENCH_ESTIMATORS_H

#include <functional>
#include <string>
#include <vector>

#include "peers_vcg.h"
#include "test_support.h"
#include "core/geodesic_march.h"

namespace nvv_bench {

// What every estimator may use: the mesh, its plain arrays, and its mean edge length.
struct Context {
  const TMesh& m;
  PlainMesh plain;
  nvv::SurfaceGraph graph;
  double lave = 0;
  std::vector<Eigen::Vector3d> awn;  // angle-weighted normals (orientation for CGAL)
  explicit Context(const TMesh& mesh) : m(mesh) {
    plain.pos.resize(m.vert.size());
    for (std::size_t i = 0; i < m.vert.size(); ++i)
      plain.pos[i] = Eigen::Vector3d(m.vert[i].cP()[0], m.vert[i].cP()[1], m.vert[i].cP()[2]);
    for (const auto& f : m.face)
      if (!f.IsD())
        plain.face.push_back({int(vcg::tri::Index(m, f.cV(0))), int(vcg::tri::Index(m, f.cV(1))),
                              int(vcg::tri::Index(m, f.cV(2)))});
    nvv::BuildSurfaceGraph(m, graph);
    lave = graph.meanEdge;
    awn = AngleWeightedNormals(m);
  }
  // Vertices within geodesic distance r of each vertex (fast marching, the core's march),
  // at least the `atLeast` nearest.
  std::vector<std::vector<int>> Neighbourhoods(double r, int atLeast) const {
    std::vector<std::vector<int>> nb(plain.pos.size());
    nvv::GeodesicMarch march(graph);
    for (int v = 0; v < graph.VertexCount(); ++v) {
      march.Run(v, r, 1 << 30);
      if (int(march.Reached().size()) < atLeast) march.Run(v, 1e300, atLeast);
      nb[v] = march.Reached();
    }
    return nb;
  }
};

typedef std::function<void(Context&, std::vector<Estimate>&)> EstimatorFn;

// kind: 0 this project's default, 1 another variant of this project, 2 a peer at the same
// radius k, 3 a peer with its own fixed neighbourhood (compared at every k).
struct Estimator {
  std::string name;
  int kind;
  double k;
  EstimatorFn fn;
  double sign = 1;
  nvv::Params params;  // kinds 0 and 1: what fn runs
};

inline void FromNvv(const std::vector<nvv::VertexResult>& res, std::vector<Estimate>& out) {
  out.assign(res.size(), Estimate());
  for (std::size_t i = 0; i < res.size(); ++i) {
    const auto& r = res[i];
    out[i].n = nvv_test::E(r.normal);
    out[i].t1 = nvv_test::E(r.t1);
    out[i].t2 = nvv_test::E(r.t2);
    out[i].k1 = r.k1;
    out[i].k2 = r.k2;
  }
}

// This project with pass-2 fit `fit` and, for the quadric fit, `rounds` fit rounds.
inline Estimator Nvv(double k, nvv::CurvatureFit fit, int rounds = nvv::Params().fitRounds) {
  nvv::Params p = nvv_test::WithK(k, fit);
  p.fitRounds = rounds;
  const bool quadric = fit == nvv::CurvatureFit::SheetQuadric;
  const bool isDefault = quadric && rounds == nvv::Params().fitRounds;
  char fitName[48];
  if (isDefault) std::snprintf(fitName, sizeof fitName, "quadric (default)");
  else if (quadric) std::snprintf(fitName, sizeof fitName, "quadric, %d fit%s", rounds, rounds == 1 ? "" : "s");
  else std::snprintf(fitName, sizeof fitName, "%s", fit == nvv::CurvatureFit::PaperTaubin ? "paper Taubin" : "Euler LSQ");
  char name[80];
  std::snprintf(name, sizeof name, "NVV %s k=%g", fitName, k);
  Estimator e{name, isDefault ? 0 : 1, k, [p](Context& c, std::vector<Estimate>& out) {
                std::vector<nvv::VertexResult> res;
                nvv::Summary sum;
                nvv::RunNormalVectorVoting(c.graph, p, res, sum);
                FromNvv(res, out);
              }, 1, p};
  return e;
}

// The defaults with k chosen from the mesh's noise (Params::autoK, noise_estimate.h); k = 3 is
// only its floor, for the sections that filter estimators by k.
inline Estimator NvvAutoK() {
  Estimator e = Nvv(3, nvv::CurvatureFit::SheetQuadric);
  e.name = "NVV quadric (default) k=auto";
  e.kind = 1;
  e.params.autoK = true;
  const nvv::Params p = e.params;
  e.fn = [p](Context& c, std::vector<Estimate>& out) {
    std::vector<nvv::VertexResult> res;
    nvv::Summary sum;
    nvv::RunNormalVectorVoting(c.graph, p, res, sum);
    FromNvv(res, out);
  };
  return e;
}

inline Estimator Vcg(const char* name, VcgMethod method, double k = 0) {
  return {name, method == VcgMethod::PCA && k > 0 ? 2 : 3, k, [method, k](Context& c, std::vector<Estimate>& out) {
            VcgCurvature(c.m, method, k * c.lave, 1.0, out);
          }, 1, nvv::Params()};
}

inline Estimator Jet(double k, double radiusFactor = 1) {
  char name[80];
  if (radiusFactor == 1) std::snprintf(name, sizeof name, "CGAL jet r=%g l_ave", k);
  else std::snprintf(name, sizeof name, "CGAL jet r=%g l_ave (2x)", k * radiusFactor);
  return {name, radiusFactor == 1 ? 2 : 4, k, [k, radiusFactor](Context& c, std::vector<Estimate>& out) {
            CgalJet(c.plain, c.Neighbourhoods(k * radiusFactor * c.lave, 10), c.awn, out);
          }, 1, nvv::Params()};
}

// Flips an answer given in the opposite curvature sign convention.
inline void ApplySign(double sign, std::vector<Estimate>& e) {
  if (sign > 0) return;
  for (auto& x : e) {
    const double k1 = -x.k2, k2 = -x.k1;
    x.k1 = k1;
    x.k2 = k2;
    std::swap(x.t1, x.t2);
  }
}

}  // namespace nvv_bench

#endif

#include "crease_curvature.h"

#include <algorithm>
#include <cmath>

namespace nvv {

double CreaseCurvature(const GeodesicMarch& march, const std::vector<VertexResult>& res, int v, double sigma) {
  const Eigen::Vector3d T = ToVec(res[v].creaseTangent);
  double num = 0, den = 0;
  for (int x : march.Reached()) {
    if (x == v || res[x].cls != VertexClass::Crease) continue;
    const double g = march.Distance(x);
    if (!(g > 0)) continue;
    const double c = std::min(1.0, std::abs(T.dot(ToVec(res[x].creaseTangent))));
    const double w = VoteWeight(g, sigma);
    num += w * std::acos(c) / g;
    den += w;
  }
  return den > 0 ? num / den : 0.0;
}

PassEnd CurvatureAlongCreases(const SurfaceGraph& g, const Pass1Settings& s, int threads, PassProgress& progress,
                              std::vector<VertexResult>& out) {
  return ParallelOverVertices<GeodesicMarch>(g, threads, progress, [&](int v, GeodesicMarch& march) {
    VertexResult& r = out[v];
    if (r.cls != VertexClass::Crease) return;
    if (!march.Run(v, s.radius, s.maxNeighbourhood)) r.flags |= kNeighbourhoodCapped;
    // Two crease vertices a denormal distance apart would give an infinite rate of turn.
    const float kappa = float(CreaseCurvature(march, out, v, s.sigma));
    r.creaseCurvature = std::isfinite(kappa) ? kappa : 0.0f;
  });
}

}  // namespace nvv

// Curvature along a crease line (par. 6.5): the CREASE neighbours within g_m turn the crease
// tangent by an angle dphi_i over the geodesic distance g_i; kappa = sum w_i dphi_i/g_i / sum w_i
// with w_i = exp(-g_i / sigma). Tangents carry no sign: each is aligned with v's before the
// angle is taken. The curvature across the crease is singular; the cusp angle stands for it.
#ifndef NVV_CORE_CREASE_CURVATURE_H
#define NVV_CORE_CREASE_CURVATURE_H

#include <cmath>
#include <vector>

#include "geodesic_march.h"
#include "vertex_result.h"

namespace nvv {

inline Eigen::Vector3d ToVec(const float* p) { return Eigen::Vector3d(p[0], p[1], p[2]); }

// `march` must hold the march from v. Returns 0 when no other crease vertex was reached.
inline double CreaseCurvature(const GeodesicMarch& march, const std::vector<VertexResult>& res, int v,
                              double sigma) {
  const Eigen::Vector3d T = ToVec(res[v].creaseTangent);
  double num = 0, den = 0;
  for (int x : march.Reached()) {
    if (x == v || res[x].cls != VertexClass::Crease) continue;
    const double g = march.Distance(x);
    if (!(g > 0)) continue;
    const double c = std::min(1.0, std::abs(T.dot(ToVec(res[x].creaseTangent))));
    const double w = std::exp(-g / sigma);
    num += w * std::acos(c) / g;
    den += w;
  }
  return den > 0 ? num / den : 0.0;
}

}  // namespace nvv

#endif

// Curvature along a crease line (par. 6.5): the CREASE neighbours within g_m turn the crease
// tangent by an angle dphi_i over the geodesic distance g_i; kappa = sum w_i dphi_i/g_i / sum w_i
// with w_i = exp(-g_i / sigma). Tangents carry no sign: each is aligned with v's before the
// angle is taken. The curvature across the crease is singular; the cusp angle stands for it.
#ifndef NVV_CORE_CREASE_CURVATURE_H
#define NVV_CORE_CREASE_CURVATURE_H

#include <vector>

#include "geodesic_march.h"
#include "normal_votes.h"
#include "parallel_pass.h"
#include "vertex_result.h"

namespace nvv {

// `march` must hold the march from v. Returns 0 when no other crease vertex was reached.
double CreaseCurvature(const GeodesicMarch& march, const std::vector<VertexResult>& res, int v, double sigma);

// The crease curvature of every CREASE vertex, from a march of radius g_m (s.radius); reads the
// classes and tangents of pass 1 and thinning only.
PassEnd CurvatureAlongCreases(const SurfaceGraph& g, const Pass1Settings& s, int threads, PassProgress& progress,
                              std::vector<VertexResult>& out);

}  // namespace nvv

#endif

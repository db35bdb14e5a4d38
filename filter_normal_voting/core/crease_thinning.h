// Thins pass 1's feature band to its ridge: non-maximum suppression across creases.
//
// Every vertex within about g_m of a crease sees both sheets in its votes, so Eq. 10 marks a
// band up to 2 k edges wide, not the crease line itself; and with a small crease angle (large
// epsilon, which Eq. 10 also applies to corners) much of that band comes out CORNER, because
// the arc votes (Eq. 6) of the far sheet's faces scatter out of the two normals' plane. On
// fandisk at k = 3 with a 30 deg crease angle this gave 1,162 corners and a per-vertex crease
// precision of 0.37 (docs/accuracy.md). Across the band the feature strength
//   s = lambda_2 + lambda_3 = 1 - lambda_1      (sorted eigenvalues of Eq. 7, summing to 1)
// peaks on the ridge: with votes w_A n_A n_A' + w_B n_B n_B' (w_A + w_B = 1, angle alpha
// between the sheets) s = (1 - sqrt(1 - 4 w_A w_B sin^2 alpha)) / 2, largest where w_A = w_B,
// i.e. on the crease; it is 2/3 at a symmetric three-sheet corner.
//
// A CREASE vertex v stays a crease when no one-ring neighbour u that is a crease or corner and
// lies across v's crease (the edge v->u at least 37 deg from v's crease tangent, |cos| < 0.8,
// which keeps the diagonals of a grid) has a larger s; neighbours along the crease are not
// compared. A CORNER vertex stays a corner when no crease or corner neighbour has a larger s.
// The others become SURFACE vertices: their normal restarts from the area-weighted normal of
// their one-ring (off the ridge its faces lie on one sheet, while pass 1's E1 there mixes both
// sheets, or is the bisector for creases above 90 deg), and pass 2 fits their curvature and
// normal like any other surface vertex (the quadric fit's agreement weights keep the other
// sheet out). Decisions read pass-1 values only and are applied afterwards, so the result does
// not depend on the order or the thread count. Params::thinCreases = false keeps the paper's
// band.
#ifndef NVV_CORE_CREASE_THINNING_H
#define NVV_CORE_CREASE_THINNING_H

#include <algorithm>
#include <cstdint>
#include <vector>

#include "crease_curvature.h"
#include "surface_graph.h"
#include "vertex_result.h"

namespace nvv {

inline bool IsFeature(const VertexResult& r) { return r.cls == VertexClass::Crease || r.cls == VertexClass::Corner; }
// lambda_2 + lambda_3 of the sorted eigenvalues (they sum to 1): 0 on a sheet, (1 - cos alpha) / 2
// on a crease of normal-angle alpha with balanced sheets, 2/3 at a symmetric three-sheet corner.
inline float FeatureStrength(const VertexResult& r) { return 1.0f - std::max(r.lambda[0], r.lambda[1]); }

// True when feature vertex v is not the ridge of its band (see the header comment).
inline bool OffRidge(const SurfaceGraph& g, const std::vector<VertexResult>& res, int v) {
  const bool crease = res[v].cls == VertexClass::Crease;
  const Eigen::Vector3d T = ToVec(res[v].creaseTangent);
  const float mine = FeatureStrength(res[v]);
  for (int i = g.FaceBegin(v); i < g.FaceEnd(v); ++i)
    for (int u : g.face[g.vfList[i]]) {
      if (u == v || !IsFeature(res[u])) continue;
      const float theirs = FeatureStrength(res[u]);
      // Ties go to the lower index, so two equal neighbours do not remove each other.
      if (theirs < mine || (theirs == mine && u > v)) continue;
      if (!crease) return true;  // a corner must be the strongest feature of its one-ring
      const Eigen::Vector3d d = (g.pos[u] - g.pos[v]).normalized();
      if (std::abs(d.dot(T)) < 0.8) return true;
    }
  return false;
}

// Demotes every off-ridge crease or corner vertex to SURFACE. Returns how many were demoted.
inline std::size_t ThinCreaseBand(const SurfaceGraph& g, std::vector<VertexResult>& res, int threads) {
  const int n = g.VertexCount();
  std::vector<std::uint8_t> demote(n, 0);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (int v = 0; v < n; ++v)
    if (IsFeature(res[v])) demote[v] = OffRidge(g, res, v);
  std::size_t count = 0;
  for (int v = 0; v < n; ++v) {
    if (!demote[v]) continue;
    VertexResult& r = res[v];
    Eigen::Vector3d ring = g.RingNormalSum(v);
    if (!(ring.squaredNorm() > 0)) continue;
    ring.normalize();
    for (int j = 0; j < 3; ++j) r.normal[j] = float(ring[j]);
    r.cls = VertexClass::Surface;
    r.flags = std::uint8_t((r.flags & ~kCreaseValid) | kNormalValid);
    for (int j = 0; j < 3; ++j) r.creaseTangent[j] = 0;
    r.cuspAngle = 0;
    ++count;
  }
  return count;
}

}  // namespace nvv

#endif

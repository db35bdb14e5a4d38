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
// Two exceptions keep true creases: a CREASE neighbour whose tangent is more than 45 deg off
// v's lies on another crease (at a cube's corner the first vertex of one edge is the diagonal
// neighbour of the first vertex of the next), so it is not compared; and a crease vertex with
// two sharp mesh edges along its own crease (OnSharpEdge) is on a ridge of the mesh itself and
// stays (a chamfer's two creases, one edge apart). On the clean cube F1 went 0.98 -> 1.00, on the ABC
// model 0.93 -> 0.99 (docs/accuracy.md).
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
#include <cmath>
#include <cstdint>
#include <vector>

#include "crease_curvature.h"
#include "params.h"
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
      // A crease vertex whose tangent is more than 45 deg off v's lies on another crease (two
      // creases meeting at a corner): it is not across v's crease, whatever the edge's direction.
      if (res[u].cls == VertexClass::Crease && std::abs(ToVec(res[u].creaseTangent).dot(T)) < 0.7) continue;
      const Eigen::Vector3d d = (g.pos[u] - g.pos[v]).normalized();
      if (std::abs(d.dot(T)) < 0.8) return true;
    }
  return false;
}

// True when CREASE vertex v lies on a crease of the mesh itself: at least two of its edges
// (v, x) run along v's crease tangent (|cos| > 0.8) and have faces whose normals are more than
// the crease angle apart (cosSharp), as the two ridge edges through a vertex of a crease line
// do. Such a v is a ridge, not the flank of one: two parallel creases one edge apart (a
// chamfer) stay two creases. Requiring two aligned edges keeps a noisy flank's one odd edge from
// vetoing its thinning. Corners are not vetoed: on the noisy capped cylinder that kept flank
// corners (F1 0.87 -> 0.71 at 10 % noise).
inline bool OnSharpEdge(const SurfaceGraph& g, const std::vector<VertexResult>& res, int v, double cosSharp) {
  if (res[v].cls != VertexClass::Crease) return false;
  const Eigen::Vector3d T = ToVec(res[v].creaseTangent);
  int sharp = 0;
  for (int i = g.FaceBegin(v); i < g.FaceEnd(v); ++i) {
    const int f = g.vfList[i];
    if (!(g.faceArea[f] > 0)) continue;
    for (int x : g.face[f]) {
      if (x == v || !(std::abs((g.pos[x] - g.pos[v]).normalized().dot(T)) > 0.8)) continue;
      const int third = g.face[f][0] + g.face[f][1] + g.face[f][2] - v - x;
      g.ForEachFaceAcross(f, v, x, [&](int o) {  // each face pair once, from its lower face
        const auto& t = g.face[o];
        const bool duplicate = t[0] == third || t[1] == third || t[2] == third;  // f again: no edge neighbour
        if (o > f && !duplicate && g.faceArea[o] > 0 && g.faceNormal[f].dot(g.faceNormal[o]) < cosSharp) ++sharp;
      });
      if (sharp >= 2) return true;
    }
  }
  return false;
}

// Median over the mesh's interior edges of the angle (radians) between the normals of the two
// faces sharing it: 0 on a clean CAD mesh, a few degrees on a noisy scan. Estimated from the
// edges of at most ~100,000 evenly spread faces, so it costs little and holds little on any mesh.
inline double MedianEdgeAngle(const SurfaceGraph& g) {
  std::vector<float> angles;
  const int stride = std::max(1, g.FaceCount() / 100000);
  for (int f = 0; f < g.FaceCount(); f += stride) {
    if (!(g.faceArea[f] > 0)) continue;
    for (int j = 0; j < 3; ++j)
      g.ForEachFaceAcross(f, g.face[f][j], g.face[f][(j + 1) % 3], [&](int o) {  // each edge once, from its lower face
        if (o > f && g.faceArea[o] > 0)
          angles.push_back(float(std::acos(std::max(-1.0, std::min(1.0, g.faceNormal[f].dot(g.faceNormal[o]))))));
      });
  }
  if (angles.empty()) return 0;
  std::nth_element(angles.begin(), angles.begin() + angles.size() / 2, angles.end());
  return angles[angles.size() / 2];
}

// Demotes every off-ridge crease or corner vertex to SURFACE. Returns how many were demoted.
// An edge counts as sharp (OnSharpEdge) above the crease angle phi, or above five times the
// mesh's median edge angle when that is larger: on a noisy mesh an edge between two faces
// of one sheet often exceeds a small phi, and a fixed phi vetoed most of the flank's thinning
// (20 deg roof at 5 % noise: F1 0.35 -> 0.19); with the median's floor every shape of the
// benchmark scores at least what it did without the veto.
inline std::size_t ThinCreaseBand(const SurfaceGraph& g, std::vector<VertexResult>& res, int threads,
                                  double creaseAngleDeg) {
  const int n = g.VertexCount();
  const double sharpAngle = std::max(DegToRad(creaseAngleDeg), 5.0 * MedianEdgeAngle(g));
  const double cosSharp = std::cos(std::min(sharpAngle, DegToRad(179.0)));
  std::vector<std::uint8_t> demote(n, 0);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (int v = 0; v < n; ++v)
    if (IsFeature(res[v])) demote[v] = OffRidge(g, res, v) && !OnSharpEdge(g, res, v, cosSharp);
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

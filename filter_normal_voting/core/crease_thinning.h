// Thins pass 1's feature band to its ridge: non-maximum suppression across creases.
//
// Two forms. The default (Params::ridgeFit, ThinCreaseBandByRidgeFit) suppresses on the F
// statistic of a two-plane fit to the vertices' heights (ridge_fit.h), and drops the band
// vertices where that fit finds no kink of at least phi: on a 20 deg roof at 5 % noise with
// phi = 10 deg, where the faces' normals scatter by more than phi and pass 1 marks nearly
// every vertex, crease F1 went 0.35 -> 0.98 (docs/accuracy.md, "Levers measured"). The form
// below suppresses on the strength of Eq. 7's covariance, which is what the rest of this
// comment describes; the ridge-fit form keeps its corner rule, its 45 deg rule and its
// sharp-edge veto.
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
#include <array>
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

// True when a one-ring neighbour u of v with a score (score(u) > 0; ties go to the lower index,
// so two equal neighbours do not remove each other) at least v's lies across v's line T: the
// edge v->u at least 37 deg from T (|cos| < cosAcross = 0.8, which keeps the diagonals of a grid). A
// neighbour whose own line (lineOf(u); zero when it has none) is more than 45 deg off T lies on
// another crease (two creases meeting at a corner) and is not compared. With T zero (a corner)
// every stronger neighbour counts: a corner must be the strongest feature of its one-ring.
template <class Score, class Line>
bool StrongerNeighbourAcross(const SurfaceGraph& g, int v, const Eigen::Vector3d& T, Score score, Line lineOf,
                             double cosAcross = 0.8) {
  const float mine = score(v);
  for (int i = g.FaceBegin(v); i < g.FaceEnd(v); ++i)
    for (int u : g.face[g.vfList[i]]) {
      if (u == v) continue;
      const float theirs = score(u);
      if (!(theirs > 0) || theirs < mine || (theirs == mine && u > v)) continue;
      if (T.squaredNorm() == 0) return true;
      const Eigen::Vector3d Tu = lineOf(u);
      if (Tu.squaredNorm() > 0 && std::abs(Tu.dot(T)) < 0.7) continue;
      if (std::abs((g.pos[u] - g.pos[v]).normalized().dot(T)) < cosAcross) return true;
    }
  return false;
}

// True when feature vertex v is not the ridge of its band (see the header comment): scored by
// FeatureStrength.
inline bool OffRidge(const SurfaceGraph& g, const std::vector<VertexResult>& res, int v) {
  const Eigen::Vector3d T = res[v].cls == VertexClass::Crease ? ToVec(res[v].creaseTangent) : Eigen::Vector3d::Zero();
  return StrongerNeighbourAcross(g, v, T,
      [&](int u) { return IsFeature(res[u]) ? std::max(FeatureStrength(res[u]), 1e-30f) : 0.0f; },
      [&](int u) { return res[u].cls == VertexClass::Crease ? ToVec(res[u].creaseTangent) : Eigen::Vector3d::Zero(); });
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

// Makes feature vertex v a SURFACE vertex whose normal restarts from its one-ring's; returns
// 1, or 0 when v has no one-ring normal (then it stays as it is).
inline int DemoteToSurface(const SurfaceGraph& g, VertexResult& r, int v) {
  Eigen::Vector3d ring = g.RingNormalSum(v);
  if (!(ring.squaredNorm() > 0)) return 0;
  ring.normalize();
  for (int j = 0; j < 3; ++j) r.normal[j] = float(ring[j]);
  r.cls = VertexClass::Surface;
  r.flags = std::uint8_t((r.flags & ~kCreaseValid) | kNormalValid);
  for (int j = 0; j < 3; ++j) r.creaseTangent[j] = 0;
  r.cuspAngle = 0;
  return 1;
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
    if (demote[v]) count += DemoteToSurface(g, res[v], v);
  }
  return count;
}

// Pass 1's feature vertex v as the ridge fit (ridge_fit.h) sees it.
struct RidgeScore {
  float F = 0;                                // the kink's F statistic; 0: not a ridge of angle >= phi
  std::array<float, 3> tangent{{0, 0, 0}};   // the fitted ridge line
  float alphaRad = 0;
};

// True when ridge candidate v is not the ridge of its band: a one-ring candidate across v's
// fitted line whose own line is within 45 deg of v's has a larger F (StrongerNeighbourAcross).
inline bool OffFittedRidge(const SurfaceGraph& g, const std::vector<RidgeScore>& ridge, int v) {
  auto line = [&](int u) { return ToVec(ridge[u].tangent.data()); };
  return StrongerNeighbourAcross(g, v, line(v), [&](int u) { return ridge[u].F; }, line);
}

// Closes one-vertex gaps in the kept ridge lines: a SURFACE vertex v with two kept ridge-fit
// CREASE neighbours a and b on opposite sides (the edges v->a and v->b within 37 deg of a's and
// b's lines, |cos| > 0.8, and of each other's reverse), whose lines are within 45 deg, becomes a
// CREASE along a->b. At a 175 deg crease pass 1 misses single ridge vertices (a fin's two sheets
// cast nearly the same vote tensor), and at 20 % noise the ridge fit drops some: crease F1 at
// k = 3 and 20 % noise went 0.91 -> 0.93 on the 90 deg roof, 0.78 -> 0.82 on the capped
// cylinder, 0.96 -> 0.97 at 10 % on the 175 deg roof (docs/accuracy.md). Reads the classes
// before it, writes after: order- and thread-independent. Returns the number of vertices closed.
inline std::size_t CloseCreaseGaps(const SurfaceGraph& g, std::vector<VertexResult>& res,
                                   const std::vector<RidgeScore>& ridge, int threads) {
  const int n = g.VertexCount();
  // True when u is a kept ridge crease and v lies on its line; d: the unit edge v -> u.
  auto onLineOf = [&](int v, int u, Eigen::Vector3d& d) {
    if (u == v || res[u].cls != VertexClass::Crease || !(ridge[u].F > 0)) return false;
    d = (g.pos[u] - g.pos[v]).normalized();
    return std::abs(d.dot(ToVec(ridge[u].tangent.data()))) > 0.8;
  };
  // The gap's two ends, or -1.
  std::vector<std::array<int, 2>> ends(n, std::array<int, 2>{{-1, -1}});
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (int v = 0; v < n; ++v) {
    if (res[v].cls != VertexClass::Surface || !g.usable[v]) continue;
    for (int i = g.FaceBegin(v); i < g.FaceEnd(v) && ends[v][0] < 0; ++i)
      for (int a : g.face[g.vfList[i]]) {
        Eigen::Vector3d da, db;
        if (!onLineOf(v, a, da)) continue;
        const Eigen::Vector3d Ta = ToVec(ridge[a].tangent.data());
        for (int j = g.FaceBegin(v); j < g.FaceEnd(v) && ends[v][0] < 0; ++j)
          for (int b : g.face[g.vfList[j]])
            if (b != a && onLineOf(v, b, db) && da.dot(db) < -0.8 &&
                std::abs(Ta.dot(ToVec(ridge[b].tangent.data()))) > 0.7) {
              ends[v] = {{a, b}};
              break;
            }
        if (ends[v][0] >= 0) break;
      }
  }
  std::size_t closed = 0;
  for (int v = 0; v < n; ++v) {
    const int a = ends[v][0], b = ends[v][1];
    if (a < 0) continue;
    VertexResult& r = res[v];
    r.cls = VertexClass::Crease;
    r.flags |= kCreaseValid | kNormalValid;
    const Eigen::Vector3d t = (g.pos[b] - g.pos[a]).normalized();
    for (int j = 0; j < 3; ++j) r.creaseTangent[j] = float(t[j]);
    r.cuspAngle = 0.5f * (ridge[a].alphaRad + ridge[b].alphaRad);
    ++closed;
  }
  return closed;
}

// The ridge-fit form of ThinCreaseBand: a feature vertex stays one when its ridge fit found a
// kink of at least phi (ridge[v].F > 0), no candidate across its line has a larger F, and no
// sharp-edge crease (below) lies clearly across it; or when it lies on a sharp mesh edge itself
// (OnSharpEdge, as in ThinCreaseBand). A kept CORNER stays a corner when it is also the strongest
// feature of its one-ring (OffRidge); otherwise it becomes a CREASE along its fitted line. Every
// kept CREASE takes the fitted line as its tangent. Last, one-vertex gaps in the kept lines are
// closed (CloseCreaseGaps). Returns the feature vertices removed, net of the gaps closed.
//
// Two rules replaced earlier ones; together, crease F1 at k = 3 (docs/accuracy.md) went at 20 %
// noise 0.89 -> 0.97 on the 40 deg roof, 0.94 -> 1.00 (60 deg), 0.93 -> 0.99 (90 deg),
// 0.83 -> 0.93 (120 deg), 0.92 -> 0.96 on the cube, 0.88 -> 0.91 on the capped cylinder, 0.89 ->
// 0.95 on the 20 deg roof at 10 %, and on fandisk / the ABC model at 10 % 0.93 -> 0.96 / 0.94:
// - A corner that was the strongest feature of its one-ring stayed a corner with no F test. At
//   10-20 % noise those were mostly noise maxima one row off the ridge; now a corner must pass
//   the same tests as a crease first.
// - A sharp-edge crease is kept whatever its F, so it suppressed no neighbour. Now a ridge-fit
//   candidate with such a crease in its one-ring, across its line (the edge within 45 deg of the
//   normal to the line, |cos| < 0.7) and along it (lines within 45 deg), is that crease's flank
//   and is dropped (120 deg roof at 20 %: 0.85 -> 0.93). The stricter 45 deg keeps a fin's
//   jagged ridge, whose next vertex along the line is often 37-45 deg off it in z (175 deg roof
//   at 20 %: 0.97, 0.95 with 37 deg).
inline std::size_t ThinCreaseBandByRidgeFit(const SurfaceGraph& g, std::vector<VertexResult>& res,
                                            const std::vector<RidgeScore>& ridge, int threads, double creaseAngleDeg) {
  const int n = g.VertexCount();
  const double sharpAngle = std::max(DegToRad(creaseAngleDeg), 5.0 * MedianEdgeAngle(g));
  const double cosSharp = std::cos(std::min(sharpAngle, DegToRad(179.0)));
  std::vector<std::uint8_t> sharp(n, 0);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (int v = 0; v < n; ++v)
    if (IsFeature(res[v])) sharp[v] = OnSharpEdge(g, res, v, cosSharp);
  auto lineOf = [&](int u) { return ridge[u].F > 0 ? ToVec(ridge[u].tangent.data()) : ToVec(res[u].creaseTangent); };
  auto sharpScore = [&](int u) { return sharp[u] ? 1.0f : 0.0f; };
  // 0 keep as is, 1 demote to surface, 2 corner to crease
  std::vector<std::uint8_t> action(n, 0);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (int v = 0; v < n; ++v) {
    if (!IsFeature(res[v])) continue;
    const bool ridgeHere = ridge[v].F > 0;
    const bool keep = sharp[v] || (ridgeHere && !OffFittedRidge(g, ridge, v) &&
                                   !StrongerNeighbourAcross(g, v, lineOf(v), sharpScore, lineOf, 0.7));
    if (!keep) action[v] = 1;
    else if (res[v].cls == VertexClass::Corner && OffRidge(g, res, v)) action[v] = 2;
  }
  // Where two fitted ridges meet (a cube's corner) the fit of the meeting vertex sees three
  // sheets and loses to its neighbours: a demoted vertex that lies on the lines of two kept
  // crease neighbours (the edge to each within 37 deg of its line) more than 45 deg apart is
  // kept as a corner.
  std::vector<std::uint8_t> corner(n, 0);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (int v = 0; v < n; ++v) {
    if (action[v] != 1) continue;
    Eigen::Vector3d first = Eigen::Vector3d::Zero();
    for (int i = g.FaceBegin(v); i < g.FaceEnd(v) && !corner[v]; ++i)
      for (int u : g.face[g.vfList[i]]) {
        if (u == v || action[u] == 1 || res[u].cls != VertexClass::Crease || !(ridge[u].F > 0)) continue;
        const Eigen::Vector3d T = ToVec(ridge[u].tangent.data());
        if (std::abs((g.pos[v] - g.pos[u]).normalized().dot(T)) < 0.8) continue;  // v is not on u's line
        if (first.squaredNorm() == 0) first = T;
        else if (std::abs(first.dot(T)) < 0.7) { corner[v] = 1; break; }
      }
  }
  std::size_t count = 0;
  for (int v = 0; v < n; ++v) {
    VertexResult& r = res[v];
    if (action[v] == 0 && r.cls == VertexClass::Crease && ridge[v].F > 0) {
      for (int j = 0; j < 3; ++j) r.creaseTangent[j] = ridge[v].tangent[j];
      continue;
    }
    if (action[v] == 2) {
      r.cls = VertexClass::Crease;
      r.flags |= kCreaseValid | kNormalValid;
      for (int j = 0; j < 3; ++j) r.creaseTangent[j] = ridge[v].tangent[j];
      r.cuspAngle = ridge[v].alphaRad;
      continue;
    }
    if (action[v] != 1) continue;
    if (corner[v]) {
      r.cls = VertexClass::Corner;
      r.flags = std::uint8_t(r.flags & ~(kCreaseValid | kNormalValid));
      continue;
    }
    count += DemoteToSurface(g, r, v);
  }
  // Net: what thinning took from pass 1's features, so features with and without it differ by it.
  const std::size_t closed = CloseCreaseGaps(g, res, ridge, threads);
  return count > closed ? count - closed : 0;
}

}  // namespace nvv

#endif

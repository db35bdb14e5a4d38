// Geodesic neighbourhood of one vertex (par. 6.1): single-source fast marching on triangles
// (Kimmel-Sethian), stopped at the radius g_m.
//
// Update of a vertex C through a triangle (A, B, C) whose A and B are accepted: unfold the
// triangle into the plane with A = (0,0), B = (|AB|,0), C above AB, and place the virtual
// source S below AB at distances d_A, d_B from A and B. When the straight segment S->C
// crosses AB between A and B, d_C = |C - S| (exact on a plane); otherwise (obtuse
// triangles, or no such S) d_C = min(d_A + |AC|, d_B + |BC|), the edge path.
//
// Scratch state is per instance (one per thread), allocated once for the whole mesh and
// reset in O(visited) after each march.
#ifndef NVV_CORE_GEODESIC_MARCH_H
#define NVV_CORE_GEODESIC_MARCH_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <vector>

#include "surface_graph.h"

namespace nvv {

// Planar unfolding update of d_C from accepted A, B (see the header comment).
inline double UnfoldedDistance(const Eigen::Vector3d& A, const Eigen::Vector3d& B,
                               const Eigen::Vector3d& C, double dA, double dB) {
  const double c = (B - A).norm();
  const double b = (C - A).norm();  // |AC|
  const double a = (C - B).norm();  // |BC|
  const double edgePath = std::min(dA + b, dB + a);
  if (!(c > 0)) return edgePath;
  const double cx = (b * b - a * a + c * c) / (2 * c);
  const double cy2 = b * b - cx * cx;
  const double sx = (dA * dA - dB * dB + c * c) / (2 * c);
  const double sy2 = dA * dA - sx * sx;
  if (!(cy2 > 0) || !(sy2 >= 0)) return edgePath;
  const double cy = std::sqrt(cy2), sy = -std::sqrt(sy2);
  // Where the segment S->C meets the line of AB (y = 0).
  const double t = -sy / (cy - sy);
  const double x = sx + t * (cx - sx);
  if (x < 0 || x > c) return edgePath;
  const double d = std::hypot(cx - sx, cy - sy);
  return std::min(d, edgePath);
}

class GeodesicMarch {
 public:
  explicit GeodesicMarch(const SurfaceGraph& g)
      : g_(g), dist_(g.VertexCount(), std::numeric_limits<double>::infinity()),
        state_(g.VertexCount(), kFar) {}

  // Marches from `source` until the next vertex would be farther than `radius` or
  // `maxVertices` vertices are accepted. `blocked(v)` true: v may be accepted (it is reached)
  // but the front does not expand through it and it never serves as A or B of an update.
  // Returns false when the march stopped at maxVertices.
  template <class Blocked>
  bool Run(int source, double radius, int maxVertices, Blocked blocked) {
    Reset();
    touched_.push_back(source);
    dist_[source] = 0;
    state_[source] = kTentative;
    heap_.push({0.0, source});
    bool complete = true;
    while (!heap_.empty()) {
      const Entry e = heap_.top();
      if (state_[e.v] == kAccepted || e.d > dist_[e.v]) { heap_.pop(); continue; }
      if (e.d > radius) break;
      if (int(reached_.size()) >= maxVertices) { complete = false; break; }
      heap_.pop();
      state_[e.v] = kAccepted;
      reached_.push_back(e.v);
      if (e.v != source && blocked(e.v)) { state_[e.v] = kAcceptedBlocked; continue; }
      Expand(e.v);
    }
    return complete;
  }
  bool Run(int source, double radius, int maxVertices) {
    return Run(source, radius, maxVertices, [](int) { return false; });
  }

  // Accepted vertices in increasing distance; the source first.
  const std::vector<int>& Reached() const { return reached_; }
  // Distance of a touched vertex (tentative beyond the radius), +inf if never touched.
  double Distance(int v) const { return dist_[v]; }
  bool IsReached(int v) const { return state_[v] == kAccepted || state_[v] == kAcceptedBlocked; }

 private:
  enum : std::uint8_t { kFar = 0, kTentative = 1, kAccepted = 2, kAcceptedBlocked = 3 };
  struct Entry {
    double d;
    int v;
    bool operator<(const Entry& o) const { return d > o.d || (d == o.d && v > o.v); }  // min-heap
  };

  void Reset() {
    for (int v : touched_) {
      dist_[v] = std::numeric_limits<double>::infinity();
      state_[v] = kFar;
    }
    touched_.clear();
    reached_.clear();
    while (!heap_.empty()) heap_.pop();
  }

  void Relax(int v, double d) {
    if (state_[v] == kAccepted || state_[v] == kAcceptedBlocked) return;
    if (state_[v] == kFar) { touched_.push_back(v); state_[v] = kTentative; }
    if (d < dist_[v]) {
      dist_[v] = d;
      heap_.push({d, v});
    }
  }

  void Expand(int x) {
    for (int i = g_.FaceBegin(x); i < g_.FaceEnd(x); ++i) {
      const int fi = g_.vfList[i];
      const auto& f = g_.face[fi];
      const int j = f[0] == x ? 0 : (f[1] == x ? 1 : 2);
      const int y = f[(j + 1) % 3], z = f[(j + 2) % 3];
      const bool useTriangle = g_.faceArea[fi] > 0;
      UpdateThrough(x, y, z, useTriangle);
      UpdateThrough(x, z, y, useTriangle);
    }
  }

  // Updates c from the accepted x, through the triangle when its third vertex o is accepted too.
  void UpdateThrough(int x, int o, int c, bool useTriangle) {
    if (IsReached(c)) return;
    double d;
    if (useTriangle && state_[o] == kAccepted)
      d = UnfoldedDistance(g_.pos[x], g_.pos[o], g_.pos[c], dist_[x], dist_[o]);
    else
      d = dist_[x] + (g_.pos[c] - g_.pos[x]).norm();
    Relax(c, d);
  }

  const SurfaceGraph& g_;
  std::vector<double> dist_;
  std::vector<std::uint8_t> state_;
  std::vector<int> touched_, reached_;
  std::priority_queue<Entry> heap_;
};

}  // namespace nvv

#endif

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
// reset in O(visited) after each march: a march of a few hundred vertices never pays for the
// mesh's size, and the per-vertex loop allocates nothing once the vectors have grown.
//
// Cost per march (what the profile of the two passes showed, and what was done about it):
//  - the edge lengths of the unfolding are read from SurfaceGraph::faceEdge, computed once,
//    instead of three square roots and three position loads per update;
//  - the front is an indexed binary heap with decrease-key, one entry per tentative vertex,
//    instead of a lazy-deletion priority queue whose stale duplicates (a vertex is improved
//    from several faces) doubled its size and the cost of every push and pop;
//  - a vertex whose tentative distance exceeds the radius keeps that distance (Distance() of the
//    one-ring needs it) but enters the heap only once an update brings it within the radius:
//    such an entry could never be popped, and the ring just outside g_m (a third of the touched
//    vertices at k = 3) only made every sift deeper;
//  - the unfolded segment length is sqrt(dx^2 + dy^2), not std::hypot: both operands are finite
//    here, and hypot's overflow-safe scaling was 7 % of the whole filter's profile.
// None changes the order of acceptance (the heap pops the unique minimum of (distance, vertex)
// among the entries within the radius); sqrt rounds differently from hypot in the last bit.
#ifndef NVV_CORE_GEODESIC_MARCH_H
#define NVV_CORE_GEODESIC_MARCH_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "huge_pages.h"
#include "surface_graph.h"

namespace nvv {

// Planar unfolding update of d_C from accepted A, B, given the lengths c = |AB|, b = |AC|,
// a = |BC| of the triangle (see the header comment).
inline double UnfoldedDistanceFromLengths(double c, double b, double a, double dA, double dB) {
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
  const double dx = cx - sx, dy = cy - sy;
  const double d = std::sqrt(dx * dx + dy * dy);
  return std::min(d, edgePath);
}

class GeodesicMarch {
 public:
  explicit GeodesicMarch(const SurfaceGraph& g)
      : g_(g), dist_(FilledOnHugePages(g.VertexCount(), std::numeric_limits<double>::infinity())),
        state_(FilledOnHugePages<std::uint8_t>(g.VertexCount(), kFar)),
        heapIndex_(FilledOnHugePages(g.VertexCount(), -1)) {}

  // Marches from `source` until the next vertex would be farther than `radius` or
  // `maxVertices` vertices are accepted. `blocked(v)` true: v may be accepted (it is reached)
  // but the front does not expand through it and it never serves as A or B of an update.
  // Returns false when the march stopped at maxVertices.
  template <class Blocked>
  bool Run(int source, double radius, int maxVertices, Blocked blocked) {
    Reset();
    radius_ = radius;
    touched_.push_back(source);
    dist_[source] = 0;
    state_[source] = kTentative;
    Push({0.0, source});
    bool complete = true;
    while (!heap_.empty()) {
      const Entry e = heap_.front();  // the tentative vertex of least (distance, index)
      if (e.d > radius) break;
      if (int(reached_.size()) >= maxVertices) { complete = false; break; }
      PopFront();
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
  };
  // Strict total order of the front: by distance, ties by vertex index, so the order of
  // acceptance does not depend on the heap's layout (nor on the thread count).
  static bool Before(const Entry& a, const Entry& b) { return a.d < b.d || (a.d == b.d && a.v < b.v); }

  void Reset() {
    for (int v : touched_) {
      dist_[v] = std::numeric_limits<double>::infinity();
      state_[v] = kFar;
    }
    for (const Entry& e : heap_) heapIndex_[e.v] = -1;
    touched_.clear();
    reached_.clear();
    heap_.clear();
  }

  // Indexed binary heap: heapIndex_[v] is v's slot in heap_ (-1 when not there). Sifting moves
  // a hole instead of swapping, and keeps heapIndex_ in step.
  void SiftUp(int i, Entry e) {
    while (i > 0) {
      const int parent = (i - 1) / 2;
      if (!Before(e, heap_[parent])) break;
      heap_[i] = heap_[parent];
      heapIndex_[heap_[i].v] = i;
      i = parent;
    }
    heap_[i] = e;
    heapIndex_[e.v] = i;
  }
  void Push(Entry e) {
    heap_.push_back(e);
    SiftUp(int(heap_.size()) - 1, e);
  }
  void PopFront() {
    heapIndex_[heap_.front().v] = -1;
    const Entry last = heap_.back();
    heap_.pop_back();
    const int n = int(heap_.size());
    if (n == 0) return;
    int i = 0;
    for (;;) {
      int child = 2 * i + 1;
      if (child >= n) break;
      if (child + 1 < n && Before(heap_[child + 1], heap_[child])) ++child;
      if (!Before(heap_[child], last)) break;
      heap_[i] = heap_[child];
      heapIndex_[heap_[i].v] = i;
      i = child;
    }
    heap_[i] = last;
    heapIndex_[last.v] = i;
  }

  void Relax(int v, double d) {
    if (state_[v] == kAccepted || state_[v] == kAcceptedBlocked) return;
    if (state_[v] == kFar) { touched_.push_back(v); state_[v] = kTentative; }
    if (d < dist_[v]) {
      dist_[v] = d;
      const int i = heapIndex_[v];
      if (i >= 0) SiftUp(i, {d, v});            // decrease-key: a smaller key only moves up
      else if (d <= radius_) Push({d, v});      // beyond g_m it could never be popped (header comment)
    }
  }

  void Expand(int x) {
    for (int i = g_.FaceBegin(x); i < g_.FaceEnd(x); ++i) {
      const int fi = g_.vfList[i];
      const auto& f = g_.face[fi];
      const int j = f[0] == x ? 0 : (f[1] == x ? 1 : 2);
      const int j1 = j == 2 ? 0 : j + 1, j2 = j == 0 ? 2 : j - 1;
      const int y = f[j1], z = f[j2];
      // faceEdge[fi][j] = |xy|, [j1] = |yz|, [j2] = |zx|.
      const auto& e = g_.faceEdge[fi];
      const bool useTriangle = g_.faceArea[fi] > 0;
      UpdateThrough(x, y, z, e[j], e[j2], e[j1], useTriangle);
      UpdateThrough(x, z, y, e[j2], e[j], e[j1], useTriangle);
    }
  }

  // Updates c from the accepted x, through the triangle when its third vertex o is accepted
  // too; xo, xc, oc are the triangle's edge lengths.
  void UpdateThrough(int x, int o, int c, double xo, double xc, double oc, bool useTriangle) {
    if (IsReached(c)) return;
    double d;
    if (useTriangle && state_[o] == kAccepted)
      d = UnfoldedDistanceFromLengths(xo, xc, oc, dist_[x], dist_[o]);
    else
      d = dist_[x] + xc;
    Relax(c, d);
  }

  const SurfaceGraph& g_;
  double radius_ = 0;
  std::vector<double> dist_;
  std::vector<std::uint8_t> state_;
  std::vector<int> heapIndex_;
  std::vector<int> touched_, reached_;
  std::vector<Entry> heap_;
};

}  // namespace nvv

#endif

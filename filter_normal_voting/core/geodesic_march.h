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
// mesh's size, and the per-vertex loop allocates nothing once the vectors have grown. A vertex's
// distance, state and heap slot share one 16-byte record: every touch of a vertex reads all
// three, so a scattered neighbour costs one cache miss instead of three.
//
// Cost per march: the edge lengths of the unfolding are read from SurfaceGraph::faceEdge; the
// front is an indexed binary heap with decrease-key (one entry per tentative vertex); a vertex
// whose tentative distance exceeds the radius keeps that distance (Distance() of the one-ring
// needs it) but enters the heap only once an update brings it within the radius, since such an
// entry could never be popped. None of these changes the order of acceptance: the heap pops the
// unique minimum of (distance, vertex) among the entries within the radius.
#ifndef NVV_CORE_GEODESIC_MARCH_H
#define NVV_CORE_GEODESIC_MARCH_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "huge_pages.h"
#include "surface_graph.h"
#include "tuning.h"

namespace nvv {

// Planar unfolding update of d_C from accepted A, B, given the lengths c = |AB|, b = |AC|,
// a = |BC| of the triangle (see the header comment).
double UnfoldedDistanceFromLengths(double c, double b, double a, double dA, double dB);

class GeodesicMarch {
 public:
  explicit GeodesicMarch(const SurfaceGraph& g);

  // Marches from `source` until the next vertex would be farther than `radius`, or
  // `maxVertices` vertices are accepted, or accepting the next would bring the faces of the
  // accepted vertices past maxVertices * tuning::kMarchFacesPerVertex (the source's aside): what
  // the march and its callers' loops over the reached faces cost is bounded either way.
  // `blocked(v)` true: v may be accepted (it is reached) but the front does not expand through
  // it and it never serves as A or B of an update. Returns false when it stopped at a bound.
  template <class Blocked>
  bool Run(int source, double radius, int maxVertices, Blocked blocked) {
    Reset();
    radius_ = radius;
    touched_.push_back(source);
    node_[source].dist = 0;
    node_[source].state = kTentative;
    Push({0.0, source});
    bool complete = true;
    const long long maxFaces = (long long)maxVertices * tuning::kMarchFacesPerVertex;
    long long faces = 0;
    while (!heap_.empty()) {
      const Entry e = heap_.front();  // the tentative vertex of least (distance, index)
      if (e.d > radius) break;
      if (int(reached_.size()) >= maxVertices) { complete = false; break; }
      if (e.v != source) {
        faces += g_.FaceEnd(e.v) - g_.FaceBegin(e.v);
        if (faces > maxFaces) { complete = false; break; }
      }
      PopFront();
      node_[e.v].state = kAccepted;
      reached_.push_back(e.v);
      if (e.v != source && blocked(e.v)) { node_[e.v].state = kAcceptedBlocked; continue; }
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
  double Distance(int v) const { return node_[v].dist; }
  bool IsReached(int v) const { return node_[v].state >= kAccepted; }

 private:
  enum : std::uint8_t { kFar = 0, kTentative = 1, kAccepted = 2, kAcceptedBlocked = 3 };
  // A vertex's scratch: its distance (+inf untouched), its slot in heap_ (-1 when not there) and
  // its state.
  struct Node {
    double dist;
    int heapIndex;
    std::uint8_t state;
  };
  struct Entry {
    double d;
    int v;
  };
  // Strict total order of the front: by distance, ties by vertex index, so the order of
  // acceptance does not depend on the heap's layout (nor on the thread count).
  static bool Before(const Entry& a, const Entry& b) { return a.d < b.d || (a.d == b.d && a.v < b.v); }

  void Reset();
  // Indexed binary heap: node_[v].heapIndex is v's slot in heap_. Sifting moves a hole instead
  // of swapping, and keeps the slots in step.
  void SiftUp(int i, Entry e);
  void Push(Entry e);
  void PopFront();
  void Relax(int v, double d);
  void Expand(int x);
  // Updates c from the accepted x, through the triangle when its third vertex o is accepted
  // too; xo, xc, oc are the triangle's edge lengths.
  void UpdateThrough(int x, int o, int c, double xo, double xc, double oc, bool useTriangle);

  const SurfaceGraph& g_;
  double radius_ = 0;
  std::vector<Node> node_;
  std::vector<int> touched_, reached_;
  std::vector<Entry> heap_;
};

}  // namespace nvv

#endif

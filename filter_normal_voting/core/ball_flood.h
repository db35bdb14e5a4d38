// Same-sheet neighbourhood of one vertex for the quadric fit of pass 2: the vertices joined to
// the source by a path of mesh edges that stays inside the Euclidean ball |x - v| <= g_m.
//
// The fit (sheet_fit.h) weighs its samples by normal agreement only, never by distance, so it
// needs the set M_v, not the distances the fast march (geodesic_march.h) computes to build it.
// The flood finds the same set up to the ball's rim: g >= |x - v| everywhere and, within
// g_m <= a few l_ave of a surface whose radii of curvature are tens of l_ave, the two differ by
// g^3 / (24 R^2), far below an edge length; across a crease the march stops at the crease's
// vertices either way (`blocked`). It costs a stamp test and one squared distance per edge end,
// where the march pays two planar unfoldings and an indexed-heap update per face corner.
//
// Scratch state is per instance (one per thread): a stamp per vertex, so a new flood resets in
// O(1); the stamps are cleared only when the 32-bit counter would wrap.
#ifndef NVV_CORE_BALL_FLOOD_H
#define NVV_CORE_BALL_FLOOD_H

#include <algorithm>
#include <cstdint>
#include <vector>

#include "surface_graph.h"
#include "tuning.h"

namespace nvv {

class BallFlood {
 public:
  explicit BallFlood(const SurfaceGraph& g) : g_(g), stamp_(g.VertexCount(), 0) {}

  // Floods from `source` through vertices within `radius` of it, breadth first, until
  // `maxVertices` are reached or their faces reach GeodesicMarch::Run's bound. `blocked(v)`
  // true: v is reached but the flood does not go on through it (as GeodesicMarch::Run).
  // Returns false when it stopped at a bound.
  template <class Blocked>
  bool Run(int source, double radius, int maxVertices, Blocked blocked) {
    // Two stamps per flood: current_ for a reached vertex, current_ + 1 for one tested outside.
    current_ += 2;
    if (current_ >= 0xfffffff0u) {  // the counter would wrap: old stamps could collide
      std::fill(stamp_.begin(), stamp_.end(), 0u);
      current_ = 2;
    }
    reached_.clear();
    const Eigen::Vector3d& c = g_.pos[source];
    const double r2 = radius * radius;
    stamp_[source] = current_;
    reached_.push_back(source);
    // The same bound on the faces of the reached vertices as GeodesicMarch::Run's.
    const long long maxFaces = (long long)maxVertices * tuning::kMarchFacesPerVertex;
    long long faces = 0;
    // reached_ is its own queue: entries before `next` have been expanded.
    for (std::size_t next = 0; next < reached_.size(); ++next) {
      const int x = reached_[next];
      if (x != source && blocked(x)) continue;
      for (int i = g_.FaceBegin(x); i < g_.FaceEnd(x); ++i) {
        for (int y : g_.face[g_.vfList[i]]) {
          if (stamp_[y] >= current_) continue;  // seen: inside or outside, it is tested once
          if ((g_.pos[y] - c).squaredNorm() > r2) {
            stamp_[y] = current_ + 1;
            continue;
          }
          if (int(reached_.size()) >= maxVertices) return false;
          faces += g_.FaceEnd(y) - g_.FaceBegin(y);
          if (faces > maxFaces) return false;
          stamp_[y] = current_;
          reached_.push_back(y);
        }
      }
    }
    return true;
  }
  bool Run(int source, double radius, int maxVertices) {
    return Run(source, radius, maxVertices, [](int) { return false; });
  }

  // Reached vertices in breadth-first order; the source first.
  const std::vector<int>& Reached() const { return reached_; }
  // Whether the last flood reached v (after a complete flood: v is within the radius and joined
  // to the source inside the ball).
  bool IsReached(int v) const { return stamp_[v] == current_; }

 private:
  const SurfaceGraph& g_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t current_ = 0;
  std::vector<int> reached_;
};

}  // namespace nvv

#endif

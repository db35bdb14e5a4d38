#include "geodesic_march.h"

namespace nvv {
namespace {

// The update itself, for the march's inner loop (its only caller) to inline.
inline double Unfolded(double c, double b, double a, double dA, double dB) {
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

}  // namespace

// Planar unfolding update of d_C from accepted A, B, given the lengths c = |AB|, b = |AC|,
// a = |BC| of the triangle (see the header comment).
double UnfoldedDistanceFromLengths(double c, double b, double a, double dA, double dB) {
  return Unfolded(c, b, a, dA, dB);
}

GeodesicMarch::GeodesicMarch(const SurfaceGraph& g)
    : g_(g), node_(FilledOnHugePages(g.VertexCount(), Node{std::numeric_limits<double>::infinity(), -1, kFar})) {}

void GeodesicMarch::Reset() {
  for (int v : touched_) {
    node_[v].dist = std::numeric_limits<double>::infinity();
    node_[v].state = kFar;
  }
  for (const Entry& e : heap_) node_[e.v].heapIndex = -1;
  touched_.clear();
  reached_.clear();
  heap_.clear();
}

void GeodesicMarch::SiftUp(int i, Entry e) {
  while (i > 0) {
    const int parent = (i - 1) / 2;
    if (!Before(e, heap_[parent])) break;
    heap_[i] = heap_[parent];
    node_[heap_[i].v].heapIndex = i;
    i = parent;
  }
  heap_[i] = e;
  node_[e.v].heapIndex = i;
}
void GeodesicMarch::Push(Entry e) {
  heap_.push_back(e);
  SiftUp(int(heap_.size()) - 1, e);
}
void GeodesicMarch::PopFront() {
  node_[heap_.front().v].heapIndex = -1;
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
    node_[heap_[i].v].heapIndex = i;
    i = child;
  }
  heap_[i] = last;
  node_[last.v].heapIndex = i;
}

void GeodesicMarch::Relax(int v, double d) {
  Node& n = node_[v];
  if (n.state >= kAccepted) return;
  if (n.state == kFar) { touched_.push_back(v); n.state = kTentative; }
  if (d < n.dist) {
    n.dist = d;
    const int i = n.heapIndex;
    if (i >= 0) SiftUp(i, {d, v});            // decrease-key: a smaller key only moves up
    else if (d <= radius_) Push({d, v});      // beyond g_m it could never be popped (header comment)
  }
}

void GeodesicMarch::Expand(int x) {
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

void GeodesicMarch::UpdateThrough(int x, int o, int c, double xo, double xc, double oc, bool useTriangle) {
  if (IsReached(c)) return;
  double d;
  if (useTriangle && node_[o].state == kAccepted)
    d = Unfolded(xo, xc, oc, node_[x].dist, node_[o].dist);
  else
    d = node_[x].dist + xc;
  Relax(c, d);
}

}  // namespace nvv

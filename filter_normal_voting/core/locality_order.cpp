#include "locality_order.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <utility>

#include "threads.h"
#include "tuning.h"

namespace nvv {
namespace {

// a[i] = a[from[i]] for every i, through a copy: the reads are independent, so they overlap in
// memory where a move along the permutation's cycles waits for each miss in turn.
template <class T>
void Gather(std::vector<T>& a, const std::vector<int>& from, int threads) {
  std::vector<T> b;
  AssignOnHugePages(b, a.size());
  const std::ptrdiff_t n = std::ptrdiff_t(a.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t i = 0; i < n; ++i) b[i] = a[std::size_t(from[i])];
  a.swap(b);
}

std::vector<int> Inverse(const std::vector<int>& to) {
  std::vector<int> from(to.size());
  for (std::size_t i = 0; i < to.size(); ++i) from[std::size_t(to[i])] = int(i);
  return from;
}

// x's low 21 bits spread to every third bit (the Morton code's interleaving).
std::uint64_t Spread21(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffull;
  x = (x | x << 16) & 0x1f0000ff0000ffull;
  x = (x | x << 8) & 0x100f00f00f00f00full;
  x = (x | x << 4) & 0x10c30c30c30c30c3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}

// The old index of each new vertex: usable vertices in the order of their Morton codes in the
// bounding cube (ties by index), then the unusable ones in index order.
std::vector<int> MortonOrder(const SurfaceGraph& g) {
  const int n = g.VertexCount();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (int v = 0; v < n; ++v)
    if (g.usable[v]) lo = lo.cwiseMin(g.pos[v]), hi = hi.cwiseMax(g.pos[v]);
  const double extent = (hi - lo).maxCoeff();
  const double scale = extent > 0 ? 2097151.0 / extent : 0.0;
  std::vector<std::pair<std::uint64_t, int>> key(static_cast<std::size_t>(n));
  for (int v = 0; v < n; ++v) {
    std::uint64_t code = ~std::uint64_t(0);  // unusable: last
    if (g.usable[v]) {
      const Eigen::Vector3d c = (g.pos[v] - lo) * scale;
      code = Spread21(std::uint64_t(c.x())) | Spread21(std::uint64_t(c.y())) << 1 | Spread21(std::uint64_t(c.z())) << 2;
    }
    key[v] = {code, v};
  }
  std::sort(key.begin(), key.end());
  std::vector<int> from(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) from[i] = key[i].second;
  return from;
}

// The old index of each new face: by lowest (renumbered) vertex, ties in face order.
std::vector<int> FacesByLowestVertex(const SurfaceGraph& g) {
  const int n = g.VertexCount(), nf = g.FaceCount();
  auto lowest = [&g](int f) { return std::min(g.face[f][0], std::min(g.face[f][1], g.face[f][2])); };
  std::vector<int> start(std::size_t(n) + 1, 0);
  for (int f = 0; f < nf; ++f) ++start[lowest(f) + 1];
  for (int v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<int> from(static_cast<std::size_t>(nf));
  for (int f = 0; f < nf; ++f) from[start[lowest(f)]++] = f;
  return from;
}

// The vertex -> face lists from the renumbered faces, and the non-manifold edge groups renumbered
// and sorted again by key and face.
void RebuildAdjacency(SurfaceGraph& g, const std::vector<int>& vertexTo, const std::vector<int>& faceTo) {
  g.BuildVertexFaces();
  const std::size_t groups = g.edgeGroupKey.size();
  if (groups == 0) return;
  std::vector<std::pair<std::array<int, 2>, std::vector<int>>> renamed(groups);
  for (std::size_t k = 0; k < groups; ++k) {
    const int a = vertexTo[g.edgeGroupKey[k][0]], b = vertexTo[g.edgeGroupKey[k][1]];
    renamed[k].first = {std::min(a, b), std::max(a, b)};
    for (int i = g.edgeGroupStart[k]; i < g.edgeGroupStart[k + 1]; ++i)
      renamed[k].second.push_back(faceTo[g.edgeGroupFaces[i]]);
    std::sort(renamed[k].second.begin(), renamed[k].second.end());
  }
  std::sort(renamed.begin(), renamed.end());
  g.edgeGroupStart.assign(1, 0);
  g.edgeGroupFaces.clear();
  for (std::size_t k = 0; k < groups; ++k) {
    g.edgeGroupKey[k] = renamed[k].first;
    g.edgeGroupFaces.insert(g.edgeGroupFaces.end(), renamed[k].second.begin(), renamed[k].second.end());
    g.edgeGroupStart.push_back(int(g.edgeGroupFaces.size()));
  }
}

// Whether the mesh's own order scatters neighbourhoods: the median, over sampled vertices, of
// the largest index distance to a vertex of the one-ring, against tuning::kLocalityWindow.
bool PoorlyOrdered(const SurfaceGraph& g) {
  const int n = g.VertexCount();
  const int stride = std::max(1, n / tuning::kLocalitySamples);
  std::vector<int> span;
  for (int v = 0; v < n; v += stride) {
    if (!g.Referenced(v)) continue;
    int s = 0;
    for (int i = g.FaceBegin(v); i < g.FaceEnd(v); ++i)
      for (int x : g.face[g.vfList[i]]) s = std::max(s, std::abs(x - v));
    span.push_back(s);
  }
  if (span.empty()) return false;
  std::nth_element(span.begin(), span.begin() + span.size() / 2, span.end());
  return span[span.size() / 2] > tuning::kLocalityWindow;
}

}  // namespace

void LocalityOrder::Apply(SurfaceGraph& g, int threads) {
  vertexTo_.clear();
  if (g.VertexCount() < tuning::kLocalityOrderMinVertices || !PoorlyOrdered(g)) return;
  const int T = ThreadCount(threads);
  const std::vector<int> vertexFrom = MortonOrder(g);
  vertexTo_ = Inverse(vertexFrom);
  for (auto& f : g.face)
    for (int j = 0; j < 3; ++j) f[j] = vertexTo_[f[j]];
  const std::vector<int> faceFrom = FacesByLowestVertex(g);
  Gather(g.pos, vertexFrom, T);
  Gather(g.usable, vertexFrom, T);
  Gather(g.face, faceFrom, T);
  Gather(g.faceNormal, faceFrom, T);
  Gather(g.faceArea, faceFrom, T);
  Gather(g.faceEdge, faceFrom, T);
  Gather(g.nonManifoldEdges, faceFrom, T);
  RebuildAdjacency(g, vertexTo_, g.edgeGroupKey.empty() ? std::vector<int>() : Inverse(faceFrom));
}

void LocalityOrder::RestoreResults(SurfaceGraph& g, std::vector<VertexResult>& res, int threads) {
  if (!Active()) return;
  g = SurfaceGraph();  // its memory is what the results' copy takes
  if (res.size() == vertexTo_.size()) Gather(res, vertexTo_, ThreadCount(threads));
  std::vector<int>().swap(vertexTo_);
}

}  // namespace nvv

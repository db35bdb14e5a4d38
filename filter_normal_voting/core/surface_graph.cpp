#include "surface_graph.h"

#include <algorithm>
#include <cmath>

#include "tuning.h"

namespace nvv {

// True when v has an edge that only one face holds: v is on the mesh's border.
bool SurfaceGraph::OnBorder(int v) const {
  for (int i = FaceBegin(v); i < FaceEnd(v); ++i) {
    const int f = vfList[i];
    for (int x : face[f]) {
      if (x == v) continue;
      bool across = false;
      ForEachFaceAcross(f, v, x, [&](int) { across = true; });
      if (!across) return true;
    }
  }
  return false;
}

// Fills the graph from positions and faces given as vertex indices (-1 marks a face to skip),
// on `threads` threads (<= 0: all). The per-face loops run in parallel; every sum is then
// taken serially in face order, so the graph is the same bits on any thread count.
void SurfaceGraph::Build(std::vector<Eigen::Vector3d>&& positions, std::vector<std::uint8_t>&& usableVertex,
                       const std::vector<std::array<int, 3>>& rawFaces, int threads) {
  const int T = ThreadCount(threads);
  pos = std::move(positions);
  usable = std::move(usableVertex);
  const int n = static_cast<int>(pos.size());
  nonFinite = 0;
  for (int v = 0; v < n; ++v) {
    if (usable[v] && !(std::isfinite(pos[v].x()) && std::isfinite(pos[v].y()) && std::isfinite(pos[v].z()))) {
      usable[v] = 0;
      ++nonFinite;
    }
  }
  face.clear();
  ReserveOnHugePages(face, rawFaces.size());
  dropped = 0;
  for (const auto& f : rawFaces) {
    bool ok = f[0] != f[1] && f[1] != f[2] && f[0] != f[2];
    for (int j = 0; j < 3 && ok; ++j) ok = f[j] >= 0 && f[j] < n && usable[f[j]];
    if (ok) face.push_back(f);
    else ++dropped;
  }
  repeated = RemoveRepeatedFaces(face, n);
  const int nf = FaceCount();
  AssignOnHugePages(faceNormal, nf, Eigen::Vector3d::Zero().eval());
  AssignOnHugePages(faceArea, nf, 0.0);
  AssignOnHugePages(faceEdge, nf);
#pragma omp parallel for schedule(static) num_threads(T)
  for (int i = 0; i < nf; ++i) {
    const auto& f = face[i];
    for (int j = 0; j < 3; ++j) faceEdge[i][j] = (pos[f[(j + 1) % 3]] - pos[f[j]]).norm();
  }
  double edgeSum = 0;
  for (int i = 0; i < nf; ++i)
    for (int j = 0; j < 3; ++j) edgeSum += faceEdge[i][j];
  meanEdge = nf > 0 ? edgeSum / (3.0 * nf) : 0.0;
  // A face is degenerate when its area is negligible against l_ave^2 (scale-free test).
  const double areaFloor = tuning::kDegenerateAreaFraction * meanEdge * meanEdge;
  double largest = 0;  // (a max and a count: the same on any thread count)
  std::size_t zeroArea = 0;
#pragma omp parallel for schedule(static) num_threads(T) reduction(max : largest) reduction(+ : zeroArea)
  for (int i = 0; i < nf; ++i) {
    const auto& f = face[i];
    const Eigen::Vector3d c = (pos[f[1]] - pos[f[0]]).cross(pos[f[2]] - pos[f[0]]);
    const double twiceArea = c.norm();
    if (!(twiceArea * 0.5 > areaFloor) || !std::isfinite(twiceArea)) {
      ++zeroArea;
      continue;
    }
    faceNormal[i] = c / twiceArea;
    faceArea[i] = 0.5 * twiceArea;
    largest = std::max(largest, faceArea[i]);
  }
  maxArea = largest;
  degenerate = zeroArea;
  BuildVertexFaces();
  unreferenced = 0;
  for (int v = 0; v < n; ++v)
    if (usable[v] && !Referenced(v)) ++unreferenced;
  BuildEdges();
}

// Vertex -> face adjacency from the faces, counting sort into CSR: each vertex's faces in
// increasing face order.
void SurfaceGraph::BuildVertexFaces() {
  const int n = VertexCount(), nf = FaceCount();
  AssignOnHugePages(vfStart, std::size_t(n) + 1, 0);
  for (const auto& f : face)
    for (int j = 0; j < 3; ++j) ++vfStart[f[j] + 1];
  for (int v = 0; v < n; ++v) vfStart[v + 1] += vfStart[v];
  AssignOnHugePages(vfList, std::size_t(vfStart[n]), 0);
  std::vector<int> fill;
  ReserveOnHugePages(fill, n);
  fill.assign(vfStart.begin(), vfStart.end() - 1);
  for (int i = 0; i < nf; ++i)
    for (int j = 0; j < 3; ++j) vfList[fill[face[i][j]]++] = i;
}

// A two-face edge used twice in the same direction means the orientation flips there.
// Every face edge is put in a bucket by its lower vertex (a counting sort) and each bucket is
// sorted by the higher vertex, so the faces on one edge come together in increasing face order:
// O(F log d) for the largest valence d, whatever the edges' multiplicity (a CSR scan per edge
// would cost the product of its two ends' valences, quadratic on a non-manifold "book").
// Orientation: an edge used in one direction only is open; used two or more times in one
// direction and never in the other, the orientation flips there. A consistently oriented mesh
// whose every edge is used both ways is closed; its signed volume (the divergence theorem, summed
// in face order) says whether the faces point outward.
void SurfaceGraph::BuildEdges() {
  const int n = VertexCount(), nf = FaceCount();
  auto from = [this](int fe) { return face[fe / 3][fe % 3]; };
  auto to = [this](int fe) { return face[fe / 3][fe % 3 == 2 ? 0 : fe % 3 + 1]; };
  auto lower = [&](int fe) { return std::min(from(fe), to(fe)); };
  auto higher = [&](int fe) { return std::max(from(fe), to(fe)); };
  std::vector<int> start(std::size_t(n) + 1, 0);
  for (int fe = 0; fe < 3 * nf; ++fe) ++start[lower(fe) + 1];
  for (int v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<int> order(std::size_t(3) * nf), fill(start.begin(), start.end() - 1);
  for (int fe = 0; fe < 3 * nf; ++fe) order[fill[lower(fe)]++] = fe;
  AssignOnHugePages(nonManifoldEdges, std::size_t(nf), std::uint8_t(0));
  edgeGroupKey.clear();
  edgeGroupStart.assign(1, 0);
  edgeGroupFaces.clear();
  bool flipped = false, open = false;
  for (int v = 0; v < n; ++v) {
    const auto first = order.begin() + start[v], last = order.begin() + start[v + 1];
    if (last - first > 1)
      std::sort(first, last, [&](int x, int y) { return higher(x) != higher(y) ? higher(x) < higher(y) : x < y; });
    for (auto it = first; it != last;) {
      auto end = it + 1;
      while (end != last && higher(*end) == higher(*it)) ++end;
      const int m = int(end - it);
      int forward = 0;  // uses of v -> higher
      for (auto e = it; e != end; ++e) forward += from(*e) == v;
      if (forward == 0 || forward == m) {
        open = true;
        flipped = flipped || m >= 2;
      }
      if (m > 2) {
        for (auto e = it; e != end; ++e) {
          nonManifoldEdges[*e / 3] |= std::uint8_t(1u << (*e % 3));
          edgeGroupFaces.push_back(*e / 3);
        }
        edgeGroupKey.push_back({v, higher(*it)});
        edgeGroupStart.push_back(int(edgeGroupFaces.size()));
      }
      it = end;
    }
  }
  consistentlyOriented = !flipped;
  closed = consistentlyOriented && !open && nf > 0;
  volume = 0;
  if (!closed) return;
  for (const auto& f : face) volume += pos[f[0]].dot(pos[f[1]].cross(pos[f[2]])) / 6.0;
}

// Drops every face whose three vertices (in any order) are those of an earlier face, keeping the
// order of the rest; returns how many. Faces are bucketed by their lowest vertex (a counting
// sort) and only buckets of two or more are sorted, so the cost is linear on ordinary meshes and
// N log N for N copies of one triangle, never N^2.
std::size_t SurfaceGraph::RemoveRepeatedFaces(std::vector<std::array<int, 3>>& faces, int n) {
  auto sorted = [](const std::array<int, 3>& f) {
    std::array<int, 3> s = f;
    std::sort(s.begin(), s.end());
    return s;
  };
  auto lowest = [](const std::array<int, 3>& f) { return std::size_t(std::min(f[0], std::min(f[1], f[2]))); };
  std::vector<int> start(std::size_t(n) + 1, 0);
  for (const auto& f : faces) ++start[lowest(f) + 1];
  for (int v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<int> order(faces.size()), fill(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < faces.size(); ++i) order[fill[lowest(faces[i])]++] = int(i);
  std::vector<std::uint8_t> drop(faces.size(), 0);
  std::size_t count = 0;
  for (int v = 0; v < n; ++v) {
    if (start[v + 1] - start[v] < 2) continue;
    auto first = order.begin() + start[v], last = order.begin() + start[v + 1];
    std::sort(first, last, [&](int x, int y) {
      const auto a = sorted(faces[x]), b = sorted(faces[y]);
      return a != b ? a < b : x < y;
    });
    for (auto it = first + 1; it != last; ++it)
      if (sorted(faces[*it]) == sorted(faces[*(it - 1)])) { drop[*it] = 1; ++count; }
  }
  if (count == 0) return 0;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < faces.size(); ++i)
    if (!drop[i]) faces[kept++] = faces[i];
  faces.resize(kept);
  return count;
}

}  // namespace nvv

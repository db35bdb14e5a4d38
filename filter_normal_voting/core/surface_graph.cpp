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
  // Vertex -> face adjacency, counting sort into CSR.
  AssignOnHugePages(vfStart, n + 1, 0);
  for (const auto& f : face)
    for (int j = 0; j < 3; ++j) ++vfStart[f[j] + 1];
  for (int v = 0; v < n; ++v) vfStart[v + 1] += vfStart[v];
  AssignOnHugePages(vfList, vfStart[n], 0);
  std::vector<int> fill;
  ReserveOnHugePages(fill, n);
  fill.assign(vfStart.begin(), vfStart.end() - 1);
  for (int i = 0; i < nf; ++i)
    for (int j = 0; j < 3; ++j) vfList[fill[face[i][j]]++] = i;
  unreferenced = 0;
  for (int v = 0; v < n; ++v)
    if (usable[v] && !Referenced(v)) ++unreferenced;
  CheckOrientation(T);
}

// A two-face edge used twice in the same direction means the orientation flips there.
// Edges with three or more faces (non-manifold) say nothing about orientation: skipped.
// Done on the CSR adjacency instead of a hash map of directed edges: the same answer with no
// allocation. A face using a -> b holds both a and b, so only the faces of the endpoint with fewer
// faces are scanned: a 100,000-valence fan vertex costs its neighbours' two faces per edge.
// A consistently oriented mesh whose every directed edge has its reverse is closed; its signed
// volume (the divergence theorem, summed in face order) says whether the faces point outward.
void SurfaceGraph::CheckOrientation(int threads) {
  // Number of faces that use the directed edge a -> b.
  auto uses = [this](int a, int b) {
    const int scan = vfStart[b + 1] - vfStart[b] < vfStart[a + 1] - vfStart[a] ? b : a;  // the endpoint with fewer faces
    int count = 0;
    for (int i = vfStart[scan]; i < vfStart[scan + 1]; ++i) {
      const auto& f = face[vfList[i]];
      for (int j = 0; j < 3; ++j) count += f[j] == a && f[(j + 1) % 3] == b;
    }
    return count;
  };
  const int nf = FaceCount();
  bool flipped = false, open = false;
#pragma omp parallel for schedule(static) num_threads(threads) reduction(|| : flipped, open)
  for (int i = 0; i < nf; ++i)
    for (int j = 0; j < 3 && !flipped; ++j) {
      const int a = face[i][j], b = face[i][(j + 1) % 3];
      const int reverse = uses(b, a);
      flipped = reverse == 0 && uses(a, b) >= 2;
      open = open || reverse == 0;
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

// A compact, read-only copy of a triangle mesh for Normal Vector Voting: positions in double,
// usable faces with their unit normals and areas, and vertex->face adjacency in CSR form
// (one offset array, one index array), built once in O(V + F).
//
// Why a copy and not the vcg mesh itself: the two passes touch each vertex's neighbourhood
// tens to hundreds of times; flat arrays of indices are several times more cache-friendly
// than vcg's pointer-linked optional components, need no VF adjacency on the user's mesh,
// and let the same compiled code serve float and double meshes.
//
// Defects are absorbed here, so nothing downstream sees them:
//  - deleted vertices and vertices with a non-finite coordinate are not "usable";
//  - faces that are deleted, repeat a vertex, or touch an unusable vertex are dropped;
//  - zero-area faces stay for distances (their edges are real) but get no normal and no vote;
//  - vertices that no usable face references are left without adjacency.
#ifndef NVV_CORE_SURFACE_GRAPH_H
#define NVV_CORE_SURFACE_GRAPH_H

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "huge_pages.h"
#include "threads.h"
#include "tuning.h"

namespace nvv {

struct SurfaceGraph {
  std::vector<Eigen::Vector3d> pos;
  std::vector<std::uint8_t> usable;           // finite, not deleted
  std::vector<std::array<int, 3>> face;       // usable faces only
  std::vector<Eigen::Vector3d> faceNormal;    // unit; zero for degenerate faces
  std::vector<double> faceArea;               // 0 for degenerate faces
  // faceEdge[i][j] = |face[i][j+1] - face[i][j]| (indices mod 3). The marcher needs these lengths
  // on every update through a face; computing them once here takes three square roots and three
  // scattered position loads out of its inner loop (the unfolding needs lengths only). Each is
  // the same Eigen expression the marcher would evaluate (|b - a| and |a - b| round alike), so
  // distances are bit-identical to computing them on the fly.
  std::vector<std::array<double, 3>> faceEdge;
  std::vector<int> vfStart;                   // CSR: faces of v are vfList[vfStart[v] .. vfStart[v+1])
  std::vector<int> vfList;
  // Bit j of nonManifoldEdges[i]: edge j of face i (face[i][j] -> face[i][j+1]) is held by three or
  // more faces. Those edges, by their sorted vertex pair edgeGroupKey[g], hold the faces
  // edgeGroupFaces[edgeGroupStart[g] .. edgeGroupStart[g+1]) in increasing order. One byte per
  // face: ordinary meshes pay nothing else.
  std::vector<std::uint8_t> nonManifoldEdges;
  std::vector<std::array<int, 2>> edgeGroupKey;
  std::vector<int> edgeGroupStart, edgeGroupFaces;
  double meanEdge = 0;                        // l_ave over the edges of usable faces
  double maxArea = 0;                         // A_max of Eq. 8
  bool consistentlyOriented = true;           // every edge shared by two faces is used in opposite directions
  bool closed = false;                        // consistently oriented and every edge has its reverse
  double volume = 0;                          // signed volume where closed: negative when the faces point inward
  std::size_t nonFinite = 0, unreferenced = 0, degenerate = 0, dropped = 0;
  std::size_t repeated = 0;                   // faces with the same three vertices as an earlier face: dropped

  int VertexCount() const { return static_cast<int>(pos.size()); }
  int FaceCount() const { return static_cast<int>(face.size()); }
  int FaceBegin(int v) const { return vfStart[v]; }
  int FaceEnd(int v) const { return vfStart[v + 1]; }
  bool Referenced(int v) const { return vfStart[v + 1] > vfStart[v]; }
  // Sum of area * unit normal over v's faces: its direction is the area-weighted one-ring normal.
  Eigen::Vector3d RingNormalSum(int v) const {
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    for (int i = FaceBegin(v); i < FaceEnd(v); ++i) s += faceArea[vfList[i]] * faceNormal[vfList[i]];
    return s;
  }

  // Mean length of the edges at v over its faces (an edge two of them hold counted twice): how
  // finely the mesh is cut there. From faceEdge: face[j] -> face[j + 1] is edge j.
  double MeanRingEdge(int v) const {
    double sum = 0;
    int count = 0;
    for (int i = FaceBegin(v); i < FaceEnd(v); ++i) {
      const int f = vfList[i];
      const int j = face[f][0] == v ? 0 : (face[f][1] == v ? 1 : 2);
      for (int k = 0; k < 3; ++k)
        if (k != j) sum += faceEdge[f][(j + 1) % 3 == k ? j : k], ++count;
    }
    return count > 0 ? sum / count : 0;
  }

  // Calls fn(o) for every face o != f that holds the edge (a, b) of face f: one on a manifold
  // edge, none on a boundary, several on a non-manifold one, in increasing face order. On an
  // edge of one or two faces the faces of the endpoint with fewer faces are scanned: from a
  // 100,000-valence fan's centre, each spoke costs the spoke's two faces, not the centre's
  // 100,000. An edge of three or more faces lists its group (edgeGroup*); one held by more than
  // tuning::kMaxFacesListedPerEdge faces (a "book" of a hundred thousand pages in a hostile
  // file) lists only its first other face, since what the callers ask of it (a dihedral angle,
  // a border) has no meaning there and listing every pair would cost the square of its faces.
  template <class Fn>
  void ForEachFaceAcross(int f, int a, int b, Fn fn) const {
    const auto& t = face[f];
    const int j = (t[2] != a && t[2] != b) ? 0 : ((t[0] != a && t[0] != b) ? 1 : 2);
    if (!((nonManifoldEdges[f] >> j) & 1)) {
      const bool aFewer = FaceEnd(a) - FaceBegin(a) <= FaceEnd(b) - FaceBegin(b);
      const int scan = aFewer ? a : b, other = aFewer ? b : a;
      for (int i = FaceBegin(scan); i < FaceEnd(scan); ++i) {
        const int o = vfList[i];
        const auto& u = face[o];
        if (o != f && (u[0] == other || u[1] == other || u[2] == other)) fn(o);
      }
      return;
    }
    const std::array<int, 2> key{std::min(a, b), std::max(a, b)};
    const int g = int(std::lower_bound(edgeGroupKey.begin(), edgeGroupKey.end(), key) - edgeGroupKey.begin());
    const int begin = edgeGroupStart[g], end = edgeGroupStart[g + 1];
    const bool listAll = end - begin <= tuning::kMaxFacesListedPerEdge;
    for (int i = begin; i < end; ++i) {
      const int o = edgeGroupFaces[i];
      if (o == f) continue;
      fn(o);
      if (!listAll) return;
    }
  }

  // Calls fn(f, o, a, b) for every face o with an area across an edge (a, b) of a face f with an area,
  // f one of at most tuning::kMedianEdgeAngleFaces evenly spread faces, each pair once (o > f): the
  // sample the mesh-wide statistics of dihedral angles are taken over.
  template <class Fn>
  void ForEachSampledEdgePair(Fn fn) const {
    const int stride = std::max(1, FaceCount() / tuning::kMedianEdgeAngleFaces);
    for (int f = 0; f < FaceCount(); f += stride) {
      if (!(faceArea[f] > 0)) continue;
      for (int j = 0; j < 3; ++j) {
        const int a = face[f][j], b = face[f][(j + 1) % 3];
        ForEachFaceAcross(f, a, b, [&](int o) {
          if (o > f && faceArea[o] > 0) fn(f, o, a, b);
        });
      }
    }
  }

  // True when v has an edge that only one face holds: v is on the mesh's border.
  bool OnBorder(int v) const;

  // Fills vfStart and vfList from `face` (Build does; so does a renumbering, locality_order.h).
  void BuildVertexFaces();

  // Fills the graph from positions and faces given as vertex indices (-1 marks a face to skip),
  // on `threads` threads (<= 0: all). The per-face loops run in parallel; every sum is then
  // taken serially in face order, so the graph is the same bits on any thread count.
  void Build(std::vector<Eigen::Vector3d>&& positions, std::vector<std::uint8_t>&& usableVertex,
             const std::vector<std::array<int, 3>>& rawFaces, int threads = 0);

 private:
  // Groups every face edge with the other faces' edges on the same two vertices, keeps the groups
  // of three or more (nonManifoldEdges, edgeGroup*) and, from the directions each edge is used
  // in, sets consistentlyOriented, closed and volume.
  void BuildEdges();
  static std::size_t RemoveRepeatedFaces(std::vector<std::array<int, 3>>& faces, int n);
};

// Builds the graph from any vcglib triangle mesh (vertex and face containers with
// IsD(), cP(), cV(j)). Results elsewhere are indexed like m.vert, deleted slots included.
template <class MeshType>
void BuildSurfaceGraph(const MeshType& m, SurfaceGraph& g, int threads = 0) {
  const int T = ThreadCount(threads);
  const std::ptrdiff_t n = std::ptrdiff_t(m.vert.size());
  std::vector<Eigen::Vector3d> positions = FilledOnHugePages(std::size_t(n), Eigen::Vector3d::Zero().eval());
  std::vector<std::uint8_t> usable(n, 0);
#pragma omp parallel for schedule(static) num_threads(T)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto& v = m.vert[i];
    if (v.IsD()) continue;
    positions[i] = Eigen::Vector3d(double(v.cP()[0]), double(v.cP()[1]), double(v.cP()[2]));
    usable[i] = 1;
  }
  std::vector<std::array<int, 3>> raw;
  ReserveOnHugePages(raw, m.face.size());
  const auto* base = n > 0 ? &m.vert[0] : nullptr;
  for (const auto& f : m.face) {
    if (f.IsD()) continue;
    std::array<int, 3> t{-1, -1, -1};
    for (int j = 0; j < 3; ++j) {
      const auto* vp = f.cV(j);
      if (vp != nullptr && base != nullptr) {
        const std::ptrdiff_t idx = vp - base;
        if (idx >= 0 && idx < n) t[j] = int(idx);
      }
    }
    raw.push_back(t);
  }
  g.Build(std::move(positions), std::move(usable), raw, T);
}

}  // namespace nvv

#endif

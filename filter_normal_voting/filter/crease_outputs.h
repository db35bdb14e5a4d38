// The crease network (core/crease_network.h) on the user's mesh: its edges and lines are already
// in the mesh's vertex indices (the SurfaceGraph keeps m.vert's slots), its patches are per graph
// face and are mapped here back to the slots of m.face; plus the counts the log, the CLI's summary
// and PyMeshLab's dictionary give.
#ifndef NVV_FILTER_CREASE_OUTPUTS_H
#define NVV_FILTER_CREASE_OUTPUTS_H

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include "core/crease_network.h"
#include "core/surface_graph.h"
#include "core/vertex_result.h"

namespace nvv {

struct CreaseOutputs {
  CreaseNetwork net;
  // Patch of each slot of m.face; -1 where the graph has no face: deleted faces, faces on a
  // deleted, non-finite or repeated vertex, and later copies of a repeated face.
  std::vector<int> meshFacePatch;
  int closedLines = 0;
  int lineCorners = 0;  // distinct corner vertices at the ends of lines

  // The index in net.edges of the crease edge (a, b), or -1.
  int EdgeIndex(int a, int b) const {
    const std::array<int, 2> key{{std::min(a, b), std::max(a, b)}};
    const auto it = std::lower_bound(net.edges.begin(), net.edges.end(), key);
    return it != net.edges.end() && *it == key ? int(it - net.edges.begin()) : -1;
  }
};

// The slot of m.face each graph face came from. BuildSurfaceGraph lists the live faces in slot
// order; Build then drops some (a repeated, deleted or non-finite vertex; a later copy of an
// earlier face) without reordering the rest or the vertices inside a face. So the graph's faces
// are a subsequence of the live faces, and matching them greedily in order finds each one's slot:
// a live face equal to the next graph face is that face (an earlier identical face would have
// been kept instead, so none is skipped over).
template <class MeshType>
std::vector<int> GraphFaceSlots(const MeshType& m, const SurfaceGraph& g) {
  std::vector<int> slot(std::size_t(g.FaceCount()), -1);
  const auto* base = m.vert.empty() ? nullptr : &m.vert[0];
  const std::ptrdiff_t n = std::ptrdiff_t(m.vert.size());
  int next = 0;
  for (std::size_t s = 0; s < m.face.size() && next < g.FaceCount(); ++s) {
    const auto& f = m.face[s];
    if (f.IsD()) continue;
    bool same = true;
    for (int j = 0; j < 3 && same; ++j) {
      const std::ptrdiff_t idx = f.cV(j) != nullptr && base != nullptr ? f.cV(j) - base : -1;
      same = idx >= 0 && idx < n && int(idx) == g.face[next][j];
    }
    if (same) slot[next++] = int(s);
  }
  return slot;
}

// The network of a finished run on m (g: the run's graph, res and sum: its results).
template <class MeshType>
CreaseOutputs FindCreaseOutputs(const MeshType& m, const SurfaceGraph& g, const std::vector<VertexResult>& res,
                                const Summary& sum, double creaseAngleDeg) {
  CreaseOutputs out;
  out.net = FindCreaseNetwork(g, res, sum.radius, creaseAngleDeg, sum.sharpEdges);
  out.meshFacePatch.assign(m.face.size(), -1);
  const std::vector<int> slot = GraphFaceSlots(m, g);
  for (std::size_t f = 0; f < slot.size(); ++f)
    if (slot[f] >= 0) out.meshFacePatch[slot[f]] = out.net.facePatch[f];
  std::vector<int> corners;
  for (const CreaseLine& l : out.net.lines) {
    out.closedLines += l.closed;
    for (int c : l.endCorner)
      if (c >= 0) corners.push_back(c);
  }
  std::sort(corners.begin(), corners.end());
  out.lineCorners = int(std::unique(corners.begin(), corners.end()) - corners.begin());
  return out;
}

// The crease lines as an edge list over their own vertices, for the lines file and MeshLab's
// lines layer: the mesh vertices the lines pass through, each once, in the order the lines first
// reach them; each line's edges in order along it (a closed line's last edge returns to its first
// vertex), so the edges of line l are those with line == l.
struct CreaseLineEdges {
  struct Edge {
    int a, b;          // indices into meshVertex
    float cuspAngle;   // radians
    int line;
  };
  std::vector<int> meshVertex;
  std::vector<std::vector<int>> polylines;  // per line, indices into meshVertex along it
  std::vector<Edge> edges;
};

inline CreaseLineEdges LinesAsEdges(const CreaseOutputs& c, std::size_t meshVertexCount) {
  CreaseLineEdges out;
  const std::vector<CreaseLine>& lines = c.net.lines;
  std::vector<int> index(meshVertexCount, -1);
  out.polylines.resize(lines.size());
  for (std::size_t l = 0; l < lines.size(); ++l)
    for (int v : lines[l].vertices) {
      if (index[v] < 0) index[v] = int(out.meshVertex.size()), out.meshVertex.push_back(v);
      out.polylines[l].push_back(index[v]);
    }
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const std::vector<int>& pl = out.polylines[l];
    const std::size_t n = pl.size();
    for (std::size_t i = 0; i + 1 < n + (lines[l].closed ? 1 : 0); ++i) {
      const int a = pl[i], b = pl[(i + 1) % n];
      const int e = c.EdgeIndex(out.meshVertex[a], out.meshVertex[b]);
      out.edges.push_back({a, b, e >= 0 ? c.net.edgeCuspAngle[e] : 0.0f, int(l)});
    }
  }
  return out;
}

// One log line: edges, lines, their corners, patches.
inline std::string CreaseNetworkLine(const CreaseOutputs& c) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "Crease network: %zu crease edges (%zu closing gaps, %zu dropped as spurs) in %zu lines "
                "(%d closed, %d corners at their ends); %d patches of %d to %d faces",
                c.net.edges.size(), c.net.gapEdges, c.net.spurEdges, c.net.lines.size(), c.closedLines,
                c.lineCorners, c.net.patchCount, c.net.smallestPatch, c.net.largestPatch);
  return buf;
}

}  // namespace nvv

#endif

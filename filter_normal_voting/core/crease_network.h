// What users do with creases: the mesh edges that lie on them, the lines those edges form, and
// the smooth patches the lines bound. The paper stops at per-vertex labels and names linking
// crease vertices into curves its open problem (par. 8); this stage works from what pass 1 found
// at each vertex (the two sheets: their bisector normal, the crease tangent and the cusp angle),
// not from the raw dihedral angle, so it holds under noise where a dihedral test breaks up.
//
//  1. Crease edges (CreaseEdgeTest): a mesh edge between two feature vertices, running along
//     the crease tangent, whose two faces lean apart across the crease line as much as half the
//     cusp angle says the sheets do. Between two corners (no tangent) the dihedral angle of the
//     two faces decides, against the crease angle.
//  2. Gaps (GapEdges): a line that stops at a crease vertex (not a corner, not the border)
//     is continued along feature vertices and edges that turn to another crease edge, or to the
//     border (a crease that runs off an open mesh), within 2 g_m ahead of it; not to a parallel
//     line beside it (a chamfer's other line).
//  3. Spurs (DropSpurs): lines shorter than g_m that still stop at a crease vertex are dropped.
//  4. Lines (TraceLines): crease edges linked into polylines that end at corners, at the
//     border, at junctions of three or more lines, or close on themselves.
//  5. Patches (GrowPatches): faces joined across every non-crease edge. Where the votes decided,
//     a gap left in a line must not join the two patches it separates: two faces whose smoothed
//     normals (their surface vertices' estimated normals) are more than half the crease angle apart
//     do not join across their edge, and the faces join from the
//     farthest from any crease edge inwards (a watershed), and two patches that meet at a neck
//     next to a line's free end, narrower than tuning::kPatchNeckRatio times the smaller patch's
//     widest point, stay two. Patches of fewer than tuning::kMinPatchFaces faces (noise between
//     crease edges) are then merged into the neighbour they share the longest border with. On a
//     clean mesh, whose classes came from its sharp edges (sharp_edges.h), neither is done: an
//     exporter's chamfer strip or countersink facet is one or two faces between sharp edges, and
//     a face of the model all the same.
#ifndef NVV_CORE_CREASE_NETWORK_H
#define NVV_CORE_CREASE_NETWORK_H

#include <array>
#include <vector>

#include "surface_graph.h"
#include "vertex_result.h"

namespace nvv {

struct CreaseLine {
  std::vector<int> vertices;    // in order along the line; a closed line does not repeat its first
  bool closed = false;
  double length = 0;            // sum of its edges' lengths
  double meanCuspAngle = 0;     // radians, weighted by edge length
  std::array<int, 2> endCorner{{-1, -1}};  // the corner vertex at each end, or -1
};

struct CreaseNetwork {
  std::vector<std::array<int, 2>> edges;  // crease edges as vertex pairs (lower index first), sorted
  std::vector<float> edgeCuspAngle;       // radians, per edge
  std::vector<int> edgeLine;              // line of each edge
  std::vector<CreaseLine> lines;
  std::vector<int> facePatch;             // per SurfaceGraph face
  int patchCount = 0;
  int smallestPatch = 0, largestPatch = 0;  // in faces
  std::size_t gapEdges = 0;               // edges added by gap closing
  std::size_t spurEdges = 0;              // edges of short lines with a free end, dropped
};

// The crease network of a run's results. radius: g_m; creaseAngleDeg: the run's crease angle;
// cleanMesh: the run's classes came from the mesh's sharp edges (Summary::sharpEdges).
CreaseNetwork FindCreaseNetwork(const SurfaceGraph& g, const std::vector<VertexResult>& res, double radius,
                                double creaseAngleDeg, bool cleanMesh = false);

}  // namespace nvv

#endif

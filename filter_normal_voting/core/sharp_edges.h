// Creases of a clean tessellation, from the dihedral angles of its one-rings.
//
// On a mesh exported by a CAD kernel every vertex lies exactly on the model's surfaces: the angle
// between two faces across an edge is exact information about a crease, which voting over a ball
// of k l_ave blurs (two crease rows closer than the ball's radius merge, and thinning the merged
// band to one ridge drops real crease vertices). Where a vertex's one-ring is clean, this stage
// therefore decides its class from the mesh edges themselves; where noise scatters the faces'
// normals, pass 1's votes and the ridge fit decide, as before.
//
//  - The stage runs on a clean mesh only: kCleanMeshOverNoise times the mesh's noise angle (the
//    lowest tenth of its dihedral angles: 0 on a CAD part, whose planes and strips hold flat
//    edges; 0.2 deg under 1 % noise, 0.85 deg under 5 %) stays below the sharp-edge angle.
//  - Noise at v: the lower quartile nu(v) of the dihedral angles of v's one-ring edges; v is
//    clean where kCleanOverNoise * nu(v) stays below the sharp-edge angle.
//  - An edge (v, x) between faces (v, x, c) and (x, v, d) is sharp where its dihedral angle theta
//    is at least the sharp-edge angle (or the crease angle, if lower), stands above what the mesh's
//    noise does to faces of those heights over the edge (slivers tilt most), and either is at
//    least kSharpEdgeAlways times that angle or is isolated: theta >= kSharpEdgeIsolation * the
//    median angle between face (v, x, c) and the other faces around c, and the same for d. A curved face tessellated into strips turns by the same angle at
//    every strip (not isolated: not a crease, whatever the angle), a crease between two sheets
//    turns once.
//  - A clean vertex with sharp edges along one line is a CREASE (tangent along them, cusp angle
//    their dihedral angle, normal the bisector), with sharp edges along several lines a CORNER,
//    and without any a SURFACE vertex.
// Decisions read pass-1 values only and are written afterwards: independent of the thread count.
#ifndef NVV_CORE_SHARP_EDGES_H
#define NVV_CORE_SHARP_EDGES_H

#include <cstddef>
#include <vector>

#include "params.h"
#include "surface_graph.h"
#include "vertex_result.h"

namespace nvv {

// Reclassifies the clean vertices from their sharp edges (Params::sharpEdgeAngleDeg > 0).
// Returns how many vertices changed class.
std::size_t ClassifyCleanVerticesBySharpEdges(const SurfaceGraph& g, const Params& p, int threads,
                                              std::vector<VertexResult>& res);

}  // namespace nvv

#endif

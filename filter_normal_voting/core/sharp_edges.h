// Creases of a clean tessellation, from the dihedral angles of its one-rings.
//
// On a mesh exported by a CAD kernel every vertex lies exactly on the model's surfaces: the angle
// between two faces across an edge is exact information about a crease, which voting over a ball
// of k l_ave blurs (two crease rows closer than the ball's radius merge, and thinning the merged
// band to one ridge drops real crease vertices). On a clean mesh this stage
// therefore decides every class from the mesh edges themselves; where noise scatters the faces'
// normals, pass 1's votes and the ridge fit decide, as in the paper, and the sharp edges only add
// the creases the votes miss (those below the crease angle, rows closer than the ball, faces the
// ball spans whole on a coarse mesh).
//
//  - The stage decides every class on a clean mesh: its noise angle below kCleanMeshNoiseDeg. The
//    noise angle is the lowest tenth of the dihedral angles, each scaled to what the same noise does
//    between faces of edge l_ave (noise sigma tilts faces of heights hc, hd over their edge apart by
//    about sigma (1/hc + 1/hd): a CAD export's slivers tilt most and must not read as a noisier mesh).
//    Every CAD export measured has exactly 0 there (its planes and strips hold flat edges), 1 % noise
//    about 0.2 deg, 5 % 0.8 deg. On a noisy mesh it only adds: a vertex on sharp edges becomes a
//    crease or corner, any other keeps the votes' class. From kLightNoiseDeg (about 9 % noise on a
//    regular grid) an edge is sharp by its angle alone (kSharpEdgeAlwaysDeg) only where it also turns
//    kSharpEdgeAloneOverNoise times what the noise tilts its faces (a coarse part's large faces,
//    whose creases the ball spans); below that only isolated edges and a chamfer's lines (below)
//    count, since noise takes a coarse cylinder's strip lines over that angle. The noise test scales
//    with the noise, so the stage fades out by itself as the noise grows.
//  - An edge (v, x) between faces (v, x, c) and (x, v, d) is sharp where its dihedral angle theta
//    is at least the sharp-edge angle (or the crease angle, if lower), stands well above what the
//    mesh's noise does to faces of those heights over the edge (slivers tilt most), and either is
//    at least kSharpEdgeAlwaysDeg or is isolated: theta >= kSharpEdgeIsolation * the largest
//    dihedral angle of the edges at c and at d that run parallel to (v, x). A curved face cut into
//    strips turns by the same angle at every strip (not isolated: not a crease, whatever the
//    angle); a crease between two sheets turns once. An edge flat on one side and beside a
//    parallel line on the other is sharp too where that line does not stand alone either (it
//    turns less than kSharpEdgeIsolation times the edge) and the surface beyond it is flat again
//    (its faces' far edges turn at most 1 / kSharpEdgeIsolation of it): a chamfer's two lines,
//    below kSharpEdgeAlwaysDeg (a shallow chamfer) or under noise. Two or more strips of a fillet
//    have a third line beyond the second. On a noisy mesh one end of such an edge must also run
//    on along another sharp edge: a chamfer's line is a chain, a noise edge beside a crease is alone.
//  - A vertex with sharp edges along one line is a CREASE (tangent along them, cusp angle their
//    dihedral angle, normal the bisector), with sharp edges along several lines a CORNER, and
//    without any a SURFACE vertex (its normal restarts from its one-ring's).
// Decisions read pass-1 values only and are written afterwards: independent of the thread count.
#ifndef NVV_CORE_SHARP_EDGES_H
#define NVV_CORE_SHARP_EDGES_H

#include <cstddef>
#include <vector>

#include "params.h"
#include "surface_graph.h"
#include "vertex_result.h"

namespace nvv {

// The mesh's noise angle (radians): the lowest tenth of the dihedral angles over the edges of at
// most kMedianEdgeAngleFaces evenly spread faces, each scaled by its faces' heights to faces of edge
// l_ave. Exactly 0 on a CAD export, whose planes and strips hold flat edges; 0.2 deg under 1 % noise,
// 0.8 deg under 5 %, on long slivers as on a uniform mesh. Unscaled: the raw angles' lowest tenth,
// which the noise estimate reads (noise_estimate.h). Both from one pass over the sampled edges.
struct MeshNoiseAngles {
  double scaled = 0;
  double unscaled = 0;
};
MeshNoiseAngles MeasureNoiseAngles(const SurfaceGraph& g);

// What a mesh's sharp edges did to the votes' classes.
enum class SharpEdgeRole {
  None,         // Params::sharpEdgeAngleDeg = 0: the votes' classes stand
  DecideAll,    // a clean mesh: every class from the sharp edges
  AddFeatures,  // a lightly noisy mesh: vertices on sharp edges become creases and corners, the rest keep the votes' class
  AddIsolated,  // a noisier mesh: the same from isolated sharp edges only (none is sharp by its angle alone)
};

// What the sharp edges will do on a mesh of this noise angle (radians, MeshNoiseAngles::scaled),
// known before pass 1: where they decide every class, thinning the votes' band would be overwritten
// and is skipped.
SharpEdgeRole SharpEdgeRoleFor(const Params& p, double noiseAngle);

// Reclassifies vertices from the mesh's sharp edges in their role (SharpEdgeRoleFor of the same
// noise angle; nothing where None); `changed`: how many vertices changed class.
void ClassifyBySharpEdges(const SurfaceGraph& g, const Params& p, SharpEdgeRole role, double noiseAngle, int threads,
                          std::vector<VertexResult>& res, std::size_t& changed);

}  // namespace nvv

#endif

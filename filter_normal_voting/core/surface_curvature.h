// Pass 2 for SURFACE vertices (par. 6.4 and its refinement): principal curvatures, directions and,
// for the quadric fit, a refined normal, over the vertex's own side of any crease.
//
// The quadric fit (sheet_fit.h, the default) runs Params::fitRounds times: round r reads the
// normals round r - 1 fitted (round 1: pass 1's voted normals) and writes its own; only the last
// round's curvature is kept, and the fitted normal is written after the last round, so every fit
// saw only the previous round's normals and any thread count gives the same bits. Its
// neighbourhood is the ball flood's (ball_flood.h), which stops at crease vertices when
// Params::stopAtCreases. The paper's forms (curvature_votes.h) march geodesically, once.
#ifndef NVV_CORE_SURFACE_CURVATURE_H
#define NVV_CORE_SURFACE_CURVATURE_H

#include <vector>

#include "normal_votes.h"
#include "parallel_pass.h"
#include "params.h"
#include "surface_graph.h"
#include "vertex_result.h"

namespace nvv {

// The number of passes over the vertices FitSurfaceCurvature makes for p.
int CurvatureRounds(const Params& p);

// Curvature of every SURFACE vertex of `out` (pass-1 classes and normals, thinned). Progress: round
// r reports from firstPercent + r * perRound, the last round up to 100.
PassEnd FitSurfaceCurvature(const SurfaceGraph& g, const Params& p, const Pass1Settings& s, int threads,
                            const Progress& cb, int firstPercent, int perRound, std::vector<VertexResult>& out);

}  // namespace nvv

#endif

// Thinning pass 1's feature band to its ridge: non-maximum suppression across creases.
//
// Every vertex within about g_m of a crease sees both sheets in its votes, so Eq. 10 marks a
// band up to 2 k edges wide, not the crease line itself; with a small crease angle much of that
// band also comes out CORNER. Thinning keeps one line of vertices per crease, the ridge, and
// makes the rest SURFACE vertices (their normal restarts from their one-ring's, and pass 2 fits
// their curvature like any other surface vertex's).
//
// Two forms:
//  - the ridge fit (default, Params::ridgeFit): every feature vertex fits a two-plane ridge to
//    its neighbours' heights (ridge_fit.h, ScoreRidges); a vertex stays a crease where that fit
//    finds a kink of at least the crease angle phi, no neighbour across its fitted line has a
//    larger kink F statistic, and no sharp mesh edge lies clearly across it. Where the faces'
//    normals scatter by more than phi under noise, the heights still show the kink. A ridge whose
//    heights fit a round profile far better than the kink (RoundedRidgeGain: a fillet narrower
//    than the ball) is demoted too, while its F still suppresses the weaker rows of its band. A
//    chamfer narrower than the ball votes as one crease across its strip: where a ridge's heights
//    fit two kinks (FitChamfer) better than any one kink or fillet and the mesh turns along both
//    lines on edges of about l_ave, the vertices on the two lines become creases (ChamferClaim,
//    applied after thinning) and the strip's middle is thinned.
//  - the strength form (ThinCreaseBand): suppression on Eq. 7's feature strength
//    lambda_2 + lambda_3, which peaks where the two sheets' votes balance, i.e. on the crease.
// Both keep a crease vertex that lies on two sharp mesh edges along its own crease
// (OnSharpEdge: the ridge of the mesh itself, e.g. a chamfer's two creases one edge apart).
// Decisions read pass-1 values only and are applied afterwards, so the result depends neither on
// the order nor on the thread count. Params::thinCreases = false keeps the paper's band.
// docs/design.md says what each rule was measured against.
#ifndef NVV_CORE_CREASE_THINNING_H
#define NVV_CORE_CREASE_THINNING_H

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "normal_votes.h"
#include "parallel_pass.h"
#include "params.h"
#include "surface_graph.h"
#include "vertex_result.h"

namespace nvv {

// lambda_2 + lambda_3 of the sorted eigenvalues (they sum to 1): 0 on a sheet, (1 - cos alpha) / 2
// on a crease of normal-angle alpha with balanced sheets, 2/3 at a symmetric three-sheet corner.
inline float FeatureStrength(const VertexResult& r) { return 1.0f - std::max(r.lambda[0], r.lambda[1]); }

// Pass 1's feature vertex v as the ridge fit (ridge_fit.h) sees it.
struct RidgeScore {
  float F = 0;                                // the kink's F statistic; 0: not a ridge of angle >= phi
  std::array<float, 3> tangent{{0, 0, 0}};   // the fitted ridge line
  float alphaRad = 0;
  bool rounded = false;  // the heights fit a rounded profile far better (RoundedRidgeGain): a fillet
  bool chamferMiddle = false;  // its heights fit a chamfer (FitChamfer) whose lines both miss v
};

// A vertex on a line of a chamfer fitted at band vertex `by` (FitChamfer): a crease along `tangent`
// turning by `alpha`.
struct ChamferClaim {
  int vertex, by;
  float tangent[3];
  float normal[3];  // the bisector of the line's two planes
  float alpha;
};

// Makes feature vertex v a SURFACE vertex whose normal restarts from its one-ring's (off the
// ridge its faces lie on one sheet, while pass 1's E1 there mixes both); returns 1, or 0 when v
// has no one-ring normal (then it stays as it is). Also used by the sharp edges (sharp_edges.h).
int DemoteToSurface(const SurfaceGraph& g, VertexResult& r, int v);

// Thins the band by the configured form (Params::thinCreases, Params::ridgeFit), scoring the
// ridges first where the ridge fit is used, then adds the chamfers' lines the ridge fit found.
// `thinned`: feature vertices removed, net of gaps closed and chamfer-line vertices added.
PassEnd ThinCreases(const SurfaceGraph& g, const Params& p, const Pass1Settings& s, int threads,
                    PassProgress& progress, std::vector<VertexResult>& res, std::size_t& thinned);

// The ridge fit of every feature vertex within a ball of about g_m (tuning.h) into `ridge`; with
// `claims`, also the chamfer fit where the ridge fit passed, and the vertices on its two lines
// (in no particular order: ApplyChamferClaims sorts them).
PassEnd ScoreRidges(const SurfaceGraph& g, const std::vector<VertexResult>& res, const Pass1Settings& s,
                    double creaseAngleDeg, int threads, PassProgress& progress, std::vector<RidgeScore>& ridge,
                    std::vector<ChamferClaim>* claims = nullptr);

// The ridge-fit form: demotes the feature vertices that are not on a fitted ridge, keeps corners
// where two kept ridges meet, and closes one-vertex gaps (CloseCreaseGaps). Returns the feature
// vertices removed, net of the gaps closed.
std::size_t ThinCreaseBandByRidgeFit(const SurfaceGraph& g, std::vector<VertexResult>& res,
                                     const std::vector<RidgeScore>& ridge, int threads, double creaseAngleDeg);

// The strength form. Returns how many feature vertices were demoted.
std::size_t ThinCreaseBand(const SurfaceGraph& g, std::vector<VertexResult>& res, int threads, double creaseAngleDeg);

// Closes one-vertex gaps in the kept ridge lines: a SURFACE vertex with two kept ridge-fit CREASE
// neighbours on opposite sides, along both of their lines, becomes a CREASE between them (a fin's
// two sheets cast nearly the same vote tensor, and heavy noise drops single ridge vertices).
// Returns the number of vertices closed.
std::size_t CloseCreaseGaps(const SurfaceGraph& g, std::vector<VertexResult>& res, const std::vector<RidgeScore>& ridge,
                            int threads);

}  // namespace nvv

#endif

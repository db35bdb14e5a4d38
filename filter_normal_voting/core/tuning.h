// Every tuned constant of the core, in one place: what it decides, and the measurement that
// chose it. "F1" is vertex-level crease F1, "near creases" the surface vertices 0.5-3 l_ave from
// a crease, both from the accuracy benchmark (docs/accuracy.md, bench/); k = 3 unless stated.
// The paper's own constants (sigma = g_m / 3, epsilon and eta from the user's angles) are
// parameters (params.h), not tuning.
#ifndef NVV_CORE_TUNING_H
#define NVV_CORE_TUNING_H

#include "limits.h"

namespace nvv {
namespace tuning {

// --- Neighbourhoods --------------------------------------------------------------------------

// Automatic neighbourhood cap: this many times k^2 vertices (a uniform triangulation holds about
// 3.6 k^2 within g_m = k l_ave, so regions four times denser than average stay whole) ...
constexpr double kAutoCapPerK2 = 16.0;
// ... and never fewer than this (small k on irregular meshes) nor more than kMaxCap.
constexpr int kAutoCapMin = 1024;
constexpr int kMaxCap = limits::kMaxNeighbourhoodCap;
// The automatic cap grows with k only up to the largest k the parameter table accepts: an
// absolute radius of 1e30 on a 6,000-vertex part marched the whole mesh from every vertex.
constexpr double kAutoCapMaxK = limits::kMaxK;
// ... and the automatic cap times the vertex count stays under this many march steps, down to
// kAutoCapMin per vertex: total time linear in the mesh at any k (about 40 s on two cores at the
// budget; the benchmarks' meshes and k never reach it).
constexpr double kAutoVisitBudget = 2.5e8;

// A march or flood may scan this many faces per vertex it may accept (maxNeighbourhood times
// this, the source's own faces aside): a uniform mesh has 6 per vertex and its balls hold far
// fewer vertices than the cap, so ordinary neighbourhoods never reach it, while the centre of a
// 100,000-face fan is no longer scanned from each of its spokes (total work quadratic in the fan;
// 32 left a 20,000-face fan at 30 s).
constexpr int kMarchFacesPerVertex = 8;
// Pass 1 keeps the votes over the Euclidean ball where they make v a surface vertex with this
// factor on Eq. 10's constants to spare (S_s >= m eps S_c and S_s >= m eps eta S_n); every other
// vertex is voted again over the geodesic neighbourhood (normal_votes.cpp).
constexpr double kFloodSurfaceMargin = 2.0;
// ... at radii of this many l_ave and more: at k = 1 the two balls differ at the scale of the
// one-ring (the flood made the smooth grids' k = 1 rows 0.65 % worse on average, an irregular
// cylinder's at 5 % noise up to 9 %), and the march is cheap there; from k = 3 they were 0.1-0.2 %
// better on average.
constexpr double kFloodFirstMinK = 2.0;
// ... and where no face of the ball turns from v's one-ring normal by more than this fraction of
// the crease angle: a Euclidean ball that reaches another sheet weighs it more than the geodesic
// one. Without the test the CAD parts' surface normals next to creases at 1 % noise were worse in
// 64 of 71 cells (ribs_default's median 0.49 -> 1.03 deg); at 0.5 and 0.75 within 1 % both ways,
// and 0.75 leaves the flood more of the twice-subdivided blade (pass 1 15.2 s against 18.6 s).
constexpr double kFloodTurnOfCreaseAngle = 0.75;
// Meshes of at least this many vertices are renumbered along a Morton curve for the passes
// (locality_order.h): their graph (about 190 bytes per vertex) is tens of MB, far beyond a core's
// cache, where a neighbourhood scattered over the arrays costs a miss per member.
constexpr int kLocalityOrderMinVertices = 200000;
// ... and only where the mesh's order scatters neighbourhoods: the median one-ring index span
// (over this many sampled vertices) above this window. A grid's rows (the 1 M torus: 1,733)
// keep their order, which beats a Morton curve there; a midpoint subdivision's does not.
constexpr int kLocalitySamples = 20000;
constexpr int kLocalityWindow = 16384;
// A non-manifold edge held by more faces than this lists only one other face to the callers
// that pair faces across an edge (SurfaceGraph::ForEachFaceAcross): dihedral angles mean
// nothing there, and every pair of a 100,000-face "book" edge is 10^10 pairs.
constexpr int kMaxFacesListedPerEdge = 16;

// --- Crease edges, lines and patches (crease_network.h) ----------------------------------------

// A crease edge runs within 45 deg of the crease tangent (a ridge on a noisy grid zigzags by up to
// half a triangle; 45 deg keeps its steps and refuses the edges across the line) ...
constexpr double kCreaseEdgeMinCosToTangent = 0.70710678118654752;
// ... and its two faces lean apart across the line by at least half what two sheets at the
// vertex's cusp angle do (faces of one sheet differ by noise only).
constexpr double kCreaseEdgeMinLean = 0.5;
// Two corners carry no tangent: the edge between them is a crease edge where its faces' normals
// are the crease angle apart, and never below this: at the default crease angle (40) the folded
// facets of the clean export block's hole split its 5 patches into 8.
constexpr double kCornerPairEdgeMinAngleDeg = 60.0;
// Patches of fewer faces than this (about a vertex's fan) are noise between crease edges:
// merged into the neighbour they share the longest border with (not on a clean mesh).
constexpr int kMinPatchFaces = 8;
// Under noise two patches that meet across a gap in a crease line stay two where the neck is
// narrower than this times the smaller one's widest point (both as distances to the crease edges;
// crease_network.cpp, GrowPatches). Chosen on the accuracy page's network section (the synthetic
// crease shapes, the CAD parts and the ABC model at 0-20 % noise): mean adjusted Rand index at 10 /
// 20 % 0.580 / 0.419 -> 0.590 / 0.483 with 0.7, 0.589 / 0.480 with 0.5, 0.573 / 0.430 with 1.0 (which
// split one-sheet patches too). Judged on two further noise draws of every CAD part at 5 / 10 / 20 %
// (0.599 / 0.418 / 0.279 -> 0.605 / 0.443 / 0.303).
constexpr double kPatchNeckRatio = 0.7;
// ... and only where a line's free end is at most this many times as far from the neck as the
// nearest crease edge is, plus this many l_ave: a gap. The neck between a hole's rim and a
// part's edge is bounded by lines that run past it, and splitting there (no end test) lost
// bracket_fine at 5 % noise (adjusted Rand index 1.00 -> 0.77).
constexpr double kPatchGapEndDistance = 2.0;
constexpr double kPatchGapEndSlackEdges = 1.0;
// Under noise two faces across a non-crease edge stay in different patches where their smoothed
// normals (their surface vertices' voted or fitted normals) are more than this times the crease
// angle apart: the two sheets of a crease the lines left a gap in still show there
// (crease_network.cpp, NormalsJump). Chosen on the accuracy page's network section
// (mean adjusted Rand index at 5 / 10 / 20 % 0.718 / 0.625 / 0.500 -> 0.729 / 0.643 / 0.565 with 0.5,
// 0.738 / 0.651 / 0.560 with 0.375, 0.721 / 0.641 / 0.546 with 0.75); judged on two further noise draws
// of every CAD part (0.626 / 0.468 / 0.341 -> 0.632 / 0.513 / 0.376). It splits a coarse fillet whose
// faces turn more than that apart (draft_boss_coarse at 20 %).
constexpr double kPatchNormalJumpOverCreaseAngle = 0.5;
// A line's direction at its free end is taken from this many edges back (one noisy edge turns
// up to 45 deg), and a gap is closed only ahead of it, within 45 deg.
constexpr int kGapDirectionEdges = 3;
// Gaps are closed up to this many g_m: the neighbourhood's diameter (at 20 % noise a 90 deg crease
// on a cube loses runs of 4 edges, 1.1 g_m).
constexpr double kGapReachOverRadius = 2.0;
// A gap's path follows the mesh's creases where it can: an edge whose faces turn less than this
// times the crease angle costs kGapFlatEdgeCost times its length (a path across a face cut the
// corners where a chamfer meets other creases, 1.2-1.4 l_ave off the true lines), and a crease
// vertex of a parallel line more than kGapSideStepEdges l_ave beside the free end's direction is no
// target (a chamfer's other line, 2 l_ave away on the fine block). Chosen on the accuracy page's
// network section (meshes whose lines match or beat both peers' best at 1 / 5 / 10 / 20 %: 26 / 24 /
// 18 / 19 -> 27 / 26 / 19 / 20 of 30; side step 1 and 2 l_ave, a cost of 3, within one mesh of it)
// and judged on its two held-out noise draws (lines at 5 / 10 / 20 %: 20 / 18 / 19 -> 23 / 21 / 19
// and 24 / 15 / 19 -> 24 / 17 / 19; mean ARI within 0.006 of before but at 20 % on draw 0,
// 0.565 -> 0.548). Falling back to the beside vertex where nothing else is found kept the patches'
// leaks closed but half the lines' gain.
constexpr double kGapFlatEdgeOverCreaseAngle = 0.5;
constexpr double kGapFlatEdgeCost = 2.0;
constexpr double kGapSideStepEdges = 1.5;

// --- Creases of clean tessellations (sharp_edges.h) -------------------------------------------
// Chosen on the gmsh CAD parts (block, shallow, draft boss, ribs, bracket; docs/accuracy.md) and
// the synthetic crease set, the ABC model ruling out a larger kSharpEdgeAlwaysDeg; fandisk (the
// accuracy page's real meshes) was not looked at.

// A mesh is clean where its noise angle (the lowest tenth of its dihedral angles, each scaled to
// faces of l_ave: sharp_edges.h) stays below this: 0 on every CAD export measured, 0.15-0.2 deg on default
// and fine parts under 1 % noise, 0.8 deg and more under 5 %. Both angles are 0.91 x the values chosen
// before the scaling (0.67, 1.5 deg): what the scaling does to a regular grid, whose roles stay.
constexpr double kCleanMeshNoiseDeg = 0.61;
// Above the clean angle the sharp edges add the creases and corners the votes miss, the votes keep every
// other class (the CAD parts at 5 % noise, default and fine meshes' +-1-edge F1 0.82 -> 0.93 and 0.83 ->
// 0.95, no cell of the synthetic crease set worse). From this noise angle on (about 9 % noise on a regular
// grid) only isolated sharp edges (and chamfers' lines: sharp_edges.h) count, none by kSharpEdgeAlwaysDeg
// alone unless far above the noise (kSharpEdgeAloneOverNoise): with it alone the 10 % roofs gained a
// lone noisy edge of 50 deg, a 10-strip cylinder at 5 % its 36 deg strip lines, and smooth spheres and tori
// at 20 % false creases. Isolated edges only, against the votes alone there: the CAD parts gain in 28
// cells of 5-20 % noise and lose in one (ribs_coarse at 20 %, +-1-edge F1 0.28 -> 0.27; draft_boss_coarse
// at 10 % 0.42 -> 0.60, ribs_default 0.68 -> 0.79), the synthetic crease set gains in 25 cells and loses
// in none, the smooth grids and variants are unchanged to the bit.
constexpr double kLightNoiseDeg = 1.36;
// An edge must turn this many times what the mesh's noise tilts faces of its heights (the noise
// angle is the lowest tenth, about a third of the typical noise angle): at 8 one in a hundred
// noisy facet lines of a 1 % cylinder passed.
constexpr double kSharpEdgeOverNoise = 30.0;
// From kLightNoiseDeg on, an edge of at least kSharpEdgeAlwaysDeg that turns this many times what the noise
// tilts faces of its heights is sharp by its angle alone, isolated or not: on a coarse part the ball spans
// whole faces and the votes miss creases its large faces, barely tilted, still show (CAD parts at 5-20 %:
// 16 cells better, none worse; draft_boss_coarse at 10 % +-1-edge F1 0.84 -> 0.97, ribs_coarse at 20 %
// 0.27 -> 0.49; new noise draws of the same parts at 10 / 20 %: 0.879 / 0.826 -> 0.895 / 0.847, patches'
// ARI 0.443 / 0.303 -> 0.485 / 0.340). 40 gained a little more on those parts but took a 54 deg noise edge
// on a 10 % cube and 8 (10 %) and 29 (20 %) on a 1 M-vertex noisy torus; 45 still 6 at 20 %, 50 none. The
// synthetic crease set moves by at most 0.005: the cube at 10-20 % better, the capped cylinder at 20 % worse
// (a 164 deg fold at a cap's centre). Asking the edge to run on along another sharp edge drops the fold, and
// most of the gain: a coarse part's lines are often one edge from corner to corner.
constexpr double kSharpEdgeAloneOverNoise = 50.0;
// An edge this sharp is a crease whatever its neighbours do (chamfers one edge wide: two creases
// side by side), below kLightNoiseDeg (above it only with kSharpEdgeAloneOverNoise); 50-60 lost the ABC
// model's 45 deg creases (F1 0.99 -> 0.91), and with the chamfer rule in place 60 still lost the export
// meshes' 45 deg chamfers cut into fans.
constexpr double kSharpEdgeAlwaysDeg = 40.0;
// Below that, it must turn this many times more than the lines parallel to it at the faces' far
// vertices: 1.5 kept noisy or irregular fillet strips (ribs_coarse F1 0.32, the 1 % capped
// cylinder 0.95), 2.5 neither. And as many times more than the two faces' other edges (below
// kSharpEdgeAlwaysDeg): a coarse fillet's irregular triangles have no parallel line to compare
// with (clean ribs_coarse 0.65 -> 1.00, block_coarse 0.94 -> 1.00, bracket_export 0.90 -> 0.98;
// no CAD or synthetic cell worse).
constexpr double kSharpEdgeIsolation = 2.5;
// "Parallel": within 30 deg.
constexpr double kSharpEdgeParallelCos = 0.8660254037844386;

// --- Degenerate input --------------------------------------------------------------------------

// A face is degenerate (no normal, no vote) when its area is below this times l_ave^2: a
// scale-free zero test.
constexpr double kDegenerateAreaFraction = 1e-12;

// --- Crease ridges (ridge_fit.h, crease_thinning.h) -------------------------------------------

// The kink's F statistic a ridge must reach: three standard deviations of a kink that is noise.
constexpr double kRidgeMinF = 9.0;
// The ridge fit's ball, in l_ave, clamped to [min, max] around g_m: a smaller ball holds too few
// heights for the fit's four unknowns; in a larger one a curved ridge (the capped cylinder's
// rims at k = 5) is no longer a straight line.
constexpr double kRidgeRadiusMin = 2.0;
constexpr double kRidgeRadiusMax = 3.0;
// The ridge fit's smallest residual that counts, times l_ave^2 per sample (clean meshes' exact
// fits give ~0, and F must stay finite).
constexpr double kRidgeResidualFloor = 1e-12;
// A crease the votes find only below this angle (Eq. 10 at this angle would call the vertex
// surface) must also be a kink of two planes within the noise: under noise the strip lines of a
// cylinder cut into 10 strips (a hole, a boss) vote like 40 deg creases, but the heights around
// them lie off any two planes; a chamfer's do not. 60: the crease angle the votes decided alone
// at before the default fell to 40.
constexpr double kRidgeConfirmAngleDeg = 60.0;
// "Within the noise": the fit's mean square across its sheets (ridge_fit.h) at most the square of
// this times the noise estimate's sigma (or the floor below, if larger). Chosen on the CAD parts (default crease
// angle 40, fit floor 60 deg): at 10 % noise, default and fine meshes' +-1-edge F1 0.85 / 0.93 with
// 2 against 0.84 / 0.90 with 3 and 0.82 / 0.89 without the test (at 5 %: 0.94 / 0.99 against 0.88 /
// 0.93 without); checked on the synthetic crease set (no cell worse) and on noisy cylinders of 10-24
// strips (tests/test_ridge_fit.cpp).
constexpr double kRidgeConfirmNoise = 2.0;
// ... floor of that sigma, in l_ave (a clean mesh's sigma is 0).
constexpr double kRidgeConfirmFloorEdges = 0.02;
// Where the edges at a vertex average less than l_ave / this, the mesh is refined (a mesher followed a
// curved profile there) and every crease the votes find must be confirmed so, whatever its angle: a
// fillet narrower than the ball (ribs_fine's 0.7 mm rib top, edges a fifth of l_ave) votes like a 90 deg
// crease. Chosen on the CAD parts: 3 takes failing done-when cells 21 -> 18 (ribs_default and ribs_fine
// at 5 %, draft_boss_export at 5 %), none new; 2 and 2.5 also fixed ribs_fine and draft_boss_default at
// 10 % but lost bracket_coarse and bracket_export at 5 % (true creases by a refined countersink lie off
// two planes); 4 fixed draft_boss_export only. Synthetic sets and the real meshes: byte-identical (no
// vertex there is that refined).
constexpr double kRefinedEdgeRatio = 3.0;

// A ridge whose heights fit a rounded profile better than a sharp kink by more than this many times
// the noise's variance (RoundedRidgeGain, ridge_fit.h) is a fillet narrower than the ball, not a
// crease: under noise such a fillet votes like a crease of its whole turn. Chosen on draft_boss_default
// and block_default at 10 % noise (one noise draw of their own: the boss fillet's ridge rows gained
// 40-130, the true creases' at most 35 but for a few on block's 2 mm chamfer); judged on the CAD
// parts (done-when cells failing 17 -> 13, three noise draws each at 5 / 10 / 20 %: mean +-1-edge F1
// 0.955 -> 0.967, 0.867 -> 0.898, 0.805 -> 0.820), the synthetic crease set (unchanged) and fandisk and
// the ABC model (held out: better at 10 %). 80 fixed no cell; 25 lost more of block_default's chamfer
// (measured while a demoted ridge still let its band's next row win).
constexpr double kRoundedRidgeGain = 40.0;
// The rounded-ridge test's grids: the line's offset across itself in steps of this many l_ave up to
// that many steps each way, and the round's radius rho in l_ave (a fillet of turn a and radius r
// is nearest to sqrt(w^2 + rho^2) with rho about r tan(a / 2)).
constexpr double kRoundedRidgeOffsetStep = 0.1;
constexpr int kRoundedRidgeOffsetSteps = 10;
constexpr double kRoundedRidgeRadii[] = {0.25, 0.5, 0.75, 1.0, 1.5};
// --- Chamfers narrower than the ball (crease_thinning.h, ridge_fit.h FitChamfer) --------------------
// Chosen on the CAD parts' first noise draw (block_default's 2 mm chamfers, 1.5 l_ave wide: at 10 %
// noise 72 vertices of their lines were missed, the votes seeing one 90 deg crease across each strip);
// judged on the parts' two held-out draws at 5 / 10 / 20 % (vertex F1: block_default at 10 % better on
// both, no other cell changed), the synthetic crease set and fandisk (unchanged) and the ABC model
// (within 0.003). docs/accuracy.md has the tables.
// The two lines' offsets across the fitted line: steps of this many l_ave, that many each way (the ball's
// radius, 2-3 l_ave).
constexpr double kChamferOffsetStep = 0.2;
constexpr int kChamferOffsetSteps = 12;
// The lines at least this far apart: closer, noise at a single crease fits two kinks (a 90 deg crease
// at 10 % noise: 0.2-0.4 l_ave); the CAD parts' chamfers are 0.8-1.6 l_ave wide.
constexpr double kChamferMinWidth = 0.6;
// The fillets a chamfer must fit better than (SmoothProfileResidual), radii in l_ave: up to a fillet
// wider than the ball.
constexpr double kChamferRoundRadii[] = {0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0};
// Each line turns within this range: a 90 deg crease beside a curved sheet (a hole's rim) fits a second
// kink of 85-135 deg beside one of 60-90; the parts' chamfers turn 20-60 deg at 10 % noise.
constexpr double kChamferMinTurnDeg = 20.0;
constexpr double kChamferMaxTurnDeg = 75.0;
// Better than the best smooth or one-kink profile by this many times the noise's variance: an F of 9
// for the one parameter more (the second kink's size; its offset is searched).
constexpr double kChamferGain = 9.0;
// A vertex lies on a fitted line within this many l_ave (the grid step and the noise across the line).
constexpr double kChamferOnLine = 0.3;
// A vertex becomes a crease when this many chamfer fits put it on a line: one fit's line through a
// rib's foot or a hole's rim is not enough.
constexpr int kChamferClaims = 2;
// Along each line the mesh's edges turn, beyond the mesh's median edge angle (what noise turns any
// edge), at least this fraction of the fitted angle: on the parts' chamfers 0.7-1.6 of it, on the
// draft boss's 2 mm fillet, which fits two kinks at 10 % noise as well, 0.3-0.6 (each of its rows turns
// 22.5 deg).
constexpr double kChamferEdgeTurn = 0.5;
// ... on edges at least this many l_ave long: a mesher refines a fillet and not a flat chamfer strip
// (the parts' chamfer lines 0.8-1.5 l_ave, the ribs' 0.7 mm fillets 0.24-0.39, the boss fillet 0.44-0.48).
constexpr double kChamferMinEdge = 0.6;

// An edge v->u lies "across" a line when |cos| of its angle with the line is below this (37 deg
// from the line: keeps the diagonals of a grid), "along" it when |cos| is above it.
constexpr double kCosAcrossLine = 0.8;
// Two lines (crease tangents) belong to the same crease when |cos| of their angle is above this
// (within 45 deg); a neighbour on another crease, e.g. at a cube's corner, is not compared.
// Also the stricter "across" of the sharp-edge flank test: 37 deg lost the jagged ridge of a
// 175 deg fin at 20 % noise (F1 0.97 with 45 deg, 0.95 with 37 deg).
constexpr double kCosSameLine = 0.7;
// An edge is sharp (vetoes thinning, OnSharpEdge) above the crease angle, or above this many
// times the mesh's median edge angle where that is larger: with a fixed phi, noise between two
// faces of one sheet vetoed most of a 20 deg roof's thinning at 5 % noise (F1 0.35 -> 0.19).
constexpr double kSharpOverMedianEdgeAngle = 5.0;
// ... and never above this many degrees (the cosine must stay above -1).
constexpr double kSharpAngleMaxDeg = 179.0;
// The mesh-wide dihedral-angle statistics (the median edge angle here, the noise angle of
// sharp_edges.h) are estimated from the edges of at most this many evenly spread faces.
constexpr int kMedianEdgeAngleFaces = 100000;

// --- The quadric fit (sheet_fit.h) -------------------------------------------------------------

// A neighbour whose normal is off v's by the crease angle or by this, whichever is larger, is on
// another sheet and gets no weight. At 20 % noise, with the default crease angle (40): sphere grid
// curvature error 11.5 % of 1 / l_ave with no floor, 10.5 % with 50, 10.1 % with 60 (9.9 % at a 60
// deg crease angle); but next to creases found at half their angle (the near-crease set) a floor
// of 60 let the other sheet in: capped cylinder normal p90 3.4 -> 4.2 deg (3.8 with 50).
constexpr double kFitSampleAngleFloorDeg = 50.0;

// Weight of the slope rows against the height rows, in l_ave: 2 won the paper's grids at 5 and
// 20 % noise against 1 and 4 (docs/accuracy.md, the fit's slope weight).
constexpr double kSlopeWeightEdges = 2.0;
// A neighbour's normal gives slope rows only where it is within about 78 deg of v's normal.
constexpr double kSlopeRowMinCos = 0.2;
// No cubic where the mesh's border is within this fraction of g_m: one-sided samples made the
// cubic tilt the clean sphere's border normals by 0.013 deg (0.0001 deg without); the whole
// radius also took the cubic from fits that needed it (irregular sphere at 20 %, k = 8).
constexpr double kBorderCubicFraction = 0.5;
// Variance ratio at which one kind of row is trusted over the other (heights vs slopes, both
// ways): a tenth.
constexpr double kRowVarianceRatio = 0.1;
// Bounds of the slope rows' weight that ratio sets, relative to the fixed weight: numerical
// guards (a weight of 0 or of infinity would make the system singular).
constexpr double kRowWeightRatioMin = 1e-9;
constexpr double kRowWeightRatioMax = 1e6;
// Cubic: its four extra terms are kept where their F statistic exceeds this (torus at k = 3:
// normal bias 0.44 -> 0.01 deg).
constexpr double kCubicSignificance = 10.0;
// Circle term beside creases: kept where its F statistic exceeds this; at 10 or 100 it also
// fired under 1 % noise beside creases and moved normals by up to 25 %.
constexpr double kCircleSignificance = 1000.0;
// Slopes' tilt test (first rounds beside creases): the heights' normal is kept where the
// slopes move it by an F(2, n - 6) statistic above this. Roof 120 deg, 1 %, k = 5: normal median
// 0.40 -> 0.16 deg; 6 cost normal p90 +7-10 % under 5 % noise, 10 no longer won the roof.
constexpr double kSlopeTiltSignificance = 8.0;
// Smallest reciprocal condition number of a fit's normal equations (a 6x6 quadratic).
constexpr double kFitMinRcond = 1e-10;
// Pivot spread of the shortcut factorisations (heights alone, slopes alone, cubic's Schur
// complement) below which they are not used.
constexpr double kFitMinPivotRatio = 1e-12;
// Curvature a neighbourhood supports (surface_curvature.cpp): a principal curvature above this over
// the nearest sample's distance (a circle through v and that sample is no tighter than radius d / 2)
// is refused ...
constexpr double kMaxCurvatureOverNearest = 2.0;
// ... and so is a fit whose samples' tangent spread along its smaller axis is below this share of
// the larger (samples on one line leave the curvature across it free).
constexpr double kFitMinSpread = 0.01;
// Samples a fit needs: any fit, the row-variance levers, the cubic, the tilt test (which needs
// more than this), the circle term.
constexpr int kFitMinSamples = 3;
constexpr int kVarianceLeverMinSamples = 10;
constexpr int kCubicMinSamples = 12;
constexpr int kTiltTestMinSamples = 12;
constexpr int kCircleMinSamples = 10;

// --- Noise estimate and automatic k (noise_estimate.h) -------------------------------------------
// Two-rings fitted: enough for a stable quantile, a fixed cost on any mesh.
constexpr int kNoiseSamples = 20000;
// A two-ring must hold this many vertices (6 unknowns plus room for a residual).
constexpr int kNoiseMinSamples = 10;
// Fits whose smallest pivot is below this share of the largest are skipped (collinear rings).
constexpr double kNoiseFitPivotRatio = 1e-8;
// The quantile of the per-vertex residuals taken: a quarter, so half the samples may lie on features.
constexpr double kNoiseQuantile = 0.25;
// Turns that quantile into the noise's standard deviation: measured on noisy planes (tests/test_noise_estimate.cpp).
constexpr double kNoiseQuantileScale = 1.2;
// The unscaled noise angle (radians) per unit of noise sigma / l_ave: measured on noisy planes (tests/test_noise_estimate.cpp).
constexpr double kNoiseAnglePerSigma = 0.31;
// Automatic k: kAutoKMin up to kAutoKLowNoise (sigma / l_ave), kAutoKMax from kAutoKHighNoise, linear between.
constexpr double kAutoKMin = 3.0;
constexpr double kAutoKMax = 5.0;
constexpr double kAutoKLowNoise = 0.02;
constexpr double kAutoKHighNoise = 0.10;

}  // namespace tuning
}  // namespace nvv

#endif

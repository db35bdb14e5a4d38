// A ridge (two-plane) fit at one vertex: is there a crease through v, and along which line?
//
// In a frame (e1, e2, n) at v (the caller's: normal_vector_voting.h tries pass 1's normal and the
// ball's mean normal), with every neighbour q of the ball M_v at
// (x, y, z) = (q - v) in that frame, and a line through v along t = cos(theta) e1 + sin(theta) e2
// with w = -x sin(theta) + y cos(theta) the signed distance across it:
//
//   plane:  z = h + p x + q y                         residual RSS_0
//   ridge:  z = h + p x + q y + b |w|                 residual RSS_1(theta), theta minimising it
//   sheets: gradients g_+- = (p, q) + (+-b) (-sin theta, cos theta); alpha = angle between
//           their normals (-g, 1)
//   F = (N - 4) (R_0 - R_1) / R_1                     (the kink's F statistic, 1 and N - 4 d.o.f.;
//                                                       R_1 floored, so exact fits compare)
//   R_0 = RSS_0 / (1 + |(p0, q0)|^2),  R_1 = sum_i e_i^2 / (1 + |g_side(i)|^2)
//
// R_0 and R_1 are the residuals across the fitted sheets rather than along n: a height error
// e on a sheet of gradient g is a distance e / sqrt(1 + |g|^2) from it, so steep sheets (a
// fin's, seen from the bisector's frame) do not drown the kink in their heights' residuals. The
// fit itself stays the linear one in the heights.
//
// The kink b uses every neighbour's height: at 20 % noise on a 20 deg roof (k = 3, ~30 samples)
// its angle is known to about 2-3 deg, where the normals of single faces scatter by ~14 deg and
// the vote covariance of Eq. 7 cannot tell the crease from the noise. On a vertex beside the
// ridge the kink is put through the wrong line, RSS_1 grows, and F is lower than on the ridge:
// non-maximum suppression of F across the fitted line (crease_thinning.h) finds the ridge.
// theta: 12 directions 15 deg apart, then seven halving steps around the best (to ~0.1 deg).
#ifndef NVV_CORE_RIDGE_FIT_H
#define NVV_CORE_RIDGE_FIT_H

#include <Eigen/Core>
#include <vector>

#include "tangent_frame.h"

namespace nvv {

struct RidgeFitResult {
  bool ok = false;
  double F = 0;                // F statistic of the kink
  double alphaRad = 0;         // angle between the two fitted sheets' normals
  double meanSquareAcross = 0; // R_1 / (N - 4): what is left across the two sheets, per degree of freedom
  Eigen::Vector3d tangent = Eigen::Vector3d::Zero();  // the fitted ridge line's direction
  Eigen::Vector2d lineInFrame = Eigen::Vector2d::Zero();  // the same, (e1, e2) of the fit's frame
};

// The signed distance w of a sample q (in a fit's frame) across the line through v along the unit
// direction `line` of the frame's plane: what every profile below is a function of.
inline double AcrossLine(const Eigen::Vector3d& q, const Eigen::Vector2d& line) {
  return -q.x() * line.y() + q.y() * line.x();
}

// `xyz`: the neighbours (v itself included) in the frame F, i.e. (e1.d, e2.d, n.d) of d = q - v.
// `floorRss`: the smallest residual that counts (a clean mesh's exact fits give ~0).
RidgeFitResult FitRidge(const TangentFrame& F, const std::vector<Eigen::Vector3d>& xyz, double floorRss);

// How much better the heights fit a rounded ridge than a sharp one along the same line: the
// residual sum of squares of the best kink z = h + p x + q y + b |w - w0| minus that of the best
// round z = h + p x + q y + b sqrt((w - w0)^2 + rho^2), w the signed distance across the line
// `lineInFrame` (a FitRidge result's), w0 and rho searched on grids in units of `meanEdge`
// (tuning.h). A crease between two planes fits the kink to the noise; a fillet narrower than the
// ball, which votes like a crease, fits the round by many times the noise's variance. 0 where the
// best round lies at the offset grid's end (another feature of the ball).
double RoundedRidgeGain(const std::vector<Eigen::Vector3d>& xyz, const Eigen::Vector2d& lineInFrame, double meanEdge);

// A chamfer across the line `lineInFrame` (a FitRidge result's): two kinks in the heights,
// z = h + p x + q y + b1 |w - w1| + b2 |w - w2|, w1 < w2 searched on a grid of offsets across the line
// (tuning::kChamferOffsetStep l_ave apart, kChamferOffsetSteps each way): the three planes of a chamfer
// strip between two sheets, which the one-kink ridge fit puts as one crease in the strip's middle.
struct ChamferFitResult {
  bool ok = false;
  double w1 = 0, w2 = 0;            // the two lines' offsets across lineInFrame
  double alpha1 = 0, alpha2 = 0;    // the surface's turn at each (radians)
  double rssTwo = 0;                // the heights' residual sum of squares
  Eigen::Vector3d sheetNormal[3];   // the three planes' normals in the fit's frame (w < w1, between, w > w2)
};
ChamferFitResult FitChamfer(const std::vector<Eigen::Vector3d>& xyz, const Eigen::Vector2d& lineInFrame,
                            double meanEdge);

// The smallest residual sum of squares of the heights across the same line by a smooth or one-kink
// profile on the same offset grid: one kink; a fillet (a hyperbola, or a parabola between two planes,
// of the radii tuning::kChamferRoundRadii); one kink between sheets that curve away from it. A chamfer
// must beat them all.
double SmoothProfileResidual(const std::vector<Eigen::Vector3d>& xyz, const Eigen::Vector2d& lineInFrame,
                             double meanEdge);

}  // namespace nvv

#endif

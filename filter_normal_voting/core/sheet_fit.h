// Curvature by a crease-aware quadratic fit: the default pass-2 estimator (docs/accuracy.md
// measures it against the paper's form and against MeshLab's and CGAL's estimators).
//
// In the frame (e1, e2, N) of v's normal, every same-sheet neighbour i at (u_i, w_i, h_i) with
// normal (n_u, n_w, n_h) gives three rows of a weighted least-squares problem for
//   h(u, w) = a u^2 + b u w + c w^2 + d u + e w + f:
//   height:  h(u_i, w_i)               = h_i
//   slopes:  2 a u_i + b w_i + d       = -n_u      (row weight 2 l_ave, tuning.h)
//            b u_i + 2 c w_i + e       = -n_w
// The slope targets are the normal's tangential components rather than the height field's true
// slopes -n_u/n_h: on spheres and cylinders they are exactly linear in position, so a quadratic
// fits them without the quartic bias a circle's height leaves in a quadratic.
// Rows are weighted by how much the neighbour's normal agrees with N,
//   w_i = clamp((N'N_i - cos phi) / (1 - cos phi), 0, 1)^2,
// so a sheet beyond the crease angle phi gets no say even where the neighbourhood crossed it.
// At the origin the normal is ~ (-d, -e, 1); the first fundamental form is
// I = [[1+d^2, de], [de, 1+e^2]], the second II = [[2a, b], [b, 2c]] / sqrt(1+d^2+e^2); the
// principal curvatures are the generalised eigenvalues of (II, I) with the sign flipped, so that
// a sphere with outward normals has +1/R.
//
// Levers on top of that plain fit, each a function of sheet_fit.cpp and each switchable alone
// (Params::levers, Params::cubicFit):
//  - the cubic: where no crease or border is near, four cubic terms where an F test finds them
//    significant (on a torus the quadratic's slope rows absorb them and tilt the normal);
//  - reweighting the slopes: where the heights fit far better than the slopes (a clean sheet
//    whose neighbours' voted normals lean towards a crease), the rows are weighted by the ratio of
//    their residual variances;
//  - curvature from the slopes: with the cubic, where the slopes fit far better than the heights
//    (normals are linear on spheres and cylinders, and already averaged under noise), the
//    second-order terms come from a slope-weighted fit; the normal stays the heights';
//  - the tilt test: in a round before the last, beside a crease, the heights' own normal where
//    the slopes would tilt it significantly;
//  - the circle term: beside a crease (one-sided samples), a column h^2 that lets the height rows
//    follow spheres and cylinders exactly.
#ifndef NVV_CORE_SHEET_FIT_H
#define NVV_CORE_SHEET_FIT_H

#include <Eigen/Core>
#include <vector>

#include "curvature_votes.h"
#include "params.h"
#include "tangent_frame.h"

namespace nvv {

struct SheetSample {
  Eigen::Vector3d d;  // neighbour position - v
  Eigen::Vector3d n;  // its (voted or fitted) unit normal
};

// The fit of v's same-sheet samples in the frame F. `scale` (g_m) makes the system scale-free;
// `slopeWeight` is the slope rows' weight in the mesh's units; `cosPhi` the crease angle's
// cosine. `cubic`: a cubic may replace the quadratic where significant (the caller allows it only
// where the neighbourhood reaches no crease and no border is near). `normalOnly`: the caller keeps
// only the normal (a fit round before the last), so the curvature-only levers are skipped.
PrincipalCurvatures SheetQuadricFit(const TangentFrame& F, const std::vector<SheetSample>& samples, double scale,
                                    double slopeWeight, double cosPhi, bool cubic = false, bool normalOnly = false,
                                    const SheetFitLevers& levers = SheetFitLevers());

}  // namespace nvv

#endif

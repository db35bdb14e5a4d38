// Pass 2 of Normal Vector Voting (par. 6.4): every SURFACE neighbour v_i within g_m casts a
// normal-curvature vote along its tangent direction; the votes give kappa1 >= kappa2, T1, T2.
//
//   t_i = (v_i - v) - (N'(v_i - v)) N,  T_i = t_i / |t_i|        (Eq. 13)
//   P_i = N x T_i,  n_i = N_i - (P_i' N_i) P_i                   (Eq. 15)
//   cos(dtheta_i) = N' n_i / |n_i|,  sign = sign(T_i' n_i)       (Eq. 16)
//   kappa_i = sign * dtheta_i / g_i                               (Eq. 14, 17)
//   w_i = exp(-g_i / sigma), normalised to sum 2 pi
//
// Paper's form: B_v = 1/(2 pi) sum w_i kappa_i T_i T_i' (Eq. 5) in the tangent plane,
// eigenvalues b1 >= b2, kappa1 = 3 b1 - b2, kappa2 = 3 b2 - b1 (Eq. 4), T1, T2 its eigenvectors.
// Euler least squares: argmin_II sum w_i (T_i' II T_i - kappa_i)^2, II symmetric 2x2;
// kappa1 >= kappa2 and T1, T2 are its eigenpairs.
// Sign: with outward normals a sphere of radius R has kappa1 = kappa2 = +1/R.
#ifndef NVV_CORE_CURVATURE_VOTES_H
#define NVV_CORE_CURVATURE_VOTES_H

#include <Eigen/Core>
#include <vector>

#include "tangent_frame.h"

namespace nvv {

struct CurvatureVote {
  Eigen::Vector2d t;  // unit tangent direction in the frame's (e1, e2)
  double kappa;
  double w;
};

struct PrincipalCurvatures {
  double k1 = 0, k2 = 0;
  Eigen::Vector3d t1 = Eigen::Vector3d::Zero(), t2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // set by fits that refine the normal
  bool ok = false;
};

// Eq. 13-17 for one neighbour; false when v_i lies on the normal line of v (no direction).
bool CurvatureVoteOf(const TangentFrame& F, const Eigen::Vector3d& d, const Eigen::Vector3d& Ni, double gi, double w,
                     CurvatureVote& out);

// Taubin's matrix (Eq. 5) and the eigenvalue relation (Eq. 4).
PrincipalCurvatures TaubinFromVotes(const TangentFrame& F, const std::vector<CurvatureVote>& votes);

// Weighted least squares of Euler's formula kappa_i = a x^2 + 2 b x y + c y^2.
PrincipalCurvatures EulerFromVotes(const TangentFrame& F, const std::vector<CurvatureVote>& votes);

}  // namespace nvv

#endif

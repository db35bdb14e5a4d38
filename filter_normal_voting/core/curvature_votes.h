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

#include <Eigen/Eigenvalues>
#include <cmath>
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
inline bool CurvatureVoteOf(const TangentFrame& F, const Eigen::Vector3d& d, const Eigen::Vector3d& Ni,
                            double gi, double w, CurvatureVote& out) {
  const Eigen::Vector3d t = d - F.n.dot(d) * F.n;
  const double tl = t.norm();
  if (!(tl > 1e-12 * d.norm()) || !(gi > 0)) return false;
  const Eigen::Vector3d T = t / tl;
  const Eigen::Vector3d P = F.n.cross(T);
  const Eigen::Vector3d ni = Ni - P.dot(Ni) * P;
  const double nl = ni.norm();
  if (!(nl > 0)) return false;
  const double c = std::max(-1.0, std::min(1.0, F.n.dot(ni) / nl));
  const double dtheta = std::acos(c);
  const double sign = T.dot(ni) >= 0 ? 1.0 : -1.0;
  out.t = F.ToPlane(T).normalized();
  out.kappa = sign * dtheta / gi;
  out.w = w;
  return true;
}

// Eigenpairs of a symmetric 2x2 matrix in the frame, largest first, mapped back to 3D.
inline void SymmetricEigen2(const TangentFrame& F, const Eigen::Matrix2d& M, double& e1, double& e2,
                            Eigen::Vector3d& v1, Eigen::Vector3d& v2) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(M);
  e1 = es.eigenvalues()(1);
  e2 = es.eigenvalues()(0);
  v1 = F.FromPlane(es.eigenvectors().col(1)).normalized();
  v2 = F.n.cross(v1);
}

// Taubin's matrix (Eq. 5) and the eigenvalue relation (Eq. 4).
inline PrincipalCurvatures TaubinFromVotes(const TangentFrame& F, const std::vector<CurvatureVote>& votes) {
  PrincipalCurvatures pc;
  double wsum = 0;
  Eigen::Matrix2d B = Eigen::Matrix2d::Zero();
  for (const auto& v : votes) {
    B.noalias() += v.w * v.kappa * v.t * v.t.transpose();
    wsum += v.w;
  }
  if (votes.size() < 2 || !(wsum > 0)) return pc;
  B /= wsum;  // = (1/2pi) sum w_i ... with the w_i normalised to sum 2 pi
  double b1, b2;
  SymmetricEigen2(F, B, b1, b2, pc.t1, pc.t2);
  pc.k1 = 3 * b1 - b2;
  pc.k2 = 3 * b2 - b1;
  pc.ok = std::isfinite(pc.k1) && std::isfinite(pc.k2);
  return pc;
}

// Weighted least squares of Euler's formula kappa_i = a x^2 + 2 b x y + c y^2.
inline PrincipalCurvatures EulerFromVotes(const TangentFrame& F, const std::vector<CurvatureVote>& votes) {
  PrincipalCurvatures pc;
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (const auto& v : votes) {
    const Eigen::Vector3d row(v.t.x() * v.t.x(), 2 * v.t.x() * v.t.y(), v.t.y() * v.t.y());
    A.noalias() += v.w * row * row.transpose();
    rhs += v.w * v.kappa * row;
  }
  // Directions must span: the normal matrix must not be (nearly) singular.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> check(A, Eigen::EigenvaluesOnly);
  if (votes.size() < 3 || !(check.eigenvalues()(0) > 1e-9 * check.eigenvalues()(2))) return pc;
  const Eigen::Vector3d x = A.ldlt().solve(rhs);
  Eigen::Matrix2d II;
  II << x(0), x(1), x(1), x(2);
  SymmetricEigen2(F, II, pc.k1, pc.k2, pc.t1, pc.t2);
  pc.ok = std::isfinite(pc.k1) && std::isfinite(pc.k2);
  return pc;
}

}  // namespace nvv

#endif

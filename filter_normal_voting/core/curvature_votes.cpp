#include "curvature_votes.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace nvv {

bool CurvatureVoteOf(const TangentFrame& F, const Eigen::Vector3d& d, const Eigen::Vector3d& Ni,
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

namespace {

// Eigenpairs of a symmetric 2x2 matrix in the frame, largest first, mapped back to 3D.
void SymmetricEigen2(const TangentFrame& F, const Eigen::Matrix2d& M, double& e1, double& e2,
                            Eigen::Vector3d& v1, Eigen::Vector3d& v2) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(M);
  e1 = es.eigenvalues()(1);
  e2 = es.eigenvalues()(0);
  v1 = F.FromPlane(es.eigenvectors().col(1)).normalized();
  v2 = F.n.cross(v1);
}

}  // namespace

PrincipalCurvatures TaubinFromVotes(const TangentFrame& F, const std::vector<CurvatureVote>& votes) {
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

PrincipalCurvatures EulerFromVotes(const TangentFrame& F, const std::vector<CurvatureVote>& votes) {
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

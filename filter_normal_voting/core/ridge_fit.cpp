#include "ridge_fit.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "tuning.h"

namespace nvv {

namespace {

// The sheet part of the model: 1, x, y. Planar sheets: quadric ones would absorb most of |w|
// (docs/design.md).
constexpr int kRidgeBasis = 3;
typedef Eigen::Matrix<double, kRidgeBasis, 1> RidgeBasis;
RidgeBasis RidgeBasisAt(const Eigen::Vector3d& q) {
  RidgeBasis u;
  u << 1, q.x(), q.y();
  return u;
}

// Moments of the samples: P = sum [u; z][u; z]' once, a profile's column per profile.
struct RidgeMoments {
  typedef Eigen::Matrix<double, kRidgeBasis + 1, kRidgeBasis + 1> Full;
  typedef Eigen::Matrix<double, kRidgeBasis + 1, 1> Column;
  Full P = Full::Zero();
  const std::vector<Eigen::Vector3d>& xyz;

  explicit RidgeMoments(const std::vector<Eigen::Vector3d>& samples) : xyz(samples) {
    for (const Eigen::Vector3d& q : xyz) {
      Column u;
      u << RidgeBasisAt(q), q.z();
      P.noalias() += u * u.transpose();
    }
  }

  // RSS of z = sheet + b profile(q) (-1 if singular); the coefficients in `beta` (b last).
  template <class Profile>
  double ResidualOf(Profile profile, Column* beta) const {
    Full A;
    Column r;
    A.topLeftCorner<kRidgeBasis, kRidgeBasis>() = P.topLeftCorner<kRidgeBasis, kRidgeBasis>();
    r.head<kRidgeBasis>() = P.block<kRidgeBasis, 1>(0, kRidgeBasis);
    RidgeBasis su = RidgeBasis::Zero();
    double sww = 0, szw = 0;
    for (const Eigen::Vector3d& q : xyz) {
      const double w = profile(q);
      su += w * RidgeBasisAt(q);
      sww += w * w;
      szw += q.z() * w;
    }
    A.block<kRidgeBasis, 1>(0, kRidgeBasis) = su;
    A.block<1, kRidgeBasis>(kRidgeBasis, 0) = su.transpose();
    A(kRidgeBasis, kRidgeBasis) = sww;
    r(kRidgeBasis) = szw;
    Eigen::LDLT<Full> ldlt(A);
    if (ldlt.info() != Eigen::Success) return -1;
    const Column b = ldlt.solve(r);
    if (!b.allFinite()) return -1;
    if (beta) *beta = b;
    return std::max(0.0, P(kRidgeBasis, kRidgeBasis) - b.dot(r));  // an exact fit may round below 0
  }

  // The ridge's RSS_1 at direction theta: the profile |w|.
  double Residual(double theta, Column* beta) const {
    const double c = std::cos(theta), s = std::sin(theta);
    return ResidualOf([c, s](const Eigen::Vector3d& q) { return std::abs(-q.x() * s + q.y() * c); }, beta);
  }
};

}  // namespace

RidgeFitResult FitRidge(const TangentFrame& F, const std::vector<Eigen::Vector3d>& xyz, double floorRss) {
  RidgeFitResult out;
  const int n = int(xyz.size());
  if (n < 2 * (kRidgeBasis + 1)) return out;
  const RidgeMoments m(xyz);
  Eigen::LDLT<Eigen::Matrix<double, kRidgeBasis, kRidgeBasis>> sheet(m.P.topLeftCorner<kRidgeBasis, kRidgeBasis>());
  if (sheet.info() != Eigen::Success) return out;
  const RidgeBasis rz = m.P.block<kRidgeBasis, 1>(0, kRidgeBasis);
  const RidgeBasis pc = sheet.solve(rz);
  const double rss0 = std::max(0.0, m.P(kRidgeBasis, kRidgeBasis) - pc.dot(rz));
  if (!std::isfinite(rss0)) return out;

  const double pi = 3.14159265358979323846;
  double bestTheta = 0, best = -1;
  for (int i = 0; i < 12; ++i) {
    const double th = i * pi / 12, r = m.Residual(th, nullptr);
    if (r >= 0 && (best < 0 || r < best)) { best = r; bestTheta = th; }
  }
  if (best < 0) return out;
  for (double step = pi / 24; step > pi / 1800; step /= 2)
    for (double th : {bestTheta - step, bestTheta + step}) {
      const double r = m.Residual(th, nullptr);
      if (r >= 0 && r < best) { best = r; bestTheta = th; }
    }
  Eigen::Matrix<double, kRidgeBasis + 1, 1> beta;
  const double rss1 = m.Residual(bestTheta, &beta);
  if (rss1 < 0) return out;
  const double c = std::cos(bestTheta), s = std::sin(bestTheta);
  // The sheets' slopes at v: the plane's gradient plus or minus the kink across the line.
  const Eigen::Vector2d across(-s, c), grad(beta(1), beta(2));
  const double kink = beta(kRidgeBasis);
  const Eigen::Vector2d gp = grad + kink * across, gm = grad - kink * across;
  const Eigen::Vector3d np = Eigen::Vector3d(-gp.x(), -gp.y(), 1).normalized();
  const Eigen::Vector3d nm = Eigen::Vector3d(-gm.x(), -gm.y(), 1).normalized();
  out.alphaRad = std::acos(std::max(-1.0, std::min(1.0, np.dot(nm))));
  const double across0 = rss0 / (1 + Eigen::Vector2d(pc(1), pc(2)).squaredNorm());
  const double wp = 1 / (1 + gp.squaredNorm()), wm = 1 / (1 + gm.squaredNorm());
  double across1 = 0;
  for (const Eigen::Vector3d& q : xyz) {
    const double w = -q.x() * s + q.y() * c;
    const double e = q.z() - beta.head<kRidgeBasis>().dot(RidgeBasisAt(q)) - kink * std::abs(w);
    across1 += e * e * (w >= 0 ? wp : wm);
  }
  out.F = (n - kRidgeBasis - 1) * std::max(0.0, across0 - across1) / std::max(across1, floorRss);
  out.meanSquareAcross = across1 / (n - kRidgeBasis - 1);
  out.lineInFrame = Eigen::Vector2d(c, s);
  out.tangent = F.FromPlane(out.lineInFrame);
  out.ok = std::isfinite(out.F) && std::isfinite(out.alphaRad);
  return out;
}

double RoundedRidgeGain(const std::vector<Eigen::Vector3d>& xyz, const Eigen::Vector2d& lineInFrame, double meanEdge) {
  const RidgeMoments m(xyz);
  auto across = [&](const Eigen::Vector3d& q) { return -q.x() * lineInFrame.y() + q.y() * lineInFrame.x(); };
  double sharp = -1, round = -1;
  int roundAt = 0;
  for (int i = -tuning::kRoundedRidgeOffsetSteps; i <= tuning::kRoundedRidgeOffsetSteps; ++i) {
    const double w0 = i * tuning::kRoundedRidgeOffsetStep * meanEdge;
    const double rs = m.ResidualOf([&](const Eigen::Vector3d& q) { return std::abs(across(q) - w0); }, nullptr);
    if (rs >= 0 && (sharp < 0 || rs < sharp)) sharp = rs;
    for (double radius : tuning::kRoundedRidgeRadii) {
      const double rho2 = radius * radius * meanEdge * meanEdge;
      const double rr = m.ResidualOf([&](const Eigen::Vector3d& q) {
        const double w = across(q) - w0;
        return std::sqrt(w * w + rho2);
      }, nullptr);
      if (rr >= 0 && (round < 0 || rr < round)) round = rr, roundAt = i;
    }
  }
  // A round best put at the grid's end lies beyond the fillet this line could be: another feature in
  // the ball (a coarse export's hole), not this ridge's profile.
  if (std::abs(roundAt) == tuning::kRoundedRidgeOffsetSteps) return 0;
  return sharp >= 0 && round >= 0 ? sharp - round : 0;
}

}  // namespace nvv

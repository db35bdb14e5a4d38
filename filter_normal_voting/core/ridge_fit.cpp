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
    const Eigen::Vector2d line(c, s);
    return ResidualOf([&line](const Eigen::Vector3d& q) { return std::abs(AcrossLine(q, line)); }, beta);
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
    const double w = AcrossLine(q, Eigen::Vector2d(c, s));
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
  double sharp = -1, round = -1;
  int roundAt = 0;
  for (int i = -tuning::kRoundedRidgeOffsetSteps; i <= tuning::kRoundedRidgeOffsetSteps; ++i) {
    const double w0 = i * tuning::kRoundedRidgeOffsetStep * meanEdge;
    const double rs =
        m.ResidualOf([&](const Eigen::Vector3d& q) { return std::abs(AcrossLine(q, lineInFrame) - w0); }, nullptr);
    if (rs >= 0 && (sharp < 0 || rs < sharp)) sharp = rs;
    for (double radius : tuning::kRoundedRidgeRadii) {
      const double rho2 = radius * radius * meanEdge * meanEdge;
      const double rr = m.ResidualOf([&](const Eigen::Vector3d& q) {
        const double w = AcrossLine(q, lineInFrame) - w0;
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

ChamferFitResult FitChamfer(const std::vector<Eigen::Vector3d>& xyz, const Eigen::Vector2d& lineInFrame,
                            double meanEdge) {
  ChamferFitResult out;
  const int n = int(xyz.size());
  if (n < 2 * (kRidgeBasis + 2)) return out;
  const int K = 2 * tuning::kChamferOffsetSteps + 1;
  auto offset = [&](int i) { return (i - tuning::kChamferOffsetSteps) * tuning::kChamferOffsetStep * meanEdge; };
  typedef Eigen::Matrix<double, kRidgeBasis + 2, 1> Column;
  typedef Eigen::Matrix<double, kRidgeBasis + 2, kRidgeBasis + 2> Normal;
  // The samples' moments once: the sheet's, each offset's profile |w - w_i| against the sheet and z,
  // so that a pair of offsets needs only the sum of the two profiles' products.
  const RidgeMoments m(xyz);
  std::vector<double> prof(std::size_t(K) * n);
  std::vector<RidgeBasis> su(K, RidgeBasis::Zero());
  std::vector<double> sww(K, 0), szw(K, 0);
  for (int i = 0; i < K; ++i)
    for (int j = 0; j < n; ++j) {
      const double w = std::abs(AcrossLine(xyz[j], lineInFrame) - offset(i));
      prof[std::size_t(i) * n + j] = w;
      su[i] += w * RidgeBasisAt(xyz[j]);
      sww[i] += w * w;
      szw[i] += xyz[j].z() * w;
    }
  Normal A = Normal::Zero();
  Column r = Column::Zero();
  A.topLeftCorner<kRidgeBasis, kRidgeBasis>() = m.P.topLeftCorner<kRidgeBasis, kRidgeBasis>();
  r.head<kRidgeBasis>() = m.P.block<kRidgeBasis, 1>(0, kRidgeBasis);
  const double zz = m.P(kRidgeBasis, kRidgeBasis);
  double best = -1;
  Column beta = Column::Zero();
  int bi = -1, bk = -1;
  for (int i = 0; i < K; ++i)
    for (int k = i + 1; k < K; ++k) {
      double cross = 0;
      const double* pi = &prof[std::size_t(i) * n];
      const double* pk = &prof[std::size_t(k) * n];
      for (int j = 0; j < n; ++j) cross += pi[j] * pk[j];
      A.block<kRidgeBasis, 1>(0, kRidgeBasis) = su[i];
      A.block<kRidgeBasis, 1>(0, kRidgeBasis + 1) = su[k];
      A.block<1, kRidgeBasis>(kRidgeBasis, 0) = su[i].transpose();
      A.block<1, kRidgeBasis>(kRidgeBasis + 1, 0) = su[k].transpose();
      A(kRidgeBasis, kRidgeBasis) = sww[i];
      A(kRidgeBasis + 1, kRidgeBasis + 1) = sww[k];
      A(kRidgeBasis, kRidgeBasis + 1) = A(kRidgeBasis + 1, kRidgeBasis) = cross;
      r(kRidgeBasis) = szw[i];
      r(kRidgeBasis + 1) = szw[k];
      Eigen::LDLT<Normal> ldlt(A);
      if (ldlt.info() != Eigen::Success) continue;
      const Column b = ldlt.solve(r);
      if (!b.allFinite()) continue;
      const double rss = std::max(0.0, zz - b.dot(r));
      if (best < 0 || rss < best) best = rss, bi = i, bk = k, beta = b;
    }
  if (best < 0) return out;
  out.rssTwo = best;
  out.w1 = offset(bi);
  out.w2 = offset(bk);
  // Slopes across the lines (times the across direction a): -(b1 + b2) before w1, b1 - b2 between, b1 + b2 after.
  const Eigen::Vector2d a(-lineInFrame.y(), lineInFrame.x()), grad(beta(1), beta(2));
  const double b1 = beta(kRidgeBasis), b2 = beta(kRidgeBasis + 1);
  auto normalOf = [&](double slope) {
    const Eigen::Vector2d gr = grad + slope * a;
    return Eigen::Vector3d(-gr.x(), -gr.y(), 1).normalized();
  };
  out.sheetNormal[0] = normalOf(-b1 - b2);
  out.sheetNormal[1] = normalOf(b1 - b2);
  out.sheetNormal[2] = normalOf(b1 + b2);
  out.alpha1 = std::acos(std::max(-1.0, std::min(1.0, out.sheetNormal[0].dot(out.sheetNormal[1]))));
  out.alpha2 = std::acos(std::max(-1.0, std::min(1.0, out.sheetNormal[1].dot(out.sheetNormal[2]))));
  out.ok = true;
  return out;
}

double SmoothProfileResidual(const std::vector<Eigen::Vector3d>& xyz, const Eigen::Vector2d& lineInFrame,
                             double meanEdge) {
  const RidgeMoments m(xyz);
  double best = -1;
  auto keep = [&](double rss) {
    if (rss >= 0 && (best < 0 || rss < best)) best = rss;
  };
  for (int i = -tuning::kChamferOffsetSteps; i <= tuning::kChamferOffsetSteps; ++i) {
    const double w0 = i * tuning::kChamferOffsetStep * meanEdge;
    keep(m.ResidualOf([&](const Eigen::Vector3d& q) { return std::abs(AcrossLine(q, lineInFrame) - w0); }, nullptr));
    for (double radius : tuning::kChamferRoundRadii) {
      const double rho = radius * meanEdge;
      // A fillet as a hyperbola, and as a parabola between two planes (the slope turning linearly over 2 rho).
      keep(m.ResidualOf([&](const Eigen::Vector3d& q) {
        const double w = AcrossLine(q, lineInFrame) - w0;
        return std::sqrt(w * w + rho * rho);
      }, nullptr));
      keep(m.ResidualOf([&](const Eigen::Vector3d& q) {
        const double w = std::abs(AcrossLine(q, lineInFrame) - w0);
        return w >= rho ? w - 0.5 * rho : 0.5 * w * w / rho;
      }, nullptr));
    }
    // One kink between sheets that curve away from it (a hole's rim beside a plane).
    Eigen::Matrix<double, kRidgeBasis + 3, kRidgeBasis + 3> N;
    N.setZero();
    Eigen::Matrix<double, kRidgeBasis + 3, 1> r = Eigen::Matrix<double, kRidgeBasis + 3, 1>::Zero();
    double zz = 0;
    for (const Eigen::Vector3d& q : xyz) {
      const double w = AcrossLine(q, lineInFrame) - w0;
      Eigen::Matrix<double, kRidgeBasis + 3, 1> u;
      u << RidgeBasisAt(q), std::abs(w), w > 0 ? w * w : 0.0, w < 0 ? w * w : 0.0;
      N.noalias() += u * u.transpose();
      r += q.z() * u;
      zz += q.z() * q.z();
    }
    Eigen::LDLT<Eigen::Matrix<double, kRidgeBasis + 3, kRidgeBasis + 3>> ldlt(N);
    if (ldlt.info() != Eigen::Success) continue;
    const Eigen::Matrix<double, kRidgeBasis + 3, 1> b = ldlt.solve(r);
    if (b.allFinite()) keep(std::max(0.0, zz - b.dot(r)));
  }
  return best;
}

}  // namespace nvv

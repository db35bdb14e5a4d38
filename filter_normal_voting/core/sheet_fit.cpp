#include "sheet_fit.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "small_ldlt.h"
#include "tuning.h"

namespace nvv {
namespace {

typedef Eigen::Matrix<double, 6, 6> Mat6;
typedef Eigen::Matrix<double, 6, 1> Vec6;

// A cheap conditioning test of a factorisation that is only a shortcut's (the fit's own solve
// uses the reciprocal condition number, Solvable).
template <int N>
bool WellConditioned(const SmallLdlt<N>& f) {
  return f.PivotsWithin(tuning::kFitMinPivotRatio);
}
bool Solvable(const SmallLdlt<6>& f) { return f.Rcond() > tuning::kFitMinRcond; }

// Sums of monomials over the weighted samples, from which the normal equations of a height
// field of degree D (2: quadratic, 3: cubic) are assembled. With the basis r (below) and
// h(u, w) = c'r, the height rows need sum w r r' (moments of degree <= 2D) and sum w h r; the slope
// rows, r_u = dr/du and r_w = dr/dw, need moments of degree <= 2D - 2 and the slopes' moments of
// degree <= D - 1. Accumulating them per sample costs far less than the outer products they
// replace; the systems are assembled once (SheetSystem).
// Rows of the moment tables are padded to an even width and aligned, so a row is updated two
// moments at a time (SSE2, every x86-64): the scalar loops kept the powers on the stack as scalars
// and read them back as pairs, a store-forwarding stall that was a third of the fit's time (perf,
// torus, k = 3). Each moment gets the same products in the same order either way: the same bits.
constexpr int PaddedWidth(int n) { return (n + 1) & ~1; }

template <int D>
struct SheetMoments {
  static constexpr int kM = 2 * D + 1, kS = 2 * D - 1;
  alignas(16) double M[kM][PaddedWidth(kM)] = {};          // sum w u^p w^q, p + q <= 2D
  alignas(16) double Mh[D + 1][PaddedWidth(D + 1)] = {};   // sum w h u^p w^q, p + q <= D
  // Slope rows' moments are M's over the samples whose normal gives slopes; the few that do not
  // are summed here instead and subtracted (Cut), which saves a second set of sums per sample.
  alignas(16) double S[kS][PaddedWidth(kS)] = {};
  // sum w s_u u^p w^q and sum w s_w u^p w^q, p + q <= D - 1
  alignas(16) double Tu[D][PaddedWidth(D)] = {}, Tw[D][PaddedWidth(D)] = {};
  double Hh = 0, Ss = 0;                // squared targets, for the residuals
  int used = 0, withSlopes = 0;

  void Add(double w, double u, double v, double h, bool slopes, double su, double sv) {
    double pu[kM];
    alignas(16) double pv[PaddedWidth(kM)];
    pu[0] = w;
    pv[0] = 1;
    for (int i = 1; i < kM; ++i) { pu[i] = pu[i - 1] * u; pv[i] = pv[i - 1] * v; }
    if (PaddedWidth(kM) > kM) pv[kM] = 0;
#if defined(__SSE2__)
    __m128d pv2[PaddedWidth(kM) / 2];  // (v^2i, v^2i+1), packed in registers
    for (int i = 0; i < PaddedWidth(kM) / 2; ++i) pv2[i] = _mm_set_pd(pv[2 * i + 1], pv[2 * i]);
    // row[b] += s * v^b for b < count, two at a time (the pad column takes the spare product).
    auto addRow = [&pv2](double* row, double s, int count) {
      const __m128d ss = _mm_set1_pd(s);
      for (int i = 0; 2 * i < count; ++i)
        _mm_store_pd(row + 2 * i, _mm_add_pd(_mm_load_pd(row + 2 * i), _mm_mul_pd(ss, pv2[i])));
    };
#else
    auto addRow = [&pv](double* row, double s, int count) {
      for (int b = 0; b < count; ++b) row[b] += s * pv[b];
    };
#endif
    for (int a = 0; a <= 2 * D; ++a) addRow(M[a], pu[a], 2 * D + 1 - a);
    for (int a = 0; a <= D; ++a) addRow(Mh[a], h * pu[a], D + 1 - a);
    Hh += w * h * h;
    if (slopes) {
      ++withSlopes;
      Ss += w * (su * su + sv * sv);
      for (int a = 0; a < D; ++a) {
        addRow(Tu[a], su * pu[a], D - a);
        addRow(Tw[a], sv * pu[a], D - a);
      }
    } else {
      for (int a = 0; a <= 2 * D - 2; ++a) addRow(S[a], pu[a], 2 * D - 1 - a);
    }
    ++used;
  }
  void Cut() {
    for (int a = 0; a <= 2 * D - 2; ++a)
      for (int b = 0; a + b <= 2 * D - 2; ++b) S[a][b] = withSlopes ? M[a][b] - S[a][b] : 0.0;
  }
};

// Basis of the height field, quadratic part first: r = (u^2, uw, w^2, u, w, 1, u^3, u^2 w, u w^2, w^3);
// monomial i is u^kPu[i] w^kPw[i].
constexpr int kPu[10] = {2, 1, 0, 1, 0, 0, 3, 2, 1, 0};
constexpr int kPw[10] = {0, 1, 2, 0, 1, 0, 0, 1, 2, 3};

// The normal equations of the height rows (Ah, bh) and of the slope rows (As, bs), of degree D and
// their quadratic corner, with the sums the residuals need.
template <int D>
struct SheetSystem {
  static constexpr int N = (D + 1) * (D + 2) / 2;
  typedef Eigen::Matrix<double, N, N> MatN;
  typedef Eigen::Matrix<double, N, 1> VecN;
  MatN AhN, AsN;
  VecN bhN, bsN;
  Mat6 Ah, As;
  Vec6 bh, bs;
  int used, withSlopes;
  double Hh, Ss, M0, S0;  // S0 > 0 where withSlopes > 0

  // Height rows: Ah(i, j) = sum w r_i r_j. Slope rows: As = sum w (r_u r_u' + r_w r_w'), with
  // d(u^a w^b)/du = a u^(a-1) w^b; bs = sum w (s_u r_u + s_w r_w).
  explicit SheetSystem(SheetMoments<D>& m) {
    m.Cut();
    for (int i = 0; i < N; ++i) {
      const int ai = kPu[i], bi = kPw[i];
      bhN(i) = m.Mh[ai][bi];
      bsN(i) = (ai ? ai * m.Tu[ai - 1][bi] : 0.0) + (bi ? bi * m.Tw[ai][bi - 1] : 0.0);
      for (int j = 0; j < N; ++j) {
        const int aj = kPu[j], bj = kPw[j];
        AhN(i, j) = m.M[ai + aj][bi + bj];
        AsN(i, j) = (ai * aj != 0 ? ai * aj * m.S[ai + aj - 2][bi + bj] : 0.0) +
                    (bi * bj != 0 ? bi * bj * m.S[ai + aj][bi + bj - 2] : 0.0);
      }
    }
    Ah = AhN.template topLeftCorner<6, 6>();
    As = AsN.template topLeftCorner<6, 6>();
    bh = bhN.template head<6>();
    bs = bsN.template head<6>();
    used = m.used;
    withSlopes = m.withSlopes;
    Hh = m.Hh;
    Ss = m.Ss;
    M0 = m.M[0][0];
    S0 = m.S[0][0];
  }
  // Residual variances of the quadratic c on the height rows and on the slope rows, from the
  // moments, corrected for the coefficients each fit spends.
  double HeightVar(const Vec6& c) const {
    return std::max(0.0, Hh - 2 * c.dot(bh) + c.dot(Ah * c)) / M0 * used / (used - 6.0);
  }
  double SlopeVar(const Vec6& c) const {
    return std::max(0.0, Ss - 2 * c.dot(bs) + c.dot(As * c)) / (2 * S0) * (2.0 * used) / (2.0 * used - 5);
  }
};

// The quadratic being fitted: its coefficients, the slope rows' weight they were solved with, and
// that system's factorisation.
struct QuadraticFit {
  Vec6 x;
  double lambda;
  SmallLdlt<6> ldlt;
};

// A sample's row weight w (the normal agreement, sheet_fit.h) and its coordinates (u, v, h) in
// the frame, scaled by 1/scale (which keeps the system well conditioned at any mesh scale); false
// where the sample gets no weight.
bool SampleInFrame(const TangentFrame& F, const SheetSample& s, double scale, double cosPhi, double& w, double& u,
                   double& v, double& h) {
  const double agree = (F.n.dot(s.n) - cosPhi) / (1.0 - cosPhi);
  if (!(agree > 0)) return false;
  w = std::min(1.0, agree) * std::min(1.0, agree);
  u = F.e1.dot(s.d) / scale;
  v = F.e2.dot(s.d) / scale;
  h = F.n.dot(s.d) / scale;
  return true;
}

// The circle term's column q_i = hq(u_i, w_i)^2, with hq the quadratic's own prediction: every
// sphere and cylinder satisfies h = Q(u, w) + L(u, w) + f + g h^2 exactly in any frame, so with
// it the height rows follow them beside a crease, where the samples are one-sided and a circle's
// quartic remainder would tilt the normal. No slope term: the slope targets are already exact
// on spheres and cylinders.
class CircleColumn {
 public:
  CircleColumn(const TangentFrame& F, const std::vector<SheetSample>& samples, double scale, double cosPhi)
      : F_(F), samples_(samples), scale_(scale), cosPhi_(cosPhi) {}
  // The sums of the column against the quadratic's basis (aq), itself (qq) and the heights (qh),
  // for the quadratic x; false where the column is zero.
  bool Sums(const Vec6& x, Vec6& aq, double& qq, double& qh) const {
    aq.setZero();
    for (const auto& s : samples_) {
      double w, u, v, h;
      if (!SampleInFrame(F_, s, scale_, cosPhi_, w, u, v, h)) continue;
      const double hq = x(0) * u * u + x(1) * u * v + x(2) * v * v + x(3) * u + x(4) * v + x(5);
      const double q = hq * hq;
      Vec6 r;
      r << u * u, u * v, v * v, u, v, 1.0;
      aq += (w * q) * r;
      qq += w * q * q;
      qh += w * q * h;
    }
    return qq > 0;
  }

 private:
  const TangentFrame& F_;
  const std::vector<SheetSample>& samples_;
  const double scale_, cosPhi_;
};

// Lever: the cubic. Given the quadratic's minimiser x (system A22 x = b2, factorised), adds the
// cubic terms where an F test finds them significant, by block elimination rather than a 10 x 10
// solve: with the Schur complement S = A33 - A32 A22^-1 A23 and the gradient g = b3 - A32 x, the
// cubic's coefficients are c3 = S^-1 g, its quadratic part x - A22^-1 A23 c3, and the residual
// drops by g'c3. `yy` is the targets' weighted square sum, `rows` the number of rows.
void CubicIfSignificant(const Eigen::Matrix<double, 10, 10>& A, const Eigen::Matrix<double, 10, 1>& b,
                        const SmallLdlt<6>& quadratic, double yy, double rows, Vec6& x) {
  const Eigen::Matrix<double, 6, 4> A23 = A.topRightCorner<6, 4>();
  const Eigen::Matrix<double, 6, 4> Z = quadratic.Solve(A23);
  const Eigen::Matrix4d S = A.bottomRightCorner<4, 4>() - A23.transpose() * Z;
  const Eigen::Vector4d g = b.tail<4>() - A23.transpose() * x;
  const SmallLdlt<4> schur(S);
  if (!WellConditioned(schur)) return;
  const Eigen::Vector4d c3 = schur.Solve(g);
  const double drop = g.dot(c3);
  const double rssQuadratic = std::max(0.0, yy - x.dot(b.head<6>()));
  const double rssCubic = std::max(1e-300, rssQuadratic - drop);
  if (drop / 4 > tuning::kCubicSignificance * rssCubic / (rows - 10)) x -= Z * c3;
}
// D = 2: no cubic terms to add.
void CubicIfSignificant(const Mat6&, const Vec6&, const SmallLdlt<6>&, double, double, Vec6&) {}

// The cubic added to the quadratic c whose slope rows were weighted `ratio`, factorised as f.
template <int D>
void AddCubic(const SheetSystem<D>& sys, double ratio, const SmallLdlt<6>& f, Vec6& c) {
  typedef typename SheetSystem<D>::MatN MatN;
  typedef typename SheetSystem<D>::VecN VecN;
  if (D == 3 && sys.used >= tuning::kCubicMinSamples)
    CubicIfSignificant(MatN(sys.AhN + ratio * sys.AsN), VecN(sys.bhN + ratio * sys.bsN), f, sys.Hh + ratio * sys.Ss,
                       sys.used + 2.0 * sys.withSlopes, c);
}

// Lever: the circle term (CircleColumn) added to the quadratic c of the system with slope weight
// `lam`, factorised as f, where an F test finds it significant, by block elimination:
// z = A^-1 a_q, s = qq - a_q'z, gradient t = qh - a_q'c, c -= (t / s) z. Returns the residual's
// drop t^2 / s, or 0 where the term is not taken. Only where no cubic is fitted (D == 2).
template <int D>
double AddCircleTerm(const SheetSystem<D>& sys, const CircleColumn* circle, const SmallLdlt<6>& f, double lam,
                     Vec6& c) {
  if (D != 2 || circle == nullptr || sys.used < tuning::kCircleMinSamples) return 0.0;
  Vec6 aq;
  double qq = 0, qh = 0;
  if (!circle->Sums(c, aq, qq, qh)) return 0.0;
  const Vec6 z = f.Solve(aq);
  const double sq = qq - aq.dot(z), t = qh - aq.dot(c);
  if (!(sq > 1e-12 * qq)) return 0.0;
  const double rss = std::max(0.0, sys.Hh + lam * sys.Ss - c.dot(sys.bh + lam * sys.bs)), drop = t * t / sq;
  const double rows = sys.used + (lam > 0 ? 2.0 * sys.withSlopes : 0.0);
  if (!(drop > tuning::kCircleSignificance * std::max(1e-300, rss - drop) / (rows - 7))) return 0.0;
  c -= (t / sq) * z;
  return drop;
}

// Lever: the slopes' tilt test. True where the joint fit x tilts the normal significantly off the
// heights' own fit xh: the gradients (d, e) compared in the heights' covariance s^2 [A_h^-1]_de,
//   T = (x - xh)_de' ([A_h^-1]_de)^-1 (x - xh)_de / (2 s^2),  s^2 = RSS_h(xh) / (n - 6),
// an F(2, n - 6) statistic where the slopes agree with the heights.
bool SlopesTiltTheNormal(const SmallLdlt<6>& heights, const Vec6& xh, const Vec6& x, double Hh, const Vec6& bh,
                         int used) {
  const double s2 = std::max(0.0, Hh - xh.dot(bh)) / (used - 6.0);
  if (!(s2 > 0)) return false;  // heights fit exactly: the variance ratio already trusts them
  const Vec6 cd = heights.Solve(Vec6::Unit(3)), ce = heights.Solve(Vec6::Unit(4));
  Eigen::Matrix2d C;  // [A_h^-1]_de
  C << cd(3), ce(3), cd(4), ce(4);
  const Eigen::Vector2d t = (x - xh).segment<2>(3);
  const double det = C(0, 0) * C(1, 1) - C(0, 1) * C(1, 0);
  if (!(det > 0)) return false;
  const Eigen::Vector2d Ct(C(1, 1) * t(0) - C(0, 1) * t(1), C(0, 0) * t(1) - C(1, 0) * t(0));  // det C^-1 t
  return t.dot(Ct) / det > 2.0 * tuning::kSlopeTiltSignificance * s2;
}

// The second-order terms the curvature-from-slopes lever found, to replace the fit's.
struct SlopeCurvature {
  bool found = false;
  Vec6 xc;
};

// Levers on the balance of height and slope rows. sw2 weighs slope rows against height rows as if
// their variances were in a fixed ratio, right under noise; where one kind of row fits far better
// than the other (kRowVarianceRatio), the variances say how to weigh them instead:
//  - reweighting: heights far better (a clean flat sheet next to a crease, whose neighbours'
//    voted normals lean towards it): the fit is solved again with the ratio of the variances;
//  - curvature from the slopes (with the cubic only: beside a crease the neighbours' normals
//    lean towards it): slopes far better: a slope-weighted fit gives the second-order terms;
//  - the tilt test, in a round before the last where no cubic is fitted (beside a crease).
// The slopes' residual at the joint fit bounds their own fit's from above, so the slope-only
// fit is skipped where even that bound cannot trigger a lever.
template <int D>
void BalanceHeightsAndSlopes(const SheetSystem<D>& sys, double sw2, bool normalOnly, const CircleColumn* circle,
                             const SheetFitLevers& levers, QuadraticFit& fit, SlopeCurvature& slopeCurvature) {
  if (!(sys.used >= tuning::kVarianceLeverMinSamples && sys.withSlopes > 0)) return;
  const SmallLdlt<6> heights(sys.Ah);
  if (!WellConditioned(heights)) return;
  // The heights' own residual, with the circle term where it is significant (on a clean cylinder
  // beside a crease only that makes the heights fit exactly).
  const Vec6 xh = heights.Solve(sys.bh);
  Vec6 xhc = xh;
  const double dropH = AddCircleTerm(sys, circle, heights, 0.0, xhc);
  const double eh = dropH > 0 ? std::max(0.0, sys.Hh - xh.dot(sys.bh) - dropH) / sys.M0 * sys.used / (sys.used - 7.0)
                              : sys.HeightVar(xh);
  const bool slopesForCurvature = D == 3 && !normalOnly && levers.slopeCurvature;
  if (slopesForCurvature || eh < tuning::kRowVarianceRatio * sw2 * sys.SlopeVar(fit.x)) {
    const SmallLdlt<5> slopes(sys.As.template topLeftCorner<5, 5>());
    if (WellConditioned(slopes)) {
      Vec6 xs = Vec6::Zero();
      xs.head<5>() = slopes.Solve(sys.bs.template head<5>());
      const double es = sys.SlopeVar(xs);
      if (levers.reweightSlopes && eh < tuning::kRowVarianceRatio * sw2 * es) {
        const double ratio = std::max(eh / es, tuning::kRowWeightRatioMin * sw2);
        const SmallLdlt<6> again(sys.Ah + ratio * sys.As);
        if (Solvable(again)) {
          fit.x = again.Solve(sys.bh + ratio * sys.bs);
          fit.lambda = ratio;
          fit.ldlt = again;
        }
      } else if (slopesForCurvature && sw2 * es < tuning::kRowVarianceRatio * eh) {
        const double ratio = std::min(eh / std::max(es, 1e-300), tuning::kRowWeightRatioMax * sw2);
        const SmallLdlt<6> again(sys.Ah + ratio * sys.As);
        if (Solvable(again)) {
          slopeCurvature.found = true;
          slopeCurvature.xc = again.Solve(sys.bh + ratio * sys.bs);
          AddCubic(sys, ratio, again, slopeCurvature.xc);
        }
      }
    }
  }
  if (levers.tiltTest && D == 2 && normalOnly && fit.lambda == sw2 && sys.used > tuning::kTiltTestMinSamples &&
      SlopesTiltTheNormal(heights, xh, fit.x, sys.Hh, sys.bh, sys.used)) {
    fit.x = xh;
    fit.lambda = 0;
    fit.ldlt = heights;
  }
}

// Principal curvatures, directions and normal of the height field with quadratic part x at the
// origin, back in the mesh's units (curvature scales as 1 / length).
PrincipalCurvatures CurvatureFromCoefficients(const TangentFrame& F, const Vec6& x, double scale) {
  PrincipalCurvatures pc;
  const double d = x(3), e = x(4);
  Eigen::Matrix2d I, II;
  I << 1 + d * d, d * e, d * e, 1 + e * e;
  const double W = std::sqrt(1 + d * d + e * e);
  II << 2 * x(0), x(1), x(1), 2 * x(2);
  II /= (W * scale);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> es(II, I);
  if (es.info() != Eigen::Success) return pc;
  // Smallest eigenvalue of II -> largest curvature after the sign flip.
  pc.k1 = -es.eigenvalues()(0);
  pc.k2 = -es.eigenvalues()(1);
  pc.normal = (F.n - d * F.e1 - e * F.e2).normalized();
  const Eigen::Vector2d x1 = es.eigenvectors().col(0);
  pc.t1 = (x1.x() * (F.e1 + d * F.n) + x1.y() * (F.e2 + e * F.n)).normalized();
  pc.t2 = pc.normal.cross(pc.t1);
  pc.ok = std::isfinite(pc.k1) && std::isfinite(pc.k2) && pc.t1.allFinite();
  return pc;
}

// The fit from the samples' moments: the plain weighted quadratic, then each lever in turn.
template <int D>
PrincipalCurvatures FitFromMoments(const TangentFrame& F, SheetMoments<D>& m, double scale, double sw2,
                                   bool normalOnly, const CircleColumn* circle, const SheetFitLevers& levers) {
  const SheetSystem<D> sys(m);
  if (sys.used < tuning::kFitMinSamples) return PrincipalCurvatures();
  // Too few or collinear samples leave A (nearly) singular: refuse rather than fit noise.
  QuadraticFit fit{Vec6(), sw2, SmallLdlt<6>(sys.Ah + sw2 * sys.As)};
  if (!Solvable(fit.ldlt)) return PrincipalCurvatures();
  fit.x = fit.ldlt.Solve(sys.bh + sw2 * sys.bs);
  SlopeCurvature slopeCurvature;
  BalanceHeightsAndSlopes(sys, sw2, normalOnly, circle, levers, fit, slopeCurvature);
  AddCubic(sys, fit.lambda, fit.ldlt, fit.x);
  AddCircleTerm(sys, circle, fit.ldlt, fit.lambda, fit.x);
  if (slopeCurvature.found) fit.x.head<3>() = slopeCurvature.xc.head<3>();
  return CurvatureFromCoefficients(F, fit.x, scale);
}

template <int D>
PrincipalCurvatures SheetFitOfDegree(const TangentFrame& F, const std::vector<SheetSample>& samples, double scale,
                                     double sw2, double cosPhi, bool normalOnly, const SheetFitLevers& levers) {
  SheetMoments<D> m;
  for (const auto& s : samples) {
    double w, u, v, h;
    if (!SampleInFrame(F, s, scale, cosPhi, w, u, v, h)) continue;
    // A normal turned far away from N says little about this sheet's slopes.
    const bool slopes = F.n.dot(s.n) > tuning::kSlopeRowMinCos;
    m.Add(w, u, v, h, slopes, slopes ? -F.e1.dot(s.n) : 0.0, slopes ? -F.e2.dot(s.n) : 0.0);
  }
  const CircleColumn circle(F, samples, scale, cosPhi);
  return FitFromMoments<D>(F, m, scale, sw2, normalOnly, levers.circleTerm ? &circle : nullptr, levers);
}

}  // namespace

PrincipalCurvatures SheetQuadricFit(const TangentFrame& F, const std::vector<SheetSample>& samples, double scale,
                                    double slopeWeight, double cosPhi, bool cubic, bool normalOnly,
                                    const SheetFitLevers& levers) {
  const double sw2 = (slopeWeight / scale) * (slopeWeight / scale);
  return cubic && samples.size() >= std::size_t(tuning::kCubicMinSamples)
             ? SheetFitOfDegree<3>(F, samples, scale, sw2, cosPhi, normalOnly, levers)
             : SheetFitOfDegree<2>(F, samples, scale, sw2, cosPhi, normalOnly, levers);
}

}  // namespace nvv

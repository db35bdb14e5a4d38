// Curvature by a crease-aware quadratic fit (the default pass-2 estimator; measured against
// the paper's form in docs/accuracy.md).
//
// In the frame (e1, e2, N) of v's voted normal, every same-sheet neighbour i (the SURFACE
// vertices the crease-stopping flood reaches, ball_flood.h, v included) at (u_i, w_i, h_i) with voted
// normal (n_u, n_w, n_h) gives three rows of a weighted least-squares problem for
//   h(u, w) = a u^2 + b u w + c w^2 + d u + e w + f:
//   height:  h(u_i, w_i)               = h_i
//   slopes:  2 a u_i + b w_i + d       = -n_u   (row weight 2 l_ave, or less where the
//            b u_i + 2 c w_i + e       = -n_w    heights alone fit far better: see below)
// The slope targets are the normal's tangential components rather than the height field's
// true slopes -n_u/n_h: on spheres and cylinders they are exactly linear in position, so a
// quadratic fits them without the quartic bias a circle's height leaves in a quadratic
// (measured on a torus with g_m = b/2: kappa1 error 7.4 % with -n_u/n_h, 0.5 % with -n_u).
// Rows are weighted by how much the neighbour's normal agrees with N:
//   w_i = clamp((N'N_i - cos phi) / (1 - cos phi), 0, 1)^2,
// so a sheet beyond the crease angle phi gets no say even where the march crossed the crease.
// At the origin: normal ~ (-d, -e, 1); first fundamental form I = [[1+d^2, de], [de, 1+e^2]],
// second II = [[2a, b], [b, 2c]] / sqrt(1+d^2+e^2); principal curvatures are the
// generalised eigenvalues of (II, I) with the sign flipped, so that a sphere with outward
// normals has +1/R (h = -(u^2+w^2)/(2R) there).
// Where the neighbourhood reaches no crease and no border is near, a cubic height field (four
// more terms, the same rows) replaces the quadratic when an F test finds its extra terms
// significant: on a clean torus the quadratic's slope rows absorb the cubic terms and tilt the
// normal (0.4 deg at k = 3).
// The quadratic's coefficients of the cubic are read at the origin just the same. There, too,
// the second-order terms come from the slope rows wherever these fit far better than the
// heights (the shape operator is the normal's derivative, and normals are exactly linear on
// spheres and cylinders and already averaged under noise); the normal stays the heights'.
#ifndef NVV_CORE_SHEET_FIT_H
#define NVV_CORE_SHEET_FIT_H

#include <Eigen/Eigenvalues>
#include <cmath>
#include <vector>

#include "curvature_votes.h"
#include "small_ldlt.h"

namespace nvv {

struct SheetSample {
  Eigen::Vector3d d;  // neighbour position - v
  Eigen::Vector3d n;  // its voted unit normal
};

// A cheap conditioning test of a factorisation that is only a shortcut's (the fit's own solve
// uses the reciprocal condition number): its pivots within 1e12 of each other.
template <int N>
bool WellConditioned(const SmallLdlt<N>& f) {
  return f.PivotsWithin(1e-12);
}

// Sums of monomials over the weighted samples, from which the normal equations of a height
// field of degree D (2: quadratic, 3: cubic) are assembled. With the basis r (below) and
// h(u, w) = c'r, the height rows need sum w r r' (moments of degree <= 2D) and sum w h r; the slope
// rows, r_u = dr/du and r_w = dr/dw, need moments of degree <= 2D - 2 and the slopes' moments of
// degree <= D - 1. Accumulating them per sample costs far less than the outer products they
// replace (the fit was the largest item of pass 2's profile); A and rhs are assembled once.
template <int D>
struct SheetMoments {
  double M[2 * D + 1][2 * D + 1] = {};  // sum w u^p w^q, p + q <= 2D
  double Mh[D + 1][D + 1] = {};         // sum w h u^p w^q, p + q <= D
  // Slope rows' moments are M's over the samples whose normal gives slopes; the few that do not
  // are summed here instead and subtracted (Cut), which saves a second set of sums per sample.
  double S[2 * D - 1][2 * D - 1] = {};
  double Tu[D][D] = {}, Tw[D][D] = {};  // sum w s_u u^p w^q and sum w s_w u^p w^q, p + q <= D - 1
  double Hh = 0, Ss = 0;                // squared targets, for the residuals
  int used = 0, withSlopes = 0;

  void Add(double w, double u, double v, double h, bool slopes, double su, double sv) {
    double pu[2 * D + 1], pv[2 * D + 1];
    pu[0] = w;
    pv[0] = 1;
    for (int i = 1; i <= 2 * D; ++i) { pu[i] = pu[i - 1] * u; pv[i] = pv[i - 1] * v; }
    for (int a = 0; a <= 2 * D; ++a)
      for (int b = 0; a + b <= 2 * D; ++b) M[a][b] += pu[a] * pv[b];
    const double hh = h;
    for (int a = 0; a <= D; ++a)
      for (int b = 0; a + b <= D; ++b) Mh[a][b] += hh * pu[a] * pv[b];
    Hh += w * h * h;
    if (slopes) {
      ++withSlopes;
      Ss += w * (su * su + sv * sv);
      for (int a = 0; a < D; ++a)
        for (int b = 0; a + b < D; ++b) { Tu[a][b] += su * pu[a] * pv[b]; Tw[a][b] += sv * pu[a] * pv[b]; }
    } else {
      for (int a = 0; a <= 2 * D - 2; ++a)
        for (int b = 0; a + b <= 2 * D - 2; ++b) S[a][b] += pu[a] * pv[b];
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

// The cubic fit replaces the quadratic where its four extra coefficients are significant:
// F = ((RSS_2 - RSS_3) / 4) / (RSS_3 / (rows - 10)) > kCubicSignificance, both residuals on the joint
// (height and slope) rows. On a torus the quadratic's slopes absorb the cubic terms (normal bias
// 0.4 deg at k = 3, 1.2 deg at k = 5, clean); docs/accuracy.md gives the thresholds measured.
constexpr double kCubicSignificance = 10.0;

// D = 2: no cubic terms to add.
inline void CubicIfSignificant(const Eigen::Matrix<double, 6, 6>&, const Eigen::Matrix<double, 6, 1>&,
                               const SmallLdlt<6>&, double, double,
                               Eigen::Matrix<double, 6, 1>&) {}

// Given the quadratic's minimiser x of |rows|^2 (system A22 x = b2, factorised), adds the cubic
// terms where they are significant, by block elimination rather than a 10 x 10 solve: with the
// Schur complement S = A33 - A32 A22^-1 A23 and the gradient g = b3 - A32 x, the cubic's
// coefficients are c3 = S^-1 g, its quadratic part x - A22^-1 A23 c3, and the residual drops by
// g'c3. `yy` is the targets' weighted square sum, `rows` the number of rows.
inline void CubicIfSignificant(const Eigen::Matrix<double, 10, 10>& A, const Eigen::Matrix<double, 10, 1>& b,
                               const SmallLdlt<6>& quadratic, double yy, double rows,
                               Eigen::Matrix<double, 6, 1>& x) {
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
  if (drop / 4 > kCubicSignificance * rssCubic / (rows - 10)) x -= Z * c3;
}

// `circle(x, aq, qq, qh)`, where given, fills the sums of the circle term's column (below) for the
// quadratic coefficients x; it is used only where no cubic is fitted (D == 2).
struct NoCircleTerm {
  bool operator()(const Eigen::Matrix<double, 6, 1>&, Eigen::Matrix<double, 6, 1>&, double&, double&) const {
    return false;
  }
};

// The circle term: where the neighbourhood reaches a crease the samples lie on one side of v,
// and a quadratic cannot follow a circle's height h = u^2 / 2R + u^4 / 8R^3 + ...: the quartic
// remainder, uneven across the one-sided samples, tilts the linear terms d, e, i.e. the normal
// (0.07 deg median beside the rims of a clean cylinder of radius 8 l_ave, k = 3). Every sphere
// and cylinder satisfies h = Q(u, w) + L(u, w) + f + g h^2 exactly in any frame (g = 1 / 2R up
// to the tilt), so the height rows get one more column, q_i = hq(u_i, w_i)^2 with hq the
// quadratic's own prediction (a known function of position: no error in the regressor), and
// no slope term (the slope targets -n_u are already exact on spheres and cylinders). Its
// coefficient g is kept only where an F test finds it significant, as the cubic's, but at a far
// higher threshold: it is meant for the remainder of clean and nearly clean curved sheets, and
// at 10 or 100 it also fired under 1 % noise beside creases, where it moved the normals by up to
// +25 % (docs/accuracy.md gives the measurements).
constexpr double kCircleSignificance = 1000.0;

// The slopes' tilt test. The slope rows of the first fit round are pass 1's voted normals, and
// beside a crease these lean towards it (their votes came from both sheets, weighted over g_m),
// by an amount that changes smoothly with the distance to the crease: the slope rows fit it
// well on their own (so the variance ratio above does not see it), yet they pull the joint
// fit's normal off the heights'. The rounds undo it only slowly (roof of 120 deg, 1 % noise,
// k = 5, 0.5-3 l_ave from the ridge: normal median 0.47, 0.40, 0.32, 0.24 deg after 1-4 rounds).
// The test compares the gradient (d, e) of the joint fit x with the heights' own xh, in the
// heights' covariance s^2 [A_h^-1]_de:
//   T = (x - xh)_de' ([A_h^-1]_de)^-1 (x - xh)_de / (2 s^2),  s^2 = RSS_h(xh) / (n - 6),
// an F(2, n - 6) statistic where the slopes agree with the heights. Where T exceeds the
// threshold, that round keeps the heights' normal (its curvature is not kept anyway), and the
// next round's slopes are those normals. Measured (docs/accuracy.md): that roof's normal median
// 0.40 -> 0.16 deg; at 3 and 6 the test also fired on consistent fits under 5 % noise at k = 3
// (normal p90 +7-10 % at 6), at 10 it no longer won the roof (0.22 deg). The same test on all six
// coefficients (the full height residual) won it only at 3, then also fired under noise; in the
// last round that form also hit the capped cylinder's curvature (the quadratic's own remainder
// beside a curved rim), so the last round is left alone.
constexpr double kSlopeTiltSignificance = 8.0;

// True where the joint fit x tilts the normal significantly off the heights' own fit xh (the
// test above); `heights` factorises A_h, Hh and bh are the heights' sum of squares and moments.
template <class Ldlt, class Vec6>
bool SlopesTiltTheNormal(const Ldlt& heights, const Vec6& xh, const Vec6& x, double Hh, const Vec6& bh, int used) {
  const double s2 = std::max(0.0, Hh - xh.dot(bh)) / (used - 6.0);
  if (!(s2 > 0)) return false;  // heights fit exactly: the variance ratio above already trusts them
  const Vec6 cd = heights.Solve(Vec6::Unit(3)), ce = heights.Solve(Vec6::Unit(4));
  Eigen::Matrix2d C;  // [A_h^-1]_de
  C << cd(3), ce(3), cd(4), ce(4);
  const Eigen::Vector2d t = (x - xh).template segment<2>(3);
  const double det = C(0, 0) * C(1, 1) - C(0, 1) * C(1, 0);
  if (!(det > 0)) return false;
  const Eigen::Vector2d Ct(C(1, 1) * t(0) - C(0, 1) * t(1), C(0, 0) * t(1) - C(1, 0) * t(0));  // det C^-1 t
  return t.dot(Ct) / det > 2.0 * kSlopeTiltSignificance * s2;
}

// `normalOnly`: the caller keeps only the fitted normal (a fit round before the last), so the
// slopes' curvature, which changes only a, b, c, is not computed; the normal is the same bits.
template <int D, class Circle = NoCircleTerm>
PrincipalCurvatures SheetFitFromMoments(const TangentFrame& F, SheetMoments<D>& m, double scale, double sw2,
                                        bool normalOnly = false, const Circle& circle = Circle()) {
  PrincipalCurvatures pc;
  typedef Eigen::Matrix<double, 6, 6> Mat6;
  typedef Eigen::Matrix<double, 6, 1> Vec6;
  constexpr int N = (D + 1) * (D + 2) / 2;
  typedef Eigen::Matrix<double, N, N> MatN;
  typedef Eigen::Matrix<double, N, 1> VecN;
  m.Cut();
  // Height rows: Ah(i, j) = sum w r_i r_j. Slope rows: As = sum w (r_u r_u' + r_w r_w'), with
  // d(u^a w^b)/du = a u^(a-1) w^b; bs = sum w (s_u r_u + s_w r_w).
  MatN AhN, AsN;
  VecN bhN, bsN;
  for (int i = 0; i < N; ++i) {
    const int ai = kPu[i], bi = kPw[i];
    bhN(i) = m.Mh[ai][bi];
    bsN(i) = (ai ? ai * m.Tu[ai - 1][bi] : 0.0) + (bi ? bi * m.Tw[ai][bi - 1] : 0.0);
    for (int j = 0; j < N; ++j) {
      const int aj = kPu[j], bj = kPw[j];
      AhN(i, j) = m.M[ai + aj][bi + bj];
      AsN(i, j) = (ai * aj ? ai * aj * m.S[ai + aj - 2][bi + bj] : 0.0) +
                  (bi * bj ? bi * bj * m.S[ai + aj][bi + bj - 2] : 0.0);
    }
  }
  const Mat6 Ah = AhN.template topLeftCorner<6, 6>(), As = AsN.template topLeftCorner<6, 6>();
  const Vec6 bh = bhN.template head<6>(), bs = bsN.template head<6>();
  const int used = m.used;
  const double Hh = m.Hh, Ss = m.Ss, M0 = m.M[0][0], S0 = m.S[0][0];  // S0 > 0 where withSlopes > 0
  if (used < 3) return pc;
  // Too few or collinear samples leave A (nearly) singular: refuse rather than fit noise. The
  // reciprocal condition number does what a 6x6 eigen-decomposition did, from the factorisation
  // the solve needs anyway.
  auto solvable = [](const SmallLdlt<6>& f) { return f.Rcond() > 1e-10; };
  // The cubic, with slope rows weighted `ratio` as in the quadratic `c` factorised as `f`, where it
  // fits significantly better (kCubicSignificance).
  auto addCubic = [&](double ratio, const SmallLdlt<6>& f, Vec6& c) {
    if (D == 3 && used >= 12)
      CubicIfSignificant(MatN(AhN + ratio * AsN), VecN(bhN + ratio * bsN), f, Hh + ratio * Ss,
                         used + 2.0 * m.withSlopes, c);
  };
  // The circle term (above) added to the quadratic c of the system with slope weight `lam`,
  // factorised as f, where it is significant, by block elimination: z = A^-1 a_q,
  // s = qq - a_q'z, gradient t = qh - a_q'c, g = t / s, c -= g z. Returns the residual's drop,
  // t^2 / s, or 0 where the term is not taken. Only where no cubic is fitted (D == 2).
  auto circleTerm = [&](const SmallLdlt<6>& f, double lam, Vec6& c) -> double {
    if (D != 2 || used < 10) return 0.0;
    Vec6 aq;
    double qq = 0, qh = 0;
    if (!circle(c, aq, qq, qh)) return 0.0;
    const Vec6 z = f.Solve(aq);
    const double sq = qq - aq.dot(z), t = qh - aq.dot(c);
    if (!(sq > 1e-12 * qq)) return 0.0;
    const double rss = std::max(0.0, Hh + lam * Ss - c.dot(bh + lam * bs)), drop = t * t / sq;
    const double rows = used + (lam > 0 ? 2.0 * m.withSlopes : 0.0);
    if (!(drop > kCircleSignificance * std::max(1e-300, rss - drop) / (rows - 7))) return 0.0;
    c -= (t / sq) * z;
    return drop;
  };
  SmallLdlt<6> ldlt(Ah + sw2 * As);  // the factorisation of the final quadratic's system
  if (!solvable(ldlt)) return pc;
  Vec6 x = ldlt.Solve(bh + sw2 * bs);
  double lambda = sw2;  // the slope rows' weight the final quadratic used
  // sw2 weighs slope rows against height rows as if their variances were in a fixed ratio,
  // right under noise. On a clean flat sheet next to a crease the heights are exact while the
  // neighbours' voted normals lean towards the crease; there the slopes only pull the fit off.
  // With ten samples or more, each kind of row is fitted alone, and where the heights' residual
  // variance is below a tenth of sw2 times the slopes', the fit is solved again with the ratio of
  // the two (a variance-component estimate). The slopes' residual at the joint fit bounds their
  // own fit's from above, so beside creases the slope-only fit is skipped where even that bound
  // cannot trigger.
  // The second-order terms from the slopes where they fit far better than the heights. The
  // slope rows are the neighbours' voted (or fitted) normals, and the shape operator is the
  // normal's derivative: on spheres and cylinders -n_u is exactly linear, so a clean slope fit
  // gives the curvature without the quartic bias of the heights, and under noise the normals
  // are already averages over their own neighbourhoods, which the heights are not. Where the
  // slopes' residual variance (times sw2) is below a tenth of the heights', the fit is solved
  // once more with the ratio of the two, and only its a, b, c are kept: the normal stays the
  // one the heights carry (measured: trusting the slopes for the normal too made the normal's
  // p90 worse at 1 % noise). Only where the neighbourhood reaches no crease (D == 3): beside a
  // crease the neighbours' normals lean towards it.
  bool slopeCurvature = false;
  Vec6 xc;
  if (used >= 10 && m.withSlopes > 0) {
    // Residual variances from the moments, corrected for the coefficients each fit spends.
    auto heightVar = [&](const Vec6& c) {
      return std::max(0.0, Hh - 2 * c.dot(bh) + c.dot(Ah * c)) / M0 * used / (used - 6.0);
    };
    auto slopeVar = [&](const Vec6& c) {
      return std::max(0.0, Ss - 2 * c.dot(bs) + c.dot(As * c)) / (2 * S0) * (2.0 * used) / (2.0 * used - 5);
    };
    const SmallLdlt<6> heights(Ah);
    if (WellConditioned(heights)) {
      // The heights' own residual, with the circle term where it is significant (on a clean
      // cylinder beside a crease only that makes the heights fit exactly, and the slopes, whose
      // normals lean to the crease, lose their weight as on a clean roof).
      const Vec6 xh = heights.Solve(bh);
      Vec6 xhc = xh;
      const double dropH = circleTerm(heights, 0.0, xhc);
      const double eh = dropH > 0 ? std::max(0.0, Hh - xh.dot(bh) - dropH) / M0 * used / (used - 7.0) : heightVar(xh);
      const bool slopesForCurvature = D == 3 && !normalOnly;
      if (slopesForCurvature || eh < 0.1 * sw2 * slopeVar(x)) {
        const SmallLdlt<5> slopes(As.topLeftCorner<5, 5>());
        if (WellConditioned(slopes)) {
          Vec6 xs = Vec6::Zero();
          xs.head<5>() = slopes.Solve(bs.head<5>());
          const double es = slopeVar(xs);
          if (eh < 0.1 * sw2 * es) {
            const double ratio = std::max(eh / es, 1e-9 * sw2);
            const SmallLdlt<6> again(Ah + ratio * As);
            if (solvable(again)) {
              x = again.Solve(bh + ratio * bs);
              lambda = ratio;
              ldlt = again;
            }
          } else if (slopesForCurvature && sw2 * es < 0.1 * eh) {
            const double ratio = std::min(eh / std::max(es, 1e-300), 1e6 * sw2);
            const SmallLdlt<6> again(Ah + ratio * As);
            if (solvable(again)) {
              slopeCurvature = true;
              xc = again.Solve(bh + ratio * bs);
              addCubic(ratio, again, xc);
            }
          }
        }
      }
      // The slopes' tilt test (kSlopeTiltSignificance): in a round whose curvature is not kept,
      // where no cubic is fitted (D == 2: beside a crease, or everywhere with the cubic turned
      // off, as for the circle term), the heights' own normal where the slopes move it significantly.
      if (D == 2 && normalOnly && lambda == sw2 && used > 12 && SlopesTiltTheNormal(heights, xh, x, Hh, bh, used)) {
        x = xh;
        lambda = 0;
        ldlt = heights;
      }
    }
  }
  addCubic(lambda, ldlt, x);
  circleTerm(ldlt, lambda, x);
  if (slopeCurvature) x.head<3>() = xc.head<3>();
  const double d = x(3), e = x(4);
  Eigen::Matrix2d I, II;
  I << 1 + d * d, d * e, d * e, 1 + e * e;
  const double W = std::sqrt(1 + d * d + e * e);
  II << 2 * x(0), x(1), x(1), 2 * x(2);
  II /= (W * scale);  // back to the mesh's units: curvature scales as 1/length
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

// A sample's row weight w (the normal agreement above) and its coordinates (u, v, h) in the
// frame, scaled by 1/scale (which keeps the system well conditioned at any mesh scale); false
// where the sample gets no weight.
inline bool SampleInFrame(const TangentFrame& F, const SheetSample& s, double scale, double cosPhi, double& w,
                          double& u, double& v, double& h) {
  const double agree = (F.n.dot(s.n) - cosPhi) / (1.0 - cosPhi);
  if (!(agree > 0)) return false;
  w = std::min(1.0, agree) * std::min(1.0, agree);
  u = F.e1.dot(s.d) / scale;
  v = F.e2.dot(s.d) / scale;
  h = F.n.dot(s.d) / scale;
  return true;
}

// The fit of v's same-sheet samples. `cubic`: a cubic may replace the quadratic where it is
// significant (the caller allows it only where the neighbourhood reaches no crease and no border
// is near: there the samples are one-sided and the cubic's extrapolation to v is unstable).
template <int D>
PrincipalCurvatures SheetFitOfDegree(const TangentFrame& F, const std::vector<SheetSample>& samples, double scale,
                                     double sw2, double cosPhi, bool normalOnly) {
  SheetMoments<D> m;
  for (const auto& s : samples) {
    double w, u, v, h;
    if (!SampleInFrame(F, s, scale, cosPhi, w, u, v, h)) continue;
    // A normal turned away from N (> 78 deg) says little about this sheet's slopes.
    const bool slopes = F.n.dot(s.n) > 0.2;
    m.Add(w, u, v, h, slopes, slopes ? -F.e1.dot(s.n) : 0.0, slopes ? -F.e2.dot(s.n) : 0.0);
  }
  auto circle = [&](const Eigen::Matrix<double, 6, 1>& x, Eigen::Matrix<double, 6, 1>& aq, double& qq, double& qh) {
    aq.setZero();
    for (const auto& s : samples) {
      double w, u, v, h;
      if (!SampleInFrame(F, s, scale, cosPhi, w, u, v, h)) continue;
      const double hq = x(0) * u * u + x(1) * u * v + x(2) * v * v + x(3) * u + x(4) * v + x(5);
      const double q = hq * hq;
      Eigen::Matrix<double, 6, 1> r;
      r << u * u, u * v, v * v, u, v, 1.0;
      aq += (w * q) * r;
      qq += w * q * q;
      qh += w * q * h;
    }
    return qq > 0;
  };
  return SheetFitFromMoments<D>(F, m, scale, sw2, normalOnly, circle);
}

inline PrincipalCurvatures SheetQuadricFit(const TangentFrame& F, const std::vector<SheetSample>& samples,
                                           double scale, double slopeWeight, double cosPhi, bool cubic = false,
                                           bool normalOnly = false) {
  const double sw2 = (slopeWeight / scale) * (slopeWeight / scale);
  return cubic && samples.size() >= 12 ? SheetFitOfDegree<3>(F, samples, scale, sw2, cosPhi, normalOnly)
                                       : SheetFitOfDegree<2>(F, samples, scale, sw2, cosPhi, normalOnly);
}

}  // namespace nvv

#endif

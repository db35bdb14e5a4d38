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
#ifndef NVV_CORE_SHEET_FIT_H
#define NVV_CORE_SHEET_FIT_H

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <vector>

#include "curvature_votes.h"

namespace nvv {

struct SheetSample {
  Eigen::Vector3d d;  // neighbour position - v
  Eigen::Vector3d n;  // its voted unit normal
};

// A cheap conditioning test of a factorisation that is only a shortcut's (the fit's own solve
// uses the reciprocal condition estimate): its pivots within 1e12 of each other.
template <class Ldlt>
bool WellConditioned(const Ldlt& f) {
  if (f.info() != Eigen::Success) return false;
  const auto D = f.vectorD().cwiseAbs();
  return D.minCoeff() > 1e-12 * D.maxCoeff();
}

inline PrincipalCurvatures SheetQuadricFit(const TangentFrame& F, const std::vector<SheetSample>& samples,
                                           double scale, double slopeWeight, double cosPhi) {
  PrincipalCurvatures pc;
  typedef Eigen::Matrix<double, 6, 6> Mat6;
  typedef Eigen::Matrix<double, 6, 1> Vec6;
  // The normal equations are sums of monomials in (u, w): with the height row
  // r = (u^2, uw, w^2, u, w, 1), sum w_i r r' needs the 15 moments of degree <= 4, sum w_i h r six
  // more; the slope rows need six moments of degree <= 2 and six of the slopes. Accumulating
  // those 33 sums costs a third of the three 6x6 outer products per sample they replace (the
  // fit was the largest item of pass 2's profile); A and rhs are assembled once below.
  // S and T are the slope moments at unit row weight; Hh and Ss the squared targets, for the
  // residuals below.
  double M[15] = {0}, Mh[6] = {0}, S[6] = {0}, T[6] = {0}, Hh = 0, Ss = 0;
  const double sw2 = (slopeWeight / scale) * (slopeWeight / scale);
  int used = 0;
  for (const auto& s : samples) {
    const double agree = (F.n.dot(s.n) - cosPhi) / (1.0 - cosPhi);
    if (!(agree > 0)) continue;
    const double w = std::min(1.0, agree) * std::min(1.0, agree);
    // Coordinates scaled by 1/scale keep the 6x6 system well conditioned at any mesh scale.
    const double u = F.e1.dot(s.d) / scale, v = F.e2.dot(s.d) / scale, h = F.n.dot(s.d) / scale;
    const double uu = u * u, uv = u * v, vv = v * v;
    const double wu = w * u, wv = w * v, wuu = w * uu, wuv = w * uv, wvv = w * vv;
    M[0] += w;  M[1] += wu;  M[2] += wv;  M[3] += wuu;  M[4] += wuv;  M[5] += wvv;
    M[6] += wuu * u;  M[7] += wuu * v;  M[8] += wvv * u;  M[9] += wvv * v;
    M[10] += wuu * uu;  M[11] += wuu * uv;  M[12] += wuu * vv;  M[13] += wuv * vv;  M[14] += wvv * vv;
    const double wh = w * h;
    Hh += wh * h;
    Mh[0] += wh * uu;  Mh[1] += wh * uv;  Mh[2] += wh * vv;  Mh[3] += wh * u;  Mh[4] += wh * v;  Mh[5] += wh;
    const double nh = F.n.dot(s.n);
    if (nh > 0.2) {  // a normal turned away from N (> 78 deg) says little about this sheet
      const double su = -F.e1.dot(s.n), sv = -F.e2.dot(s.n);
      Ss += w * (su * su + sv * sv);
      S[0] += w;  S[1] += wu;  S[2] += wv;  S[3] += wuu;  S[4] += wuv;  S[5] += wvv;
      const double wsu = w * su, wsv = w * sv;
      T[0] += wsu * u;  T[1] += wsu * v;  T[2] += wsv * u;  T[3] += wsv * v;  T[4] += wsu;  T[5] += wsv;
    }
    ++used;
  }
  // Height rows: Ah(i, j) = sum w r_i r_j.
  Mat6 Ah, As;
  Ah << M[10], M[11], M[12], M[6], M[7], M[3],
       M[11], M[12], M[13], M[7], M[8], M[4],
       M[12], M[13], M[14], M[8], M[9], M[5],
       M[6],  M[7],  M[8],  M[3], M[4], M[1],
       M[7],  M[8],  M[9],  M[4], M[5], M[2],
       M[3],  M[4],  M[5],  M[1], M[2], M[0];
  // Slope rows r_u = (2u, w, 0, 1, 0, 0) and r_w = (0, u, 2w, 0, 1, 0): As = sum w (r_u r_u' + r_w r_w').
  As.setZero();
  As(0, 0) = 4 * S[3];
  As(0, 1) = As(1, 0) = 2 * S[4];
  As(0, 3) = As(3, 0) = 2 * S[1];
  As(1, 1) = S[3] + S[5];
  As(1, 2) = As(2, 1) = 2 * S[4];
  As(1, 3) = As(3, 1) = S[2];
  As(1, 4) = As(4, 1) = S[1];
  As(2, 2) = 4 * S[5];
  As(2, 4) = As(4, 2) = 2 * S[2];
  As(3, 3) = S[0];
  As(4, 4) = S[0];
  Vec6 bh, bs;
  bh << Mh[0], Mh[1], Mh[2], Mh[3], Mh[4], Mh[5];
  bs << 2 * T[0], T[1] + T[2], 2 * T[3], T[4], T[5], 0;
  if (used < 3) return pc;
  // Too few or collinear samples leave A (nearly) singular: refuse rather than fit noise. The
  // LDLT's reciprocal condition estimate does what a 6x6 eigen-decomposition did, for the cost
  // of the factorisation the solve needs anyway.
  Eigen::LDLT<Mat6> ldlt(Ah + sw2 * As);
  if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-10)) return pc;
  Vec6 x = ldlt.solve(bh + sw2 * bs);
  // sw2 weighs slope rows against height rows as if their variances were in a fixed ratio,
  // right under noise. On a clean flat sheet next to a crease the heights are exact while the
  // neighbours' voted normals lean towards the crease; there the slopes only pull the fit off.
  // With ten samples or more, each kind of row is fitted alone, and where the heights' residual
  // variance is below a tenth of sw2 times the slopes', the fit is solved again with the ratio of
  // the two (a variance-component estimate). The slopes' residual at the joint fit bounds their
  // own fit's from above, so the slope-only fit is skipped where even that bound cannot trigger.
  if (used >= 10 && S[0] > 0) {
    // Residual variances from the moments, corrected for the coefficients each fit spends.
    auto heightVar = [&](const Vec6& c) {
      return std::max(0.0, Hh - 2 * c.dot(bh) + c.dot(Ah * c)) / M[0] * used / (used - 6.0);
    };
    auto slopeVar = [&](const Vec6& c) {
      return std::max(0.0, Ss - 2 * c.dot(bs) + c.dot(As * c)) / (2 * S[0]) * (2.0 * used) / (2.0 * used - 5);
    };
    const Eigen::LDLT<Mat6> heights(Ah);
    if (WellConditioned(heights)) {
      const double eh = heightVar(heights.solve(bh));
      if (eh < 0.1 * sw2 * slopeVar(x)) {
        const Eigen::LDLT<Eigen::Matrix<double, 5, 5>> slopes(As.topLeftCorner<5, 5>());
        if (WellConditioned(slopes)) {
          Vec6 xs = Vec6::Zero();
          xs.head<5>() = slopes.solve(bs.head<5>());
          const double es = slopeVar(xs);
          if (eh < 0.1 * sw2 * es) {
            const double ratio = std::max(eh / es, 1e-9 * sw2);
            const Eigen::LDLT<Mat6> again(Ah + ratio * As);
            if (again.info() == Eigen::Success && again.rcond() > 1e-10) x = again.solve(bh + ratio * bs);
          }
        }
      }
    }
  }
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

}  // namespace nvv

#endif

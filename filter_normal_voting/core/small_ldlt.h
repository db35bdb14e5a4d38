// LDL' factorisation of a small symmetric positive (semi-)definite matrix of fixed size N, for
// the normal equations of the quadric fit (sheet_fit.h):
//   A = L D L',  L unit lower triangular, D = diag(d_1 .. d_N),
//   d_k = A_kk - sum_{j<k} L_kj^2 d_j,   L_ik = (A_ik - sum_{j<k} L_ij L_kj d_j) / d_k   (i > k).
//
// Normal equations are positive semi-definite, where LDL' is stable without pivoting (every
// |L_ij| sqrt(d_j) <= sqrt(A_ii)), so the factorisation is the plain loop above, unrolled at the
// fixed size, which costs far less than a general pivoting LDLT on these 4 x 4 to 6 x 6 systems.
//
// A pivot that is not positive (or not finite) stops the factorisation: the matrix is singular
// to rounding or indefinite, Ok() is false, and the fit that asked is refused, as a zero pivot or
// a vanishing condition estimate refused it before.
#ifndef NVV_CORE_SMALL_LDLT_H
#define NVV_CORE_SMALL_LDLT_H

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace nvv {

template <int N>
class SmallLdlt {
 public:
  typedef Eigen::Matrix<double, N, N> Mat;
  typedef Eigen::Matrix<double, N, 1> Vec;

  SmallLdlt() = default;
  explicit SmallLdlt(const Mat& A) { Compute(A); }

  void Compute(const Mat& A) {
    ok_ = false;
    norm1_ = 0;
    for (int j = 0; j < N; ++j) norm1_ = std::max(norm1_, A.col(j).cwiseAbs().sum());
    for (int k = 0; k < N; ++k) {
      double ld[N];  // L_kj d_j
      double dk = A(k, k);
      for (int j = 0; j < k; ++j) {
        ld[j] = L_(k, j) * d_[j];
        dk -= L_(k, j) * ld[j];
      }
      if (!(dk > 0) || !std::isfinite(dk)) return;
      d_[k] = dk;
      for (int i = k + 1; i < N; ++i) {
        double s = A(i, k);
        for (int j = 0; j < k; ++j) s -= L_(i, j) * ld[j];
        L_(i, k) = s / dk;
      }
    }
    ok_ = true;
  }

  // Every pivot positive and finite.
  bool Ok() const { return ok_; }
  // Ok() and the pivots within `ratio` of each other: a cheap conditioning test.
  bool PivotsWithin(double ratio) const {
    if (!ok_) return false;
    const double* e = d_ + N;
    return *std::min_element(d_, e) > ratio * *std::max_element(d_, e);
  }
  // The reciprocal condition number in the 1-norm, 1 / (|A|_1 |A^-1|_1), with A^-1 formed
  // column by column (N solves: exact, where an estimator gives a bound). 0 unless Ok().
  double Rcond() const {
    if (!ok_ || !(norm1_ > 0)) return 0;
    double inv1 = 0;
    for (int j = 0; j < N; ++j) inv1 = std::max(inv1, Solve(Vec::Unit(j)).cwiseAbs().sum());
    return 1.0 / (norm1_ * inv1);
  }

  // x = A^-1 b: L y = b, z = D^-1 y, L' x = z. Only where Ok().
  Vec Solve(const Vec& b) const {
    Vec x = b;
    for (int i = 1; i < N; ++i)
      for (int j = 0; j < i; ++j) x(i) -= L_(i, j) * x(j);
    for (int i = 0; i < N; ++i) x(i) /= d_[i];
    for (int i = N - 2; i >= 0; --i)
      for (int j = i + 1; j < N; ++j) x(i) -= L_(j, i) * x(j);
    return x;
  }
  template <int M>
  Eigen::Matrix<double, N, M> Solve(const Eigen::Matrix<double, N, M>& B) const {
    Eigen::Matrix<double, N, M> X;
    for (int c = 0; c < M; ++c) X.col(c) = Solve(Vec(B.col(c)));
    return X;
  }

 private:
  Mat L_ = Mat::Zero();  // strictly lower part used
  double d_[N] = {};
  double norm1_ = 0;
  bool ok_ = false;
};

}  // namespace nvv

#endif

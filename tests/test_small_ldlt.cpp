// The fit's fixed-size LDL' (core/small_ldlt.h) against Eigen's dense inverse and its own
// definition: solutions, the 1-norm condition number, and refusal of singular, indefinite and
// non-finite systems.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "core/small_ldlt.h"

namespace {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;

// B B' of a random 6 x R matrix B: positive definite for R >= 6, rank R below.
template <int R>
Mat6 Gram(std::mt19937& rng) {
  std::normal_distribution<double> g;
  Eigen::Matrix<double, 6, R> B;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < R; ++j) B(i, j) = g(rng);
  return B * B.transpose();
}

double Rcond1(const Mat6& A) {
  const Mat6 inv = A.inverse();
  return 1.0 / (A.cwiseAbs().colwise().sum().maxCoeff() * inv.cwiseAbs().colwise().sum().maxCoeff());
}

TEST(SmallLdlt, SolvesPositiveDefiniteSystemsAndGivesTheirConditionNumber) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  for (int t = 0; t < 200; ++t) {
    const Mat6 A = Gram<8>(rng);
    Vec6 b;
    for (int i = 0; i < 6; ++i) b(i) = g(rng);
    const nvv::SmallLdlt<6> f(A);
    ASSERT_TRUE(f.Ok());
    const Vec6 x = f.Solve(b), ref = A.inverse() * b;
    EXPECT_LT((x - ref).norm(), 1e-9 * ref.norm()) << "trial " << t;
    EXPECT_LT((A * x - b).norm(), 1e-10 * A.norm() * x.norm()) << "trial " << t;
    EXPECT_NEAR(f.Rcond(), Rcond1(A), 1e-8 * Rcond1(A)) << "trial " << t;
    // Several right-hand sides at once give the single solves' columns.
    Eigen::Matrix<double, 6, 4> B;
    for (int c = 0; c < 4; ++c) B.col(c) = A.col(c) + b;
    const Eigen::Matrix<double, 6, 4> X = f.Solve(B);
    for (int c = 0; c < 4; ++c) EXPECT_EQ(X.col(c), f.Solve(Vec6(B.col(c))));
  }
}

TEST(SmallLdlt, IllConditionedButRegularSystemIsSolvedAndMeasured) {
  Mat6 H;  // Hilbert matrix: condition number ~1e7 in the 1-norm
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) H(i, j) = 1.0 / (i + j + 1);
  const nvv::SmallLdlt<6> f(H);
  ASSERT_TRUE(f.Ok());
  EXPECT_NEAR(f.Rcond(), Rcond1(H), 1e-4 * Rcond1(H));
  EXPECT_GT(f.Rcond(), 1e-10);
  EXPECT_LT(f.Rcond(), 1e-6);
  const Vec6 x = f.Solve(H * Vec6::Ones());
  EXPECT_LT((x - Vec6::Ones()).norm(), 1e-7);
}

TEST(SmallLdlt, RefusesSingularIndefiniteAndNonFiniteSystems) {
  std::mt19937 rng(11);
  for (int t = 0; t < 50; ++t) {
    const nvv::SmallLdlt<6> f(Gram<4>(rng));  // rank 4
    EXPECT_TRUE(!f.Ok() || f.Rcond() < 1e-12) << "trial " << t << ": rcond " << f.Rcond();
    EXPECT_FALSE(f.PivotsWithin(1e-12) && f.Rcond() > 1e-10);
  }
  Mat6 indefinite = Mat6::Identity();
  indefinite(3, 3) = -1;
  EXPECT_FALSE(nvv::SmallLdlt<6>(indefinite).Ok());
  Mat6 zeroColumn = Mat6::Identity();
  zeroColumn(2, 2) = 0;
  EXPECT_FALSE(nvv::SmallLdlt<6>(zeroColumn).Ok());
  EXPECT_EQ(nvv::SmallLdlt<6>(zeroColumn).Rcond(), 0.0);
  Mat6 nan = Mat6::Identity();
  nan(5, 1) = nan(1, 5) = std::nan("");
  EXPECT_FALSE(nvv::SmallLdlt<6>(nan).Ok());
  Mat6 inf = Mat6::Identity();
  inf(0, 0) = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(nvv::SmallLdlt<6>(inf).Ok());
  // Pivots far apart: positive, but not within 1e12 of each other.
  Mat6 spread = Mat6::Identity();
  spread(4, 4) = 1e-14;
  const nvv::SmallLdlt<6> s(spread);
  EXPECT_TRUE(s.Ok());
  EXPECT_FALSE(s.PivotsWithin(1e-12));
  EXPECT_TRUE(s.PivotsWithin(1e-15));
}

}  // namespace

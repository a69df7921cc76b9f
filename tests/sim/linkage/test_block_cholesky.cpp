// The mass-matrix solve (sim/linkage/block_cholesky.hpp) against Eigen's LLT
// on seeded symmetric positive definite matrices with the linkage's patterns:
// two independent blocks interleaved, an arrow (one coordinate coupling
// every other), a full matrix, a block starting past row 0, and a pattern
// that changes between solves with the profile kept.

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <limits>
#include <random>
#include <vector>

#include "sim/linkage/block_cholesky.hpp"

namespace fourbar {
namespace {

/// A random SPD n × n matrix whose off-diagonal (i, j) is zero unless
/// `coupled(i, j)`: B·Bᵀ restricted to the pattern, made diagonally dominant.
template <class Coupled>
ZMat patterned_spd(int n, std::mt19937& rng, Coupled coupled) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  ZMat a = ZMat::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < i; ++j)
      if (coupled(i, j)) a(i, j) = a(j, i) = u(rng);
  for (int i = 0; i < n; ++i) a(i, i) = n + 1.0 + u(rng);
  return a;
}

ZVec random_vector(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  ZVec b(n);
  for (int i = 0; i < n; ++i) b(i) = u(rng);
  return b;
}

/// Relative difference between the block solve and Eigen's LLT on the
/// n × n block of `a` at `first`.
double solve_error(const ZMat& a, int first, int n, const ZVec& b, BlockProfile& profile) {
  ZVec x = b;
  EXPECT_TRUE(block_cholesky_solve(a, first, n, x, profile));
  const Eigen::MatrixXd block = a.block(first, first, n, n);
  const Eigen::VectorXd reference = block.llt().solve(Eigen::VectorXd(b));
  return (Eigen::VectorXd(x) - reference).norm() / reference.norm();
}

TEST(BlockCholesky, InterleavedBlocksArrowAndFullMatchEigen) {
  std::mt19937 rng(2026);
  // The speed case's shape with the coordinates interleaved: even indices one
  // block, odd the other.
  const auto interleaved = [](int i, int j) { return (i - j) % 2 == 0; };
  const auto arrow = [](int i, int j) { return j == 0 || i == j; };
  const auto full = [](int, int) { return true; };
  for (int trial = 0; trial < 20; ++trial) {
    for (int n : {1, 2, 5, 10, 16}) {
      BlockProfile p1, p2, p3;
      const ZVec b = random_vector(n, rng);
      EXPECT_LT(solve_error(patterned_spd(n, rng, interleaved), 0, n, b, p1), 1e-13) << n;
      EXPECT_LT(solve_error(patterned_spd(n, rng, arrow), 0, n, b, p2), 1e-13) << n;
      EXPECT_LT(solve_error(patterned_spd(n, rng, full), 0, n, b, p3), 1e-13) << n;
    }
  }
}

TEST(BlockCholesky, FindsTheTwoBlocksOfAnInterleavedPattern) {
  std::mt19937 rng(7);
  const ZMat a = patterned_spd(10, rng, [](int i, int j) { return (i - j) % 2 == 0; });
  BlockProfile p;
  ZVec x = random_vector(10, rng);
  ASSERT_TRUE(block_cholesky_solve(a, 0, 10, x, p));
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(p.order[static_cast<std::size_t>(i)], 2 * i);
    EXPECT_EQ(p.order[static_cast<std::size_t>(5 + i)], 2 * i + 1);
    EXPECT_EQ(p.start[static_cast<std::size_t>(i)], 0);
    EXPECT_EQ(p.start[static_cast<std::size_t>(5 + i)], 5);
  }
}

TEST(BlockCholesky, ABlockPastRowZeroIsSolvedAlone) {
  std::mt19937 rng(11);
  const ZMat a = patterned_spd(12, rng, [](int, int) { return true; });
  BlockProfile p;
  EXPECT_LT(solve_error(a, 2, 9, random_vector(9, rng), p), 1e-13);
}

TEST(BlockCholesky, APatternThatChangesIsReadAgain) {
  std::mt19937 rng(3);
  BlockProfile p;
  const ZVec b = random_vector(8, rng);
  ZMat a = patterned_spd(8, rng, [](int i, int j) { return (i < 4) == (j < 4); });
  EXPECT_LT(solve_error(a, 0, 8, b, p), 1e-13);
  // A coupling the kept profile leaves out: the solve must see it.
  a(6, 1) = a(1, 6) = 0.7;
  EXPECT_LT(solve_error(a, 0, 8, b, p), 1e-13);
  // One block now, in the natural order; row 6 starts at the new entry.
  for (int i = 0; i < 8; ++i) EXPECT_EQ(p.order[static_cast<std::size_t>(i)], i);
  EXPECT_EQ(p.start[6], 1);
}

TEST(BlockCholesky, ANonPositivePivotIsRefused) {
  ZMat a = ZMat::Identity(4, 4);
  a(2, 2) = -1;
  BlockProfile p;
  ZVec x = ZVec::Ones(4);
  EXPECT_FALSE(block_cholesky_solve(a, 0, 4, x, p));
  a(2, 2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(block_cholesky_solve(a, 0, 4, x, p));
  // Indefinite through a coupling: [[1, 2], [2, 1]].
  ZMat c = ZMat::Identity(2, 2);
  c(0, 1) = c(1, 0) = 2;
  BlockProfile q;
  ZVec y = ZVec::Ones(2);
  EXPECT_FALSE(block_cholesky_solve(c, 0, 2, y, q));
}

}  // namespace
}  // namespace fourbar

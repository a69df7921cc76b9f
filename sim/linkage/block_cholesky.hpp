#pragma once
// The linkage's mass-matrix solve: Cholesky on the independent blocks of a
// symmetric positive definite matrix, each row's work from its first non-zero
// entry on (its profile). With clearance at B only, nothing in the linkage's
// mass matrix couples the coupler (θ3 and its modes) with the rocker (θ4 and
// its modes): the pin forces couple them, not the inertia; the speed case's
// 10 × 10 is two 5 × 5 blocks. The blocks and profiles are read from the
// matrix's exact zeros and kept for the next solve, which only checks that
// the entries left out are still zero (and reads them again if not), so any
// pattern is solved exactly: a product left out is one the full factor would
// have taken with a zero.

#include <array>

#include "sim/linkage/full_vectors.hpp"

namespace fourbar {

/// The order of the coordinates (block after block) and every row's first
/// non-zero column in it: what one solve learns of the matrix for the next.
struct BlockProfile {
  int first = -1, size = 0;           ///< the block of the matrix it describes (none yet)
  std::array<int, kMaxFull> order{};  ///< row of the matrix for each position
  std::array<int, kMaxFull> start{};  ///< first non-zero column of each row, in positions
};

/// Solves A·x = b in place (x holds b on entry, indexed from 0) for the
/// symmetric positive definite n × n block of `a` starting at row and column
/// `first`; `a` is read only (its lower triangle). False when a pivot is not
/// positive (or not a number): x is then not the solution.
bool block_cholesky_solve(const ZMat& a, int first, int n, ZVec& x, BlockProfile& profile);

}  // namespace fourbar

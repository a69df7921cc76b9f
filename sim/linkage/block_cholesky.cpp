#include "sim/linkage/block_cholesky.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace fourbar {

namespace {

constexpr std::size_t at(int i) { return static_cast<std::size_t>(i); }

/// The blocks (connected components of the graph of A's non-zero entries,
/// each in its coordinates' order, the one holding the smallest first) and
/// the profile in that order.
void read_profile(const ZMat& a, int first, int n, BlockProfile& b) {
  std::array<int, kMaxFull> root{};
  const auto find = [&root](int i) {
    while (root[at(i)] != i) i = root[at(i)];
    return i;
  };
  for (int i = 0; i < n; ++i) root[at(i)] = i;
  for (int i = 1; i < n; ++i)
    for (int j = 0; j < i; ++j)
      if (a(first + i, first + j) != 0) {
        const int ri = find(i), rj = find(j);
        root[at(std::max(ri, rj))] = std::min(ri, rj);
      }
  int m = 0;
  for (int r = 0; r < n; ++r)
    if (find(r) == r)
      for (int i = r; i < n; ++i)
        if (find(i) == r) b.order[at(m++)] = first + i;
  for (int i = 0; i < n; ++i) {
    int s = i;
    for (int j = 0; j < i; ++j)
      if (a(b.order[at(i)], b.order[at(j)]) != 0) {
        s = j;
        break;
      }
    b.start[at(i)] = s;
  }
  b.first = first;
  b.size = n;
}

/// Whether every entry `b` leaves out of A is zero.
bool holds(const ZMat& a, int first, int n, const BlockProfile& b) {
  if (b.first != first || b.size != n) return false;
  for (int i = 1; i < n; ++i)
    for (int j = 0; j < b.start[at(i)]; ++j)
      if (a(b.order[at(i)], b.order[at(j)]) != 0) return false;
  return true;
}

}  // namespace

bool block_cholesky_solve(const ZMat& a, int first, int n, ZVec& x, BlockProfile& profile) {
  if (!holds(a, first, n, profile)) read_profile(a, first, n, profile);
  const std::array<int, kMaxFull>& p = profile.order;
  const std::array<int, kMaxFull>& start = profile.start;
  // L row by row (row-major, so the inner products run over memory in order).
  double L[kMaxFull][kMaxFull];
  for (int i = 0; i < n; ++i) {
    const int si = start[at(i)];
    for (int j = si; j <= i; ++j) {
      double v = a(p[at(i)], p[at(j)]);
      for (int k = std::max(si, start[at(j)]); k < j; ++k) v -= L[i][k] * L[j][k];
      if (j < i) {
        L[i][j] = v / L[j][j];
      } else {
        if (!(v > 0)) return false;
        L[i][i] = std::sqrt(v);
      }
    }
  }
  std::array<double, kMaxFull> y{};
  for (int i = 0; i < n; ++i) {  // L·y = P·b
    double v = x(p[at(i)] - first);
    for (int k = start[at(i)]; k < i; ++k) v -= L[i][k] * y[at(k)];
    y[at(i)] = v / L[i][i];
  }
  for (int i = n - 1; i >= 0; --i) {  // Lᵀ·(P·x) = y, in place
    double v = y[at(i)];
    for (int k = i + 1; k < n; ++k)
      if (start[at(k)] <= i) v -= L[k][i] * y[at(k)];
    y[at(i)] = v / L[i][i];
  }
  for (int i = 0; i < n; ++i) x(p[at(i)] - first) = y[at(i)];
  return true;
}

}  // namespace fourbar

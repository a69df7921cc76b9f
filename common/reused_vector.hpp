#pragma once
// Working arrays refilled record after record (the chunks of a long
// recording): resize_reusing grows a vector's memory with some headroom, so
// that the next record, a little longer, fits without a new allocation —
// fresh memory is paged in by the kernel at every first touch, which costs
// as much as a tenth of the work on arrays of millions of samples.

#include <cstddef>
#include <vector>

namespace fourbar {

/// v.resize(n), reserving n + n/8 first when v held something before but
/// not n elements (the first fill takes exactly n).
template <class T>
void resize_reusing(std::vector<T>& v, std::size_t n) {
  if (v.capacity() < n) v.reserve(v.capacity() == 0 ? n : n + n / 8);
  v.resize(n);
}

/// v.assign(first, last) with the same growth as resize_reusing.
template <class T, class It>
void assign_reusing(std::vector<T>& v, It first, It last) {
  const auto n = static_cast<std::size_t>(last - first);
  if (v.capacity() < n) v.reserve(v.capacity() == 0 ? n : n + n / 8);
  v.assign(first, last);
}

}  // namespace fourbar

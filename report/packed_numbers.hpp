#pragma once
// Display data packed small for summary.json and the report page: values as
// signed integer counts of a stated step (count × step = value, the step
// 1/max_count of the largest |value|, so rounding is at most half a step),
// little-endian bytes in base64. The page's script and tests unpack them.

#include <cstdint>
#include <string>
#include <vector>

namespace fourbar {

/// Counts of `step` for `values`: step = largest |value| / max_count (0 when all are 0).
struct PackedCounts {
  std::vector<std::int32_t> counts;
  double step = 0;
};
PackedCounts quantise(const std::vector<double>& values, int max_count);

/// int8 or int16 (bytes 1 or 2) counts, little-endian, as base64.
std::string pack_base64(const std::vector<std::int32_t>& counts, int bytes);

/// The counts back (for tests and tools).
std::vector<std::int32_t> unpack_base64(const std::string& base64, int bytes);

}  // namespace fourbar

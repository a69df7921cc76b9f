#include "report/packed_numbers.hpp"

#include <algorithm>
#include <cmath>

#include <openssl/evp.h>

namespace fourbar {

PackedCounts quantise(const std::vector<double>& values, int max_count) {
  PackedCounts p;
  double largest = 0;
  for (double v : values) largest = std::max(largest, std::abs(v));
  p.step = largest / max_count;
  p.counts.reserve(values.size());
  for (double v : values) p.counts.push_back(largest > 0 ? static_cast<std::int32_t>(std::lround(v / p.step)) : 0);
  return p;
}

std::string pack_base64(const std::vector<std::int32_t>& counts, int bytes) {
  std::string raw;
  raw.reserve(counts.size() * static_cast<std::size_t>(bytes));
  for (std::int32_t c : counts) {
    const auto u = static_cast<std::uint32_t>(c);
    for (int b = 0; b < bytes; ++b) raw.push_back(static_cast<char>((u >> (8 * b)) & 0xFF));
  }
  std::string out(4 * ((raw.size() + 2) / 3) + 1, '\0');
  const int n = EVP_EncodeBlock(reinterpret_cast<unsigned char*>(out.data()),
                                reinterpret_cast<const unsigned char*>(raw.data()), static_cast<int>(raw.size()));
  out.resize(static_cast<std::size_t>(n));
  return out;
}

std::vector<std::int32_t> unpack_base64(const std::string& b64, int bytes) {
  std::string raw(3 * (b64.size() / 4) + 3, '\0');
  const int n = EVP_DecodeBlock(reinterpret_cast<unsigned char*>(raw.data()),
                                reinterpret_cast<const unsigned char*>(b64.data()), static_cast<int>(b64.size()));
  if (n < 0) return {};
  std::size_t len = static_cast<std::size_t>(n);  // EVP_DecodeBlock counts the padding as zero bytes
  if (!b64.empty() && b64.back() == '=') --len;
  if (b64.size() > 1 && b64[b64.size() - 2] == '=') --len;
  std::vector<std::int32_t> out(len / static_cast<std::size_t>(bytes));
  for (std::size_t i = 0; i < out.size(); ++i) {
    std::uint32_t u = 0;
    for (int b = 0; b < bytes; ++b) u |= static_cast<std::uint32_t>(static_cast<unsigned char>(raw[i * bytes + b])) << (8 * b);
    const std::uint32_t sign = 1u << (8 * bytes - 1);
    out[i] = static_cast<std::int32_t>(u ^ sign) - static_cast<std::int32_t>(sign);
  }
  return out;
}

}  // namespace fourbar

#pragma once
// Test support: one set of channels with known statistics, written in every
// format fourbar reads — through libsndfile and libmatio directly and as text,
// independently of fourbar's readers.

#include <matio.h>
#include <sndfile.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fourbar::testing {

struct TestSignals {
  double rate_hz = 10000;
  std::vector<std::string> names;                 ///< channel names (text and .mat)
  std::vector<std::vector<double>> columns;       ///< one per channel
};

constexpr std::size_t kFrames = 20000;            // 2 s at 10 kHz
constexpr std::size_t kSinePeriod = 200;          // 50 Hz, 100 whole periods
constexpr std::size_t kPulsePeriod = 500;         // 20 Hz = 1200 rpm at one pulse per turn
constexpr std::size_t kPulseWidth = 25;           // 5 % high
constexpr double kPulseHigh = 0.8;

/// coupler_t: 0.1 + 0.5 sin (mean 0.1, AC RMS 0.5/√2); pulse: 0 / 0.8, high
/// 25 of every 500 samples; rocker_t: 1.5 sin clamped to ±1 (clipped); spare: 0.
inline TestSignals inspection_signals() {
  TestSignals s;
  s.names = {"coupler_t", "pulse", "rocker_t", "spare"};
  s.columns.assign(4, std::vector<double>(kFrames));
  for (std::size_t i = 0; i < kFrames; ++i) {
    const double phase = 2 * std::numbers::pi * static_cast<double>(i % kSinePeriod) / kSinePeriod;
    s.columns[0][i] = 0.1 + 0.5 * std::sin(phase);
    s.columns[1][i] = (i % kPulsePeriod) >= 100 && (i % kPulsePeriod) < 100 + kPulseWidth ? kPulseHigh : 0.0;
    s.columns[2][i] = std::clamp(1.5 * std::sin(phase), -1.0, 1.0);
    s.columns[3][i] = 0.0;
  }
  return s;
}

/// Samples of the clipped channel at ±1.
inline std::size_t clipped_count(const TestSignals& s) {
  return static_cast<std::size_t>(std::count_if(s.columns[2].begin(), s.columns[2].end(),
                                                [](double v) { return std::abs(v) >= 1.0; }));
}

inline void write_sndfile(const std::filesystem::path& file, int format, const TestSignals& s) {
  SF_INFO info{};
  info.samplerate = static_cast<int>(s.rate_hz);
  info.channels = static_cast<int>(s.columns.size());
  info.format = format;
  SNDFILE* f = sf_open(file.c_str(), SFM_WRITE, &info);
  if (!f) throw std::runtime_error("sf_open " + file.string() + ": " + sf_strerror(nullptr));
  std::vector<double> frames;
  for (std::size_t i = 0; i < kFrames; ++i)
    for (const auto& c : s.columns) frames.push_back(c[i]);
  sf_command(f, SFC_SET_CLIPPING, nullptr, SF_TRUE);
  sf_writef_double(f, frames.data(), static_cast<sf_count_t>(kFrames));
  sf_close(f);
}

/// Each channel a column vector (the second one a row vector), and the rate
/// as the scalar `rate_name` (none when empty).
inline void write_mat(const std::filesystem::path& file, mat_ft version, const TestSignals& s,
                      const std::string& rate_name = "fs", matio_compression compression = MAT_COMPRESSION_NONE) {
  mat_t* mat = Mat_CreateVer(file.c_str(), nullptr, version);
  if (!mat) throw std::runtime_error("Mat_CreateVer " + file.string());
  for (std::size_t c = 0; c < s.columns.size(); ++c) {
    std::size_t dims[2] = {kFrames, 1};
    if (c == 1) std::swap(dims[0], dims[1]);
    matvar_t* v = Mat_VarCreate(s.names[c].c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims,
                                const_cast<double*>(s.columns[c].data()), 0);
    Mat_VarWrite(mat, v, compression);
    Mat_VarFree(v);
  }
  if (!rate_name.empty()) {
    double rate = s.rate_hz;
    std::size_t dims[2] = {1, 1};
    matvar_t* v = Mat_VarCreate(rate_name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, &rate, 0);
    Mat_VarWrite(mat, v, compression);
    Mat_VarFree(v);
  }
  Mat_Close(mat);
}

/// A DAQ text export: `;`-separated, decimal comma, a units row under the header.
inline void write_csv_with_units_row(const std::filesystem::path& file, const TestSignals& s) {
  std::ofstream out(file);
  out << "# exported by the DAQ\ntime";
  for (const auto& n : s.names) out << ";" << n;
  out << "\ns";
  for (std::size_t c = 0; c < s.names.size(); ++c) out << ";V";
  out << "\n";
  out.precision(17);
  auto decimal_comma = [](double v) {
    std::ostringstream os;
    os.precision(17);
    os << v;
    std::string t = os.str();
    std::replace(t.begin(), t.end(), '.', ',');
    return t;
  };
  for (std::size_t i = 0; i < kFrames; ++i) {
    out << decimal_comma(static_cast<double>(i) / s.rate_hz);
    for (const auto& c : s.columns) out << ";" << decimal_comma(c[i]);
    out << "\n";
  }
}

}  // namespace fourbar::testing

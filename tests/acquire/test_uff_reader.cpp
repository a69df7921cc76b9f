// Universal File Format dataset 58/58b: the ASCII and the binary file of the
// same record from pyuff's examples (../shared/realdata/uff58/) read as the
// same values at the rate the realdata README states; records written here
// in both forms (several records as channels, units, byte orders) read back;
// what fourbar does not read is a named error.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "acquire/inspect.hpp"
#include "acquire/manifest_template.hpp"
#include "acquire/reader.hpp"
#include "common/error.hpp"
#include "support/realdata.hpp"
#include "support/temp_dir.hpp"
#include "read_recording.hpp"

namespace fourbar {
namespace {

using testing::read_all;
using testing::open_error_of;
using testing::TempDir;

TEST(UffReader, PyuffAsciiAndBinaryOfOneRecordReadTheSameValues) {
  FOURBAR_REALDATA_FILE(ascii_file, "uff58/Sample_UFF58_ascii.uff");
  const auto binary_file = ascii_file.parent_path() / "Sample_UFF58b_bin.uff";
  const auto a = open_recording(ascii_file), b = open_recording(binary_file);
  for (const Reader* r : {a.get(), b.get()}) {
    const RecordingInfo& i = r->info();
    EXPECT_EQ(i.format, "UFF58");
    EXPECT_EQ(i.channels, 1);
    EXPECT_EQ(i.frames, 79292u);                 // README: 79 292 samples
    EXPECT_EQ(i.sample_rate_hz, 65536.0);        // README: 65 536 Hz (the file prints 1.52588E-05 s)
    EXPECT_NEAR(i.duration_s(), 1.21, 0.005);    // README: 1.21 s
    EXPECT_EQ(i.channel_units, std::vector<std::string>{"Pa"});  // ordinate type 21, Pa
    EXPECT_EQ(i.channel_names, std::vector<std::string>{"Mic 01.0Scalar"});
    EXPECT_EQ(i.started_at, "18-Apr-16 13:49:58");
  }
  const auto va = read_all(*a, 1000), vb = read_all(*b, 777);
  ASSERT_EQ(va.size(), 79292u);
  ASSERT_EQ(vb.size(), 79292u);
  // The ASCII file holds each value printed as E13.5 (6 significant digits),
  // the binary file the same value stored as a float: they agree to half a
  // unit of the 6th digit plus half a float ulp (the ASCII was printed from
  // the value before it was rounded to float: 650 values lie on the other
  // side of a rounding boundary than their float does, 0.8 %).
  std::size_t differ = 0, printed_equal = 0;
  for (std::size_t k = 0; k < va.size(); ++k) {
    char printed[32];
    std::snprintf(printed, sizeof printed, "%.5E", vb[k]);
    printed_equal += std::strtod(printed, nullptr) == va[k];
    if (vb[k] == 0) {
      differ += va[k] != 0;
      continue;
    }
    const double digit = std::pow(10.0, std::floor(std::log10(std::abs(vb[k]))) - 5);
    differ += std::abs(va[k] - vb[k]) > 0.5 * digit + std::abs(vb[k]) * 0x1p-24;
  }
  EXPECT_EQ(differ, 0u) << "ASCII values farther from the binary value than the two formats' rounding";
  EXPECT_GT(printed_equal, va.size() * 99 / 100) << "nearly every ASCII value is the float printed to 6 digits";
  double peak = 0;
  for (double v : vb) peak = std::max(peak, std::abs(v));
  EXPECT_GT(peak, 1e-3) << "a microphone signal, not zeros";
}

/// One dataset 58 record: ASCII (single: 6E13.5, double: 4E20.12) or 58b binary.
std::string record(const std::string& name, const std::vector<double>& v, double dx, const std::string& unit,
                   int ordinate_type, int binary_order /*0 ASCII, 1 LE, 2 BE*/) {
  const bool dbl = ordinate_type == 4;
  std::string data;
  if (binary_order) {
    for (double x : v) {
      unsigned char b[8];
      const float f = static_cast<float>(x);
      if (dbl) std::memcpy(b, &x, 8);
      else std::memcpy(b, &f, 4);
      const std::size_t n = dbl ? 8 : 4;
      for (std::size_t k = 0; k < n; ++k) data += static_cast<char>(b[binary_order == 2 ? n - 1 - k : k]);
    }
  } else {
    const std::size_t per = dbl ? 4 : 6;
    for (std::size_t i = 0; i < v.size(); ++i) {
      char cell[32];
      std::snprintf(cell, sizeof cell, dbl ? "%20.12E" : "%13.5E", v[i]);
      data += cell;
      if (i % per == per - 1 || i + 1 == v.size()) data += "\n";
    }
  }
  char line[160];
  std::string s = "    -1\n";
  if (binary_order) {
    std::snprintf(line, sizeof line, "    58b%6d%6d%12d%12zu%6d%6d%12d%12d\n", binary_order, 2, 11, data.size(), 0, 0, 0, 0);
    s += line;
  } else {
    s += "    58\n";
  }
  s += name + "\nNONE\n27-Nov-26 10:15:32\nNONE\nNONE\n";
  std::snprintf(line, sizeof line, "%5d%10d%5d%10d %-10s%10d%4d %-10s%10d%4d\n", 1, 0, 0, 0, name.substr(0, 10).c_str(), 1, 3, "NONE", 0, 0);
  s += line;
  std::snprintf(line, sizeof line, "%10d%10zu%10d%13.5E%13.5E%13.5E\n", ordinate_type, v.size(), 1, 0.0, dx, 0.0);
  s += line;
  s += "        17    0    0    0 Time                 s                   \n";
  std::snprintf(line, sizeof line, "%10d%5d%5d%5d %-20s %-20s\n", 12, 0, 0, 0, "Acceleration", unit.c_str());
  s += line;
  s += "         0    0    0    0 NONE                 NONE                \n";
  s += "         0    0    0    0 NONE                 NONE                \n";
  s += data;
  s += binary_order ? "\n    -1\n" : "    -1\n";
  return s;
}

void write(const std::filesystem::path& f, const std::string& s) { std::ofstream(f, std::ios::binary) << s; }

TEST(UffReader, RecordsAreChannelsInEveryFormAndByteOrder) {
  TempDir dir;
  std::vector<double> a;  // quarters: exact in float and in E13.5
  for (int i = 0; i < 20; ++i) a.push_back(0.25 * i - 2);
  const std::string header = "    -1\n   151\nmodel\nfrom a test\n    -1\n";
  for (int form : {0, 1, 2}) {
    for (int type : {2, 4}) {
      const auto f = dir.path() / ("r" + std::to_string(form) + std::to_string(type) + ".uff");
      write(f, header + record("acc1", a, 1.0 / 1024, "m/s2", type, form) + record("acc2", a, 1.0 / 1024, "g", type, form));
      const auto r = open_recording(f);
      EXPECT_EQ(r->info().channels, 2) << f;
      EXPECT_EQ(r->info().channel_names, (std::vector<std::string>{"acc1", "acc2"}));
      EXPECT_EQ(r->info().channel_units, (std::vector<std::string>{"m/s^2", "g"}));
      EXPECT_EQ(r->info().sample_rate_hz, 1024.0);
      const auto got = read_all(*r, 7);
      ASSERT_EQ(got.size(), 40u);
      for (std::size_t i = 0; i < 20; ++i) EXPECT_EQ(got[2 * i], a[i]) << f << " value " << i;
      // The template calibrates channels in physical units: volts_per_unit per m/s^2 at full_scale_V = 1.
      r->rewind();
      const std::string t = manifest_template(inspect_recording(*r), {});
      EXPECT_NE(t.find("full_scale_V = 1  # the file holds acceleration"), std::string::npos) << t;
      EXPECT_NE(t.find("column = \"acc1\"\nrole = \"FILL IN\""), std::string::npos) << t;
      EXPECT_NE(t.find("volts_per_unit = 1  # the file holds m/s^2"), std::string::npos) << t;
      EXPECT_NE(t.find("volts_per_unit = 0.1019716213  # the file holds g"), std::string::npos) << t;
    }
  }
  // A double-precision binary record keeps every bit.
  const auto f = dir.path() / "bits.uff";
  std::vector<double> c;
  for (int i = 0; i < 9; ++i) c.push_back(std::sin(i) / 3.0);
  write(f, record("x", c, 0.001, "V", 4, 2));
  EXPECT_EQ(read_all(*open_recording(f), 4), c);
  EXPECT_EQ(open_recording(f)->info().sample_rate_hz, 1000.0);
}

TEST(UffReader, WhatIsNotReadIsANamedError) {
  TempDir dir;
  const auto f = dir.path() / "bad.uff";
  const std::vector<double> v{1, 2, 3};
  write(f, record("a", v, 0.001, "g", 2, 0) + record("b", {1, 2}, 0.001, "g", 2, 0));
  EXPECT_NE(open_error_of(f).find("bad.uff: dataset 58 record 2 (line 17) has length 2, record 1 3"), std::string::npos) << open_error_of(f);
  write(f, record("a", v, 0.001, "g", 2, 0) + record("b", v, 0.002, "g", 2, 0));
  EXPECT_NE(open_error_of(f).find("has abscissa increment 0.002, record 1 0.001"), std::string::npos) << open_error_of(f);
  write(f, record("a", v, 0.001, "g", 5, 0));
  EXPECT_NE(open_error_of(f).find("bad.uff: dataset 58 record 1 (line 2): complex ordinate data (type 5)"), std::string::npos) << open_error_of(f);
  std::string cut = record("a", v, 0.001, "g", 2, 1);
  write(f, cut.substr(0, cut.size() - 12));
  EXPECT_NE(open_error_of(f).find("the file ends first (cut short)"), std::string::npos) << open_error_of(f);
  write(f, "    -1\n   151\nmodel\n    -1\n");
  EXPECT_NE(open_error_of(f).find("no dataset 58 (time history)"), std::string::npos) << open_error_of(f);
}

}  // namespace
}  // namespace fourbar

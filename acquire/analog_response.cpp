#include "acquire/analog_response.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "common/toml_section.hpp"
#include "common/toml_writer.hpp"

namespace fourbar {

DaqFilter read_daq_filter(TomlSection& t) {
  DaqFilter f;
  f.type = t.choice("daq_filter", kDaqFilterTypes, "none");
  const bool bw = f.type == "butterworth", lp = f.type == "linear_phase";
  for (const char* k : {"daq_filter_order", "daq_filter_cutoff_Hz"})
    if (!bw && t.has(k)) t.fail(k, "is for daq_filter = \"butterworth\"; set that or remove this key");
  if (!lp && t.has("daq_filter_delay_us"))
    t.fail("daq_filter_delay_us", "is for daq_filter = \"linear_phase\"; set that or remove this key");
  if (bw) {
    f.order = static_cast<int>(t.integer("daq_filter_order", 1, 12));
    f.cutoff_hz = t.positive("daq_filter_cutoff_Hz");
  }
  if (lp) f.delay_s = t.in_range("daq_filter_delay_us", 0, 1e6) * 1e-6;
  return f;
}

std::string daq_filter_toml(const DaqFilter& f) {
  std::ostringstream os;
  if (f.type == "butterworth")
    os << "daq_filter = \"butterworth\"\ndaq_filter_order = " << f.order
       << "\ndaq_filter_cutoff_Hz = " << toml_number(f.cutoff_hz) << "\n";
  else if (f.type == "linear_phase")
    os << "daq_filter = \"linear_phase\"\ndaq_filter_delay_us = " << toml_number(f.delay_s * 1e6) << "\n";
  return os.str();
}

std::vector<AnalogSection> butterworth_sections(int order, double cutoff_hz) {
  std::vector<AnalogSection> s;
  for (int k = 1; k <= order / 2; ++k)
    s.push_back({2, cutoff_hz, 1.0 / (2.0 * std::sin((2 * k - 1) * std::numbers::pi / (2.0 * order)))});
  if (order % 2) s.push_back({1, cutoff_hz, 0});
  return s;
}

std::vector<AnalogSection> daq_filter_sections(const DaqFilter& f) {
  if (f.type == "butterworth") return butterworth_sections(f.order, f.cutoff_hz);
  return {};
}

std::complex<double> analog_response(const std::vector<AnalogSection>& sections, double f_hz) {
  std::complex<double> h = 1;
  for (const AnalogSection& s : sections) {
    const std::complex<double> jw(0, f_hz / s.f0_hz);  // normalised s/ω0
    h *= s.order == 1 ? 1.0 / (jw + 1.0) : 1.0 / (jw * jw + jw / s.q + 1.0);
  }
  return h;
}

}  // namespace fourbar

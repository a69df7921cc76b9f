#pragma once
// What a lab knows about the analog path in front of the ADC, as a cascade
// of first- and second-order low-pass sections: the accelerometer's mounted
// resonance (calibration sheet: f_r, Q) and the DAQ's anti-alias filter
// (a Butterworth of given order and cutoff, or a linear-phase FIR whose
// only effect in band is its group delay). The virtual rig simulates them
// (virtual_rig/analog_filter_sim.hpp); analyze divides their response out
// in band (analyze/known_response.hpp).
//
//   second-order section  H(s) = ω0² / (s² + (ω0/Q)·s + ω0²)
//   first-order section   H(s) = ω0 / (s + ω0)
// Butterworth of order n, cutoff ωc: ⌊n/2⌋ second-order sections with
// ω0 = ωc, Q_k = 1/(2·sin((2k−1)π/(2n))), k = 1…⌊n/2⌋, plus one first-order
// section for odd n; |H(jωc)| = 1/√2.

#include <complex>
#include <string>
#include <vector>

namespace fourbar {

class TomlSection;

struct AnalogSection {
  int order = 2;        ///< 1 or 2
  double f0_hz = 0;     ///< natural (corner) frequency
  double q = 0;         ///< quality factor (second order only)
};

/// The DAQ's anti-alias filter on the accelerometer channels (the crank
/// pulse on a digital or counter input is taken as unfiltered).
struct DaqFilter {
  std::string type = "none";  ///< none, butterworth, linear_phase
  int order = 0;              ///< butterworth
  double cutoff_hz = 0;       ///< butterworth: −3 dB frequency
  double delay_s = 0;         ///< linear_phase: group delay
  bool known() const { return type != "none"; }
};

inline const std::vector<std::string> kDaqFilterTypes{"none", "butterworth", "linear_phase"};

/// Reads `daq_filter`, `daq_filter_order`, `daq_filter_cutoff_Hz`,
/// `daq_filter_delay_us` from a table (the manifest's root or the scene's
/// [recording]); InputError naming the key (an unknown type lists the known
/// ones; a key of another type is refused).
DaqFilter read_daq_filter(TomlSection& table);
/// The keys as TOML lines ("" for none).
std::string daq_filter_toml(const DaqFilter& f);

std::vector<AnalogSection> butterworth_sections(int order, double cutoff_hz);
/// The filter's sections (empty for none and for linear_phase, whose
/// response is the delay alone).
std::vector<AnalogSection> daq_filter_sections(const DaqFilter& f);
/// Response of a cascade at frequency f (Hz).
std::complex<double> analog_response(const std::vector<AnalogSection>& sections, double f_hz);

}  // namespace fourbar

#pragma once
// Zero-phase filter specification and design: low-, high-, band-pass or
// band-stop, optionally with a mains comb (notches at k·f_mains up to the
// Nyquist frequency). The ideal response is 1 on a set of disjoint pass
// bands and 0 elsewhere.
//
// Two realisations (fft_filter.hpp applies both):
//  - ideal (transition_hz = 0, rectangular window): every FFT bin of the
//    whole record is kept or zeroed, the thesis's FFT band-pass (§7.2);
//  - windowed-sinc kernel (transition_hz > 0): the ideal impulse response,
//    symmetric about 0 (so the frequency response is real: zero phase),
//    truncated to 2M + 1 taps by the chosen window. The window sets the
//    stop-band leakage (rectangular ≈ −21 dB, Hann ≈ −44 dB, Kaiser β = 8
//    ≈ −80 dB) and, with the tap count, the transition width; the tap count
//    follows from transition_hz.

#include <string>
#include <vector>

#include "analyze/window.hpp"

namespace fourbar {

enum class BandType { all_pass, lowpass, highpass, bandpass, bandstop };

/// Whether a band of this type has a lower corner (high-pass, band-pass,
/// band-stop) / an upper corner (low-pass, band-pass, band-stop).
inline bool uses_low(BandType b) { return b == BandType::highpass || b == BandType::bandpass || b == BandType::bandstop; }
inline bool uses_high(BandType b) { return b == BandType::lowpass || b == BandType::bandpass || b == BandType::bandstop; }

struct FilterSpec {
  BandType band = BandType::all_pass;
  double low_hz = 0;          ///< lower corner (highpass, bandpass, bandstop)
  double high_hz = 0;         ///< upper corner (lowpass, bandpass, bandstop)
  double mains_hz = 0;        ///< mains comb base frequency (50 or 60); 0: no comb
  double mains_width_hz = 1;  ///< full width of each mains notch
  WindowSpec window;          ///< kernel window
  double transition_hz = 0;   ///< transition width; 0: ideal bin-wise response (rectangular only)
};

/// A closed frequency interval [lo_hz, hi_hz].
struct Band {
  double lo_hz, hi_hz;
};

/// Checks the spec against the sample rate. Throws InputError naming the key
/// and value: a corner negative or at/above the Nyquist frequency, corners in
/// the wrong order, a mains notch wider than its spacing, a window parameter
/// out of range, a non-rectangular window without a transition width.
void validate_filter(const FilterSpec& spec, double sample_rate_hz);

/// The pass bands, sorted and disjoint, within [0, fs/2].
std::vector<Band> pass_bands(const FilterSpec& spec, double sample_rate_hz);

/// Whether the ideal response passes frequency f (|f| ≤ fs/2).
bool passes(const std::vector<Band>& bands, double f_hz);

/// Kernel taps 2M + 1 for a windowed design (transition_hz > 0).
std::size_t kernel_taps(const FilterSpec& spec, double sample_rate_hz);

/// The symmetric kernel h[−M..M] (index i ↔ tap i − M), windowed sinc of the
/// pass bands. Requires transition_hz > 0.
std::vector<double> design_kernel(const FilterSpec& spec, double sample_rate_hz);

/// One line describing the filter, for provenance.
std::string describe(const FilterSpec& spec);

}  // namespace fourbar

#pragma once
// Window functions for filter design and spectra: rectangular (the thesis's
// FFT routine, §7.2), Hann, Tukey(α) and Kaiser(β).
//
// Symmetric windows (w[0] = w[n−1]) shape FIR filter kernels; periodic
// ("DFT-even") windows, the first n of a symmetric window of n + 1 points,
// are the usual choice for spectra (as scipy.signal.get_window).

#include <string>
#include <string_view>
#include <vector>

namespace fourbar {

enum class WindowType { rectangular, hann, tukey, kaiser };
enum class WindowSymmetry { symmetric, periodic };

struct WindowSpec {
  WindowType type = WindowType::rectangular;
  /// Tukey: taper fraction α in [0, 1] (0 rectangular, 1 Hann);
  /// Kaiser: β in [0, 50] (0 rectangular; 8.6 ≈ 90 dB side lobes). Unused otherwise.
  double parameter = 0;
};

/// "rectangular", "hann", "tukey:0.25", "kaiser:8"; throws InputError naming
/// `what` (e.g. the option) and the accepted forms.
WindowSpec parse_window(std::string_view text, std::string_view what);

/// The inverse of parse_window.
std::string to_string(const WindowSpec& w);

/// Throws InputError naming `what` when the parameter is out of range.
void validate_window(const WindowSpec& w, std::string_view what);

/// n samples of the window (n ≥ 1; a single sample is 1).
std::vector<double> make_window(const WindowSpec& w, std::size_t n, WindowSymmetry symmetry);

/// Null-to-null width of the window's main lobe, in bins of 1/n (rectangular
/// 2, Hann 4, Tukey ≈ 2 + 2α, Kaiser 2·√(1 + (β/π)²)). A windowed-sinc kernel
/// of n taps has a transition band about this many fs/n wide.
double main_lobe_width_bins(const WindowSpec& w);

}  // namespace fourbar

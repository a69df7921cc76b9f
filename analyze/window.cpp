#include "analyze/window.hpp"

#include <boost/math/special_functions/bessel.hpp>
#include <charconv>
#include <cmath>
#include <sstream>

#include "common/error.hpp"
#include "common/units.hpp"

namespace fourbar {

namespace {

constexpr double kMaxKaiserBeta = 50.0;

[[noreturn]] void bad_window(std::string_view what, std::string_view text, std::string_view why) {
  std::ostringstream os;
  os << what << ": window '" << text << "' " << why
     << "; use rectangular, hann, tukey:ALPHA (0..1) or kaiser:BETA (0..50)";
  throw InputError(os.str());
}

// Window value at x in [−1, 1] (position from the centre, ±1 the end points).
double value_at(const WindowSpec& w, double x) {
  const double ax = std::min(1.0, std::abs(x));
  switch (w.type) {
    case WindowType::rectangular: return 1.0;
    case WindowType::hann: return 0.5 * (1.0 + std::cos(units::kPi * ax));
    case WindowType::tukey: {
      const double a = w.parameter, flat = 1.0 - a;
      if (ax <= flat || a == 0) return 1.0;
      return 0.5 * (1.0 + std::cos(units::kPi * (ax - flat) / a));
    }
    case WindowType::kaiser: {
      // Double-precision evaluation (Boost promotes to long double by default).
      using DoublePolicy = boost::math::policies::policy<boost::math::policies::promote_double<false>>;
      const double b = w.parameter;
      return boost::math::cyl_bessel_i(0, b * std::sqrt(std::max(0.0, 1.0 - ax * ax)), DoublePolicy()) /
             boost::math::cyl_bessel_i(0, b, DoublePolicy());
    }
  }
  return 1.0;
}

}  // namespace

WindowSpec parse_window(std::string_view text, std::string_view what) {
  const auto colon = text.find(':');
  const std::string_view name = text.substr(0, colon);
  WindowSpec w;
  if (name == "rectangular") w.type = WindowType::rectangular;
  else if (name == "hann") w.type = WindowType::hann;
  else if (name == "tukey") w.type = WindowType::tukey;
  else if (name == "kaiser") w.type = WindowType::kaiser;
  else bad_window(what, text, "is unknown");
  const bool has_param = w.type == WindowType::tukey || w.type == WindowType::kaiser;
  if (has_param != (colon != std::string_view::npos))
    bad_window(what, text, has_param ? "needs its parameter" : "takes no parameter");
  if (has_param) {
    const std::string_view p = text.substr(colon + 1);
    const auto [end, ec] = std::from_chars(p.data(), p.data() + p.size(), w.parameter);
    if (ec != std::errc() || end != p.data() + p.size()) bad_window(what, text, "has a parameter that is not a number");
  }
  validate_window(w, what);
  return w;
}

std::string to_string(const WindowSpec& w) {
  std::ostringstream os;
  switch (w.type) {
    case WindowType::rectangular: return "rectangular";
    case WindowType::hann: return "hann";
    case WindowType::tukey: os << "tukey:" << w.parameter; break;
    case WindowType::kaiser: os << "kaiser:" << w.parameter; break;
  }
  return os.str();
}

void validate_window(const WindowSpec& w, std::string_view what) {
  std::ostringstream os;
  if (w.type == WindowType::tukey && !(w.parameter >= 0 && w.parameter <= 1)) {
    os << what << ": Tukey window taper fraction alpha = " << w.parameter << " is out of range; give 0 <= alpha <= 1";
    throw InputError(os.str());
  }
  if (w.type == WindowType::kaiser && !(w.parameter >= 0 && w.parameter <= kMaxKaiserBeta)) {
    os << what << ": Kaiser window beta = " << w.parameter << " is out of range; give 0 <= beta <= " << kMaxKaiserBeta;
    throw InputError(os.str());
  }
}

std::vector<double> make_window(const WindowSpec& w, std::size_t n, WindowSymmetry symmetry) {
  std::vector<double> out(n, 1.0);
  if (n <= 1) return out;
  const std::size_t span = symmetry == WindowSymmetry::symmetric ? n - 1 : n;  // periodic: n + 1 points, last dropped
  // w(x) is even: compute one half (x ≤ 0) and mirror it about the centre.
  for (std::size_t i = 0; 2 * i <= span; ++i) {
    out[i] = value_at(w, 2.0 * static_cast<double>(i) / span - 1.0);
    if (span - i < n) out[span - i] = out[i];
  }
  return out;
}

double main_lobe_width_bins(const WindowSpec& w) {
  switch (w.type) {
    case WindowType::rectangular: return 2.0;
    case WindowType::hann: return 4.0;
    case WindowType::tukey: return 2.0 + 2.0 * w.parameter;
    case WindowType::kaiser: return 2.0 * std::sqrt(1.0 + (w.parameter / units::kPi) * (w.parameter / units::kPi));
  }
  return 2.0;
}

}  // namespace fourbar

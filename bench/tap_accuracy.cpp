// fourbar tap's identification on virtual tap recordings (tests/analyze/
// tap_recording.hpp) over 20 noise seeds per case: the worst frequency and
// damping-ratio errors, how often the truth lies within 2 standard errors of
// the fit (σ) and within 2 printed uncertainties (u: σ and the later-start
// fit's change in quadrature), and the median u/σ of the frequencies. Prints
// the markdown table in docs/flex.md "Tap test".
//
//   build/bench/tap_accuracy

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analyze/tap_modes.hpp"
#include "analyze/tap_recording.hpp"

using namespace fourbar;
using testing::TapModeTruth;

int main() {
  struct Case {
    std::string name;
    std::vector<TapModeTruth> modes;
  };
  const std::vector<Case> cases = {
      {"one mode, 614 Hz, ζ 0.02", {{614.0, 0.02, 1.0, 0.3}}},
      {"one mode, 614 Hz, ζ 0.005", {{614.0, 0.005, 1.0, 1.2}}},
      {"close: 600/625 Hz, ζ 0.01/0.015", {{600.0, 0.01, 1.0, 0.0}, {625.0, 0.015, 0.7, 2.0}}},
      {"thesis coupler: 614/2456 Hz, ζ 0.02/0.015", {{614.1, 0.02, 1.0, 0.5}, {2456.3, 0.015, 0.5, 1.0}}},
  };
  std::printf("| case | SNR (dB) | worst f error | worst ζ error | truth within 2σ (f, ζ) | within 2u (f, ζ) | median u/σ (f) | bounces found | ms per fit |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  constexpr int kSeeds = 20;
  for (const Case& c : cases)
    for (double snr : {20.0, 30.0, 40.0}) {
      double worst_f = 0, worst_z = 0, ms = 0;
      int inside_f = 0, inside_z = 0, inside_uf = 0, inside_uz = 0, total = 0, bounces = 0;
      std::vector<double> inflation;
      for (int seed = 1; seed <= kSeeds; ++seed) {
        const auto rec = testing::virtual_tap(c.modes, snr, static_cast<unsigned>(seed) + 100);
        const auto t0 = std::chrono::steady_clock::now();
        const TapResult r = identify_tap_modes(rec.samples, rec.sample_rate_hz);
        ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        bounces += r.later_strikes_s.empty() ? 0 : 1;
        if (r.modes.size() != c.modes.size()) {
          std::printf("| %s | %.0f | found %zu modes (seed %d) | | | |\n", c.name.c_str(), snr, r.modes.size(), seed);
          continue;
        }
        for (std::size_t k = 0; k < c.modes.size(); ++k) {
          const TapMode& m = r.modes[k];
          const double ef = m.frequency_Hz - c.modes[k].frequency_Hz, ez = m.damping_ratio - c.modes[k].damping_ratio;
          worst_f = std::max(worst_f, std::abs(ef / c.modes[k].frequency_Hz));
          worst_z = std::max(worst_z, std::abs(ez / c.modes[k].damping_ratio));
          inside_f += std::abs(ef) <= 2 * m.frequency_sigma_Hz;
          inside_z += std::abs(ez) <= 2 * m.damping_sigma;
          inside_uf += std::abs(ef) <= 2 * m.frequency_uncertainty_Hz();
          inside_uz += std::abs(ez) <= 2 * m.damping_uncertainty();
          inflation.push_back(m.frequency_uncertainty_Hz() / m.frequency_sigma_Hz);
          ++total;
        }
      }
      std::sort(inflation.begin(), inflation.end());
      const double median_inflation = inflation.empty() ? 0.0 : inflation[inflation.size() / 2];
      std::printf("| %s | %.0f | %.2e | %.1f %% | %d/%d, %d/%d | %d/%d, %d/%d | %.2f | %d/%d | %.0f |\n", c.name.c_str(),
                  snr, worst_f, 100 * worst_z, inside_f, total, inside_z, total, inside_uf, total, inside_uz, total,
                  median_inflation, bounces, kSeeds, ms / kSeeds);
    }
  return 0;
}

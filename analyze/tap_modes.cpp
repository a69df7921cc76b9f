#include "analyze/tap_modes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "analyze/fftw_plan.hpp"
#include "common/error.hpp"
#include "common/format.hpp"

namespace fourbar {

namespace {

constexpr double pi = std::numbers::pi;
/// A peak of the decay's (or the residual's) spectrum counts when it stands
/// this far above the spectrum's median (18 dB; white noise's highest bin of
/// 10⁴ stands about 11 dB above it).
constexpr double kPeakOverMedian = 8;
/// The second fit's later start (tap_modes.hpp step 4): a beam's modes above
/// the fitted ones (ζ 3–5 % at 5–10 kHz) have fallen 20–60 dB by then, the
/// thesis coupler's second mode (2.5 kHz, ζ 1.5 %) keeps 40 % of its energy.
constexpr double kLateStart_s = 0.002;
/// Later strikes (later_strikes): the linear predictor's order (a mode is
/// two; kMaxTapModes modes, a tone and the AC coupling's pole fit in it),
/// the blocks its error is judged over, how far (in the error's σ) a
/// strike stands out (Gaussian noise's largest of 10⁵ samples: about 4.4),
/// and how long after the decay's start (0.2 ms after the first strike's
/// peak) that strike's own end (the hammer's contact, the DAQ filter) may
/// still show.
constexpr std::size_t kPredictorOrder = 24;
constexpr double kStrikeBlock_s = 0.0005;
constexpr double kStrikeOverNoise = 10;
constexpr double kStrikeSettle_s = 0.0008;
/// A fitted component whose amplitude is not shown to fall by more than this
/// (σ·T, T the fitted window) over the window is a steady tone, not a mode.
constexpr double kSteadyDecay = 0.1;

/// The decay model's basis at (σ_k, ω_k): columns e^{−σt}cos ωt, e^{−σt}sin ωt.
Eigen::MatrixXd basis(const Eigen::VectorXd& theta, double dt, Eigen::Index n) {
  const Eigen::Index k = theta.size() / 2;
  Eigen::MatrixXd a(n, 2 * k);
  for (Eigen::Index j = 0; j < k; ++j) {
    const double sigma = theta(2 * j), omega = theta(2 * j + 1);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) * dt, e = std::exp(-sigma * t);
      a(i, 2 * j) = e * std::cos(omega * t);
      a(i, 2 * j + 1) = e * std::sin(omega * t);
    }
  }
  return a;
}

/// Variable projection: the residual after the best amplitudes.
Eigen::VectorXd projected_residual(const Eigen::VectorXd& theta, const Eigen::VectorXd& y, double dt,
                                   Eigen::VectorXd* amplitudes = nullptr) {
  const Eigen::MatrixXd a = basis(theta, dt, y.size());
  const Eigen::VectorXd c = a.colPivHouseholderQr().solve(y);
  if (amplitudes) *amplitudes = c;
  return y - a * c;
}

/// Spectrum peaks of the decay: (frequency in rad/s, magnitude), strongest first.
std::vector<std::pair<double, double>> spectrum_peaks(const Eigen::VectorXd& y, double fs, double over_median) {
  const std::size_t n = fast_fft_size(std::max<std::size_t>(8 * static_cast<std::size_t>(y.size()), 1 << 14));
  RealFft fft(n);
  auto time = fft.time();
  std::fill(time.begin(), time.end(), 0.0);
  // A half Hann (falling) taper: the decay starts at its largest and ends in
  // the noise; no window at the start keeps the leakage of the first cycles low.
  const auto m = static_cast<std::size_t>(y.size());
  for (std::size_t i = 0; i < m; ++i) time[i] = y(static_cast<Eigen::Index>(i)) * 0.5 * (1 + std::cos(pi * i / m));
  fft.forward();
  const auto spec = fft.spectrum();
  std::vector<double> mag(spec.size());
  for (std::size_t i = 0; i < spec.size(); ++i) mag[i] = std::abs(spec[i]);
  std::vector<double> sorted = mag;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double median = sorted[sorted.size() / 2];
  std::vector<std::pair<double, double>> peaks;
  for (std::size_t i = 2; i + 1 < mag.size(); ++i)
    if (mag[i] > mag[i - 1] && mag[i] >= mag[i + 1] && mag[i] > over_median * median) {
      // Parabolic interpolation of the log magnitude around the peak bin.
      const double a = std::log(mag[i - 1]), b = std::log(mag[i]), c = std::log(mag[i + 1]);
      const double shift = 0.5 * (a - c) / (a - 2 * b + c);
      peaks.emplace_back(2 * pi * (static_cast<double>(i) + shift) * fs / static_cast<double>(n), mag[i]);
    }
  std::sort(peaks.begin(), peaks.end(), [](const auto& p, const auto& q) { return p.second > q.second; });
  return peaks;
}

/// Levenberg–Marquardt on (σ_k, ω_k) with the amplitudes projected out.
void fit_decay(Eigen::VectorXd& theta, const Eigen::VectorXd& y, double dt, double fs) {
  Eigen::VectorXd r = projected_residual(theta, y, dt);
  double cost = r.squaredNorm(), lambda = 1e-3;
  const Eigen::Index m = y.size(), k = theta.size() / 2;
  for (int iter = 0; iter < 200; ++iter) {
    Eigen::MatrixXd jac(m, 2 * k);
    for (Eigen::Index p = 0; p < 2 * k; ++p) {
      Eigen::VectorXd t2 = theta;
      const double h = 1e-7 * std::max(std::abs(theta(p)), 1.0 + 1e-3 * std::abs(theta(p ^ 1)));
      t2(p) += h;
      jac.col(p) = (projected_residual(t2, y, dt) - r) / h;
    }
    const Eigen::MatrixXd jtj = jac.transpose() * jac;
    const Eigen::VectorXd g = jac.transpose() * r;
    bool improved = false;
    for (int tries = 0; tries < 20 && !improved; ++tries) {
      // A decay rate may not go below zero. One that a step would take there
      // (a steady tone's, σ → 0) is held at zero and the step solved for the
      // others: rejecting the whole step instead raised λ until no parameter
      // moved (3 % hum held the beam's third mode at its starting ζ 0.0100).
      Eigen::VectorXd step;
      std::vector<bool> held(static_cast<std::size_t>(k), false);
      for (bool again = true; again;) {
        Eigen::MatrixXd a = jtj;
        a.diagonal() += lambda * jtj.diagonal();
        Eigen::VectorXd rhs = -g;
        for (Eigen::Index j = 0; j < k; ++j)
          if (held[static_cast<std::size_t>(j)]) {
            a.row(2 * j).setZero();
            a.col(2 * j).setZero();
            a(2 * j, 2 * j) = 1;
            rhs(2 * j) = -theta(2 * j);  // to zero
          }
        step = a.ldlt().solve(rhs);
        again = false;
        for (Eigen::Index j = 0; j < k; ++j)
          if (!held[static_cast<std::size_t>(j)] && theta(2 * j) + step(2 * j) < 0)
            held[static_cast<std::size_t>(j)] = again = true;
      }
      const Eigen::VectorXd candidate = theta + step;
      bool valid = true;
      for (Eigen::Index j = 0; j < k; ++j)
        valid = valid && candidate(2 * j) >= 0 && candidate(2 * j + 1) > 0 && candidate(2 * j + 1) < pi * fs;
      const Eigen::VectorXd rc = valid ? projected_residual(candidate, y, dt) : r;
      if (valid && rc.squaredNorm() < cost) {
        const double gain = (cost - rc.squaredNorm()) / cost;
        theta = candidate;
        r = rc;
        cost = rc.squaredNorm();
        lambda = std::max(lambda / 5, 1e-12);
        improved = true;
        if (gain < 1e-12) return;  // converged
      } else {
        lambda *= 10;
      }
    }
    if (!improved) break;
  }
}

/// Samples at the record's limits: an overloaded recorder clips a hard tap's
/// first cycles flat there (the bounce search took them for strikes, and at a
/// limit of 0.2 of the peak the beam's second mode came out at 602 Hz).
struct Clip {
  std::size_t samples = 0;  ///< 0: not clipped
  std::size_t last = 0;     ///< the last clipped sample
  double low = 0, high = 0; ///< the record's limits
};

/// Three or more samples at the record's largest or smallest value (a
/// continuous signal has one each), two of them neighbours (a flat top), the
/// last before the record's last tenth (a steady tone sampled in step with
/// the recorder repeats its extremes exactly, to the record's end) are a
/// clip. Throws InputError when most samples sit at the limits: a digital
/// line or a saturated channel, not a tap.
Clip find_clip(std::span<const double> x) {
  const std::size_t n = x.size();
  const auto [lo_it, hi_it] = std::minmax_element(x.begin(), x.end());
  Clip c;
  c.low = *lo_it, c.high = *hi_it;
  if (!(c.high > c.low)) return c;
  const double rail = 1e-12 * (c.high - c.low);
  std::size_t count = 0, last = 0;
  bool flat = false;
  for (std::size_t i = 0; i < n; ++i)
    if (x[i] >= c.high - rail || x[i] <= c.low + rail) {
      flat = flat || (count > 0 && last + 1 == i && x[i] == x[last]);
      ++count, last = i;
    }
  if (2 * count > n)
    throw InputError("sits at its largest or smallest value (" + format_number(c.low) + ", " + format_number(c.high) +
                     ") in " + std::to_string(count) + " of its " + std::to_string(n) +
                     " samples: a digital line or a saturated channel, not an accelerometer's tap; give the "
                     "accelerometer's --channel, or set the recorder's input range larger");
  if (count >= 3 && flat && last < n - n / 10) c.samples = count, c.last = last;
  return c;
}

/// Later strikes of the hammer (it bounced, or was struck twice): samples
/// where a free decay's linear prediction fails. A sum of damped sinusoids
/// (and a steady tone) obeys a linear recursion, so an autoregressive
/// predictor of order kPredictorOrder fitted by least squares over the
/// record from `from` leaves only the noise; a new strike is an input the
/// recursion cannot predict and stands out in the prediction error, whatever
/// the modes' beating does to the envelope. Returns, for each run of blocks
/// (kStrikeBlock_s) whose largest |error| exceeds kStrikeOverNoise times the
/// error's noise σ, the sample of the first one's largest error.
std::vector<std::size_t> later_strikes(std::span<const double> x, std::size_t from, double offset, double fs) {
  const std::size_t n = std::min(x.size(), from + (std::size_t{1} << 16));
  const std::size_t p = kPredictorOrder;
  const auto block = std::max<std::size_t>(8, static_cast<std::size_t>(std::lround(kStrikeBlock_s * fs)));
  if (n < from + 8 * p + 8 * block) return {};
  const auto rows = static_cast<Eigen::Index>(n - from - p);
  Eigen::MatrixXd a(rows, static_cast<Eigen::Index>(p));
  Eigen::VectorXd b(rows);
  for (Eigen::Index i = 0; i < rows; ++i) {
    const std::size_t t = from + p + static_cast<std::size_t>(i);
    b(i) = x[t] - offset;
    for (std::size_t j = 0; j < p; ++j) a(i, static_cast<Eigen::Index>(j)) = x[t - 1 - j] - offset;
  }
  const Eigen::MatrixXd ata = a.transpose() * a;
  const Eigen::VectorXd coef = ata.ldlt().solve(a.transpose() * b);
  const Eigen::VectorXd error = b - a * coef;
  // The noise's scale from the median |error| (robust to the strikes' few
  // samples): σ ≈ 1.4826 · median for Gaussian noise.
  std::vector<double> magnitude(static_cast<std::size_t>(error.size()));
  for (Eigen::Index i = 0; i < error.size(); ++i) magnitude[static_cast<std::size_t>(i)] = std::abs(error(i));
  std::vector<double> sorted = magnitude;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double sigma = 1.4826 * sorted[sorted.size() / 2];
  // The first strike's own end (its force, the DAQ filter's ringing) is
  // not a strike: samples within kStrikeSettle_s of `from` are skipped.
  // Then a strike is a block whose largest |error| is kStrikeOverNoise σ;
  // the next block that is not one starts the search for the next strike.
  const auto settle = static_cast<std::size_t>(kStrikeSettle_s * fs);
  const auto blocks = magnitude.size() / block;
  std::vector<std::size_t> strikes;
  bool inside = false;
  for (std::size_t k = 0; k < blocks; ++k) {
    const auto first = magnitude.begin() + static_cast<std::ptrdiff_t>(k * block);
    const auto peak = std::max_element(first, first + static_cast<std::ptrdiff_t>(block));
    const std::size_t at = p + static_cast<std::size_t>(peak - magnitude.begin());
    const bool strike = at >= settle && *peak > kStrikeOverNoise * sigma;
    if (strike && !inside) strikes.push_back(from + at);
    inside = strike;
  }
  return strikes;
}
/// The decay a tap leaves, ready to fit.
struct Decay {
  Eigen::VectorXd y;      ///< the fitted samples, offset removed
  std::size_t block = 0;  ///< the envelope's block (5 ms, at least 16 samples)
  std::string harder;     ///< what a technician does about too little decay
};

/// The decay to fit (tap_modes.hpp step 1): the tap (the largest sample),
/// the offset and the noise from before it (else from the record's last
/// tenth), the start after the tap, a clip and any later strike, and the end
/// at twice the time the envelope takes to reach the noise. Fills the
/// result's tap, clip, strike, noise and decay entries; InputError when
/// there is no free decay.
Decay find_decay(std::span<const double> samples, double fs, TapResult& result) {
  const std::size_t n = samples.size();
  std::size_t tap = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (std::abs(samples[i]) > std::abs(samples[tap])) tap = i;
  result.tap_time_s = static_cast<double>(tap) / fs;
  const std::size_t pre = tap > 200 ? tap - static_cast<std::size_t>(std::ceil(0.002 * fs)) : 0;
  std::span<const double> before = pre > 100 ? samples.subspan(0, pre) : std::span<const double>();
  std::span<const double> tail = samples.subspan(n - n / 10);
  const double offset = before.empty()
                            ? std::accumulate(tail.begin(), tail.end(), 0.0) / static_cast<double>(tail.size())
                            : std::accumulate(before.begin(), before.end(), 0.0) / static_cast<double>(before.size());
  auto centred_rms = [&](std::span<const double> x) {
    double s = 0;
    for (double v : x) s += (v - offset) * (v - offset);
    return x.empty() ? 0.0 : std::sqrt(s / static_cast<double>(x.size()));
  };
  const double noise = before.empty() ? centred_rms(tail) : centred_rms(before);
  std::size_t start = std::min(n - 1, tap + std::max<std::size_t>(1, static_cast<std::size_t>(2e-4 * fs)));
  // After a clip or a later strike the decay is fitted from 0.5 ms on: a
  // strike's own end (the hammer's contact, about 0.25 ms; the DAQ filter).
  const std::size_t after = std::max<std::size_t>(1, static_cast<std::size_t>(5e-4 * fs));
  // An overloaded recorder's flat tops are not the link's motion: the decay
  // is fitted from after the last clipped sample, where it is free again
  // (find_clip).
  const Clip clip = find_clip(samples);
  if (clip.samples > 0) {
    result.clipped_samples = clip.samples;
    result.clipped_until_s = static_cast<double>(clip.last) / fs;
    start = std::max(start, std::min(n - 1, clip.last + after));
  }
  // What to do about too little decay: a clipped tap needs a softer one.
  const std::string harder =
      result.clipped_samples > 0
          ? "tap softer or set the recorder's input range larger (the record is clipped until " +
                format_number(result.clipped_until_s) + " s, and only the decay after that is fitted)"
          : "tap harder";
  // A free decay starts only after the hammer's last strike: a bounce 4 ms
  // after the tap made the beam's fit report 603.8 Hz, ζ 0.117 as its
  // second mode (truth 2451.7 Hz, 0.015). The decay after the last strike
  // is fitted, and the strikes are reported.
  for (const std::size_t k : later_strikes(samples, start, offset, fs)) {
    result.later_strikes_s.push_back(static_cast<double>(k) / fs);
    start = std::min(n - 1, k + after);
  }
  const std::size_t block = std::max<std::size_t>(16, static_cast<std::size_t>(0.005 * fs));
  if (start + 4 * block > n && result.clipped_samples > 0)
    throw InputError("is clipped: " + std::to_string(result.clipped_samples) + " samples sit at its limits (" +
                     format_number(clip.low) + ", " + format_number(clip.high) + "), the last at " +
                     format_number(result.clipped_until_s) +
                     " s, too near its end for a free decay to follow; tap softer or set the recorder's input "
                     "range larger, and record until the ringing has died away");
  if (start + 4 * block > n)
    throw InputError("has its largest peak at " + format_number(result.tap_time_s) +
                     " s, too near its end for a decay to follow; record from before the tap until the ringing "
                     "has died away");
  const double first = centred_rms(samples.subspan(start, block));
  std::size_t end = start + block;
  double last = first;
  while (end + block <= n) {
    last = centred_rms(samples.subspan(end, block));
    end += block;
    if (last < 1.5 * noise) break;
  }
  result.noise_rms = noise;
  result.decay_db = 20 * std::log10(first / std::max(last, 1e-300));
  const double to_tail_db = 20 * std::log10(first / std::max(centred_rms(tail), 1e-300));
  if (!(result.decay_db >= 6) || !(to_tail_db >= 10))
    throw InputError("has no free decay: the signal after its largest peak (at " + format_number(result.tap_time_s) +
                     " s) does not die away (its envelope falls " + format_number(result.decay_db, 2) +
                     " dB, and the record's last tenth is " + format_number(to_tail_db, 2) +
                     " dB below its start; a tap test needs 6 and 10 dB); record a hammer tap on the link, from "
                     "before the tap until the ringing has died away, with the link free to ring");
  // Twice as long as it takes to reach the floor (the tail still tells the
  // fit where the slowest mode ends), at most 60 000 samples (its cost).
  end = std::min({n, start + 2 * (end - start), start + 60'000});
  const auto m = static_cast<Eigen::Index>(end - start);
  Eigen::VectorXd y(m);
  for (Eigen::Index i = 0; i < m; ++i) y(i) = samples[start + static_cast<std::size_t>(i)] - offset;
  result.decay_start_s = static_cast<double>(start) / fs;
  result.decay_duration_s = static_cast<double>(m) / fs;
  return {std::move(y), block, harder};
}

/// Modes one at a time (tap_modes.hpp steps 2–3): the strongest peak of what
/// the modes so far leave unexplained, then a fit of all of them (so that two
/// close modes that make one hump in the spectrum come out as two). Returns
/// (σ_k, ω_k).
Eigen::VectorXd fit_modes(const Eigen::VectorXd& y, double fs, const TapOptions& options, const std::string& harder) {
  const double dt = 1 / fs;
  std::vector<std::pair<double, double>> peaks = spectrum_peaks(y, fs, kPeakOverMedian);
  if (peaks.empty())
    throw InputError(
        "shows no resonance peak in its decay (nothing rings above the noise); " + harder + ", or closer "
        "to the middle of the link");
  // With --modes N the N lowest are wanted, not the N strongest: a hammer
  // excites a link's higher modes strongly in acceleration (∝ ω²), and a
  // rig file whose second entry is the third mode is wrong without a word.
  // So every mode that stands out is fitted (at most kMaxTapModes), the N
  // lowest are reported.
  const int wanted = options.modes > 0 ? kMaxTapModes : 4;
  Eigen::VectorXd theta(2);
  theta << 0.01 * peaks.front().first, peaks.front().first;  // ζ ≈ 1 % to start
  fit_decay(theta, y, dt, fs);
  while (theta.size() / 2 < wanted) {
    const Eigen::VectorXd residual = projected_residual(theta, y, dt);
    const auto more = spectrum_peaks(residual, fs, kPeakOverMedian);
    if (more.empty()) {
      if (options.modes > theta.size() / 2)
        throw InputError("shows " + std::to_string(theta.size() / 2) + " mode(s) in its decay, fewer than the " +
                         std::to_string(options.modes) + " asked; give --modes " + std::to_string(theta.size() / 2) +
                         " or " + harder);
      break;
    }
    Eigen::VectorXd grown(theta.size() + 2);
    grown << theta, 0.01 * more.front().first, more.front().first;
    fit_decay(grown, y, dt, fs);
    theta = grown;
  }
  return theta;
}

/// Steps 4–5 (tap_modes.hpp): the modes' frequencies and damping ratios with their standard
/// errors (the covariance of all parameters at the optimum) and the change
/// of a fit from kLateStart_s on; steady tones set aside; the N lowest kept.
void report_modes(const Eigen::VectorXd& theta, const Decay& d, double fs, const TapOptions& options,
                  TapResult& result) {
  const Eigen::VectorXd& y = d.y;
  const std::string& harder = d.harder;
  const std::size_t block = d.block;
  const auto m = y.size();
  const double dt = 1 / fs;
  const Eigen::Index k = theta.size() / 2;
  // The same modes fitted from kLateStart_s on, when enough decay is left.
  const auto late = static_cast<Eigen::Index>(std::llround(kLateStart_s * fs));
  Eigen::VectorXd theta_late = theta;
  const bool window_check = m - late >= 4 * static_cast<Eigen::Index>(block);
  if (window_check) fit_decay(theta_late, y.tail(m - late), dt, fs);
  Eigen::VectorXd r;
  Eigen::VectorXd c;
  r = projected_residual(theta, y, dt, &c);
  result.residual_rms = std::sqrt(r.squaredNorm() / static_cast<double>(m));

  // The covariance of all parameters (a, b, σ, ω per mode) at the optimum.
  Eigen::MatrixXd full(m, 4 * k);
  for (Eigen::Index j = 0; j < k; ++j) {
    const double sigma = theta(2 * j), omega = theta(2 * j + 1), a = c(2 * j), b = c(2 * j + 1);
    for (Eigen::Index i = 0; i < m; ++i) {
      const double t = static_cast<double>(i) * dt, e = std::exp(-sigma * t);
      const double co = e * std::cos(omega * t), si = e * std::sin(omega * t);
      full(i, 4 * j) = co;
      full(i, 4 * j + 1) = si;
      full(i, 4 * j + 2) = -t * (a * co + b * si);
      full(i, 4 * j + 3) = t * (-a * si + b * co);
    }
  }
  const double s2 = r.squaredNorm() / static_cast<double>(std::max<Eigen::Index>(1, m - 4 * k));
  const Eigen::MatrixXd cov = s2 * (full.transpose() * full).ldlt().solve(Eigen::MatrixXd::Identity(4 * k, 4 * k));
  for (Eigen::Index j = 0; j < k; ++j) {
    const double sigma = theta(2 * j), omega = theta(2 * j + 1);
    const double wn = std::hypot(sigma, omega);
    TapMode mode;
    mode.frequency_Hz = wn / (2 * pi);
    mode.damping_ratio = sigma / wn;
    mode.amplitude = std::hypot(c(2 * j), c(2 * j + 1));
    const Eigen::Matrix2d cs = cov.block<2, 2>(4 * j + 2, 4 * j + 2);
    const Eigen::Vector2d dwn(sigma / wn, omega / wn);                                          // ∂ωn/∂(σ, ω)
    const Eigen::Vector2d dz(omega * omega / (wn * wn * wn), -sigma * omega / (wn * wn * wn));  // ∂ζ/∂(σ, ω)
    mode.frequency_sigma_Hz = std::sqrt(std::max(0.0, dwn.dot(cs * dwn))) / (2 * pi);
    mode.damping_sigma = std::sqrt(std::max(0.0, dz.dot(cs * dz)));
    if (window_check) {
      const double sl = theta_late(2 * j), wl = std::hypot(sl, theta_late(2 * j + 1));
      mode.frequency_window_Hz = std::abs(wl - wn) / (2 * pi);
      mode.damping_window = std::abs(sl / wl - mode.damping_ratio);
    }
    // A steady tone (mains hum, a machine nearby) fits as a "mode" that does
    // not decay: 0.3 % hum under a beam's tap became mode 1 at 50 Hz. Its
    // decay over the fitted window, σ·T, not shown above kSteadyDecay (by 2
    // standard errors) marks it; it stays in the fit, out of the modes.
    const double window_s = static_cast<double>(m) * dt;
    if ((sigma - 2 * std::sqrt(std::max(0.0, cs(0, 0)))) * window_s < kSteadyDecay) {
      result.steady_tones_Hz.push_back(mode.frequency_Hz);
      continue;
    }
    result.modes.push_back(mode);
  }
  std::sort(result.steady_tones_Hz.begin(), result.steady_tones_Hz.end());
  std::sort(result.modes.begin(), result.modes.end(),
            [](const TapMode& p, const TapMode& q) { return p.frequency_Hz < q.frequency_Hz; });
  if (result.modes.empty())
    throw InputError("shows no decaying mode: what rings after its largest peak is a steady tone (" +
                     format_number(result.steady_tones_Hz.front(), 4) +
                     " Hz); record a hammer tap on the link, with the link free to ring");
  if (options.modes > 0 && result.modes.size() < static_cast<std::size_t>(options.modes))
    throw InputError("shows " + std::to_string(result.modes.size()) + " decaying mode(s), fewer than the " +
                     std::to_string(options.modes) + " asked (and a steady tone at " +
                     format_number(result.steady_tones_Hz.front(), 4) + " Hz); give --modes " +
                     std::to_string(result.modes.size()) + " or " + harder);
  if (options.modes > 0 && result.modes.size() > static_cast<std::size_t>(options.modes)) {
    for (std::size_t j = static_cast<std::size_t>(options.modes); j < result.modes.size(); ++j)
      result.higher_modes_Hz.push_back(result.modes[j].frequency_Hz);
    result.modes.resize(static_cast<std::size_t>(options.modes));
  }
}

}  // namespace

double TapMode::frequency_uncertainty_Hz() const { return std::hypot(frequency_sigma_Hz, frequency_window_Hz); }
double TapMode::damping_uncertainty() const { return std::hypot(damping_sigma, damping_window); }

TapResult identify_tap_modes(std::span<const double> samples, double fs, const TapOptions& options) {
  TapResult result;
  const std::size_t n = samples.size();
  if (n < 64 || !(fs > 0)) throw InputError("is too short to hold a tap (" + std::to_string(n) + " samples)");
  const Decay decay = find_decay(samples, fs, result);
  report_modes(fit_modes(decay.y, fs, options, decay.harder), decay, fs, options, result);
  return result;
}

}  // namespace fourbar

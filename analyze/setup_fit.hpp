#pragma once
// The set-up check's fit algebra, private to analyze/setup_check.cpp (not
// for other includes): a channel's recovered reading and its correlations
// with the nominal templates at every pulse angle and direction, the one-
// and two-term fits read from them, the joint search's points, and the
// confidence of a finding.

#include <algorithm>
#include <array>
#include <complex>
#include <limits>
#include <optional>
#include <vector>

#include "acquire/manifest.hpp"
#include "analyze/sensor_mount.hpp"

namespace fourbar::setup_fit {

/// One analysed accelerometer channel: the reading recovered on the grid,
/// its templates for each link it may belong to, and its correlations.
struct Channel {
  const ChannelSpec* spec = nullptr;
  SensedLink link = SensedLink::coupler;  // as the manifest says
  SensorAxis axis = SensorAxis::tangential;
  double r_m = 0, h_m = 0;
  std::vector<double> m;                  // recovered reading (calibrated, on the grid)
  std::vector<double> f0;                 // the part of it the manifest's model added back (not filtered)
  std::vector<std::complex<double>> m_hat;  // G·m over the fitted orders (FFT bins 0 … N/2)
  double energy = 0;                      // ‖G·m‖² over the fitted orders
  struct Fit {
    std::array<std::vector<double>, 2> t;       // f0, f1 on φj = θ0 + 2πj/N
    double g00 = 0, g01 = 0, g11 = 0;           // Gram matrix
    std::array<std::array<std::vector<double>, 2>, 2> c;  // [τ index][template][s]
  };
  std::array<std::optional<Fit>, 2> fit;  // by link (coupler, rocker)
};

/// Unexplained share of a reading's in-band energy that the nominal model
/// leaves even with the right set-up (see confidence()).
constexpr double kMisfitFloor = 0.02;

/// Share of a reading's energy the crank-pin and gravity term must carry
/// (beyond what α explains) for its position to be estimated: 5 × the floor.
constexpr double kPositionShare = 5 * kMisfitFloor;

/// Index of a link in Channel::fit, of a direction τ in Fit::c.
constexpr std::size_t link_index(SensedLink l) { return l == SensedLink::coupler ? 0 : 1; }
constexpr std::size_t tau_index(double tau) { return tau > 0 ? 0 : 1; }

/// Share of ‖m‖² the two-term fit explains, and its coefficients.
struct TwoTerm {
  double r2 = 0, a = 0, b = 0;
};
inline TwoTerm two_term(const Channel& ch, const Channel::Fit& f, std::size_t ti, std::size_t s) {
  const double c0 = f.c[ti][0][s], c1 = f.c[ti][1][s];
  const double det = f.g00 * f.g11 - f.g01 * f.g01;
  TwoTerm out;
  if (!(det > 1e-12 * f.g00 * f.g11) || ch.energy <= 0) {
    out.a = f.g00 > 0 ? c0 / f.g00 : 0.0;
    out.r2 = ch.energy > 0 && f.g00 > 0 ? c0 * c0 / (f.g00 * ch.energy) : 0.0;
    return out;
  }
  out.a = (f.g11 * c0 - f.g01 * c1) / det;
  out.b = (f.g00 * c1 - f.g01 * c0) / det;
  out.r2 = (out.a * c0 + out.b * c1) / ch.energy;
  return out;
}

/// The one-term fit k·(f0 + r·f1) with r fixed: the share explained with a
/// given k (one_term_r2), and k fitted (one_term).
struct OneTerm {
  double k = 0, r2 = 0;
};
inline double one_term_r2(const Channel& ch, const Channel::Fit& f, std::size_t ti, std::size_t s, double r, double k) {
  const double c = f.c[ti][0][s] + r * f.c[ti][1][s];
  const double tt = f.g00 + 2 * r * f.g01 + r * r * f.g11;
  return ch.energy > 0 ? (2 * k * c - k * k * tt) / ch.energy : 0.0;
}
inline OneTerm one_term(const Channel& ch, const Channel::Fit& f, std::size_t ti, std::size_t s, double r) {
  const double c = f.c[ti][0][s] + r * f.c[ti][1][s];
  const double tt = f.g00 + 2 * r * f.g01 + r * r * f.g11;
  OneTerm o;
  o.k = tt > 0 ? c / tt : 0.0;
  o.r2 = one_term_r2(ch, f, ti, s, r, o.k);
  return o;
}

/// The share of the misfit with the manifest's value that the data's value
/// removes. Both shares carry kMisfitFloor: the nominal templates are not the
/// rig's exact motion (crank-speed wander, the filter's edges, a sensor's
/// small misalignment), so a gain below that floor is no evidence.
inline double confidence(double unexplained_data, double unexplained_manifest) {
  const double u_data = std::max(0.0, unexplained_data) + kMisfitFloor;
  const double u_manifest = std::max(0.0, unexplained_manifest) + kMisfitFloor;
  return std::clamp(1.0 - u_data / u_manifest, 0.0, 1.0);
}

/// A point of the joint search and its score (Σ share explained).
struct Best {
  double score = -std::numeric_limits<double>::infinity();
  bool swapped = false;
  std::size_t ti = 0, s = 0;
};

/// The joint search over assignment × direction × pulse angle: its best,
/// and its best keeping the manifest's direction, its pulse angle, both,
/// or the channels as the manifest assigns them.
struct JointSearch {
  Best best, best_dir_m, best_offset_m, best_straight, best_crank_m;
};

}  // namespace fourbar::setup_fit

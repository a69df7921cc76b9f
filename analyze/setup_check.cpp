// The set-up check (setup_check.hpp): the reading put back together from
// the analysed averages, the nominal templates, the joint search over pulse
// angle, direction and coupler/rocker assignment, the per-channel fits and
// the findings.
#include "analyze/setup_check.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>

#include "analyze/analysis_channels.hpp"
#include "analyze/crank_orders.hpp"
#include "analyze/fftw_plan.hpp"
#include "analyze/filter_design.hpp"
#include "analyze/link_motion.hpp"
#include "analyze/pipeline.hpp"
#include "analyze/sensor_corner.hpp"
#include "analyze/setup_finding.hpp"
#include "analyze/setup_fit.hpp"
#include "common/format.hpp"
#include "common/units.hpp"
#include "mechanism/kinematics.hpp"

namespace fourbar {

namespace {

using namespace setup_fit;

/// The nominal templates' energy left above the fitted band: the band ends
/// at the order that holds all but this share of each template's energy.
constexpr double kTemplateTail = 1e-4;

/// Gain below which the filter is taken to have removed an order.
constexpr double kMinOrderGain = 0.5;

void remove_mean(std::vector<double>& x) {
  double s = 0;
  for (double v : x) s += v;
  s /= static_cast<double>(x.size());
  for (double& v : x) v -= s;
}

/// f0, f1 of a sensor on `link` at offset h, steady crank speed w, at φj.
std::array<std::vector<double>, 2> templates(const Rig& rig, SensedLink link, SensorAxis axis, double h_m, double w,
                                             double theta0, std::size_t N) {
  std::array<std::vector<double>, 2> t{std::vector<double>(N), std::vector<double>(N)};
  for (std::size_t j = 0; j < N; ++j) {
    const double phi = theta0 + units::kTwoPi * static_cast<double>(j) / static_cast<double>(N);
    const SensedLinkMotion k = nominal_link_motion(rig, link, CrankState{phi, w, 0.0});
    const Vec2 u = k.u, n = u.perp();
    const double w2 = k.omega_rad_s * k.omega_rad_s;
    if (axis == SensorAxis::tangential) {
      t[0][j] = fourbar::dot(k.joint_accel_m_s2, n) - h_m * w2 + rig.gravity_m_s2 * n.y;
      t[1][j] = k.alpha_rad_s2;
    } else {
      t[0][j] = fourbar::dot(k.joint_accel_m_s2, u) - h_m * k.alpha_rad_s2 + rig.gravity_m_s2 * u.y;
      t[1][j] = -w2;
    }
  }
  remove_mean(t[0]);
  remove_mean(t[1]);
  return t;
}

/// The data's high-pass corner of a channel on its own link, at the joint
/// best pulse angle and direction, the manifest's position.
CornerFit corner_fit(const Channel& ch, const Channel::Fit& f, std::size_t ti, std::size_t s,
                     const std::vector<double>& gain, double crank_hz, double fs, RealFft& fft) {
  const std::size_t N = ch.m.size(), K = gain.size() - 1;
  std::vector<double> shifted(N);
  for (std::size_t k = 0; k < N; ++k) {
    const std::size_t j = ti == 0 ? (s + k) % N : (s + N - k % N) % N;
    shifted[k] = f.t[0][j] + ch.r_m * f.t[1][j];
  }
  const auto T = band_spectrum(shifted, gain, fft);
  std::vector<double> order_hz(K + 1);
  for (std::size_t q = 0; q <= K; ++q) order_hz[q] = static_cast<double>(q) * crank_hz;
  return fit_high_pass_corner(std::span(ch.m_hat).first(K + 1), std::span(T).first(K + 1), order_hz,
                              ch.spec->ac_coupled ? ch.spec->highpass_hz : 0.0, fs);
}

/// An offset within this (or a tenth of the width) of the pulse's width is its other edge.
constexpr double kWidthMatchDeg = 1.0;

double wrap_deg(double d) {
  d = std::fmod(d, 360.0);
  if (d > 180) d -= 360;
  if (d <= -180) d += 360;
  return d;
}

/// The crank state on the grid: θ2 as the manifest says, ω2 averaged, α2 = ω2·dω2/dθ2.
std::vector<CrankState> grid_crank(const RecordingAnalysis& a, double dir_m) {
  const std::size_t N = a.grid_points_per_rev;
  std::vector<CrankState> crank(N);
  const double dtheta = dir_m * units::kTwoPi / static_cast<double>(N);
  for (std::size_t k = 0; k < N; ++k) {
    const auto& w = a.crank_speed_rad_s.mean;
    const double dw = w[(k + 1) % N] - w[(k + N - 1) % N];
    crank[k] = {units::deg_to_rad(a.crank_deg[k]), w[k], w[k] * dw / (2 * dtheta)};
  }
  return crank;
}

/// The channels: the reading recovered by running the conversion forward on
/// the analysed averages (a normal channel's consistency goes to `out`).
std::vector<Channel> recover_channels(const RecordingAnalysis& a, const Manifest& manifest,
                                      const std::vector<CrankState>& crank, SetupCheck& out) {
  const Rig& rig = *a.rig;
  const std::size_t N = a.grid_points_per_rev;
  const AnalysisChannels chosen = analysis_channels(manifest);
  auto spec_of = [&](const std::string& name) -> const ChannelSpec* {
    for (const ChannelSpec& c : manifest.channels)
      if (c.name == name) return &c;
    return nullptr;
  };
  std::vector<Channel> channels;
  for (const LinkChannels& lc : chosen.links) {
    const LinkResult* lr = lc.link == SensedLink::coupler ? (a.coupler ? &*a.coupler : nullptr)
                                                          : (a.rocker ? &*a.rocker : nullptr);
    if (!lr || lr->alpha_rad_s2.mean.size() != N) continue;
    for (const auto* ac : {&lc.tangential, &lc.normal}) {
      if (!*ac) continue;
      const bool tangential = (*ac)->mount.axis == SensorAxis::tangential;
      if (!tangential && (!lr->normal || lr->normal->omega_sq_rad2_s2.mean.size() != N)) continue;
      Channel ch;
      ch.spec = spec_of((*ac)->mount.channel);
      if (!ch.spec) continue;
      const ResolvedMount mount = resolve_mount(rig, (*ac)->mount);
      ch.link = lc.link, ch.axis = mount.axis, ch.r_m = mount.r_m, ch.h_m = mount.h_m;
      ch.m.resize(N), ch.f0.resize(N);
      for (std::size_t k = 0; k < N; ++k) {
        const SensedLinkMotion mo = nominal_link_motion(rig, lc.link, crank[k]);
        const Vec2 u = mo.u, n = u.perp();
        const double alpha = lr->alpha_rad_s2.mean[k];
        if (tangential) {
          ch.f0[k] = fourbar::dot(mo.joint_accel_m_s2, n) - mount.h_m * mo.omega_rad_s * mo.omega_rad_s +
                     rig.gravity_m_s2 * n.y;
          ch.m[k] = ch.f0[k] + mount.r_m * alpha;
        } else {
          ch.f0[k] = fourbar::dot(mo.joint_accel_m_s2, u) - mount.h_m * alpha + rig.gravity_m_s2 * u.y;
          ch.m[k] = ch.f0[k] - mount.r_m * lr->normal->omega_sq_rad2_s2.mean[k];
        }
      }
      channels.push_back(std::move(ch));
      if (!tangential) out.normal_consistency.emplace_back((*ac)->mount.channel, lr->normal->rel_rms_difference);
    }
  }
  return channels;
}

/// The orders the fit uses (1 … K) and the analysis filters' gains on them:
/// the α (or ω²) was filtered, the terms added back were not, so per order
/// the recovered reading is G·m + (1 − G)·f0_manifest. Fitted: G·m against
/// G·template.
struct FitBand {
  std::size_t K = 3;
  std::vector<double> alpha_gain, normal_gain;
  const std::vector<double>& gain(const Channel& ch) const {
    return ch.axis == SensorAxis::tangential ? alpha_gain : normal_gain;
  }
};

/// The templates of each link a channel may belong to; returns the band they
/// occupy (the order holding all but kTemplateTail of each one's energy,
/// below N/2).
std::size_t add_templates(const Rig& rig, std::vector<Channel>& channels, double w_mean, double theta0, std::size_t N,
                          RealFft& fft) {
  std::size_t K = 3;
  for (Channel& ch : channels) {
    for (SensedLink l : {SensedLink::coupler, SensedLink::rocker}) {
      if (l != ch.link && ch.axis != SensorAxis::tangential) continue;
      Channel::Fit f;
      f.t = templates(rig, l, ch.axis, ch.h_m, w_mean, theta0, N);
      for (const auto& t : f.t) K = std::max(K, band_order(t, kTemplateTail, fft));
      ch.fit[link_index(l)] = std::move(f);
    }
  }
  return std::min(K, N / 2 - 1);
}

/// Each reading's in-band spectrum, energy and correlations with its
/// templates at every pulse angle and both directions.
void correlate(std::vector<Channel>& channels, const FitBand& band, std::size_t N, RealFft& fft) {
  const std::size_t K = band.K;
  for (Channel& ch : channels) {
    const auto& gain = band.gain(ch);
    std::vector<double> ones(K + 1, 1.0), rest(K + 1, 0.0);
    ones[0] = 0;
    for (std::size_t q = 1; q <= K; ++q) rest[q] = 1 - gain[q];
    auto m_hat = band_spectrum(ch.m, ones, fft);
    const auto f0_hat = band_spectrum(ch.f0, rest, fft);
    for (std::size_t q = 0; q < m_hat.size(); ++q) m_hat[q] -= f0_hat[q];
    ch.energy = parseval_inner(m_hat, m_hat, N);
    ch.m_hat = m_hat;
    for (auto& f : ch.fit) {
      if (!f) continue;
      const auto t0 = band_spectrum(f->t[0], gain, fft), t1 = band_spectrum(f->t[1], gain, fft);
      f->g00 = parseval_inner(t0, t0, N), f->g01 = parseval_inner(t0, t1, N), f->g11 = parseval_inner(t1, t1, N);
      for (std::size_t p = 0; p < 2; ++p) {
        const auto c = correlations(m_hat, p == 0 ? t0 : t1, fft);
        f->c[0][p] = c[0];
        f->c[1][p] = c[1];
      }
    }
  }
}

/// The link a channel is fitted as: its own, or the other one when the
/// tangential channels are taken as swapped.
SensedLink fitted_link(const Channel& ch, bool swapped) {
  if (!swapped || ch.axis != SensorAxis::tangential) return ch.link;
  return ch.link == SensedLink::coupler ? SensedLink::rocker : SensedLink::coupler;
}

JointSearch joint_search(const std::vector<Channel>& channels, bool can_swap, double dir_m, std::size_t N) {
  JointSearch js;
  Best &best = js.best, &best_dir_m = js.best_dir_m, &best_offset_m = js.best_offset_m,
       &best_straight = js.best_straight, &best_crank_m = js.best_crank_m;
  for (bool swapped : {false, true}) {
    if (swapped && !can_swap) continue;
    for (std::size_t ti = 0; ti < 2; ++ti)
      for (std::size_t s = 0; s < N; ++s) {
        double score = 0;
        for (const Channel& ch : channels) score += two_term(ch, *ch.fit[link_index(fitted_link(ch, swapped))], ti, s).r2;
        const Best here{score, swapped, ti, s};
        if (score > best.score) best = here;
        if (ti == tau_index(dir_m) && score > best_dir_m.score) best_dir_m = here;
        if (s == 0 && score > best_offset_m.score) best_offset_m = here;
        if (s == 0 && ti == tau_index(dir_m) && score > best_crank_m.score) best_crank_m = here;
        if (!swapped && score > best_straight.score) best_straight = here;
      }
  }
  return js;
}

/// The crank's findings and the channels' swap, from the joint search (out's
/// crank entries already set). Direction and pulse angle are each judged
/// against the best fit that keeps the manifest's value of it. With few
/// channels the response can look nearly the same mirrored (other direction)
/// at another pulse angle; then neither alone is sure, but the manifest's
/// pair still fits far worse than the data's: one finding names both keys.
void judge_crank(const RecordingAnalysis& a, const Manifest& manifest, const SetupCheckLimits& lim,
                 const std::vector<Channel>& channels, const JointSearch& js, bool crank_judged, SetupCheck& out) {
  const std::size_t N = a.grid_points_per_rev;
  const double dir_m = manifest.crank_direction, n_ch = static_cast<double>(channels.size());
  const Best &best = js.best, &best_dir_m = js.best_dir_m, &best_offset_m = js.best_offset_m,
             &best_straight = js.best_straight, &best_crank_m = js.best_crank_m;
  const double u_best = 1 - best.score / n_ch, tau = out.crank_direction;
  const ChannelSpec& pulse = manifest.pulse_channel();
  const std::string offset_key = channel_key(pulse.name, "crank_offset_deg");
  auto direction_name = [](double d) { return std::string(d > 0 ? "\"ccw\"" : "\"cw\""); };
  auto pulse_deg = [&](const Best& b) {
    return wrap_deg(a.crank_deg[0] + 360.0 * static_cast<double>(b.s) / static_cast<double>(N));
  };
  const double offset_diff = wrap_deg(360.0 * static_cast<double>(best.s) / static_cast<double>(N));
  const bool offset_off = std::abs(offset_diff) > lim.offset_tolerance_deg;
  const double conf_crank = confidence(u_best, 1 - best_crank_m.score / n_ch);
  const double conf_dir = tau != dir_m ? confidence(u_best, 1 - best_dir_m.score / n_ch) : 0.0;
  const double conf_offset = offset_off ? confidence(u_best, 1 - best_offset_m.score / n_ch) : 0.0;
  if (crank_judged && tau != dir_m && conf_dir >= lim.min_confidence)
    add_finding(out, "crank_direction", "", "crank_direction", direction_name(dir_m), direction_name(tau), conf_dir);
  // An offset by the pulse's own width: the polarity picks the mark's other
  // edge, so every crank angle is late or early by the width.
  const double width_deg = a.acquisition.pulse_width_deg, offset_m = units::rad_to_deg(pulse.crank_offset_rad);
  const double mark_deg = std::min(width_deg, 360 - width_deg);  // the pulse's short part
  const bool by_width = std::isfinite(width_deg) && mark_deg > lim.offset_tolerance_deg &&
                        std::min(std::abs(wrap_deg(offset_diff - width_deg)), std::abs(wrap_deg(offset_diff + width_deg))) <=
                            std::max(kWidthMatchDeg, 0.1 * mark_deg);
  auto polarity = [](bool rising) { return std::string(rising ? "\"rising\"" : "\"falling\"") + " with crank_offset_deg = "; };
  const bool rising = pulse.polarity == PulsePolarity::rising;
  if (crank_judged && offset_off && conf_offset >= lim.min_confidence)
    add_finding(out, by_width ? "polarity" : "crank_offset_deg", pulse.name,
                by_width ? channel_key(pulse.name, "polarity") + " or " + offset_key : offset_key,
                (by_width ? polarity(rising) : "") + format_number(offset_m, 4),
                by_width ? polarity(!rising) + format_number(offset_m, 4) + ", or " + polarity(rising) +
                               format_number(out.crank_offset_deg, 4) + " (the angle is off by the pulse's width, " +
                               format_number(std::abs(offset_diff), 3) + "°: the edge used is the pulse's other edge)"
                         : format_number(out.crank_offset_deg, 4),
                conf_offset);
  const bool ambiguous = (tau != dir_m && conf_dir < lim.min_confidence) || (offset_off && conf_offset < lim.min_confidence);
  if (crank_judged && ambiguous && out.findings.empty() && conf_crank >= lim.min_confidence)
    add_finding(out, tau != dir_m ? "crank_direction" : "crank_offset_deg", "", "crank_direction or " + offset_key,
                direction_name(dir_m) + " with crank_offset_deg = " + format_number(units::rad_to_deg(pulse.crank_offset_rad), 4),
                direction_name(tau) + " with crank_offset_deg = " + format_number(pulse_deg(best), 4) + ", or " +
                    direction_name(dir_m) + " with crank_offset_deg = " + format_number(pulse_deg(best_dir_m), 4) +
                    " (these channels cannot tell the two apart)",
                conf_crank);
  std::string coupler_t, rocker_t;
  for (const Channel& ch : channels)
    if (ch.axis == SensorAxis::tangential) (ch.link == SensedLink::coupler ? coupler_t : rocker_t) = ch.spec->name;
  if (best.swapped) {
    const double conf = confidence(u_best, 1 - best_straight.score / n_ch);
    if (conf >= lim.min_confidence)
      add_finding(out, "channels_swapped", "", channel_key(coupler_t, "index") + " and " + channel_key(rocker_t, "index"),
                  "'" + coupler_t + "' on the coupler, '" + rocker_t + "' on the rocker",
                  "'" + coupler_t + "' reads the rocker, '" + rocker_t + "' the coupler", conf);
  }

}

/// Per channel at the joint best: sign and scale (manifest position),
/// position, the high-pass corner; then the scales across channels.
void judge_channels(const RecordingAnalysis& a, const Manifest& manifest, const SetupCheckLimits& lim,
                    const std::vector<Channel>& channels, const std::vector<CornerFit>& corners, const Best& best,
                    double crank_hz, SetupCheck& out) {
  const double dir_m = manifest.crank_direction, n_ch = static_cast<double>(channels.size());
  const double fs = a.acquisition.recording.sample_rate_hz;
  double fit_manifest = 0;
  std::vector<double> judged_scales;  // channels on their own link, within the scale tolerance
  std::vector<std::pair<const ChannelSpec*, double>> channel_scales;  // the same, by channel
  std::vector<std::pair<const ChannelSpec*, double>> all_scales;  // every channel on its own link
  for (std::size_t i = 0; i < channels.size(); ++i) {
    const Channel& ch = channels[i];
    ChannelSetupEstimate e;
    e.channel = ch.spec->name;
    e.role = ch.spec->role;
    const SensedLink l = fitted_link(ch, best.swapped);
    e.fitted_as = std::string(to_string(l)) + "_" + to_string(ch.axis);
    const Channel::Fit& f = *ch.fit[link_index(l)];
    const Channel::Fit& fm = *ch.fit[link_index(ch.link)];
    const double ch_fit_manifest = std::max(0.0, one_term_r2(ch, fm, tau_index(dir_m), 0, ch.r_m, 1.0));
    fit_manifest += ch_fit_manifest / n_ch;
    e.fit_manifest = ch_fit_manifest;
    const OneTerm one = one_term(ch, f, best.ti, best.s, ch.r_m);
    const TwoTerm two = two_term(ch, f, best.ti, best.s);
    e.scale = one.k;
    e.fit = two.r2;
    // The position is B/A: it is known only when the f0 term (the part of it
    // f1 does not explain) carries a share of the reading well above the floor.
    const double f0_alone = f.g11 > 0 ? (f.g00 - f.g01 * f.g01 / f.g11) * two.a * two.a : 0.0;
    e.position_mm = ch.energy > 0 && f0_alone >= kPositionShare * ch.energy ? units::m_to_mm(two.b / two.a)
                                                                           : std::numeric_limits<double>::quiet_NaN();
    e.position_confidence = confidence(1 - two.r2, 1 - one.r2);
    const std::string& name = ch.spec->name;
    if (l == ch.link && one.r2 >= lim.min_fit) {
      if (one.k < 0)
        add_finding(out, "axis_sign", name, channel_key(name, "axis_sign"), ch.spec->axis_sign > 0 ? "+1" : "-1",
                    ch.spec->axis_sign > 0 ? "-1" : "+1", confidence(1 - one.r2, 1.0));
      const double ratio = std::abs(one.k);
      all_scales.emplace_back(ch.spec, ratio);
      if (!(ratio > lim.scale_tolerance || ratio < 1 / lim.scale_tolerance))
        judged_scales.push_back(ratio), channel_scales.emplace_back(ch.spec, ratio);
      if (ratio > lim.scale_tolerance || ratio < 1 / lim.scale_tolerance) {
        const double sign = one.k < 0 ? -1.0 : 1.0;
        const double conf = confidence(1 - one.r2, 1 - one_term_r2(ch, f, best.ti, best.s, ch.r_m, sign));
        if (conf >= lim.min_confidence) add_calibration_finding(out, *ch.spec, ratio, conf);
      }
    }
    // The sensor's high-pass corner: when another corner explains the reading
    // better than the data's position does, the corner is the mistake.
    const CornerFit& corner = corners[i];
    const double corner_conf = confidence(corner.unexplained, corner.unexplained_manifest);
    const bool corner_off = l == ch.link && corner_conf >= lim.min_confidence && 1 - corner.unexplained >= lim.min_fit &&
                            corner.unexplained < 1 - two.r2;
    if (corner_off) add_corner_finding(out, *ch.spec, corner.corner_hz, crank_hz, corner_conf);
    if (!corner_off && l == ch.link && two.r2 >= lim.min_fit && std::isfinite(e.position_mm) &&
        std::abs(e.position_mm - units::m_to_mm(ch.r_m)) > lim.position_tolerance_mm &&
        e.position_confidence >= lim.min_confidence)
      add_finding(out, "position_mm", name, channel_key(name, "position_mm"), format_number(units::m_to_mm(ch.r_m), 4),
                  format_number(e.position_mm, 3), e.position_confidence);
    out.channels.push_back(std::move(e));
  }
  out.fit_manifest = fit_manifest;
  if (!best.swapped)
    add_common_scale_finding(out, judged_scales, lim.common_scale_tolerance, manifest.rig_file.string(), fs,
                             lim.min_confidence);
  if (!best.swapped) add_channel_scale_findings(out, channel_scales, lim.channel_scale_tolerance);
  if (!best.swapped)
    add_rig_file_finding(out, all_scales, lim.channel_scale_tolerance, manifest.rig_file.string(),
                         manifest.rig ? manifest.rig->name : std::string());
}

}  // namespace

SetupCheck check_setup(const RecordingAnalysis& a, const Manifest& manifest, const SetupCheckLimits& lim) {
  SetupCheck out;
  if (a.options.conversion != ConversionMethod::full) {
    out.not_checked = "the thesis conversion leaves out terms the check needs (run without --thesis)";
    return out;
  }
  const std::size_t N = a.grid_points_per_rev;
  if (!a.rig || N < 8 || a.crank_deg.size() != N || a.crank_speed_rad_s.mean.size() != N) {
    out.not_checked = "no averaged revolutions";
    return out;
  }
  const double dir_m = manifest.crank_direction;
  const double theta0 = units::deg_to_rad(a.crank_deg[0]);
  double w_mean = 0;
  for (double w : a.crank_speed_rad_s.mean) w_mean += std::abs(w) / static_cast<double>(N);
  std::vector<Channel> channels = recover_channels(a, manifest, grid_crank(a, dir_m), out);
  if (channels.empty()) {
    out.not_checked = "no analysed accelerometer channel";
    return out;
  }

  RealFft fft(N);
  FitBand band;
  band.K = add_templates(*a.rig, channels, w_mean, theta0, N, fft);
  const std::size_t K = band.K;
  const double fs = a.acquisition.recording.sample_rate_hz, crank_hz = w_mean / units::kTwoPi;
  band.alpha_gain = order_gains(a.filter, a.spectra.filter_gain, a.spectra.segment_length, fs, crank_hz, K);
  band.normal_gain = order_gains(a.normal_filter, {}, 0, fs, crank_hz, K);
  std::erase_if(channels, [&](const Channel& ch) {
    const auto& g = band.gain(ch);
    return std::count_if(g.begin(), g.end(), [](double v) { return v >= kMinOrderGain; }) < 2;
  });
  if (channels.empty()) {
    out.not_checked = "the analysis filter passes fewer than 2 of the crank orders 1-" + std::to_string(K) +
                      " that hold the nominal response";
    return out;
  }
  correlate(channels, band, N, fft);
  out.band_orders = K;
  const bool can_swap = std::count_if(channels.begin(), channels.end(),
                                      [](const Channel& ch) { return ch.axis == SensorAxis::tangential; }) == 2;
  const JointSearch js = joint_search(channels, can_swap, dir_m, N);
  const Best& best = js.best;
  const double n_ch = static_cast<double>(channels.size());
  // Each sensor's high-pass corner at the manifest's crank. A wrong corner
  // shifts the first orders' phase, which one channel's best pulse angle can
  // partly absorb: when the corners explain the readings at the manifest's
  // crank as well as the data's crank does, the crank is not judged.
  std::vector<CornerFit> corners;
  double corner_score = 0;
  for (const Channel& ch : channels) {
    const Channel::Fit& fm = *ch.fit[link_index(ch.link)];
    corners.push_back(corner_fit(ch, fm, tau_index(dir_m), 0, band.gain(ch), crank_hz, fs, fft));
    corner_score += std::max(two_term(ch, fm, tau_index(dir_m), 0).r2, 1 - corners.back().unexplained);
  }
  const bool crank_judged = corner_score < best.score;
  out.checked = true;
  out.crank_direction = best.ti == 0 ? 1.0 : -1.0;
  out.crank_offset_deg = wrap_deg(a.crank_deg[0] + 360.0 * static_cast<double>(best.s) / static_cast<double>(N));
  out.swapped = best.swapped;
  out.fit = best.score / n_ch;
  judge_crank(a, manifest, lim, channels, js, crank_judged, out);
  judge_channels(a, manifest, lim, channels, corners, best, crank_hz, out);
  return out;
}

}  // namespace fourbar

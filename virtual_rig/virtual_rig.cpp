#include "virtual_rig/virtual_rig.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <random>

#include "acquire/manifest.hpp"
#include "common/progress.hpp"
#include "common/atomic_output.hpp"
#include "common/csv_writer.hpp"
#include "common/error.hpp"
#include "common/angle_unwrap.hpp"
#include "common/units.hpp"
#include "common/version.hpp"
#include "virtual_rig/clearance_motion_source.hpp"
#include "virtual_rig/link_ringing.hpp"
#include "virtual_rig/linkage_motion_source.hpp"
#include "virtual_rig/recording_writer.hpp"
#include "virtual_rig/analog_filter_sim.hpp"
#include "virtual_rig/sensor_signal.hpp"
#include "virtual_rig/wheel_signal.hpp"

namespace fourbar {

namespace {

/// First-order high-pass H(s) = s/(s + ωc) by the bilinear transform.
class HighPass {
 public:
  HighPass(double corner_hz, double sample_rate_hz) {
    const double k = 2.0 * sample_rate_hz, wc = units::kTwoPi * corner_hz;
    b_ = k / (k + wc);
    a_ = (k - wc) / (k + wc);
  }
  double operator()(double x) {
    const double y = b_ * (x - x_prev_) + a_ * y_prev_;
    x_prev_ = x, y_prev_ = y;
    return y;
  }
  void prime(double x) { x_prev_ = x, y_prev_ = 0; }

 private:
  double b_ = 1, a_ = 0, x_prev_ = 0, y_prev_ = 0;
};

/// The pulse channel's shape in [0, 1] from a sorted list of edges.
class PulseShape {
 public:
  struct Pulse {
    double lead_s, trail_s;
  };
  PulseShape(std::vector<Pulse> pulses, double rise_s) : pulses_(std::move(pulses)), rise_(rise_s) {
    std::sort(pulses_.begin(), pulses_.end(), [](const Pulse& a, const Pulse& b) { return a.lead_s < b.lead_s; });
  }
  /// Times must come in increasing order.
  double operator()(double t) {
    while (first_ < pulses_.size() && pulses_[first_].trail_s + rise_ < t) ++first_;
    double s = 0;
    for (std::size_t k = first_; k < pulses_.size() && pulses_[k].lead_s - rise_ <= t; ++k)
      s += ramp(t - pulses_[k].lead_s) - ramp(t - pulses_[k].trail_s);
    return std::clamp(s, 0.0, 1.0);
  }

 private:
  double ramp(double dt) const { return rise_ > 0 ? std::clamp(dt / rise_ + 0.5, 0.0, 1.0) : (dt >= 0 ? 1.0 : 0.0); }
  std::vector<Pulse> pulses_;
  double rise_;
  std::size_t first_ = 0;
};

/// The recording, its manifest and its truth must not land on a file the run
/// reads (the scene, the rig): `--out S.flac` beside the scene `S.toml` would
/// write the manifest S.toml over the scene.
void refuse_overwriting_inputs(const std::filesystem::path& out, bool write_truth, const Provenance& provenance) {
  std::vector<std::filesystem::path> outputs{out, sidecar_manifest_path(out)};
  if (write_truth) outputs.push_back(truth_path(out));
  for (const auto& o : outputs)
    for (const auto& in : provenance.inputs) {
      std::error_code ec;
      if (std::filesystem::exists(o, ec) && std::filesystem::equivalent(o, in, ec))
        throw InputError("virtual-rig: writing " + out.string() + " would overwrite the input " + in.string() +
                         (o == out ? "" : " (with the recording's " + std::string(o == sidecar_manifest_path(out) ? "manifest" : "truth") + ")") +
                         "; give the recording another name or folder, e.g. --out " +
                         (out.parent_path() / (out.stem().string() + "_rec" + out.extension().string())).string());
    }
}

}  // namespace

std::filesystem::path truth_path(const std::filesystem::path& recording) {
  return recording.parent_path() / (recording.stem().string() + ".truth.csv");
}

CrankDrive crank_drive(const Scene& scene, const RecordingSpec& spec) {
  CrankDrive d;
  d.start_angle_rad = scene.start_angle_rad;
  d.mean_speed_rad_s = scene.crank_speed_rad_s;
  d.fluctuation = spec.speed_fluctuation;
  d.harmonics = spec.speed_harmonics;
  d.fluctuation_period_s =
      spec.speed_fluctuation_period_s.value_or(10.0 * units::kTwoPi / std::abs(scene.crank_speed_rad_s));
  return d;
}

VirtualRigResult make_virtual_recording(const Scene& scene, const RecordingSpec& spec, const CrankDrive& drive,
                                        const MotionSource& motion, const std::filesystem::path& out,
                                        const Provenance& provenance, const VirtualRigOptions& options) {
  refuse_overwriting_inputs(out, options.write_truth, provenance);
  const Rig& rig = *scene.rig;
  const double fs = spec.sample_rate_hz;
  const double w0 = std::abs(drive.mean_speed_rad_s), direction = drive.mean_speed_rad_s > 0 ? 1.0 : -1.0;
  const double mean_period = units::kTwoPi / w0;
  const double duration = spec.duration_s ? *spec.duration_s : *spec.revolutions * mean_period;
  const auto frames = static_cast<std::uint64_t>(std::llround(duration * fs));
  if (frames < 2) throw InputError(scene.source.string() + ": [recording] gives fewer than two samples");
  if (!is_text_recording(out) && std::abs(fs - std::round(fs)) > 1e-9)
    throw InputError(scene.source.string() + ": key 'recording.sample_rate_hz' = " + format_double(fs) +
                     ": audio files store whole-number rates; round it or write a .csv");
  const std::size_t nsens = spec.sensors.size();
  std::mt19937_64 rng(spec.seed);
  std::normal_distribution<double> normal(0.0, 1.0);

  // Pulses: leading edge where θ2 passes angle_deg, trailing edge width_deg later.
  const PulseSpec& ps = spec.pulse;
  const double base = std::fmod(std::fmod(direction * (ps.angle_rad - drive.start_angle_rad), units::kTwoPi) +
                                    units::kTwoPi, units::kTwoPi);
  std::vector<PulseShape::Pulse> shape_pulses;
  VirtualRigResult result;
  for (long long k = -1;; ++k) {
    const double phi = base + units::kTwoPi * static_cast<double>(k);
    const double jitter = ps.jitter_s > 0 ? ps.jitter_s * normal(rng) : 0.0;
    const double lead = drive.time_at_turned(direction * phi) + jitter;
    const double trail = drive.time_at_turned(direction * (phi + ps.width_rad)) + jitter;
    if (lead - ps.rise_s > duration) break;
    if (k >= 0 && std::find(ps.missing.begin(), ps.missing.end(), k) != ps.missing.end()) continue;
    shape_pulses.push_back({lead, trail});
    if (lead >= 0 && lead < duration) result.pulse_times_s.push_back(lead);
    if (k >= 0 && std::find(ps.echo.begin(), ps.echo.end(), k) != ps.echo.end())
      shape_pulses.push_back({lead + ps.echo_delay_s, trail + ps.echo_delay_s});
  }
  // A tooth wheel or an encoder in place of the once-per-turn pulse, and its
  // further channels (encoder B, index) after it.
  std::vector<EdgeChannel> wheel;
  std::vector<PulseShape> extra;
  if (spec.wheel.active()) {
    wheel = wheel_channels(spec.wheel, drive, ps.angle_rad, duration, ps.rise_s, ps.name, spec.seed);
    auto shaped = [](const EdgeChannel& c) {
      std::vector<PulseShape::Pulse> p;
      for (const auto& [lead, trail] : c.pulses) p.push_back({lead, trail});
      return p;
    };
    shape_pulses = shaped(wheel[0]);
    for (std::size_t k = 1; k < wheel.size(); ++k) extra.emplace_back(shaped(wheel[k]), ps.rise_s);
  }
  PulseShape shape(shape_pulses, ps.rise_s);
  const std::size_t nch = nsens + 1 + extra.size();
  const double idle = ps.polarity == PulsePolarity::rising ? ps.low_V : ps.high_V;
  const double swing = ps.polarity == PulsePolarity::rising ? ps.high_V - ps.low_V : ps.low_V - ps.high_V;

  // Mains hum phases, then the noise level of each sensor from its clean
  // signal over one mean revolution.
  std::vector<double> hum_phase;
  for (std::size_t h = 0; h < spec.hum_harmonics.size(); ++h)
    hum_phase.push_back(units::kTwoPi * std::uniform_real_distribution<double>(0, 1)(rng));
  result.noise_V.assign(nsens, 0.0);
  if (spec.noise_snr_db) {
    constexpr int kPoints = 1024;
    for (std::size_t c = 0; c < nsens; ++c) {
      double sum = 0, sum_sq = 0;
      for (int i = 0; i < kPoints; ++i) {
        const double v = spec.sensors[c].volts_per_m_s2 *
                         specific_force(rig, motion.at(mean_period * i / kPoints), spec.sensors[c].role,
                                        spec.sensors[c].position_m, spec.sensors[c].offset_m);
        sum += v, sum_sq += v * v;
      }
      const double rms_ac = std::sqrt(std::max(0.0, sum_sq / kPoints - (sum / kPoints) * (sum / kPoints)));
      result.noise_V[c] = rms_ac / std::pow(10.0, *spec.noise_snr_db / 20.0);
    }
  }

  // The links' ringing, driven by the clearance motion's bearing impulses.
  std::optional<LinkRinging> ringing;
  if (!spec.link_modes.empty()) {
    const auto* clearance = dynamic_cast<const ClearanceMotionSource*>(&motion);
    if (!clearance)
      throw InputError(scene.source.string() + ": [[recording.link_mode]] needs the clearance model's motion "
                       "(model = \"clearance\"): the bearing impacts ring the links");
    ringing.emplace(spec.link_modes, bearing_impulses(clearance->impacts()));
  }
  // The linkage model reads its tangential sensors itself (rigid frame plus
  // the elastic links' deflection): what it adds to the rigid formula from
  // the frames' motion is its links' vibration.
  const auto* linkage = dynamic_cast<const LinkageMotionSource*>(&motion);
  const bool vibration = ringing || (linkage && linkage->elastic());
  // At any time, in any order: a skewed channel and an analog filter's sub-steps ask out of order.
  // Channel c's specific force at t from the links' state `st` there: the rigid part and the links' vibration.
  struct Force {
    double rigid = 0, vibration = 0;
  };
  auto force_parts = [&](std::size_t c, double t, const LinkState& st) {
    const ChannelSpec& s = spec.sensors[c];
    Force f{specific_force(rig, st, s.role, s.position_m, s.offset_m), 0.0};
    if (linkage && linkage->reads(c)) f.vibration = linkage->reading(c, t) - f.rigid;
    else if (ringing) f.vibration = ringing->sensor_acceleration_at(t, s.role);
    return f;
  };
  std::vector<double> rigid_sum(nsens, 0.0), rigid_sq(nsens, 0.0), ring_sq(nsens, 0.0);

  // Each sensor channel's chain: the specific force at its sample time (a
  // multiplexed ADC's skew, a linear-phase filter's delay), the mounted
  // resonance and a Butterworth anti-alias filter (analog_filter_sim.hpp),
  // then the AC coupling's high-pass; all run in from before t = 0.
  const double skew_s = spec.multiplexed ? spec.skew_s.value_or(1.0 / (fs * static_cast<double>(nch))) : 0.0;
  if (skew_s * static_cast<double>(nch - 1) >= 1.0 / fs)
    throw InputError(scene.source.string() + ": key 'recording.skew_us' = " + format_double(skew_s * 1e6) +
                     ": a scan of " + std::to_string(nch) + " channels must end within the sample period " +
                     format_double(1e6 / fs) + " us; give at most " + format_double(1e6 / (fs * static_cast<double>(nch))) +
                     " (the default)");
  std::vector<double> sample_offset_s(nsens);
  std::vector<AnalogFilterSim> analog;
  std::vector<std::optional<HighPass>> hp(nsens);
  double warmup_s = 0;
  for (std::size_t c = 0; c < nsens; ++c) {
    const ChannelSpec& s = spec.sensors[c];
    sample_offset_s[c] = skew_s * static_cast<double>(c) - spec.daq_filter.delay_s;
    std::vector<AnalogSection> sections = daq_filter_sections(spec.daq_filter);
    if (s.sensor_resonance_hz > 0) sections.push_back({2, s.sensor_resonance_hz, s.sensor_resonance_q});
    for (const AnalogSection& a : sections)  // twelve decay times of each section
      warmup_s = std::max(warmup_s, 12.0 * (a.order == 2 ? 2.0 * a.q : 1.0) / (units::kTwoPi * a.f0_hz));
    analog.emplace_back(std::move(sections), fs);
    if (s.ac_coupled) {
      hp[c].emplace(s.highpass_hz, fs);
      warmup_s = std::max(warmup_s, 12.0 / (units::kTwoPi * s.highpass_hz));
    }
  }
  const auto parts_at = [&](std::size_t c, double t, const LinkState* st) {
    const double ts = t + sample_offset_s[c];
    return force_parts(c, ts, sample_offset_s[c] != 0 || !st ? motion.at(ts) : *st);
  };
  const auto force_at = [&](std::size_t c, double t, const LinkState* st) {
    const Force f = parts_at(c, t, st);
    return f.rigid + f.vibration;
  };
  if (warmup_s > 0) {
    const auto warm = static_cast<std::int64_t>(std::ceil(warmup_s * fs));
    for (std::int64_t i = -warm; i < 0; ++i) {
      const double t = static_cast<double>(i) / fs;
      const LinkState st = motion.at(t);
      for (std::size_t c = 0; c < nsens; ++c) {
        if (!hp[c] && analog[c].empty()) continue;
        double f = force_at(c, t, &st);
        if (i == -warm) analog[c].prime(f);
        if (!analog[c].empty()) f = analog[c].step(t - 1.0 / fs, [&](double tau) { return force_at(c, tau, nullptr); });
        if (!hp[c]) continue;
        if (i == -warm) hp[c]->prime(f);
        (*hp[c])(f);
      }
    }
  }

  // Writers.
  std::vector<std::string> names;
  for (const auto& s : spec.sensors) names.push_back(s.name);
  names.push_back(ps.name);
  for (std::size_t k = 1; k < wheel.size(); ++k) names.push_back(wheel[k].name);
  // The recording names what made it, but not where it was written to, so
  // that the same scene and seed give the same bytes anywhere.
  std::vector<std::string> made_by{std::string("made by fourbar ") + kVersion + " virtual-rig"};
  nlohmann::json made_by_json = {{"tool", "fourbar"}, {"version", kVersion}, {"command", "virtual-rig"},
                                 {"inputs", nlohmann::json::array()}, {"seed", spec.seed}};
  for (const auto& p : provenance.inputs) {
    made_by.push_back("input: " + p.filename().string());
    made_by_json["inputs"].push_back(p.filename().string());
  }
  made_by.push_back("seed: " + std::to_string(spec.seed));
  const bool text_out = is_text_recording(out);
  auto writer = open_recording_writer(out, static_cast<int>(nch), fs, names, spec.sample_format.value_or(""),
                                      text_out && !options.csv_comments ? std::vector<std::string>{} : made_by);
  if (text_out) writer->describe_in_sidecar(std::move(made_by_json));
  const int bits = writer->integer_bits();
  const double to_recorded = bits > 0 ? 1.0 / spec.full_scale_V : 1.0;  // integer: ±1 full scale; else volts
  std::unique_ptr<CsvWriter> truth;
  result.truth = truth_path(out);
  if (options.write_truth) {
    std::vector<std::string> cols{"crank_deg",    "time_s",        "theta2_rad",    "omega2_rad_s",
                                  "alpha2_rad_s2", "theta3_rad",    "omega3_rad_s", "alpha3_rad_s2",
                                  "theta4_rad",   "omega4_rad_s",  "alpha4_rad_s2"};
    for (std::size_t c = 0; c < nsens; ++c) {
      cols.push_back(spec.sensors[c].name + "_m_s2");
      if (hp[c]) cols.push_back(spec.sensors[c].name + "_hp_m_s2");
    }
    truth = std::make_unique<CsvWriter>(result.truth, options.csv_comments ? provenance.comment_lines()
                                                                           : std::vector<std::string>{}, cols);
    truth->describe_in_sidecar(provenance.to_json());
  }

  // Samples, block by block.
  constexpr std::size_t kBlock = 4096;
  std::vector<double> block;
  std::vector<double> row;
  double theta3_prev = 0, theta4_prev = 0;
  const double q_step = spec.quantisation_bits && bits == 0 ? std::ldexp(spec.full_scale_V, 1 - *spec.quantisation_bits) : 0;
  Progress progress("virtual-rig", frames, options.progress);
  for (std::uint64_t first = 0; first < frames; first += kBlock) {
    const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(kBlock, frames - first));
    block.assign(n * nch, 0.0);
    for (std::size_t f = 0; f < n; ++f) {
      const double t = static_cast<double>(first + f) / fs;
      const LinkState st = motion.at(t);
      double hum = 0;
      for (std::size_t h = 0; h < spec.hum_harmonics.size(); ++h)
        hum += spec.hum_V * spec.hum_harmonics[h] *
               std::sin(units::kTwoPi * spec.hum_frequency_hz * static_cast<double>(h + 1) * t + hum_phase[h]);
      if (truth) {
        double th3 = st.theta3_rad, th4 = st.theta4_rad;
        if (first + f > 0) th3 = units::unwrap_rad(th3, theta3_prev), th4 = units::unwrap_rad(th4, theta4_prev);
        theta3_prev = th3, theta4_prev = th4;
        row = {units::rad_to_deg(st.crank.angle_rad), t, st.crank.angle_rad, st.crank.speed_rad_s,
               st.crank.accel_rad_s2, th3, st.omega3_rad_s, st.alpha3_rad_s2, th4, st.omega4_rad_s, st.alpha4_rad_s2};
      }
      for (std::size_t c = 0; c < nsens; ++c) {
        const ChannelSpec& s = spec.sensors[c];
        const Force parts = parts_at(c, t, &st);
        const double force = parts.rigid + parts.vibration, ringing_now = parts.vibration, rigid = parts.rigid;
        rigid_sum[c] += rigid, rigid_sq[c] += rigid * rigid, ring_sq[c] += ringing_now * ringing_now;
        const double analog_out =
            analog[c].empty() ? force : analog[c].step(t - 1.0 / fs, [&](double tau) { return force_at(c, tau, nullptr); });
        const double sensed = hp[c] ? (*hp[c])(analog_out) : analog_out;
        if (truth) {
          row.push_back(force);
          if (hp[c]) row.push_back(sensed);
        }
        double v = s.axis_sign * sensed * s.volts_per_m_s2 + hum;
        if (result.noise_V[c] > 0) v += result.noise_V[c] * normal(rng);
        if (std::abs(v) >= spec.full_scale_V) ++result.clipped_samples;
        v = std::clamp(v, -spec.full_scale_V, spec.full_scale_V);
        if (q_step > 0) v = std::clamp(std::nearbyint(v / q_step) * q_step, -spec.full_scale_V, spec.full_scale_V - q_step);
        block[f * nch + c] = v * to_recorded;
      }
      double pv = idle + swing * shape(t + skew_s * static_cast<double>(nsens));
      if (ps.noise_V > 0) pv += ps.noise_V * normal(rng);
      pv = std::clamp(pv, -spec.full_scale_V, spec.full_scale_V);
      block[f * nch + nsens] = pv * to_recorded;
      for (std::size_t k = 0; k < extra.size(); ++k) {
        double ev = idle + swing * extra[k](t + skew_s * static_cast<double>(nsens + 1 + k));
        if (ps.noise_V > 0) ev += ps.noise_V * normal(rng);
        block[f * nch + nsens + 1 + k] = std::clamp(ev, -spec.full_scale_V, spec.full_scale_V) * to_recorded;
      }
      if (truth) truth->row(row);
    }
    writer->write(block);
    progress.update(first + n);
  }
  progress.finish();

  // The manifest that goes with it.
  Manifest m;
  m.rig_file = rig.source;
  m.clearance_m = scene.clearance_m();
  if (scene.model == Model::linkage) {  // the coupler–rocker joint's, else the largest
    const auto& xi = scene.linkage.spec.clearance_m;
    m.clearance_m = xi[1] > 0 ? xi[1] : *std::max_element(xi.begin(), xi.end());
  }
  m.full_scale_V = bits > 0 ? spec.full_scale_V : 1.0;
  if (bits == 0) m.adc_range_V = spec.full_scale_V;
  m.crank_direction = direction;
  m.channel_skew_s = skew_s;
  m.daq_filter = spec.daq_filter;
  m.notes = "written by fourbar virtual-rig from " + scene.source.string() +
            (scene.model == Model::clearance
                 ? "; motion: clearance model, e = " + format_double(scene.clearance.restitution) + ", contact " +
                       to_string(scene.clearance.contact)
             : scene.model == Model::linkage
                 ? "; motion: linkage model, e = " + format_double(scene.linkage.spec.law.restitution) +
                       (linkage && linkage->elastic() ? ", elastic links" : ", rigid links")
                 : std::string("; motion: nominal mechanism")) +
            (spec.notes.empty() ? "" : "; " + spec.notes);
  const bool text = is_text_recording(out);
  for (std::size_t c = 0; c < nsens; ++c) {
    ChannelSpec s = spec.sensors[c];
    if (text) s.column = s.name, s.index.reset();
    else s.index = static_cast<int>(c);
    m.channels.push_back(s);
  }
  ChannelSpec pc;
  pc.name = ps.name;
  pc.role = ChannelRole::crank_pulse;
  pc.crank_offset_rad = ps.angle_rad;
  for (std::size_t k = 0; k < std::max<std::size_t>(wheel.size(), 1); ++k) {
    if (!wheel.empty()) pc = wheel_manifest_channel(spec.wheel, wheel[k], ps.angle_rad);
    if (text) pc.column = pc.name;
    else pc.index = static_cast<int>(nsens + k);
    pc.polarity = ps.polarity;
    m.channels.push_back(pc);
  }
  result.manifest = sidecar_manifest_path(out);
  const std::string manifest_text = manifest_to_toml(m, std::filesystem::absolute(out).parent_path());

  // Everything complete: move it into place together.
  writer->commit();
  if (truth) truth->commit();
  write_text_file(result.manifest, manifest_text);
  result.recording = out;
  result.frames = frames;
  result.channels = static_cast<int>(nch);
  result.sample_rate_hz = fs;
  if (vibration)
    for (std::size_t c = 0; c < nsens; ++c) {
      const double nf = static_cast<double>(frames), mean = rigid_sum[c] / nf;
      const double rigid_rms = std::sqrt(std::max(0.0, rigid_sq[c] / nf - mean * mean));
      result.ringing_rms_share.push_back(rigid_rms > 0 ? std::sqrt(ring_sq[c] / nf) / rigid_rms : 0.0);
    }
  return result;
}

}  // namespace fourbar

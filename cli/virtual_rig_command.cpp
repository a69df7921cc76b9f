// `fourbar virtual-rig SCENE.toml --out REC.wav`: the recording (plus its
// manifest and the truth) that the rig's sensors would produce for a scene.

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

#include "cli/command.hpp"
#include "common/atomic_output.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/provenance.hpp"
#include "common/units.hpp"
#include "virtual_rig/clearance_motion_source.hpp"
#include "virtual_rig/linkage_motion_source.hpp"
#include "virtual_rig/virtual_rig.hpp"

namespace po = boost::program_options;

namespace fourbar::cli {

namespace {

constexpr const char* kVirtualRigDetails = R"(Writes REC (format by extension: .wav .w64 .rf64 .flac .caf .aiff .aif .csv),
REC's manifest (same name, .toml) and REC's truth (<stem>.truth.csv: crank_deg,
time_s, theta2..alpha4 and each sensor's true specific force <name>_m_s2, plus
<name>_hp_m_s2 after the high-pass of an AC-coupled sensor), from the scene's
motion at its crank_speed_rpm and start_angle_deg: the nominal mechanism
(model = "nominal"), the clearance model (model = "clearance", with the
scene's [clearance] table) or the linkage model (model = "linkage", with its
[linkage] table: rigid or elastic links, whose vibration the tangential
sensors then read), started warmup_revolutions turns before the recording;
the manifest then carries the scene's clearance (the coupler-rocker joint's
for a linkage). Each CSV
written (the truth, a .csv recording) has its provenance in NAME.csv.json
beside it.

The scene's [recording] table (docs/virtual-rig.md lists every key):
  sample_rate_hz, duration_s | revolutions, sample_format (pcm16 pcm24 pcm32
  float double), full_scale_V, quantisation_bits, noise_snr_db,
  hum_frequency_hz, hum_mV, hum_harmonics, speed_fluctuation_pct,
  speed_fluctuation_period_s, sampling (simultaneous|multiplexed) + skew_us,
  daq_filter (none|butterworth|linear_phase) + daq_filter_order +
  daq_filter_cutoff_Hz | daq_filter_delay_us, seed, notes,
  warmup_revolutions (clearance and linkage scenes, default 20);
  [recording.pulse] name, angle_deg, low_V, high_V, polarity, width_deg,
  rise_us, jitter_us, noise_mV, missing, echo, echo_delay_ms;
  [[recording.sensor]] name, role, position_mm, offset_mm, axis_sign,
  sensitivity_mV_per_m_s2 + gain | volts_per_unit, ac_coupled, highpass_hz,
  sensor_resonance_Hz + sensor_resonance_Q.
)";

}  // namespace

int run_virtual_rig(const Invocation& inv) {
  std::string scene_file, out;
  bool no_truth = false, csv_comments = false, quiet = false;
  po::options_description opts("options");
  opts.add_options()("scene", po::value(&scene_file)->required(), "scene file (TOML) with a [recording] table")(
      "out,o", po::value(&out)->required(), "recording to write (REC.wav, REC.flac, REC.csv, ...)")(
      "no-truth", po::bool_switch(&no_truth), "do not write REC.truth.csv (long recordings)");
  add_csv_comments_option(opts, csv_comments);
  add_quiet_option(opts, quiet);
  po::positional_options_description pos;
  pos.add("scene", 1);
  po::variables_map vm;
  if (!parse_arguments("virtual-rig", "SCENE.toml --out REC.wav [--no-truth] [-q]", kVirtualRigDetails, opts, pos, inv, vm)) return 0;

  const Scene scene = load_scene(scene_file);
  const RecordingSpec spec = read_recording_spec(scene);
  const std::filesystem::path out_path(out);
  if (out_path.has_parent_path()) ensure_output_dir(out_path.parent_path());
  const CrankDrive drive = crank_drive(scene, spec);
  std::unique_ptr<MotionSource> motion;
  if (scene.model == Model::clearance || scene.model == Model::linkage) {
    // Simulated from warmup_revolutions turns before the earliest time the rig
    // asks for (the AC filters' run-in), to past the end.
    const double run_in_s = recording_run_in_s(spec);
    const double period_s = units::kTwoPi / std::abs(drive.mean_speed_rad_s);
    const double duration_s = spec.duration_s ? *spec.duration_s : *spec.revolutions * period_s;
    if (scene.model == Model::clearance)
      motion = std::make_unique<ClearanceMotionSource>(scene.rig, drive, scene.clearance, scene.clearance_m(),
                                                       -run_in_s - (spec.warmup_revolutions + 1) * period_s,
                                                       duration_s + period_s, 1.0 / spec.sample_rate_hz);
    else
      motion = std::make_unique<LinkageMotionSource>(scene, drive, spec.sensors,
                                                     -run_in_s - (spec.warmup_revolutions + 1) * period_s,
                                                     -run_in_s - period_s, duration_s + period_s, 1.0 / spec.sample_rate_hz);
  } else {
    motion = std::make_unique<NominalMotionSource>(scene.rig, drive);
  }
  VirtualRigOptions options;
  options.progress = !quiet;
  options.write_truth = !no_truth;
  options.csv_comments = csv_comments;
  const VirtualRigResult r =
      make_virtual_recording(scene, spec, drive, *motion, out_path, Provenance{inv.command_line, {scene.source, scene.rig->source}}, options);
  std::cout << "wrote " << r.recording.string() << " (" << r.frames << " frames x " << r.channels << " channels at "
            << r.sample_rate_hz << " Hz, " << r.pulse_times_s.size() << " crank pulses), " << r.manifest.string();
  if (options.write_truth) std::cout << " and " << r.truth.string();
  std::cout << "\n";
  for (std::size_t c = 0; c < r.ringing_rms_share.size(); ++c)
    std::cout << "link ringing on " << spec.sensors[c].name << ": " << format_number(100 * r.ringing_rms_share[c], 3)
              << " % of the rigid signal's RMS" << (scene.model == Model::linkage ? " (the linkage model's elastic links)\n" : "\n");
  if (r.clipped_samples > 0)
    std::cerr << "fourbar: warning: " << r.clipped_samples << " accelerometer samples clipped at +-"
              << spec.full_scale_V << " V (lower the gain or raise full_scale_V)\n";
  return 0;
}

}  // namespace fourbar::cli

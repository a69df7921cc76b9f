#pragma once
// The manifest: a TOML sidecar that says what each channel of a recording is
// and how to turn its numbers into physical units (docs/acquire.md "Recordings and
// manifests" lists every key). `REC.toml` beside `REC.wav`, or any file given
// with --manifest. Strict: an unknown or misspelt key is an error with a
// suggestion; a channel index or column that the recording lacks is an error
// naming the channel.
//
// Sensor frame (per accelerometer channel, on the coupler or the rocker):
//   position   P = J + position·u + offset·n, where J is the link's first
//              joint (coupler: crank pin A; rocker: rocker pivot O4), u the
//              unit vector along the link towards its other joint, and
//              n = u turned +90° (counter-clockwise);
//   tangential axis = +n, normal axis = +u (pointing away from J);
//   axis_sign = −1 when the sensor is mounted the other way round.
// Calibrated value (m/s²) = axis_sign · volts / volts_per_m_s2, with
// volts = recorded value · full_scale_V. An accelerometer measures specific
// force a − g (g = (0, −gravity) in the rig frame), so the calibrated value
// still contains the gravity projection; analyze removes it.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "acquire/analog_response.hpp"
#include "acquire/reader.hpp"
#include "mechanism/rig.hpp"

namespace fourbar {

enum class ChannelRole {
  coupler_tangential,
  coupler_normal,
  rocker_tangential,
  rocker_normal,
  crank_pulse,
  crank_index,  ///< once-per-turn mark beside a tooth wheel or an encoder (Z)
  encoder_a,    ///< quadrature encoder, channel A
  encoder_b,    ///< quadrature encoder, channel B
  crank_speed,  ///< a processed speed track (rpm), integrated to the crank angle (acquire/speed_angle.hpp)
  ignore
};

const char* to_string(ChannelRole role);
/// Every role name, for messages and --help.
std::vector<std::string> channel_role_names();
/// True for the four accelerometer roles.
bool is_accelerometer(ChannelRole role);
/// True for coupler_* roles (the sensor rides on the coupler).
bool is_on_coupler(ChannelRole role);
/// True for *_tangential roles.
bool is_tangential(ChannelRole role);
/// True for the crank-angle roles (crank_pulse, crank_index, encoder_a, encoder_b).
bool is_angle_channel(ChannelRole role);

enum class PulsePolarity { rising, falling };

struct ChannelSpec {
  std::string name;                    ///< output column stem; default: the role (role_N when repeated)
  std::optional<int> index;            ///< 0-based channel in the recording (`index`)
  std::optional<std::string> column;   ///< or a text recording's column name (`column`)
  ChannelRole role = ChannelRole::ignore;

  // Accelerometer channels.
  double volts_per_m_s2 = 0;           ///< sensitivity·gain (or `volts_per_unit`)
  /// The key the manifest gave the calibration in ("volts_per_unit",
  /// "sensitivity_mV_per_m_s2" or "sensitivity_mV_per_g") and the factor
  /// from volts_per_m_s2 to that key's value (with its gain): what the set-up
  /// check names and says.
  std::string calibration_key = "volts_per_unit";
  double calibration_per_volts_per_m_s2 = 1;
  double axis_sign = 1;                ///< +1 or −1
  double position_m = 0;               ///< along the link from its first joint
  double offset_m = 0;                 ///< perpendicular to the link, +n side
  bool ac_coupled = false;             ///< piezo sensor / AC-coupled amplifier
  double highpass_hz = 0;              ///< its first-order high-pass corner (when ac_coupled)
  /// Mounted resonance from the calibration sheet (`sensor_resonance_Hz`,
  /// `sensor_resonance_Q`; 0: not known): a second-order low-pass section.
  double sensor_resonance_hz = 0, sensor_resonance_q = 0;

  // The crank-pulse channel.
  PulsePolarity polarity = PulsePolarity::rising;
  std::optional<double> threshold_low_V, threshold_high_V;  ///< Schmitt thresholds (default: automatic)
  double crank_offset_rad = 0;         ///< crank angle at the pulse's leading edge
  double debounce_s = 0;               ///< ignore edges closer than this to the previous one
  // Tooth wheels and encoders (acquire/wheel_*.hpp): on crank_pulse or encoder_a.
  int pulses_per_rev = 1;              ///< crank_pulse: tooth positions per turn (missing ones included)
  int missing_teeth = 0;               ///< crank_pulse: teeth left out of the wheel (a 60−2 wheel: 2)
  int lines_per_rev = 0;               ///< encoder_a: encoder lines per turn (4 edges each)
  bool correct_tooth_spacing = false;  ///< estimate each tooth's angle over the turns and use it
  // A crank_speed channel: rpm = recorded value (no rpm_per_V), or
  // recorded value · full_scale_V · rpm_per_V (a tacho voltage).
  std::optional<double> rpm_per_V;
  /// crank_speed without a crank_pulse: crank_offset_deg given (the crank
  /// angle at the first sample analysed), so the zero is known.
  bool crank_offset_given = false;
  /// On crank_pulse or encoder_a (crank_smoothing = "spline", crank_smoothing.hpp): the shortest
  /// period of a speed change, in turns, that the crank motion keeps; 0 (crank_smoothing = "none",
  /// the default): the motion through every edge.
  double smoothing_period_turns = 0;

  std::string notes;
};

struct Manifest {
  std::filesystem::path file;          ///< the manifest itself
  std::filesystem::path rig_file;
  std::shared_ptr<const Rig> rig;
  double clearance_m = 0;              ///< default: the rig's radial clearance
  bool clearance_from_rig = false;     ///< no clearance_mm in the manifest: the rig file's was taken
  double full_scale_V = 1;             ///< volts per recorded unit
  std::optional<double> adc_range_V;   ///< input range, for clipping detection in float/text recordings
  std::optional<double> sample_rate_hz;  ///< text recordings without a time column
  std::optional<std::string> time_column;
  std::optional<std::string> rate_variable;  ///< MATLAB recordings: the variable holding the rate in Hz
  std::optional<double> start_s, end_s;  ///< the part to analyse (acquire/time_range.hpp); --start-s/--end-s override
  std::optional<std::size_t> header_line;    ///< text recordings: the line of the column names
  double crank_direction = 1;          ///< +1: the crank turns counter-clockwise (θ2 increases), −1 clockwise
  /// `sampling = "multiplexed"`: one ADC scans the channels in index order,
  /// channel i sampled `skew_us`·i after channel 0 (`skew_us`, required then;
  /// a scan over the whole period: 1e6/(fs·channels)). 0: simultaneous.
  double channel_skew_s = 0;
  DaqFilter daq_filter;                ///< the anti-alias filter on the accelerometer channels (`daq_filter…`)
  std::vector<ChannelSpec> channels;   ///< as listed, `[[channel]]`
  std::string notes;

  ReaderOptions reader_options() const { return {sample_rate_hz, time_column, rate_variable, header_line}; }
  /// The crank-angle source's main channel: the crank_pulse channel, or
  /// encoder_a, or (no pulse) crank_speed. Its thresholds, offset and tooth keys apply.
  const ChannelSpec& pulse_channel() const;
  /// The crank_speed channel (the crank angle integrated from an rpm track), or null.
  const ChannelSpec* speed_channel() const { return channel_with(ChannelRole::crank_speed); }
  /// The channel with this role, or null.
  const ChannelSpec* channel_with(ChannelRole role) const;
  /// True when the crank angle comes from more than one edge per turn (a
  /// tooth wheel with an index or missing teeth, or a quadrature encoder).
  bool multi_edge_angle() const;
  /// Time of the signal in `channel`'s samples (its bound index) minus that
  /// in the crank channel's: the multiplexed scan's skew, less a
  /// linear-phase anti-alias filter's group delay on accelerometer channels.
  double sample_delay_s(const ChannelSpec& channel) const;
};

/// Whether `name` can name a channel: non-empty, without spaces, commas,
/// semicolons, quotes or control characters (tab, newline, U+0000–U+001F,
/// U+007F). A name becomes a column of CSV outputs and of the virtual rig's
/// text recordings, which must read back to the same name.
bool is_channel_name(std::string_view name);
inline constexpr const char* kChannelNameRule =
    "must be a non-empty word without spaces, commas, semicolons, quotes or control characters";

class TomlSection;
/// Reads one channel table (`[[channel]]` keys; without index/column unless
/// `with_index`); `roles` are the roles allowed here. Calls finish().
ChannelSpec read_channel_spec(TomlSection& table, bool with_index, const std::vector<std::string>& roles);

/// `REC.toml` for `REC.wav`.
std::filesystem::path sidecar_manifest_path(const std::filesystem::path& recording);

/// Reads and validates a manifest and its rig; InputError naming file, line and key.
Manifest load_manifest(const std::filesystem::path& file);

/// Resolves every channel's `column` to an index and checks indices against
/// the recording; InputError naming the channel. Fills `index` for all.
void bind_channels(Manifest& manifest, const RecordingInfo& recording);

/// The manifest as TOML text (what the virtual rig writes); paths relative to
/// `manifest_dir` when possible. load_manifest reads it back unchanged.
std::string manifest_to_toml(const Manifest& manifest, const std::filesystem::path& manifest_dir);

}  // namespace fourbar

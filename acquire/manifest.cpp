#include "acquire/manifest.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "acquire/crank_smoothing.hpp"
#include "acquire/csv_units.hpp"
#include "acquire/manifest_placeholders.hpp"
#include "common/csv_writer.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/toml_section.hpp"
#include "common/toml_writer.hpp"
#include "common/units.hpp"

namespace fourbar {

namespace {

/// Standard gravity g (m/s²): the "g" of a sensor sheet's mV/g.
constexpr double kStandardGravity_m_s2 = 9.80665;

constexpr std::array kRoles{
    std::pair{ChannelRole::coupler_tangential, "coupler_tangential"},
    std::pair{ChannelRole::coupler_normal, "coupler_normal"},
    std::pair{ChannelRole::rocker_tangential, "rocker_tangential"},
    std::pair{ChannelRole::rocker_normal, "rocker_normal"},
    std::pair{ChannelRole::crank_pulse, "crank_pulse"},
    std::pair{ChannelRole::crank_index, "crank_index"},
    std::pair{ChannelRole::encoder_a, "encoder_a"},
    std::pair{ChannelRole::encoder_b, "encoder_b"},
    std::pair{ChannelRole::crank_speed, "crank_speed"},
    std::pair{ChannelRole::ignore, "ignore"},
};

ChannelRole role_from_string(const std::string& s) {
  for (const auto& [role, name] : kRoles)
    if (s == name) return role;
  return ChannelRole::ignore;
}

// The reader's unit conversions, shared with manifest_to_toml so that what it
// writes converts back to the same SI value.
double mm_to_m(double mm) { return units::mm_to_m(mm); }
double deg_to_rad(double deg) { return units::deg_to_rad(deg); }
double ms_to_s(double ms) { return ms * 1e-3; }

std::string label(const ChannelSpec& c, std::size_t i) {
  return "channel[" + std::to_string(i) + "] ('" + c.name + "')";
}

int count(const Manifest& m, ChannelRole role) {
  return static_cast<int>(std::count_if(m.channels.begin(), m.channels.end(), [&](const ChannelSpec& c) { return c.role == role; }));
}

/// One crank-angle source: a crank_pulse channel (once per turn, or a tooth
/// wheel with a crank_index channel or missing teeth), or encoder_a and
/// encoder_b with an optional crank_index.
void check_angle_source(const Manifest& m) {
  const std::string f = m.file.string() + ": ";
  const int pulses = count(m, ChannelRole::crank_pulse), a = count(m, ChannelRole::encoder_a),
            b = count(m, ChannelRole::encoder_b), index = count(m, ChannelRole::crank_index),
            speeds = count(m, ChannelRole::crank_speed);
  if (speeds > 1)
    throw InputError(f + std::to_string(speeds) +
                     " channels have role = \"crank_speed\"; the crank angle is integrated from one rpm track: keep one "
                     "and set the others to role = \"ignore\"");
  if (speeds == 1) {
    const ChannelSpec& s = *m.channel_with(ChannelRole::crank_speed);
    if (a > 0 || b > 0 || index > 0)
      throw InputError(f + "channel '" + s.name + "' has role = \"crank_speed\" beside an encoder or a crank_index "
                           "channel; the crank angle comes from one source: remove the speed channel (set it to role = "
                           "\"ignore\") or the encoder/index channels");
    if (pulses > 1)
      throw InputError(f + std::to_string(pulses) + " channels have role = \"crank_pulse\" beside the speed channel '" +
                       s.name + "'; give at most one (once per turn: it sets the angle's zero)");
    if (pulses == 1 && s.crank_offset_given)
      throw InputError(f + "channel '" + s.name + "' key 'crank_offset_deg' beside the crank_pulse channel '" +
                       m.channel_with(ChannelRole::crank_pulse)->name +
                       "': the pulse sets the zero; give crank_offset_deg on the pulse channel and remove it here");
    if (pulses == 1 && m.channel_with(ChannelRole::crank_pulse)->pulses_per_rev != 1)
      throw InputError(f + "channel '" + m.channel_with(ChannelRole::crank_pulse)->name +
                       "' key 'pulses_per_rev' beside the speed channel '" + s.name +
                       "': with a speed channel the crank_pulse only sets the angle's zero, once per turn; remove "
                       "pulses_per_rev (and missing_teeth), or remove the speed channel to use the wheel");
    return;
  }
  if (index > 1) throw InputError(f + std::to_string(index) + " channels have role = \"crank_index\"; give at most one");
  if (a > 0 || b > 0) {
    if (a != 1 || b != 1)
      throw InputError(f + std::to_string(a) + " encoder_a and " + std::to_string(b) +
                       " encoder_b channels; a quadrature encoder needs exactly one of each");
    if (pulses > 0)
      throw InputError(f + "both a crank_pulse channel and an encoder; the crank angle comes from one: give the "
                           "encoder's index as role = \"crank_index\" and remove the crank_pulse channel");
    return;
  }
  if (pulses != 1)
    throw InputError(f + std::to_string(pulses) +
                     " channels have role = \"crank_pulse\"; exactly one must (the once-per-revolution crank pulse, "
                     "or a tooth wheel with pulses_per_rev), or describe an encoder as encoder_a and encoder_b, or an rpm "
                     "track as crank_speed");
  const ChannelSpec& p = *m.channel_with(ChannelRole::crank_pulse);
  const std::string key = "channel '" + p.name + "' key ";
  if (p.pulses_per_rev == 1 && index > 0)
    throw InputError(f + "a crank_index channel but " + key +
                     "'pulses_per_rev' is 1 (once per turn needs no index); give the wheel's pulses_per_rev or remove "
                     "the crank_index channel");
  if (p.pulses_per_rev == 1 && p.missing_teeth > 0)
    throw InputError(f + key + "'missing_teeth' needs 'pulses_per_rev', the tooth positions of the wheel (60 for a 60-2 wheel)");
  if (p.pulses_per_rev > 1 && index > 0 && p.missing_teeth > 0)
    throw InputError(f + key + "'missing_teeth' and a crank_index channel both mark the turns; keep one of them");
  if (p.pulses_per_rev > 1 && index == 0 && p.missing_teeth == 0)
    throw InputError(f + key + "'pulses_per_rev' = " + std::to_string(p.pulses_per_rev) +
                     " needs a way to count turns: add a channel with role = \"crank_index\" (once per turn) or "
                     "give 'missing_teeth' (a 60-2 wheel: 2)");
}

}  // namespace

bool is_channel_name(std::string_view name) {
  if (name.empty()) return false;
  for (const char ch : name) {
    const auto byte = static_cast<unsigned char>(ch);
    if (byte < 0x20 || byte == 0x7F || ch == ' ' || ch == ',' || ch == ';' || ch == '"') return false;
  }
  return true;
}

ChannelSpec read_channel_spec(TomlSection& s, bool with_index, const std::vector<std::string>& roles) {
  ChannelSpec c;
  c.role = role_from_string(s.choice("role", roles));
  if (with_index) {
    if (s.has("index")) c.index = static_cast<int>(s.integer("index", 0, 1 << 20));
    if (auto col = s.optional_string("column")) c.column = *col;
    if (c.index && c.column) s.fail("column", "and 'index' both given; keep one of them");
    if (!c.index && !c.column)
      s.fail("index", "missing: give the channel's 0-based 'index' (or a text column's name as 'column')");
  }
  if (auto n = s.optional_string("name")) {
    if (!is_channel_name(*n)) s.fail("name", "= " + toml_quoted(*n) + " " + kChannelNameRule);
    c.name = *n;
  }

  if (is_accelerometer(c.role)) {
    // The calibration in one of three keys: V per m/s² with the gain in it,
    // or the sensor's sheet value in mV per m/s² or mV per g, times `gain`.
    const bool has_sens = s.has("sensitivity_mV_per_m_s2"), has_vpu = s.has("volts_per_unit"),
               has_g = s.has("sensitivity_mV_per_g");
    if (has_sens + has_vpu + has_g > 1)
      s.fail(has_vpu ? "volts_per_unit" : "sensitivity_mV_per_m_s2",
             "and another calibration key both given; keep one of volts_per_unit (V per m/s², gain included), "
             "sensitivity_mV_per_m_s2 or sensitivity_mV_per_g (the sensor's sheet, with gain)");
    if (has_vpu) {
      c.volts_per_m_s2 = s.positive("volts_per_unit");
    } else if (has_g) {
      const double gain = s.in_range("gain", 1e-6, 1e6, 1.0);
      c.volts_per_m_s2 = s.positive("sensitivity_mV_per_g") * 1e-3 * gain / kStandardGravity_m_s2;
      c.calibration_key = "sensitivity_mV_per_g";
      c.calibration_per_volts_per_m_s2 = 1e3 * kStandardGravity_m_s2 / gain;
    } else {
      const double gain = s.in_range("gain", 1e-6, 1e6, 1.0);
      c.volts_per_m_s2 = s.positive("sensitivity_mV_per_m_s2") * 1e-3 * gain;
      c.calibration_key = "sensitivity_mV_per_m_s2";
      c.calibration_per_volts_per_m_s2 = 1e3 / gain;
    }
    c.axis_sign = s.in_range("axis_sign", -1, 1, 1.0);
    if (c.axis_sign != 1 && c.axis_sign != -1) s.fail("axis_sign", "must be 1 or -1");
    c.position_m = mm_to_m(s.in_range("position_mm", -1e5, 1e5));
    c.offset_m = mm_to_m(s.in_range("offset_mm", -1e5, 1e5, 0.0));
    c.ac_coupled = s.boolean("ac_coupled", false);
    if (c.ac_coupled) c.highpass_hz = s.positive("highpass_hz");
    else if (s.has("highpass_hz")) s.fail("highpass_hz", "is given but ac_coupled is not true; set ac_coupled = true or remove it");
    if (s.has("sensor_resonance_Hz") != s.has("sensor_resonance_Q"))
      s.fail(s.has("sensor_resonance_Hz") ? "sensor_resonance_Q" : "sensor_resonance_Hz",
             "is missing: a mounted resonance needs both sensor_resonance_Hz and sensor_resonance_Q (calibration sheet)");
    if (s.has("sensor_resonance_Hz")) {
      c.sensor_resonance_hz = s.in_range("sensor_resonance_Hz", 1, 1e7);
      c.sensor_resonance_q = s.in_range("sensor_resonance_Q", 0.5, 1e4);
    }
  }
  if (is_angle_channel(c.role)) {
    c.polarity = s.choice("polarity", {"rising", "falling"}, "rising") == "rising" ? PulsePolarity::rising
                                                                                  : PulsePolarity::falling;
    c.threshold_low_V = s.optional_number("threshold_low_V");
    c.threshold_high_V = s.optional_number("threshold_high_V");
    if (c.threshold_low_V.has_value() != c.threshold_high_V.has_value())
      s.fail(c.threshold_low_V ? "threshold_high_V" : "threshold_low_V",
             "missing: give both Schmitt thresholds or neither (automatic)");
    if (c.threshold_low_V && !(*c.threshold_low_V < *c.threshold_high_V))
      s.fail("threshold_low_V", "must be below threshold_high_V");
    if (c.role == ChannelRole::crank_pulse || c.role == ChannelRole::encoder_a)
      c.crank_offset_rad = deg_to_rad(s.in_range("crank_offset_deg", -360, 360, 0.0));
    c.debounce_s = ms_to_s(s.in_range("debounce_ms", 0, 1e6, 0.0));
  }
  if (c.role == ChannelRole::crank_pulse) {
    c.pulses_per_rev = static_cast<int>(s.integer("pulses_per_rev", 1, 100000, 1));
    c.missing_teeth = static_cast<int>(s.integer("missing_teeth", 0, 100000, 0));
    if (c.missing_teeth > 0 && 2 * c.missing_teeth >= c.pulses_per_rev)
      s.fail("missing_teeth", "= " + std::to_string(c.missing_teeth) + " must be less than half of pulses_per_rev = " +
                                  std::to_string(c.pulses_per_rev) + " (a 60-2 wheel: pulses_per_rev = 60, missing_teeth = 2)");
  }
  if (c.role == ChannelRole::encoder_a)
    c.lines_per_rev = static_cast<int>(s.integer("lines_per_rev", 1, 1 << 22));
  if ((c.role == ChannelRole::crank_pulse && c.pulses_per_rev > 1) || c.role == ChannelRole::encoder_a)
    c.correct_tooth_spacing = s.boolean("correct_tooth_spacing", false);
  if (c.role == ChannelRole::crank_pulse || c.role == ChannelRole::encoder_a) {
    const bool spline = s.choice("crank_smoothing", {"none", "spline"}, "none") == "spline";
    if (spline) {
      // Knots every period/3 turns need at least two edges between them.
      const int edges_per_turn = c.role == ChannelRole::encoder_a ? 4 * c.lines_per_rev : c.pulses_per_rev;
      const double shortest = kSmoothingKnotsPerPeriod * 2.0 / edges_per_turn;
      c.smoothing_period_turns = s.in_range("smoothing_period_turns", 1e-6, 1e6, std::max(shortest, kDefaultSmoothingPeriodTurns));
      if (c.smoothing_period_turns < shortest)
        s.fail("smoothing_period_turns", "= " + format_number(c.smoothing_period_turns, 6) + " is shorter than " +
                                             format_number(shortest, 6) + " turns, the least that smooths " +
                                             std::to_string(edges_per_turn) + " edge" + (edges_per_turn == 1 ? "" : "s") +
                                             " per turn (knots every period/3 turns, two edges between knots)");
    } else if (s.has("smoothing_period_turns")) {
      s.fail("smoothing_period_turns", "is given but crank_smoothing is not \"spline\"; set crank_smoothing = \"spline\" or remove it");
    }
  }
  if (c.role == ChannelRole::crank_speed) {
    if (s.has("rpm_per_V")) c.rpm_per_V = s.positive("rpm_per_V");
    c.crank_offset_given = s.has("crank_offset_deg");
    c.crank_offset_rad = deg_to_rad(s.in_range("crank_offset_deg", -360, 360, 0.0));
  }
  if (auto n = s.optional_string("notes")) c.notes = *n;
  s.finish();
  return c;
}

const char* to_string(ChannelRole role) {
  for (const auto& [r, name] : kRoles)
    if (r == role) return name;
  return "ignore";
}

std::vector<std::string> channel_role_names() {
  std::vector<std::string> v;
  for (const auto& kv : kRoles) v.emplace_back(kv.second);
  return v;
}

bool is_accelerometer(ChannelRole r) {
  return !is_angle_channel(r) && r != ChannelRole::ignore && r != ChannelRole::crank_speed;
}
bool is_angle_channel(ChannelRole r) {
  return r == ChannelRole::crank_pulse || r == ChannelRole::crank_index || r == ChannelRole::encoder_a ||
         r == ChannelRole::encoder_b;
}
bool is_on_coupler(ChannelRole r) { return r == ChannelRole::coupler_tangential || r == ChannelRole::coupler_normal; }
bool is_tangential(ChannelRole r) { return r == ChannelRole::coupler_tangential || r == ChannelRole::rocker_tangential; }

const ChannelSpec& Manifest::pulse_channel() const {
  if (const ChannelSpec* c = channel_with(ChannelRole::crank_pulse)) return *c;
  if (const ChannelSpec* c = channel_with(ChannelRole::encoder_a)) return *c;
  if (const ChannelSpec* c = channel_with(ChannelRole::crank_speed)) return *c;
  throw InputError(file.string() + ": no channel has role = \"crank_pulse\"");  // load_manifest prevents this
}

const ChannelSpec* Manifest::channel_with(ChannelRole role) const {
  for (const auto& c : channels)
    if (c.role == role) return &c;
  return nullptr;
}

bool Manifest::multi_edge_angle() const {
  const ChannelSpec& p = pulse_channel();
  return speed_channel() || p.role == ChannelRole::encoder_a || p.pulses_per_rev > 1;
}

double Manifest::sample_delay_s(const ChannelSpec& channel) const {
  // A linear-phase anti-alias filter delays the accelerometer channels.
  const double filter_s = is_accelerometer(channel.role) ? -daq_filter.delay_s : 0.0;
  if (channel_skew_s == 0) return filter_s;
  const ChannelSpec& p = pulse_channel();
  if (!channel.index || !p.index)
    throw InputError(file.string() + ": channel '" + (channel.index ? p.name : channel.name) +
                     "' has no channel index yet; sampling = \"multiplexed\" needs the channels bound to the recording");
  return filter_s + channel_skew_s * static_cast<double>(*channel.index - *p.index);
}

std::filesystem::path sidecar_manifest_path(const std::filesystem::path& recording) {
  std::filesystem::path p = recording;
  return p.replace_extension(".toml");
}

namespace {

/// clearance_mm: required. A run's clearance is what the report judges by,
/// and the rig file's is a nominal that a forgotten key used to take
/// silently (0.254 mm for a 0.0254 mm run: "the model is 1.7x too violent").
/// `clearance_mm = "rig"` takes the rig file's on purpose.
void read_clearance(const toml::table& doc, TomlSection& root, Manifest& m) {
  const std::string rig_says = format_number(units::m_to_mm(m.rig->radial_clearance_m)) + " mm";
  if (!root.has("clearance_mm")) {
    // A misspelt key is the likelier slip: name it as finish() would.
    for (const auto& [key, value] : doc)
      if (closest_match(key.str(), {"clearance_mm"}))
        root.fail(key.str(), "unknown key '" + std::string(key.str()) + "' (did you mean 'clearance_mm'?); correct it");
    throw InputError(root.file().string() + ": key 'clearance_mm' is missing: add the line clearance_mm = <this run's "
                     "radial clearance of the coupler-rocker bearing in mm (bore radius - pin radius)>; the rig file " +
                     m.rig_file.string() + "'s clearance (" + rig_says +
                     ") is not taken without being asked: clearance_mm = \"rig\" takes it");
  }
  if (doc["clearance_mm"].is_string()) {
    const std::string text = root.string("clearance_mm");
    if (text != "rig")
      root.fail("clearance_mm", "= \"" + text + "\": give the radial clearance in mm as a number (e.g. "
                                "clearance_mm = 0.254), or \"rig\" for the rig file's (" + rig_says + ")");
    m.clearance_from_rig = true;
    m.clearance_m = m.rig->radial_clearance_m;
    return;
  }
  m.clearance_from_rig = false;
  m.clearance_m = mm_to_m(root.non_negative("clearance_mm"));
}

}  // namespace

Manifest load_manifest(const std::filesystem::path& file) {
  const toml::table doc = parse_toml_file(file);
  reject_placeholders(doc, file);
  TomlSection root(doc, file);
  Manifest m;
  m.file = file;
  m.rig_file = root.path("rig");
  try {
    m.rig = std::make_shared<const Rig>(load_rig(m.rig_file));
  } catch (const InputError& e) {
    throw InputError(root.where("rig") + ": " + e.what());
  }
  read_clearance(doc, root, m);
  m.full_scale_V = root.in_range("full_scale_V", 1e-9, 1e9, 1.0);
  if (root.has("adc_range_V")) m.adc_range_V = root.positive("adc_range_V");
  if (root.has("sample_rate_hz")) m.sample_rate_hz = root.positive("sample_rate_hz");
  m.time_column = root.optional_string("time_column");
  m.rate_variable = root.optional_string("rate_variable");
  if (root.has("header_line")) m.header_line = static_cast<std::size_t>(root.integer("header_line", 1, 1'000'000));
  if (m.rate_variable && m.sample_rate_hz)
    root.fail("rate_variable", "and 'sample_rate_hz' both given; keep one of them");
  m.crank_direction = root.choice("crank_direction", {"ccw", "cw"}, "ccw") == "ccw" ? 1.0 : -1.0;
  if (root.has("start_s")) m.start_s = root.number("start_s");
  if (root.has("end_s")) m.end_s = root.number("end_s");
  if (m.start_s && m.end_s && !(*m.end_s > *m.start_s))
    root.fail("end_s", "must be after start_s (" + format_number(*m.start_s) + " s)");
  m.daq_filter = read_daq_filter(root);
  if (root.choice("sampling", {"simultaneous", "multiplexed"}, "simultaneous") == "multiplexed") {
    if (!root.has("skew_us"))
      root.fail("sampling", "= \"multiplexed\" needs 'skew_us', the time between neighbouring channels' samples "
                            "(for a scan over the whole sample period: 1e6/(sample rate · channels))");
    m.channel_skew_s = root.in_range("skew_us", 0, 1e6) * 1e-6;
  } else if (root.has("skew_us")) {
    root.fail("skew_us", "is for sampling = \"multiplexed\"; add that key or remove this one");
  }
  if (auto n = root.optional_string("notes")) m.notes = *n;

  auto sections = root.sections("channel");
  if (sections.empty())
    throw InputError(file.string() + ": no [[channel]] tables; describe at least the crank_pulse channel");
  for (std::size_t i = 0; i < sections.size(); ++i)
    m.channels.push_back(read_channel_spec(sections[i], true, channel_role_names()));
  root.finish();
  check_angle_source(m);

  // Default names: the role, numbered when a role appears more than once.
  for (std::size_t i = 0; i < m.channels.size(); ++i) {
    ChannelSpec& c = m.channels[i];
    if (!c.name.empty()) continue;
    int same = 0, before = 0;
    for (std::size_t j = 0; j < m.channels.size(); ++j)
      if (m.channels[j].role == c.role) ++same, before += j < i;
    c.name = to_string(c.role);
    if (same > 1) c.name += "_" + std::to_string(before + 1);
  }
  for (std::size_t i = 0; i < m.channels.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (m.channels[i].name == m.channels[j].name)
        throw InputError(file.string() + ": " + label(m.channels[i], i) + " has the same name as " +
                         label(m.channels[j], j) + "; give each a different 'name'");
  return m;
}

void bind_channels(Manifest& m, const RecordingInfo& rec) {
  for (std::size_t i = 0; i < m.channels.size(); ++i) {
    ChannelSpec& c = m.channels[i];
    if (c.column) {
      const auto& names = rec.channel_names;
      auto it = std::find(names.begin(), names.end(), *c.column);
      if (it == names.end()) it = std::find(names.begin(), names.end(), split_unit(*c.column).name);  // `coupler_t [V]`
      if (it == names.end() || c.column->empty()) {
        std::string hint, found;
        std::vector<std::string> present;
        for (const auto& n : names)
          if (!n.empty()) present.push_back(n), found += (found.empty() ? "'" : ", '") + n + "'";
        if (auto best = closest_match(*c.column, present)) hint = " (did you mean '" + *best + "'?)";
        throw InputError(m.file.string() + ": " + label(c, i) + ": column '" + *c.column + "' is not in " +
                         rec.file.string() + hint +
                         (present.empty() ? "; audio files have no column names, use 'index'"
                                          : "; its channels are " + found + " (fix the column name)"));
      }
      c.index = static_cast<int>(it - names.begin());
    }
    if (*c.index >= rec.channels)
      throw InputError(m.file.string() + ": " + label(c, i) + ": index = " + std::to_string(*c.index) + " but " +
                       rec.file.string() + " has " + std::to_string(rec.channels) + " channel" +
                       (rec.channels == 1 ? "" : "s") + " (indices 0.." + std::to_string(rec.channels - 1) +
                       "); fix the index");
    for (std::size_t j = 0; j < i; ++j)
      if (m.channels[j].index == c.index)
        throw InputError(m.file.string() + ": " + label(c, i) + " and " + label(m.channels[j], j) +
                         " both describe recording channel " + std::to_string(*c.index) + "; describe each channel once");
  }
}

std::string manifest_to_toml(const Manifest& m, const std::filesystem::path& manifest_dir) {
  // Relative to the manifest when they share a folder below the root.
  auto rel = [&](const std::filesystem::path& p) {
    std::error_code ec;
    const auto abs = std::filesystem::absolute(p, ec), dir = std::filesystem::absolute(manifest_dir, ec);
    const auto r = abs.lexically_relative(dir);
    std::size_t up = 0, depth = 0;
    for (const auto& part : r) up += part == "..";
    for (const auto& part : dir.relative_path()) depth += !part.empty();
    return (ec || r.empty() || up >= depth) ? abs.generic_string() : r.generic_string();
  };
  auto num = [](double v) { return toml_number(v); };
  // Values converted from SI back to the file's unit (mm, degrees, ms) are
  // written as the shortest number that the reader's conversion turns back
  // into the same SI value (0.258 mm is kept as 0.000258 m, and 0.000258 ·
  // 1000 = 0.25800000000000006 would drift on every round trip).
  auto mm = [](double metres) { return toml_number_in_unit(metres, units::m_to_mm(metres), mm_to_m); };
  auto deg = [](double rad) { return toml_number_in_unit(rad, units::rad_to_deg(rad), deg_to_rad); };
  auto ms = [](double s) { return toml_number_in_unit(s, s * 1e3, ms_to_s); };
  auto quoted = [](const std::string& s) { return toml_quoted(s); };
  std::ostringstream os;
  os << "# Recording manifest (keys: docs/acquire.md).\n";
  os << "rig = " << quoted(rel(m.rig_file)) << "\n";
  if (m.clearance_from_rig) os << "clearance_mm = \"rig\"\n";
  else os << "clearance_mm = " << mm(m.clearance_m) << "\n";
  os << "full_scale_V = " << num(m.full_scale_V) << "\n";
  if (m.adc_range_V) os << "adc_range_V = " << num(*m.adc_range_V) << "\n";
  if (m.sample_rate_hz) os << "sample_rate_hz = " << num(*m.sample_rate_hz) << "\n";
  if (m.time_column) os << "time_column = " << quoted(*m.time_column) << "\n";
  if (m.rate_variable) os << "rate_variable = " << quoted(*m.rate_variable) << "\n";
  if (m.header_line) os << "header_line = " << *m.header_line << "\n";
  os << "crank_direction = \"" << (m.crank_direction > 0 ? "ccw" : "cw") << "\"\n";
  if (m.start_s) os << "start_s = " << num(*m.start_s) << "\n";
  if (m.end_s) os << "end_s = " << num(*m.end_s) << "\n";
  os << daq_filter_toml(m.daq_filter);
  if (m.channel_skew_s > 0) os << "sampling = \"multiplexed\"\nskew_us = " << num(m.channel_skew_s * 1e6) << "\n";
  if (!m.notes.empty()) os << "notes = " << quoted(m.notes) << "\n";
  for (const auto& c : m.channels) {
    os << "\n[[channel]]\n";
    if (c.column) os << "column = " << quoted(*c.column) << "\n";
    else os << "index = " << c.index.value_or(0) << "\n";
    os << "name = " << quoted(c.name) << "\n";
    os << "role = \"" << to_string(c.role) << "\"\n";
    if (is_accelerometer(c.role)) {
      os << "volts_per_unit = " << num(c.volts_per_m_s2) << "\n";
      os << "axis_sign = " << (c.axis_sign > 0 ? 1 : -1) << "\n";
      os << "position_mm = " << mm(c.position_m) << "\n";
      if (c.offset_m != 0) os << "offset_mm = " << mm(c.offset_m) << "\n";
      os << "ac_coupled = " << (c.ac_coupled ? "true" : "false") << "\n";
      if (c.ac_coupled) os << "highpass_hz = " << num(c.highpass_hz) << "\n";
      if (c.sensor_resonance_hz > 0)
        os << "sensor_resonance_Hz = " << num(c.sensor_resonance_hz) << "\nsensor_resonance_Q = "
           << num(c.sensor_resonance_q) << "\n";
    }
    if (is_angle_channel(c.role)) {
      os << "polarity = \"" << (c.polarity == PulsePolarity::rising ? "rising" : "falling") << "\"\n";
      if (c.threshold_low_V) os << "threshold_low_V = " << num(*c.threshold_low_V) << "\n";
      if (c.threshold_high_V) os << "threshold_high_V = " << num(*c.threshold_high_V) << "\n";
      if (c.role == ChannelRole::crank_pulse || c.role == ChannelRole::encoder_a)
        os << "crank_offset_deg = " << deg(c.crank_offset_rad) << "\n";
      if (c.debounce_s > 0) os << "debounce_ms = " << ms(c.debounce_s) << "\n";
      if (c.pulses_per_rev > 1) os << "pulses_per_rev = " << c.pulses_per_rev << "\n";
      if (c.missing_teeth > 0) os << "missing_teeth = " << c.missing_teeth << "\n";
      if (c.lines_per_rev > 0) os << "lines_per_rev = " << c.lines_per_rev << "\n";
      if (c.correct_tooth_spacing) os << "correct_tooth_spacing = true\n";
      if (c.smoothing_period_turns > 0)
        os << "crank_smoothing = \"spline\"\nsmoothing_period_turns = " << num(c.smoothing_period_turns) << "\n";
    }
    if (c.rpm_per_V) os << "rpm_per_V = " << num(*c.rpm_per_V) << "\n";
    if (c.crank_offset_given) os << "crank_offset_deg = " << deg(c.crank_offset_rad) << "\n";
    if (!c.notes.empty()) os << "notes = " << quoted(c.notes) << "\n";
  }
  return os.str();
}

}  // namespace fourbar

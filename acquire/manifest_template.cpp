#include "acquire/manifest_template.hpp"

#include <cstdio>
#include <sstream>

#include "acquire/csv_units.hpp"
#include "acquire/manifest_placeholders.hpp"
#include "common/format.hpp"
#include "common/toml_writer.hpp"

namespace fourbar {

namespace {

/// Text for a TOML comment: UTF-8, control characters (TOML forbids them in
/// comments; a newline would end the comment) written as \xNN.
std::string comment_text(const std::string& text) {
  std::string out;
  for (const char ch : as_utf8(text)) {
    const auto c = static_cast<unsigned char>(ch);
    if ((c < 0x20 && c != '\t') || c == 0x7F) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", c);
      out += buf;
    } else {
      out += ch;
    }
  }
  return out;
}

void comment_line(std::ostream& os, const std::string& text) { os << "# " << comment_text(text) << "\n"; }

/// `key = "FILL IN"  # what` as one line.
std::string fill_in(const char* key, const std::string& what) {
  return std::string(key) + " = " + toml_quoted(kFillIn) + "  # FILL IN: " + comment_text(what) + "\n";
}

/// The one unit every channel states, or empty.
std::string common_unit(const RecordingInspection& r) {
  std::string unit;
  for (const auto& ch : r.channels) {
    if (ch.unit.empty() || (!unit.empty() && ch.unit != unit)) return "";
    unit = ch.unit;
  }
  return unit;
}


/// True when every channel states an acceleration unit (UFF58, TDMS): the
/// DAQ software has calibrated them already.
bool all_acceleration(const RecordingInspection& r) {
  for (const auto& ch : r.channels)
    if (ch.unit != "m/s^2" && ch.unit != "g") return false;
  return !r.channels.empty();
}

}  // namespace

std::string manifest_template(const RecordingInspection& r, const ReaderOptions& options) {
  const RecordingInfo& info = r.info;
  const bool named = !info.channel_names.empty() && !info.channel_names.front().empty();
  std::ostringstream os;
  comment_line(os, "Manifest for " + info.file.filename().string() + ", started by `fourbar inspect --manifest-template`.");
  comment_line(os, info.format + " " + info.sample_format + ", " + std::to_string(info.channels) + " channels, " +
                       format_number(info.sample_rate_hz, 10) + " Hz, " + std::to_string(info.frames) + " samples (" +
                       format_number(info.duration_s(), 10) + " s).");
  os << "# Replace every \"FILL IN\" by its value (the comment says what it is): acquire refuses this\n"
     << "# file while one is left. Every key: docs/acquire.md.\n\n";
  os << fill_in("rig", "the rig file, relative to this manifest, e.g. \"../rigs/thesis.toml\"");
  os << fill_in("clearance_mm", "this run's radial clearance of the coupler-rocker bearing in mm (bore radius - pin radius); "
                                "required; \"rig\" takes the rig file's");
  const std::string unit = common_unit(r);
  if (info.integer_bits > 0) {
    os << fill_in("full_scale_V", "the DAQ's input range in V (" + std::to_string(info.integer_bits) +
                                      "-bit integer samples are read as +-1 = full scale)");
  } else if (unit == "V" || unit == "mV") {
    os << "full_scale_V = " << (unit == "V" ? "1" : "0.001") << "  # the export states every channel in " << unit << "\n";
  } else if (all_acceleration(r)) {
    os << "full_scale_V = 1  # the file holds acceleration (m/s^2 or g), not volts: volts_per_unit converts\n";
  } else {
    os << fill_in("full_scale_V", "volts per recorded unit (1 when the " + info.format + " file holds volts" +
                                      (unit.empty() ? "" : "; its channels are in " + unit) + ")");
  }
  if (info.integer_bits == 0)
    os << "# adc_range_V = 10  # the DAQ's input range in V: samples at +- this are counted as clipped\n";
  if (options.sample_rate_hz) os << "sample_rate_hz = " << format_number(*options.sample_rate_hz, 10) << "  # as given to inspect\n";
  else if (info.rate_variable) os << "rate_variable = " << toml_quoted(*info.rate_variable) << "  # the variable holding the sample rate in Hz\n";
  if (options.time_column) os << "time_column = " << toml_quoted(*options.time_column) << "\n";
  if (options.header_line) os << "header_line = " << *options.header_line << "  # the line of the column names\n";
  os << fill_in("crank_direction", "\"ccw\" when the crank angle increases counter-clockwise in the rig frame "
                                   "(README \"Sensor orientation\"), \"cw\" when it turns the other way");
  os << "# start_s = 0    # optional: only the turns from this recording time (s) on; acquire/analyze warn with\n"
        "# end_s = 60     # the values to type when a coast-down, a stall or a run-up should be cut\n";
  if (r.pulse_channel < 0)
    os << "\n# No channel looks like a crank-pulse train: give the pulse channel role = \"crank_pulse\"\n"
          "# (and polarity, crank_offset_deg), and delete its accelerometer keys; or an rpm track\n"
          "# role = \"crank_speed\" (rpm_per_V when it is a voltage; a pulse, if any, sets the zero).\n";

  for (const auto& ch : r.channels) {
    os << "\n";
    comment_line(os, "channel " + std::to_string(ch.index) + (ch.name.empty() ? "" : " '" + ch.name + "'") +
                          (ch.unit.empty() ? "" : " [" + ch.unit + "]") + ": " + ch.reason);
    if (ch.constant) {
      os << "# (not listed: a channel without a [[channel]] table is ignored)\n";
      continue;
    }
    os << "[[channel]]\n";
    if (named) os << "column = " << toml_quoted(ch.name) << "\n";
    else os << "index = " << ch.index << "\n";
    if (ch.role == "crank_pulse") {
      os << "role = \"crank_pulse\"  # from the data: a regular pulse train\n";
      os << "polarity = \"" << (ch.pulse->short_state_high ? "rising" : "falling") << "\"  # from the data: the short state is "
         << (ch.pulse->short_state_high ? "high, its rising" : "low, its falling") << " edge leads; check which edge marks the crank\n";
      os << fill_in("crank_offset_deg", "crank angle from the ground line at the marking edge, in degrees");
      os << "# crank_smoothing = \"spline\"  # a steady run: smooth the pulse times across turns (docs/acquire.md)\n"
            "# smoothing_period_turns = 10  # with spline: the shortest speed change kept, in crank turns\n";
      continue;
    }
    if (!ch.role.empty() && ch.role != "ignore")
      os << "role = \"" << ch.role << "\"  # from its name: check\n";
    else
      os << fill_in("role", "coupler_tangential, coupler_normal, rocker_tangential or rocker_normal "
                            "(a channel you do not use: delete this table)");
    if (ch.unit == "m/s^2")
      os << "volts_per_unit = 1  # the file holds m/s^2 (with full_scale_V = 1)\n";
    else if (ch.unit == "g")
      os << "volts_per_unit = 0.1019716213  # the file holds g: 1 / 9.80665 (with full_scale_V = 1)\n";
    else
      os << fill_in("volts_per_unit", "sensor sensitivity x amplifier gain in V per m/s^2, from the calibration sheet "
                                      "(or sensitivity_mV_per_m_s2 and gain instead)");
    os << fill_in("axis_sign", "1 when the sensor axis points along +n (tangential) or +u (normal) of its link, "
                               "-1 when mounted the other way round");
    os << fill_in("position_mm", "sensor position along its link: on the coupler from the crank pin A, on the rocker "
                                 "from the pivot O4, in mm");
    os << "offset_mm = 0  # perpendicular to the link, + on the counter-clockwise side, in mm\n";
    os << fill_in("ac_coupled", "true for a piezo sensor or an AC-coupled amplifier (then give highpass_hz), false for DC");
    os << "# highpass_hz = 0.5  # AC-coupled: the first-order high-pass corner in Hz\n";
  }
  return os.str();
}

}  // namespace fourbar

#include "report/views_record.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "acquire/channel_inputs.hpp"
#include "common/units.hpp"
#include "report/packed_numbers.hpp"

namespace fourbar {

using nlohmann::json;

namespace {

json finite_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json stats_json(const ChannelStats& s, bool checked) {
  return {{"min", finite_or_null(s.min)},
          {"max", finite_or_null(s.max)},
          {"mean", finite_or_null(s.mean)},
          {"rms", finite_or_null(s.rms)},
          {"clipping_checked", checked},
          {"clipped_samples", s.clipped_samples},
          {"first_clip_s", s.clipped_samples > 0 ? finite_or_null(s.first_clip_s) : json(nullptr)}};
}

/// The set-up check's word on one channel ("" for the crank).
json channel_check(const json& sc, const std::string& channel) {
  if (sc.is_null() || !sc.is_object()) return nullptr;
  json out = {{"status", "not checked"}, {"findings", json::array()}};
  if (sc.contains("not_checked")) {
    out["note"] = sc["not_checked"];
    return out;
  }
  bool judged = channel.empty();
  if (sc.contains("data"))
    for (const json& c : sc["data"].value("channels", json::array()))
      if (c.value("channel", "") == channel) {
        out["fit"] = c["fit"], out["fit_manifest"] = c["fit_manifest"], out["scale"] = c["scale"];
        out["position_mm"] = c["position_mm"], out["fitted_as"] = c["fitted_as"];
        judged = true;
      }
  for (const json& f : sc.value("findings", json::array()))
    if (f.value("channel", "") == channel) out["findings"].push_back(f["message"]);
  if (judged) out["status"] = out["findings"].empty() ? "consistent" : "check set-up";
  if (channel.empty() && sc.contains("data"))
    out["crank_offset_deg"] = sc["data"]["crank_offset_deg"], out["crank_direction"] = sc["data"]["crank_direction"];
  return out;
}

}  // namespace

json channel_sheet_json(const Manifest& m, const AcquisitionReport& acq, const json& sc) {
  const ClipRange clip = clip_range(acq.recording, m);
  json rows = json::array();
  for (const ChannelSpec& c : m.channels) {
    json row = {{"name", c.name}, {"index", c.index ? json(*c.index) : json(nullptr)}, {"role", to_string(c.role)}};
    if (c.column) row["column"] = *c.column;
    if (!c.notes.empty()) row["notes"] = c.notes;
    if (is_accelerometer(c.role)) {
      const double v_per_unit = m.full_scale_V;
      row["unit"] = "m/s²";
      row["volts_per_m_s2"] = c.volts_per_m_s2;
      row["axis_sign"] = c.axis_sign;
      row["position_mm"] = units::m_to_mm(c.position_m);
      row["offset_mm"] = units::m_to_mm(c.offset_m);
      row["ac_coupled"] = c.ac_coupled;
      if (c.ac_coupled) row["highpass_hz"] = c.highpass_hz;
      if (clip.checked)
        row["input_range"] = {{"min", clip.low * v_per_unit / c.volts_per_m_s2}, {"max", clip.high * v_per_unit / c.volts_per_m_s2}};
      for (std::size_t i = 0; i < acq.channels.size() && i < acq.channel_stats.size(); ++i)
        if (acq.channels[i].name == c.name) row["recorded"] = stats_json(acq.channel_stats[i], acq.clipping_checked);
      row["setup_check"] = channel_check(sc, c.name);
    } else if (c.role == ChannelRole::crank_speed) {  // the crank angle integrated from it (acquire/speed_angle)
      row["unit"] = c.rpm_per_V ? "V" : "rpm";
      if (c.rpm_per_V) row["rpm_per_V"] = *c.rpm_per_V;
      row["zero"] = m.channel_with(ChannelRole::crank_pulse) ? "at the crank_pulse" : "unknown (no crank_pulse)";
    } else if (is_angle_channel(c.role)) {
      row["unit"] = "V";
      if (clip.checked) row["input_range"] = {{"min", clip.low * m.full_scale_V}, {"max", clip.high * m.full_scale_V}};
      row["polarity"] = c.polarity == PulsePolarity::rising ? "rising" : "falling";
      if (&c == &m.pulse_channel()) {
        const PulseThresholds& t = acq.thresholds;
        row["recorded"] = stats_json(acq.pulse_stats, false);
        row["crank_offset_deg"] = units::rad_to_deg(c.crank_offset_rad);
        row["thresholds"] = {{"low_V", finite_or_null(t.low)},
                             {"high_V", finite_or_null(t.high)},
                             {"bottom_level_V", finite_or_null(t.bottom_level)},
                             {"top_level_V", finite_or_null(t.top_level)},
                             {"noise_V", finite_or_null(t.noise)},
                             {"automatic", t.automatic},
                             {"follows_baseline", t.follows_baseline}};
        if (c.pulses_per_rev > 1) row["pulses_per_rev"] = c.pulses_per_rev, row["missing_teeth"] = c.missing_teeth;
        if (c.lines_per_rev > 0) row["lines_per_rev"] = c.lines_per_rev;
        row["setup_check"] = channel_check(sc, "");
      }
    }
    rows.push_back(row);
  }
  return {{"full_scale_V", m.full_scale_V},
          {"sample_rate_hz", acq.recording.sample_rate_hz},
          {"sample_format", acq.recording.sample_format},
          {"clipping_checked", acq.clipping_checked},
          {"channels", rows}};
}

json excerpt_json(const AcquisitionReport& acq) {
  if (!acq.excerpt || acq.excerpt->frames == 0) return nullptr;
  const SignalExcerpt& x = *acq.excerpt;
  json traces = json::array();
  for (const ExcerptTrace& t : x.traces) {
    const PackedCounts p = quantise(t.values, 32767);
    traces.push_back({{"name", t.name}, {"role", t.role}, {"unit", t.unit}, {"unit_per_count", p.step},
                      {"values_int16_base64", pack_base64(p.counts, 2)}});
  }
  // The points lie on a uniform time grid (two per bucket, or every frame).
  const double fs = acq.recording.sample_rate_hz;
  const double step_s = x.bucket_frames == 1 ? 1.0 / fs : 0.5 * static_cast<double>(x.bucket_frames) / fs;
  const PulseThresholds& th = acq.thresholds;
  return {{"start_s", x.start_s},
          {"end_s", x.end_s},
          {"frames", x.frames},
          {"bucket_frames", x.bucket_frames},
          {"points", x.time_s.size()},
          {"time_first_s", x.time_s.empty() ? 0.0 : x.time_s.front()},
          {"time_step_s", step_s},
          {"traces", traces},
          {"pulse_channel", acq.pulse_channel},
          {"pulse_s", x.pulse_s},
          {"pulse_inserted", x.pulse_inserted},
          {"removed_edge_s", x.removed_edge_s},
          {"wheel_edge_s", x.wheel_edge_s},
          {"thresholds", {{"low_V", finite_or_null(th.low)}, {"high_V", finite_or_null(th.high)}, {"follows_baseline", th.follows_baseline}}},
          {"edge_level_V", finite_or_null(acq.edge_level_V)}};
}

json speed_json(const AcquisitionReport& acq) {
  std::size_t revolutions = 0;
  for (const auto& s : acq.pulses.segments) revolutions += s.size() - 1;
  const std::size_t k = std::max<std::size_t>(1, (revolutions + kSpeedMaxPoints - 1) / kSpeedMaxPoints);
  json time = json::array(), mean = json::array(), lo = json::array(), hi = json::array(), seg = json::array(),
       repaired = json::array();
  for (std::size_t si = 0; si < acq.pulses.segments.size(); ++si) {
    const std::vector<Pulse>& p = acq.pulses.segments[si];
    for (std::size_t i = 0; i + 1 < p.size(); i += k) {
      const std::size_t end = std::min(i + k, p.size() - 1);
      double sum = 0, mn = std::numeric_limits<double>::infinity(), mx = 0;
      bool rep = false;
      for (std::size_t j = i; j < end; ++j) {
        const double rpm = 60.0 / (p[j + 1].time_s - p[j].time_s);
        sum += rpm, mn = std::min(mn, rpm), mx = std::max(mx, rpm);
        rep |= p[j].inserted || p[j + 1].inserted;
      }
      time.push_back(p[i].time_s), mean.push_back(sum / static_cast<double>(end - i));
      lo.push_back(mn), hi.push_back(mx), seg.push_back(si), repaired.push_back(rep);
    }
  }
  return {{"revolutions_per_point", k},
          {"time_s", time},
          {"rpm", mean},
          {"rpm_min", lo},
          {"rpm_max", hi},
          {"segment", seg},
          {"repaired", repaired},
          {"mean_rpm", acq.speed.mean_rpm},
          {"std_rpm", acq.speed.std_rpm},
          {"source", (acq.wheel.positions_per_rev > 0 ? acq.wheel.source + ": one point per turn"
                                                      : std::string("once-per-turn pulses: 60 s / period")) +
                         (acq.range.active() ? "; only the turns in the manifest's range " + describe_range(acq.range)
                                             : std::string())},
          {"rule", k == 1 ? "one point per revolution, at its start"
                          : "one point per " + std::to_string(k) + " consecutive revolutions: mean, min and max"}};
}

json views_record(const RecordingAnalysis& a, const DeviationMapCollector& map, const json& record) {
  Manifest m = load_manifest(a.manifest_file);
  bind_channels(m, a.acquisition.recording);
  json v = {{"channels", channel_sheet_json(m, a.acquisition, record.value("setup_check", json(nullptr)))},
            {"excerpt", excerpt_json(a.acquisition)},
            {"speed", speed_json(a.acquisition)}};
  const std::string q = map.coupler() ? "alpha3_rad_s2" : "alpha4_rad_s2";
  const json* nominal = nullptr;
  if (record.contains("series") && record["series"].contains(q)) nominal = &record["series"][q]["nominal"];
  v["map"] = nominal ? map.map_json(nominal->get<std::vector<double>>(), a.crank_deg.empty() ? 0.0 : a.crank_deg[0],
                                    a.crank_direction)
                     : json(nullptr);
  return v;
}

}  // namespace fourbar

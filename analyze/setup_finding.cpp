#include "analyze/setup_finding.hpp"

#include "common/format.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fourbar {

std::string SetupCheck::status() const {
  if (!checked) return "not checked";
  return findings.empty() ? "ok" : "check set-up";
}

namespace {

std::string percent(double x) { return std::to_string(static_cast<int>(std::lround(100 * x))) + " %"; }

}  // namespace

std::string channel_key(const std::string& name, const std::string& key) {
  return "[[channel]] name=\"" + name + "\" " + key;
}

std::string finding_label(const std::string& item, const std::string& key) {
  if (key.rfind("[[channel]] ", 0) != 0 || key.find(" and ") != std::string::npos || key.find(" or ") != std::string::npos)
    return item;
  const std::size_t space = key.find_last_of(' ');
  const std::string leaf = key.substr(space + 1);
  return leaf.empty() || leaf.find('"') != std::string::npos ? item : leaf;
}

void add_finding(SetupCheck& out, std::string item, std::string channel, std::string key, std::string manifest,
                 std::string data, double confidence) {
  SetupFinding f{std::move(item), std::move(channel), std::move(key), std::move(manifest), std::move(data), confidence, {}};
  f.message = (f.channel.empty() ? std::string() : "channel '" + f.channel + "': ") + finding_label(f.item, f.key) + ": the manifest says " +
              f.manifest + ", the data say " + f.data + " (confidence " + percent(f.confidence) + "); change " + f.key;
  out.findings.push_back(std::move(f));
}

void add_corner_finding(SetupCheck& out, const ChannelSpec& channel, double data_corner_hz, double crank_hz,
                        double confidence) {
  const std::string manifest = channel.ac_coupled ? "ac_coupled = true, highpass_hz = " + format_number(channel.highpass_hz, 3)
                                                  : "ac_coupled = false (no high-pass)";
  // Below 2 % of the crank frequency a corner moves the first order by < 1.2°: DC and such a corner look alike.
  const double resolvable_hz = 0.02 * crank_hz;
  const std::string data =
      data_corner_hz < resolvable_hz
          ? "ac_coupled = false, or a high-pass corner below " + format_number(resolvable_hz, 2) + " Hz"
          : "ac_coupled = true, highpass_hz about " + format_number(data_corner_hz, 2) +
                " (the lowest crank orders come out scaled and shifted as that corner does)";
  add_finding(out, "highpass_hz", channel.name, channel_key(channel.name, "ac_coupled") + " and highpass_hz",
              manifest, data, confidence);
}

void add_channel_scale_findings(SetupCheck& out, const std::vector<std::pair<const ChannelSpec*, double>>& scales,
                                double tolerance) {
  for (const SetupFinding& f : out.findings)
    if (f.item == "common_scale") return;
  for (const auto& [spec, k] : scales) {
    const double deviation = std::abs(k - 1);
    if (deviation <= tolerance) continue;
    add_calibration_finding(out, *spec, k, std::clamp(1 - kChannelScaleSpread / deviation, 0.0, 1.0));
  }
}

void add_common_scale_finding(SetupCheck& out, const std::vector<double>& scales, double tolerance,
                              const std::string& rig_file, double sample_rate_hz, double min_confidence) {
  if (scales.size() < 2) return;
  double mean = 0, nearest = 1e300;
  bool above = true, below = true;
  for (double k : scales) {
    mean += (k - 1) / static_cast<double>(scales.size());
    nearest = std::min(nearest, std::abs(k - 1));
    above = above && k > 1, below = below && k < 1;
  }
  if (!(above || below) || nearest <= tolerance) return;
  double var = 0;
  for (double k : scales) var += (k - 1 - mean) * (k - 1 - mean) / static_cast<double>(scales.size());
  const double confidence = std::clamp(1 - std::sqrt(var) / std::abs(mean), 0.0, 1.0);
  if (confidence < min_confidence) return;
  std::string each;
  for (double k : scales) each += (each.empty() ? "" : ", ") + format_number(k, 3);
  add_finding(out, "common_scale", "", "the link lengths in " + rig_file + ", full_scale_V, or the recording's sample rate",
              "the rig's nominal motion (factor 1)",
              "every accelerometer reads " + format_number(1 + mean, 3) + " x it (" + each +
                  "); a cause common to all sensors: a wrong rig file, recording scale or sample rate (the file says " +
                  format_number(sample_rate_hz, 6) + " Hz; a DAQ that really sampled at about " +
                  format_number(sample_rate_hz * std::sqrt(1 + mean), 5) + " Hz would read so)",
              confidence);
}

std::string unit_mixup(double ratio) {
  // ratio = the data's calibration over the manifest's (V per m/s²). Each
  // known factor within 3 % (the scale's spread on correct manifests is
  // 2.4 %) is named; 10 and g lie 2 % apart, so a ×10 gain step and an
  // mV/g mix-up are both named when the data cannot tell them apart.
  constexpr double g = 9.80665;
  const std::pair<double, const char*> known[] = {
      {1 / g, "1/g = 1/9.81: a sensitivity in mV/g written as mV per m/s²; give it as sensitivity_mV_per_g"},
      {g, "g = 9.81: a sensitivity in mV per m/s² written as mV/g; give it as sensitivity_mV_per_m_s2"},
      {0.1, "1/10: a gain step of 10 (check gain and the amplifier's range)"},
      {10, "10: a gain step of 10 (check gain and the amplifier's range)"},
      {1e-3, "1/1000: a value in mV written where V are meant (volts_per_unit is in V per m/s²)"},
      {1e3, "1000: a value in V written where mV are meant (sensitivity_mV_per_… is in mV)"},
      {1e-3 / g, "1/(1000 g): a sensitivity in mV/g written as volts_per_unit (V per m/s²); give it as sensitivity_mV_per_g"},
      {1e3 * g, "1000 g: a value in V per m/s² written as mV/g; give it as volts_per_unit"}};
  std::string out;
  for (const auto& [factor, text] : known)
    if (std::abs(ratio / factor - 1) <= 0.03) out += (out.empty() ? "" : ", or ") + std::string(text);
  return out;
}

void add_calibration_finding(SetupCheck& out, const ChannelSpec& channel, double ratio, double confidence) {
  const double per = channel.calibration_per_volts_per_m_s2;
  const std::string mixup = unit_mixup(ratio);
  add_finding(out, "volts_per_unit", channel.name, channel_key(channel.name, channel.calibration_key),
              format_number(channel.volts_per_m_s2 * per, 4),
              format_number(channel.volts_per_m_s2 * per * ratio, 3) + " (" + format_number(ratio, 3) + " x" +
                  (mixup.empty() ? std::string() : ", a unit mix-up or gain step: the factor is " + mixup) + ")",
              confidence);
}

void add_rig_file_finding(SetupCheck& out, const std::vector<std::pair<const ChannelSpec*, double>>& scales,
                          double tolerance, const std::string& rig_file, const std::string& rig_name) {
  double confidence = 0;
  for (const SetupFinding& f : out.findings) {
    if (f.item == "common_scale") return;
    if (f.item == "volts_per_unit") confidence = std::max(confidence, f.confidence);
  }
  std::vector<double> off;
  std::string each;
  for (const auto& [spec, k] : scales) {
    each += (each.empty() ? "" : ", ") + spec->name + " " + format_number(k, 3) + " x";
    if (std::abs(k - 1) > tolerance) off.push_back(k);
  }
  if (off.size() < 2 || confidence <= 0) return;
  // Different factors: the largest and smallest off-channel differ by more than the tolerance.
  const auto [lo, hi] = std::minmax_element(off.begin(), off.end());
  if (*hi / *lo < 1 + tolerance) return;
  SetupCheck rig;
  add_finding(rig, "rig_file", "", "rig (the manifest's rig file)",
              "\"" + rig_file + "\"" + (rig_name.empty() ? std::string() : " ('" + rig_name + "')"),
              "the accelerometers read the rig's nominal motion at different factors (" + each +
                  "), as a rig file with other link lengths makes them; check that rig names this rig's file before "
                  "changing any calibration",
              confidence);
  out.findings.insert(out.findings.begin(), std::move(rig.findings.front()));
}

}  // namespace fourbar

#include "virtual_rig/recording_spec.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "acquire/manifest.hpp"
#include "acquire/sndfile_formats.hpp"
#include "common/error.hpp"
#include "common/number_text.hpp"
#include "common/toml_section.hpp"
#include "common/toml_writer.hpp"
#include "common/units.hpp"

namespace fourbar {

namespace {

/// Takes the array `key` out of `table` (TomlSection reads no number arrays),
/// checking each element with `ok`; InputError naming file, line and key.
template <class T, class Ok>
std::optional<std::vector<T>> take_array(toml::table& table, std::string_view key, const Scene& scene,
                                         const std::string& dotted, Ok ok, const char* what) {
  toml::node* n = table.get(key);
  if (!n) return std::nullopt;
  const std::string where = scene.source.string() + ":" + std::to_string(n->source().begin.line) + ": key '" +
                            dotted + "' ";
  const toml::array* arr = n->as_array();
  if (!arr) throw InputError(where + "must be an array of " + what);
  std::vector<T> out;
  for (const auto& el : *arr) {
    const auto v = el.value<T>();
    if (!v || !ok(*v)) throw InputError(where + "must hold only " + what);
    out.push_back(*v);
  }
  table.erase(key);
  return out;
}

ChannelRole role_of(const std::string& name) {
  const auto names = channel_role_names();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<ChannelRole>(i);
  return ChannelRole::ignore;
}

}  // namespace

double recording_run_in_s(const RecordingSpec& spec) {
  double run_in_s = 0;
  for (const ChannelSpec& c : spec.sensors) {
    if (c.ac_coupled) run_in_s = std::max(run_in_s, 12.0 / (units::kTwoPi * c.highpass_hz));
    std::vector<AnalogSection> sections = daq_filter_sections(spec.daq_filter);
    if (c.sensor_resonance_hz > 0) sections.push_back({2, c.sensor_resonance_hz, c.sensor_resonance_q});
    for (const AnalogSection& a : sections)
      run_in_s = std::max(run_in_s, 12.0 * (a.order == 2 ? 2.0 * a.q : 1.0) / (units::kTwoPi * a.f0_hz));
  }
  return run_in_s + spec.daq_filter.delay_s + 2.0 / spec.sample_rate_hz;
}

RecordingSpec read_recording_spec(const Scene& scene) {
  if (!scene.recording)
    throw InputError(scene.source.string() + ": no [recording] table; the virtual rig needs one (see "
                     "'fourbar virtual-rig --help')");
  // Re-read the table from the scene file when there is one: a copied TOML
  // table loses its line numbers, and errors should name the line.
  toml::table parsed, copy;
  toml::table* found = nullptr;
  std::error_code ec;
  if (!scene.source.empty() && std::filesystem::is_regular_file(scene.source, ec)) {
    parsed = parse_toml_file(scene.source);
    found = parsed["recording"].as_table();
  }
  if (!found) copy = *scene.recording, found = &copy;
  toml::table& table = *found;
  RecordingSpec spec;
  if (auto h = take_array<double>(table, "hum_harmonics", scene, "recording.hum_harmonics",
                                  [](double v) { return std::isfinite(v) && v >= 0; }, "numbers >= 0, e.g. [1.0, 0.3]"))
    spec.hum_harmonics = *h;
  if (auto h = take_array<double>(table, "speed_harmonics_pct", scene, "recording.speed_harmonics_pct",
                                  [](double v) { return std::isfinite(v) && std::abs(v) <= 20; },
                                  "numbers within ±20, e.g. [0.5, 0.3]")) {
    for (double v : *h) spec.speed_harmonics.push_back(v * 1e-2);
  }
  if (toml::table* pt = table["pulse"].as_table()) {
    auto whole = [](long long v) { return v >= 0; };
    if (auto v = take_array<long long>(*pt, "missing", scene, "recording.pulse.missing", whole, "pulse numbers >= 0"))
      spec.pulse.missing = *v;
    if (auto v = take_array<long long>(*pt, "echo", scene, "recording.pulse.echo", whole, "pulse numbers >= 0"))
      spec.pulse.echo = *v;
  }
  TomlSection r(table, scene.source, "recording");
  spec.sample_rate_hz = r.in_range("sample_rate_hz", 1, 10e6);
  if (r.has("duration_s") == r.has("revolutions"))
    r.fail("duration_s", "and 'recording.revolutions': give exactly one of them");
  if (r.has("duration_s")) spec.duration_s = r.in_range("duration_s", 1e-3, 1e6);
  else spec.revolutions = r.in_range("revolutions", 0.01, 1e7);
  if (r.has("sample_format")) {
    std::vector<std::string> names;
    for (const auto& s : sndfile_subtypes()) names.emplace_back(s.name);
    spec.sample_format = r.choice("sample_format", names);
  }
  spec.full_scale_V = r.in_range("full_scale_V", 1e-6, 1e6, 10.0);
  if (r.has("quantisation_bits")) spec.quantisation_bits = static_cast<int>(r.integer("quantisation_bits", 4, 32));
  spec.noise_snr_db = r.optional_number("noise_snr_db");
  spec.hum_frequency_hz = r.in_range("hum_frequency_hz", 1, 1e4, 50.0);
  spec.hum_V = r.in_range("hum_mV", 0, 1e6, 0.0) * 1e-3;
  spec.speed_fluctuation = r.in_range("speed_fluctuation_pct", 0, 50, 0.0) * 1e-2;
  if (r.has("speed_fluctuation_period_s"))
    spec.speed_fluctuation_period_s = r.in_range("speed_fluctuation_period_s", 1e-3, 1e6);
  spec.daq_filter = read_daq_filter(r);
  spec.multiplexed = r.choice("sampling", {"simultaneous", "multiplexed"}, "simultaneous") == "multiplexed";
  if (r.has("skew_us")) {
    if (!spec.multiplexed) r.fail("skew_us", "is for sampling = \"multiplexed\"; add that key or remove this one");
    spec.skew_s = r.in_range("skew_us", 0, 1e6) * 1e-6;
  }
  spec.seed = static_cast<std::uint64_t>(r.integer("seed", 0, std::numeric_limits<long long>::max(), 1));
  if (auto n = r.optional_string("notes")) spec.notes = *n;
  if (r.has("warmup_revolutions")) {
    if (scene.model != Model::clearance && scene.model != Model::linkage)
      r.fail("warmup_revolutions", "is for clearance and linkage scenes (model = \"clearance\" or \"linkage\") only; remove it");
    spec.warmup_revolutions = static_cast<int>(r.integer("warmup_revolutions", 0, 100000));
  }

  std::vector<std::string> accel_roles;
  for (const auto& name : channel_role_names())
    if (is_accelerometer(role_of(name))) accel_roles.push_back(name);
  for (auto& s : r.sections("sensor")) spec.sensors.push_back(read_channel_spec(s, false, accel_roles));
  for (std::size_t i = 0; i < spec.sensors.size(); ++i) {
    ChannelSpec& c = spec.sensors[i];
    if (c.name.empty()) c.name = std::string(to_string(c.role)) + (i ? "_" + std::to_string(i) : "");
    for (std::size_t j = 0; j < i; ++j)
      if (spec.sensors[j].name == c.name)
        throw InputError(scene.source.string() + ": recording.sensor[" + std::to_string(i) + "] has the name '" +
                         c.name + "' of sensor[" + std::to_string(j) + "]; give each a different 'name'");
    c.index = static_cast<int>(i);
  }

  for (auto& lm : r.sections("link_mode")) {
    if (scene.model == Model::linkage)
      lm.fail("link", "(recording.link_mode) is the clearance model's stand-in for link vibration; a linkage scene's "
                      "links vibrate by themselves when elastic ([linkage] elastic_links, the rig's [<link>.elastic] "
                      "table): remove the [[recording.link_mode]] tables");
    if (scene.model != Model::clearance)
      lm.fail("link", "(recording.link_mode) needs a clearance scene (model = \"clearance\"): the bearing impacts ring the links; remove it");
    LinkMode m;
    m.link = lm.choice("link", {"coupler", "rocker"}) == "coupler" ? RingingLink::coupler : RingingLink::rocker;
    m.frequency_hz = lm.in_range("frequency_hz", 1, 1e6);
    if (m.frequency_hz >= 0.5 * spec.sample_rate_hz)
      lm.fail("frequency_hz", "= " + format_double(m.frequency_hz) + " is at or above the Nyquist frequency " +
                                  format_double(0.5 * spec.sample_rate_hz) + " Hz of recording.sample_rate_hz; lower it or raise the rate");
    m.damping_ratio = lm.in_range("damping_ratio", 1e-5, 0.9, 0.02);
    m.modal_mass_kg = lm.in_range("modal_mass_kg", 1e-6, 1e6);
    m.shape_at_bearing = lm.in_range("shape_at_bearing", -1e3, 1e3, 1.0);
    m.shape_at_sensor = lm.in_range("shape_at_sensor", -1e3, 1e3, 1.0);
    lm.finish();
    spec.link_modes.push_back(m);
  }

  TomlSection p = r.section("pulse");
  PulseSpec& pulse = spec.pulse;
  if (auto n = p.optional_string("name")) {
    if (!is_channel_name(*n)) p.fail("name", "= " + toml_quoted(*n) + " " + kChannelNameRule);
    pulse.name = *n;
  }
  pulse.angle_rad = units::deg_to_rad(p.in_range("angle_deg", -360, 360, 0.0));
  pulse.low_V = p.in_range("low_V", -1e6, 1e6, 0.0);
  pulse.high_V = p.in_range("high_V", -1e6, 1e6, 5.0);
  if (!(pulse.high_V > pulse.low_V)) p.fail("high_V", "must be above low_V");
  pulse.polarity = p.choice("polarity", {"rising", "falling"}, "rising") == "rising" ? PulsePolarity::rising
                                                                                   : PulsePolarity::falling;
  pulse.width_rad = units::deg_to_rad(p.in_range("width_deg", 0.01, 180, 10.0));
  pulse.rise_s = p.in_range("rise_us", 0, 1e6, 0.0) * 1e-6;
  if (pulse.rise_s == 0) pulse.rise_s = 4.0 / spec.sample_rate_hz;  // default: four samples
  pulse.jitter_s = p.in_range("jitter_us", 0, 1e6, 0.0) * 1e-6;
  pulse.noise_V = p.in_range("noise_mV", 0, 1e6, 0.0) * 1e-3;
  pulse.echo_delay_s = p.in_range("echo_delay_ms", 0, 1e6, 1.0) * 1e-3;
  p.finish();
  if (auto wt = r.optional_section("wheel")) {
    WheelSpec& w = spec.wheel;
    w.teeth = static_cast<int>(wt->integer("teeth", 0, 100000, 0));
    w.missing_teeth = static_cast<int>(wt->integer("missing_teeth", 0, 100000, 0));
    w.encoder_lines = static_cast<int>(wt->integer("encoder_lines", 0, 1 << 22, 0));
    w.index = wt->boolean("index", false);
    if (wt->has("index_offset_pitch")) {
      // The index names the edge it coincides with or the first after it:
      // tooth (line) 0 within one pitch (an encoder's: one quadrature edge).
      const bool enc = wt->has("encoder_lines");
      w.index_offset_pitch = enc ? wt->in_range("index_offset_pitch", -0.1875, 0.0625)
                                 : wt->in_range("index_offset_pitch", -0.75, 0.25);
      if (!w.index) wt->fail("index_offset_pitch", "places the index channel: set index = true too");
    }
    w.tooth_error_rad = units::deg_to_rad(wt->in_range("tooth_error_deg", 0, 10, 0.0));
    w.correct_tooth_spacing = wt->boolean("correct_tooth_spacing", false);
    if ((w.teeth > 0) == (w.encoder_lines > 0)) wt->fail("teeth", "and 'encoder_lines': give exactly one of them");
    if (w.teeth == 1) wt->fail("teeth", "must be at least 2 (one tooth is the [recording.pulse])");
    if (w.missing_teeth > 0 && (w.encoder_lines > 0 || w.index || 2 * w.missing_teeth >= w.teeth))
      wt->fail("missing_teeth", "is for a tooth wheel without index, below half the teeth");
    if (w.teeth > 0 && w.missing_teeth == 0 && !w.index)
      wt->fail("index", "must be true for a wheel without missing teeth (the turns must be countable)");
    wt->finish();
  }
  r.finish();

  if (spec.sample_format && spec.quantisation_bits)
    if (auto st = sndfile_subtype(*spec.sample_format); st && st->integer_bits > 0)
      r.fail("quantisation_bits", "is for float or text outputs; sample_format = \"" + *spec.sample_format +
                                      "\" already fixes " + std::to_string(st->integer_bits) + " bits");
  return spec;
}

}  // namespace fourbar

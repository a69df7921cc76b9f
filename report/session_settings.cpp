#include "report/session_settings.hpp"

#include <cstdio>

#include "report/comparison_record.hpp"

#include <algorithm>
#include <set>

#include "acquire/manifest.hpp"
#include "common/error.hpp"
#include "common/number_text.hpp"
#include "common/toml_section.hpp"
#include "common/units.hpp"

namespace fourbar {

namespace {

const char* kSessionFile = "session.toml";

ContactLaw contact_from(const std::string& s) {
  if (s == "rough") return ContactLaw::rough;
  if (s == "stick-slip") return ContactLaw::stick_slip;
  return ContactLaw::smooth;
}

/// The compliant contact's keys, read with the scene's reader (same names,
/// checks and messages), over the values `s` holds.
void read_compliant_theory(TomlSection& t, TheorySettings& s) {
  ClearanceSettings c;
  c.restitution = s.restitution;
  c.friction_coefficient = s.friction_coefficient;
  c.compliant = s.compliant;
  read_compliant_settings(t, c);
  s.compliant = c.compliant;
  s.friction_coefficient = c.friction_coefficient;
}

/// [theory] keys (also allowed in each [[recording]]), over `base`.
TheorySettings read_theory(TomlSection& t, TheorySettings s, const std::string& source) {
  s.source = source;
  s.restitution = t.in_range("restitution", 0.0, 1.0, s.restitution);
  if (t.has("model")) {
    const ClearanceKind m =
        t.choice("model", {"three-mode", "compliant"}) == "compliant" ? ClearanceKind::compliant : ClearanceKind::three_mode;
    if (m != s.model) s.friction_coefficient = 0;  // μ means the impact law's or the wall's: not carried over
    s.model = m;
  }
  if (s.model == ClearanceKind::compliant) {
    read_compliant_theory(t, s);
  } else {
    for (const char* key : {"damping", "contact_stiffness_N_per_m_n", "contact_exponent", "friction_stick_speed_mm_s",
                            "friction_slip_speed_mm_s", "damping_floor_speed_mm_s"})
      if (t.has(key)) t.fail(key, "is only used with model = \"compliant\"; remove it or set model = \"compliant\"");
    if (t.has("contact")) s.contact = contact_from(t.choice("contact", {"smooth", "rough", "stick-slip"}));
    if (t.has("friction_coefficient")) {
      if (s.contact != ContactLaw::stick_slip)
        t.fail("friction_coefficient", "is used only with contact = \"stick-slip\"; set contact or remove it");
      s.friction_coefficient = t.in_range("friction_coefficient", 0.0, 100.0);  // the scene's bounds for μ
    }
    // As in a scene: stick-slip without μ would silently be smooth contact.
    if (t.has("contact") && s.contact == ContactLaw::stick_slip && !t.has("friction_coefficient") &&
        s.friction_coefficient == 0)
      t.fail("contact", "= \"stick-slip\" needs friction_coefficient (Coulomb's mu of the bearing); add it, or use "
                        "contact = \"smooth\"");
  }
  s.warmup_revolutions = static_cast<int>(t.integer("warmup_revolutions", 0, 10000, s.warmup_revolutions));
  s.averaged_revolutions = static_cast<int>(t.integer("averaged_revolutions", 1, 10000, s.averaged_revolutions));
  s.tolerance = t.in_range("tolerance", 1e-14, 1e-4, s.tolerance);
  s.max_order = static_cast<int>(t.integer("max_order", 1, 100000, s.max_order));
  return s;
}

void read_analysis(TomlSection& a, AnalyzeOptions& o) {
  o.grid_points_per_rev = static_cast<std::size_t>(a.integer("points_per_rev", 0, 1 << 20, 0));
  if (o.grid_points_per_rev != 0 && o.grid_points_per_rev < 4)
    a.fail("points_per_rev", "= " + std::to_string(o.grid_points_per_rev) +
                                 " must be at least 4 crank angles per revolution (or 0: automatic)");
  if (a.has("low_hz")) o.filter.low_hz = a.positive("low_hz");
  if (a.has("high_hz")) o.filter.high_hz = a.positive("high_hz");
  o.filter.mains_hz = a.in_range("mains_hz", 0, 1e5, 0.0);
  o.filter.mains_width_hz = a.in_range("mains_width_hz", 1e-6, 1e4, o.filter.mains_width_hz);
  if (a.has("window")) {
    const std::string w = a.string("window");
    try {
      o.filter.window = parse_window(w, "analysis.window");
    } catch (const InputError& e) {
      a.fail("window", e.what());
    }
  }
  if (a.has("transition_hz")) {
    o.filter.transition_hz = a.non_negative("transition_hz");
    if (*o.filter.transition_hz == 0 && o.filter.window.type != WindowType::rectangular)
      a.fail("transition_hz", "= 0 (the ideal bin-wise filter) takes window = \"rectangular\", not \"" +
                                  to_string(o.filter.window) + "\"; set the window or a transition width > 0");
  }
  o.guard_revolutions = static_cast<std::size_t>(a.integer("guard_revolutions", 0, 1000, 0));
  if (a.has("integration")) {
    const std::string m = a.choice("integration", {"spectral", "closed_trapezoid", "trapezoid"});
    o.integration = m == "trapezoid" ? IntegrationMethod::trapezoid
                    : m == "closed_trapezoid" ? IntegrationMethod::closed_trapezoid
                                              : IntegrationMethod::spectral;
  }
}

}  // namespace

const TheorySettings& SessionSettings::theory_for(const std::string& recording_file) const {
  const auto it = theory_by_recording.find(recording_file);
  return it == theory_by_recording.end() ? theory : it->second;
}

nlohmann::json SessionSettings::to_json() const {
  nlohmann::json a = {{"points_per_rev", analysis.grid_points_per_rev == 0 ? nlohmann::json("auto") : nlohmann::json(analysis.grid_points_per_rev)},
                      {"low_hz", analysis.filter.low_hz ? nlohmann::json(*analysis.filter.low_hz) : nlohmann::json("auto")},
                      {"high_hz", analysis.filter.high_hz ? nlohmann::json(*analysis.filter.high_hz) : nlohmann::json("auto")},
                      {"mains_hz", analysis.filter.mains_hz},
                      {"mains_width_hz", analysis.filter.mains_width_hz},
                      {"window", to_string(analysis.filter.window)},
                      {"transition_hz", analysis.filter.transition_hz ? nlohmann::json(*analysis.filter.transition_hz) : nlohmann::json("auto")},
                      {"guard_revolutions", analysis.guard_revolutions},
                      {"integration", to_string(analysis.integration)},
                      {"conversion", to_string(analysis.conversion)}};
  nlohmann::json per = nlohmann::json::object();
  for (const auto& [name, t] : theory_by_recording) per[name] = theory_settings_json(t);
  return {{"file", file.empty() ? nlohmann::json(nullptr) : nlohmann::json(file.filename().string())},
          {"title", title},
          {"notes", notes},
          {"date", date},
          {"operator", operator_name},
          {"rig_id", rig_id},
          {"bearing", bearing},
          {"analysis", a},
          {"theory", theory_settings_json(theory)},
          {"model_family", {{"band_width_hz", model_family.band_width_hz}, {"max_frequency_hz", model_family.max_frequency_hz},
                            {"contact_stiffness_N_per_m_n", model_family.contact_stiffness_N_per_m_n}}},
          {"theory_by_recording", per}};
}

SessionSettings load_session_settings(const std::filesystem::path& dir) {
  SessionSettings s;
  s.title = std::filesystem::absolute(dir).lexically_normal().filename().string();
  if (s.title.empty()) s.title = std::filesystem::absolute(dir).lexically_normal().parent_path().filename().string();
  s.analysis.keep_revolutions = true;
  const std::filesystem::path file = dir / kSessionFile;
  if (!std::filesystem::exists(file)) return s;
  s.file = file;
  const toml::table table = parse_toml_file(file);
  TomlSection root(table, file);
  if (auto t = root.optional_string("title")) s.title = *t;
  if (auto n = root.optional_string("notes")) s.notes = *n;
  // The date is text as the operator writes it; a bare TOML date is asked for in quotes.
  if (const auto d = table["date"].value<toml::date>()) {
    char text[16];
    std::snprintf(text, sizeof text, "%04d-%02d-%02d", static_cast<int>(d->year), static_cast<int>(d->month),
                  static_cast<int>(d->day));
    root.fail("date", std::string("is a TOML date; write it as text: date = \"") + text + "\"");
  }
  if (auto ds = root.optional_string("date")) s.date = *ds;
  if (auto o = root.optional_string("operator")) s.operator_name = *o;
  if (auto r = root.optional_string("rig_id")) s.rig_id = *r;
  if (auto b = root.optional_string("bearing")) s.bearing = *b;
  if (auto a = root.optional_section("analysis")) {
    read_analysis(*a, s.analysis);
    a->finish();
  }
  if (auto t = root.optional_section("theory")) {
    s.theory = read_theory(*t, s.theory, std::string(kSessionFile) + " [theory]");
    t->finish();
  }
  if (auto m = root.optional_section("model_family")) {
    s.model_family.band_width_hz = m->in_range("band_width_hz", 1, 1e5, s.model_family.band_width_hz);
    s.model_family.max_frequency_hz = m->in_range("max_frequency_hz", 1, 1e7, 0.0);
    s.model_family.contact_stiffness_N_per_m_n = m->in_range("contact_stiffness_N_per_m_n", 1e3, 1e15, 0.0);
    m->finish();
  }
  std::set<std::string> recordings;  // what a [[recording]] may name: the folder's recordings, nothing else
  for (const auto& p : find_session_files(dir).recordings) recordings.insert(p.filename().string());
  for (TomlSection& r : root.sections("recording")) {
    const std::string name = r.string("file");
    if (!recordings.count(name))
      r.fail("file", "'" + name + "' is not a recording in the session folder " + dir.string() +
                         " (a file name with its extension, e.g. \"run1.flac\", as fourbar report lists it)");
    if (s.theory_by_recording.count(name)) r.fail("file", "'" + name + "' has two [[recording]] tables; merge them");
    s.theory_by_recording[name] = read_theory(r, s.theory, std::string(kSessionFile) + " [[recording]] " + name);
    r.finish();
  }
  root.finish();
  return s;
}

void check_band_limit(const SessionSettings& s, const std::string& recording, double fs) {
  const double top = s.model_family.max_frequency_hz;
  if (top > 0 && fs > 0 && top > 0.5 * fs)
    throw InputError((s.file.empty() ? std::string(kSessionFile) : s.file.string()) + ": key 'model_family.max_frequency_hz' = " +
                     format_double(top) + " Hz lies above the Nyquist frequency " + format_double(0.5 * fs) + " Hz of " +
                     recording + " (sampled at " + format_double(fs) + " Hz): the recording holds nothing there; give at most " +
                     format_double(0.5 * fs) + " or leave the key out (the check then ends at the analysis filter's upper corner)");
}

SessionFiles find_session_files(const std::filesystem::path& dir) {
  if (!std::filesystem::is_directory(dir))
    throw InputError(dir.string() + ": not a folder; give the session folder that holds the recordings");
  static const std::set<std::string> kExtensions{".wav", ".w64", ".rf64", ".flac", ".caf", ".aiff", ".aif",
                                                 ".mat", ".csv", ".tsv", ".txt"};
  SessionFiles f;
  std::set<std::string> stems;
  std::vector<std::filesystem::path> manifests;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const std::filesystem::path p = e.path();
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const std::string name = p.filename().string();
    if (ext == ".toml") {
      if (name != kSessionFile) manifests.push_back(p);
    } else if (kExtensions.count(ext) && !name.ends_with(".truth.csv")) {
      f.recordings.push_back(p);
      stems.insert(p.stem().string());
    } else if (!name.starts_with(".") && !name.ends_with(".truth.csv") && !name.ends_with(".csv.json")) {
      f.other_files.push_back(p);
    }
  }
  std::sort(f.other_files.begin(), f.other_files.end());
  for (const auto& m : manifests)
    if (!stems.count(m.stem().string())) f.orphan_manifests.push_back(m);
  std::sort(f.recordings.begin(), f.recordings.end());
  std::sort(f.orphan_manifests.begin(), f.orphan_manifests.end());
  return f;
}

}  // namespace fourbar

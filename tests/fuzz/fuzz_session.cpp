// Fuzz target: a session folder's session.toml (report/session_settings.cpp):
// title, notes, [analysis], [theory] with either model's keys (three-mode:
// restitution, contact, friction_coefficient; compliant: the scene's
// compliant keys, read by sim/three_mode/compliant_settings.cpp) and the
// [[recording]] tables that override them per recording. `fourbar fit`
// reads the same file for its prior.
//
// A session that loads must be usable as `fourbar report` and `fourbar fit`
// use it, with no exception but InputError:
//  * its settings as JSON (the report's settings table and cache key);
//  * its [analysis] options accepted by the analysis (validate_options): a
//    bad value is refused here, naming the session.toml key, not once per
//    recording naming a command-line option;
//  * every theory within the bounds a scene's [clearance] table accepts for
//    the same keys (the same simulators run both);
//  * a compliant theory's stiffness resolved against a rig without bearing
//    bodies (InputError naming the key) and one with them (finite, > 0), as
//    the matched theory does once the recording's rig is known;
//  * every [[recording]] names a recording of the folder.
// The folder holds three recordings (empty files: only their names matter)
// and a rig file, which a [[recording]] must not be able to name.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>

#include "common/error.hpp"
#include "common/json_text.hpp"
#include "fuzz_support.hpp"
#include "mechanism/rig.hpp"
#include "report/comparison_record.hpp"
#include "report/session_settings.hpp"
#include "sim/compliant/contact_stiffness.hpp"

namespace {

using namespace fourbar;

constexpr double kClearance_m = 0.254e-3;

const std::filesystem::path& session_dir() {
  static const std::filesystem::path dir = [] {
    const auto d = fuzz::workspace().dir() / "session";
    std::filesystem::create_directories(d);
    for (const char* name : {"run1.flac", "run2.csv", "run 3.wav", "rig.toml"}) std::ofstream(d / name) << "";
    return d;
  }();
  return dir;
}

/// The thesis rig with a steel pin in a bronze bushing (the bearing bodies
/// the compliant contact's stiffness is computed from).
Rig rig_with_bearing() {
  Rig rig = thesis_rig();
  rig.bearing.pin_radius_m = 10e-3;
  rig.bearing.bushing_radius_m = 10e-3 + kClearance_m;
  rig.bearing.length_m = 10e-3;
  rig.bearing.pin_youngs_modulus_Pa = 210e9;
  rig.bearing.pin_poisson_ratio = 0.3;
  rig.bearing.bushing_youngs_modulus_Pa = 110e9;
  rig.bearing.bushing_poisson_ratio = 0.34;
  return rig;
}

void require(bool ok) {
  if (!ok) std::abort();
}

void check_theory(const TheorySettings& t) {
  // The bounds of the scene's [clearance] reader for the same keys.
  require(t.restitution >= 0 && t.restitution <= 1);
  require(t.friction_coefficient >= 0 && t.friction_coefficient <= 100);
  require(t.tolerance > 0 && std::isfinite(t.tolerance));
  require(t.warmup_revolutions >= 0 && t.averaged_revolutions >= 1 && t.max_order >= 1);
  (void)json_text(theory_settings_json(t));
  if (t.model != ClearanceKind::compliant) return;
  const CompliantSettings& k = t.compliant;
  require(k.exponent >= 1 && k.exponent <= 3);
  require(k.friction_stick_speed_m_s >= 0 && k.friction_slip_speed_m_s > k.friction_stick_speed_m_s);
  require(k.damping_floor_speed_m_s > 0 && std::isfinite(k.damping_floor_speed_m_s));
  require(!k.stiffness_given || (k.stiffness_N_per_m_n > 0 && std::isfinite(k.stiffness_N_per_m_n)));
  static const Rig bare = thesis_rig(), with_bearing = rig_with_bearing();
  for (const Rig* rig : {&bare, &with_bearing}) {
    ClearanceSettings cs;
    cs.model = t.model;
    cs.restitution = t.restitution;
    cs.friction_coefficient = t.friction_coefficient;
    cs.compliant = t.compliant;
    try {
      resolve_contact_stiffness(*rig, kClearance_m, cs, [](const char* key, const std::string& what) {
        throw InputError(std::string(key) + " " + what);
      });
    } catch (const InputError&) {
      require(rig == &bare || k.exponent != 1.5);  // with the bearing's bodies and n = 1.5, K is always computable
      continue;
    }
    require(cs.compliant.stiffness_N_per_m_n > 0 && std::isfinite(cs.compliant.stiffness_N_per_m_n));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path& dir = session_dir();
  fuzz::workspace().write("session/session.toml", data, size);
  SessionSettings s;
  try {
    s = load_session_settings(dir);
  } catch (const InputError&) {
    return 0;
  }
  (void)json_text(s.to_json());
  try {
    validate_options(s.analysis);
  } catch (const InputError&) {
    std::abort();
  }
  check_theory(s.theory);
  static const std::set<std::string> recordings = [&] {
    std::set<std::string> names;
    for (const auto& p : find_session_files(dir).recordings) names.insert(p.filename().string());
    return names;
  }();
  for (const auto& [name, theory] : s.theory_by_recording) {
    require(recordings.count(name) == 1);
    require(&s.theory_for(name) != &s.theory);
    check_theory(theory);
  }
  return 0;
}

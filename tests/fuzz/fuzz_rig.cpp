// Fuzz target: the rig loader (mechanism/rig.cpp, common/toml_section.cpp),
// with the bearing's bodies of its [clearance] table (radii, length, Young's
// moduli, Poisson ratios). A rig that loads must be usable: its report walks
// a whole turn, and with a clearance the compliant contact's stiffness
// computed from its bodies (sim/compliant/contact_stiffness.cpp, what a
// scene or session without contact_stiffness_N_per_m_n uses) is either
// refused naming a key (InputError) or finite and positive.
#include <cmath>
#include <cstdlib>
#include <string>

#include "common/error.hpp"
#include "fuzz_support.hpp"
#include "mechanism/rig.hpp"
#include "mechanism/rig_report.hpp"
#include "sim/compliant/contact_stiffness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fourbar;
  const auto file = fuzz::workspace().write("fuzz_rig.toml", data, size);
  Rig rig;
  try {
    rig = load_rig(file);
    (void)report_rig(rig);  // a loaded rig must be usable: the report walks a whole turn
  } catch (const InputError&) {
    return 0;
  }
  if (!(rig.radial_clearance_m > 0)) return 0;
  ClearanceSettings cs;
  cs.model = ClearanceKind::compliant;
  try {
    resolve_contact_stiffness(rig, rig.radial_clearance_m, cs, [](const char* key, const std::string& what) {
      throw InputError(std::string(key) + " " + what);
    });
  } catch (const InputError&) {
    return 0;
  }
  const double k = cs.compliant.stiffness_N_per_m_n;
  if (!(k > 0) || !std::isfinite(k)) std::abort();
  return 0;
}

#include "sim/scene.hpp"

#include <algorithm>
#include <cmath>

#include "common/csv_writer.hpp"
#include "common/error.hpp"
#include "common/toml_section.hpp"
#include "common/units.hpp"
#include "sim/compliant/contact_stiffness.hpp"
#include "sim/outputs.hpp"

namespace fourbar {

namespace {

/// The requested outputs: each must be one the model computes, none twice,
/// crank_deg never (it is always the first column).
std::vector<std::string> read_outputs(TomlSection& root, Model model) {
  std::vector<std::string> outputs = root.strings("outputs");
  if (outputs.empty()) root.fail("outputs", "is empty; name at least one output (see 'fourbar sim --help')");
  const bool clearance = model != Model::nominal;
  std::vector<std::string> known;
  if (clearance)
    for (const auto& o : clearance_outputs()) known.emplace_back(o.name);
  else
    for (const auto& o : nominal_outputs()) known.emplace_back(o.name);
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const std::string& name = outputs[i];
    if (name == "crank_deg")
      root.fail("outputs", "names 'crank_deg', which is always the first column; remove it");
    if (clearance && !find_clearance_output(name) && find_output(name))
      root.fail("outputs", "names '" + name + "', which the clearance model does not compute; remove it");
    if (!clearance && find_clearance_output(name) && !find_output(name))
      root.fail("outputs", "names '" + name + "', which only model = \"clearance\" computes; remove it");
    if (clearance ? !find_clearance_output(name) : !find_output(name)) {
      std::string hint;
      if (auto m = closest_match(name, known)) hint = " (did you mean '" + *m + "'?)";
      root.fail("outputs", "names unknown output '" + name + "'" + hint +
                               "; 'fourbar sim --help' lists the outputs");
    }
    if (std::find(outputs.begin(), outputs.begin() + static_cast<std::ptrdiff_t>(i), name) !=
        outputs.begin() + static_cast<std::ptrdiff_t>(i))
      root.fail("outputs", "names '" + name + "' twice");
  }
  return outputs;
}

}  // namespace

Scene load_scene(const std::filesystem::path& file) {
  const toml::table doc = parse_toml_file(file);
  TomlSection root(doc, file);
  Scene scene;
  scene.source = file;

  const std::filesystem::path rig_file = root.path("rig");
  try {
    scene.rig = std::make_shared<const Rig>(load_rig(rig_file));
  } catch (const InputError& e) {
    throw InputError(root.where("rig") + ": " + e.what());
  }

  const std::string model = root.choice("model", {"nominal", "clearance", "linkage"}, "nominal");
  scene.model = model == "nominal" ? Model::nominal : model == "clearance" ? Model::clearance : Model::linkage;
  const toml::node* linkage_table = doc.get("linkage");
  const bool crank_table = scene.model == Model::linkage && linkage_table && linkage_table->is_table() &&
                           linkage_table->as_table()->contains("crank_motion");

  if (crank_table) {
    if (root.has("crank_speed_rpm"))
      root.fail("crank_speed_rpm", "is not used: [linkage] crank_motion prescribes the crank; remove one of them");
  } else {
    const double rpm = root.in_range("crank_speed_rpm", -1e5, 1e5);
    if (rpm == 0) root.fail("crank_speed_rpm", "= 0: the crank must turn; give a speed (negative turns clockwise)");
    scene.crank_speed_rad_s = units::rpm_to_rad_s(rpm);
  }
  if (crank_table && root.has("start_angle_deg"))
    root.fail("start_angle_deg", "is not used: [linkage] crank_motion gives the crank angle; remove it");
  scene.start_angle_rad = units::deg_to_rad(root.in_range("start_angle_deg", -360.0, 360.0, 0.0));
  scene.revolutions = static_cast<int>(root.integer("revolutions", 1, 1'000'000, 1));
  scene.samples_per_revolution = static_cast<int>(root.integer("samples_per_revolution", 4, 10'000'000, 360));

  scene.outputs = read_outputs(root, scene.model);

  if (auto sec = root.optional_section("clearance")) {
    if (scene.model != Model::clearance)
      root.fail("clearance", "is only used with model = \"clearance\"; remove the table or change model (model = "
                             "\"linkage\" reads [linkage])");
    scene.clearance = read_clearance_settings(*sec, scene.rig->radial_clearance_m);
    if (const double margin = toggle_margin_m(*scene.rig); !(scene.clearance_m() < margin))
      sec->fail("radial_mm", "= " + format_double(units::m_to_mm(scene.clearance_m())) +
                                 " mm does not fit the rig: its loop comes within " +
                                 format_double(std::round(units::m_to_mm(margin) * 1e6) / 1e6) +
                                 " mm of a toggle, so the pin on the bushing wall cannot close it; use a clearance "
                                 "below that");
    if (scene.clearance.model == ClearanceKind::compliant)
      resolve_contact_stiffness(*sec, *scene.rig, scene.clearance_m(), scene.clearance);
    else if (scene.rig->bearing.lubricant_viscosity_Pa_s)
      sec->fail("model", "is the three-mode model, which has no lubricant film, but the rig's bearing is lubricated "
                         "(its [clearance] lubricant_viscosity_Pa_s); use model = \"compliant\" or remove the "
                         "viscosity from the rig for a dry bearing");
    sec->finish();
  } else if (scene.model == Model::clearance) {
    root.fail("clearance", "is missing: model = \"clearance\" needs a [clearance] table (at least restitution)");
  }

  if (auto sec = root.optional_section("linkage")) {
    if (scene.model != Model::linkage)
      root.fail("linkage", "is only used with model = \"linkage\"; remove the table or change model");
    scene.linkage = read_linkage_settings(*sec, *scene.rig);
    sec->finish();
  } else if (scene.model == Model::linkage) {
    root.fail("linkage", "is missing: model = \"linkage\" needs a [linkage] table (at least restitution and "
                         "contact_stiffness_N_per_m_n)");
  }

  if (auto rec = root.optional_section("recording")) scene.recording = *doc["recording"].as_table();
  root.optional_string("notes");
  root.finish();
  return scene;
}

}  // namespace fourbar

// `fourbar sim --help`: the outputs and scene tables a scene may use.
#include "cli/sim_help.hpp"

#include <algorithm>
#include <string_view>

#include "sim/outputs.hpp"

namespace fourbar::cli {

namespace {

std::string help_line(std::string_view name, std::string_view description) {
  return "  " + std::string(name) + std::string(20 - std::min<std::size_t>(19, name.size()), ' ') +
         std::string(description) + "\n";
}

}  // namespace

std::string sim_outputs_help() {
  std::string s = "Outputs a scene may request (column names; crank_deg is always first):\n";
  for (const auto& o : nominal_outputs()) s += help_line(o.name, o.description);
  s += "\nWith model = \"clearance\" (three-mode clearance model) the outputs are:\n";
  for (const auto& o : clearance_outputs()) s += help_line(o.name, o.description);
  s += "\n[clearance] table (model = \"clearance\"):\n";
  s += help_line("radial_mm", "radial clearance ξ in mm, > 0 (default: the rig's [clearance] radial_mm)");
  s += help_line("restitution", "Newton coefficient of restitution e in [0, 1] (required)");
  s += help_line("contact", "\"smooth\" (default), \"rough\" (no slip) or \"stick-slip\" (Coulomb)");
  s += help_line("friction_coefficient", "Coulomb μ >= 0, required with and only with stick-slip");
  s += help_line("following_friction",
                 "true: μ also acts while the pin follows the wall (slide/stick; default false = thesis)");
  s += help_line("tolerance", "relative integration tolerance (default 1e-10)");
  s += help_line("integrator", "\"odeint\" (Dormand-Prince 5, default) or \"cvode\" (SUNDIALS Adams)");
  s += help_line("settle_speed_mm_s", "normal speed below which contact is resting (default 0.001)");
  s += help_line("steady_state", "true: run turns until the motion is steady, then output (default false)");
  s += help_line("steady_criterion",
                 "\"periodic\" (state repeats), \"statistical\" (window means agree) or \"either\" (default)");
  s += help_line("max_revolutions", "bound on the turns run to reach steady state (default 200)");
  s += help_line("steady_tolerance", "repeat tolerance of the scaled turn-start state (default 1e-6)");
  s += help_line("max_period", "longest period in turns looked for (default 8)");
  s += help_line("statistical_window", "W: turns per window of the statistical criterion (default 20)");
  s += help_line("statistical_tolerance", "relative agreement of the two windows' means (default 0.05)");
  s += help_line("tables", "extra CSV files: [\"impacts\", \"revolutions\"] (default none)");
  s += help_line("model", "\"three-mode\" (default: following / free flight / Newton impacts) or \"compliant\"");
  s += "\nWith [clearance] model = \"compliant\" (continuous contact force; no contact, following_friction,\n"
       "integrator keys; CVODE BDF):\n";
  s += help_line("damping", "\"calibrated\" (default: rebounds with e), \"flores\", \"hunt-crossley\" or\n"
                 "                      \"lankarani-nikravesh\" (damping from e)");
  s += help_line("contact_stiffness_N_per_m_n",
                 "K in N/m^n > 0 (default: from the rig's bearing_length_mm, moduli, Poisson ratios)");
  s += help_line("contact_exponent", "n in [1, 3] (default 1.5; must be 1.5 when K comes from the rig)");
  s += help_line("friction_coefficient", "wall friction mu >= 0 (default 0)");
  s += help_line("friction_stick_speed_mm_s", "v0: no friction below this slip speed (default 0.1)");
  s += help_line("friction_slip_speed_mm_s", "v1: full mu*F_n above (default 1; cubic ramp between)");
  s += help_line("damping_floor_speed_mm_s", "least approach speed in the damping c(e)/v (default 0.01)");
  s += help_line("lubricant_viscosity_Pa_s", "lubricated bearing: viscosity > 0 (default: the rig's, else dry;\n"
                 "                      needs the rig's bearing_length_mm and pin_radius_mm)");
  s += help_line("film", "\"cavitated\" (default), \"pinkus-sternlicht\" or \"full\": the film's extent");
  s += help_line("film_break_eccentricity", "eps_t in [0.5, 0.999] (default 0.95): the film gives way to dry contact\n"
                 "                      between eps_t and the wall");
  s += "impacts.csv (compliant): one row per contact: crank_deg, time_s, revolution, normal_impulse_Ns (first\n"
       "compression-restitution cycle), contact_impulse_Ns (whole contact), tangential_impulse_Ns, eta_deg,\n"
       "approach_speed_m_s, rebound_speed_m_s, peak_force_N, contact_duration_s, max_penetration_mm,\n"
       "energy_loss_J, mode_after (1: the pin stayed on the wall after the first cycle).\n";
  s += "\nWith model = \"linkage\" (rigid links, clearance in any joint; docs/linkage-model.md) the outputs are\n"
       "the clearance model's (single-bearing columns: the joint that closes the loop, coupler-rocker when it has\n"
       "clearance; mode 1 while any joint is in contact), then per clearance joint J: J_gap_mm,\n"
       "J_penetration_mm, J_contact_force_N, J_fx_N, J_fy_N. [linkage] table:\n";
  s += help_line("crank_coupler_radial_mm", "radial clearance of the crank-coupler joint (default 0: ideal)");
  s += help_line("coupler_rocker_radial_mm", "coupler-rocker joint (default: the rig's [clearance] radial_mm)");
  s += help_line("rocker_ground_radial_mm", "rocker-ground joint (default 0: ideal)");
  s += help_line("elastic_links", "[\"coupler\", \"rocker\"]: links with the rig's [<link>.elastic] modes\n"
                 "                      (default: none, rigid); modal damping is booked as its own loss");
  s += help_line("elastic_modes", "pinned-pinned modes per elastic link, 1 to 4 (default: the table's modes)");
  s += help_line("coupler_sensors_mm", "[distance, offset, ...] pairs (mm from A, lateral): an accelerometer's\n"
                 "                      tangential reading column coupler_acc_<d>mm_<h>mm_m_s2 (rigid plus elastic)");
  s += help_line("rocker_sensors_mm", "the same on the rocker (distance from O4): rocker_acc_<d>mm_<h>mm_m_s2");
  s += help_line("restitution", "e in [0, 1] (required)");
  s += help_line("contact_stiffness_N_per_m_n", "K > 0 (required); damping, contact_exponent, friction_* and the\n"
                 "                      film keys as with [clearance] model = \"compliant\"");
  s += help_line("tolerance", "CVODE BDF tolerance on the scaled state (default 1e-10)");
  s += help_line("settle_speed_mm_s", "an onset faster than this is an impact (default 0.001)");
  s += help_line("crank_motion", "CSV time_s,crank_rad,crank_rad_s (uniform times) prescribing the crank,\n"
                 "                      relative to the scene; replaces crank_speed_rpm and start_angle_deg");
  s += help_line("duration_s", "with crank_motion: the run's length (default: the table's)");
  s += "impacts.csv (linkage): one row per contact: joint (crank_coupler, coupler_rocker, rocker_ground),\n"
       "time_s, approach_speed_m_s, crank_deg, impact, eta_deg, slip_speed_m_s, peak_force_N,\n"
       "max_penetration_mm, contact_duration_s, normal_impulse_Ns, contact_impulse_Ns, energy_loss_J,\n"
       "contact_lost, release_time_s, release_crank_deg, release_eta_deg.\n";
  return s;
}

}  // namespace fourbar::cli

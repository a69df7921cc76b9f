#pragma once
// The theory matched to a measurement (thesis ch. 8): the nominal mechanism
// and a clearance model — the three-mode model, or the compliant contact
// (model = "compliant", README "Compliant contact") — at the measured
// operating point (mean crank speed of the analysed revolutions, the
// recording's clearance, the contact law), both on the measurement's
// crank-angle grid.
//
// The clearance model's following mode is undamped, so a strict steady state
// is rarely reached (docs/clearance-model.md: not within 300 turns for
// e = 0.5 … 0 on the thesis rig). The theory therefore runs a fixed number of
// warm-up turns from the nominal start (sec. 3.4/6.1), then averages a fixed
// number of turns in the crank-angle domain, exactly as the measurement is
// averaged. Both numbers are settings and go into the report.
//
// α on the grid is the mean over each grid cell, (ω(θ+h/2) − ω(θ−h/2))/Δt:
// the impulse of an impact (a jump in ω) then counts in the cell it falls in,
// as in any sampled, anti-aliased accelerometer signal; the nominal α is
// computed the same way, so that ξ → 0 gives the nominal response exactly.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "analyze/averaging.hpp"
#include "analyze/filter_design.hpp"
#include "compare/link_quantity.hpp"
#include "sim/three_mode/settings.hpp"
#include "mechanism/rig.hpp"

namespace fourbar {

struct TheorySettings {
  ClearanceKind model = ClearanceKind::three_mode;
  double restitution = 0.5;                ///< Newton e (thesis ch. 8 suggests e < 1; the bushing is brass)
  ContactLaw contact = ContactLaw::smooth;  ///< three-mode only
  double friction_coefficient = 0.0;       ///< Coulomb μ (three-mode: stick-slip only; compliant: the wall's)
  /// model = compliant: the contact law. A stiffness of 0 (not given) is
  /// computed from the recording's rig bearing (contact_stiffness.hpp).
  CompliantSettings compliant;
  int warmup_revolutions = 20;             ///< turns simulated and discarded
  int averaged_revolutions = 20;           ///< turns averaged on the grid
  double tolerance = 1e-8;                 ///< integrator tolerance
  int max_order = 50;                      ///< orders in the spectral comparison
  /// Modelling choices without a physical counterpart (benches only, no
  /// session key; docs/fit.md "Modelling choices"): the three-mode model's
  /// settle speed (ClearanceSettings::settle_speed_m_s), and α at each grid
  /// point instead of the mean over its cell.
  double settle_speed_m_s = 1e-6;
  bool point_samples = false;
  /// Where these settings were given (e.g. "session.toml [theory]"): named in
  /// the errors found only once the recording's rig is known.
  std::string source;
};

/// An impact on the bearing, located in each part's own frame (thesis Fig.
/// 8.11: "locally oriented"): the contact point sits at angle η from the
/// bushing centre (direction of the eccentricity, pin side); on the pin, which
/// rides on the coupler, it is measured from the coupler's axis u3; on the
/// bushing, which rides on the rocker, from the rocker's axis u4.
struct BearingImpact {
  double turned_deg = 0;          ///< crank angle turned from the grid start within its turn
  int revolution = 0;             ///< among the averaged turns (0 … M−1)
  double normal_impulse_Ns = 0;   ///< F
  double global_deg = 0;          ///< η from the ground line
  double pin_deg = 0;             ///< η − θ3, in [0, 360)
  double bushing_deg = 0;         ///< η − θ4, in [0, 360)
};

struct TheorySeries {
  std::vector<double> nominal;                ///< N
  AngleAverage clearance;                     ///< mean and spread over the averaged turns
  std::vector<double> clearance_revolutions;  ///< M × N
};

struct TheorySeverity {
  double impacts_per_rev = 0;             ///< n
  double sum_normal_impulse_per_rev_Ns = 0;  ///< ΣF
  std::optional<double> impact_index_Ns;  ///< I_n = ΣF / n (pooled over the turns); absent without impacts
  double contact_losses_per_rev = 0;
  double following_share = 0;             ///< time share in the following mode
  std::vector<int> impacts_by_rev;        ///< n per averaged turn
  std::vector<double> sum_impulse_by_rev_Ns;  ///< ΣF per averaged turn
};

struct MatchedTheory {
  CrankGrid grid;
  double crank_speed_rad_s = 0;
  double clearance_m = 0;
  TheorySettings settings;
  std::array<TheorySeries, 4> series;  ///< by LinkQuantity
  std::vector<BearingImpact> impacts;  ///< in the averaged turns
  TheorySeverity severity;
  double energy_residual_rel = 0;      ///< energy balance of the run (docs/clearance-model.md)
  double max_penetration_rel = 0;
};

/// The clearance run's settings from the theory's: the three-mode impact
/// law, or the compliant contact with its stiffness resolved from the rig's
/// bearing. Throws InputError for settings the rig cannot take.
ClearanceSettings clearance_settings(const Rig& rig, double clearance_m, const TheorySettings& settings);

/// Simulates nominal and clearance response. Throws InputError for bad
/// settings (named by key as in session.toml), RunError if the model fails.
MatchedTheory simulate_matched_theory(const Rig& rig, double clearance_m, double crank_speed_rad_s,
                                      const CrankGrid& grid, const TheorySettings& settings);

/// Puts every theory series through the measurement's pass band (the ideal
/// response of `spec`: bins outside its bands zeroed) in the crank-angle
/// domain at constant speed (grid rate N·|ω2|/2π): theory and measurement
/// then hold the same orders. The per-turn mean of ω is kept.
void apply_pass_band(MatchedTheory& theory, const FilterSpec& spec);

}  // namespace fourbar

#pragma once
// The units of the linkage simulator's scaled state (CVODE's error test
// weighs every component of it alike, so these decide what a tolerance
// means): the compliant model's deviation scaling for the angles (ξ/l3) and
// the joint offsets (their ξ), rates by |ω2| too; modal coordinate k by its
// static deflection under the force scale, F/K_kk, and its rate by that
// times ω_k = √(K_kk/M_kk). Both then stand for the same acceleration F/M_kk
// (ω_k²·F/K_kk) for every mode: the error test weighs a mode by what an
// accelerometer reads of it, its position and rate alike.

#include <array>
#include <string>
#include <vector>

#include "mechanism/kinematics.hpp"
#include "sim/linkage/linkage_model.hpp"

namespace fourbar {

struct LinkageScales {
  double w = 1;       ///< |ω2| at the start (1 rad/s for a held crank)
  double delta = 1;   ///< angle unit ξ_ref/l3 (any unit for an all-ideal linkage, whose angles are prescribed)
  double energy = 1;  ///< energy scale (1 J when the model's is zero)
  double force = 1;   ///< the model's force scale
  /// Per coordinate (from index 2): the unit of its scaled position and of its scaled rate.
  std::array<double, kMaxFullCoordinates> position{}, rate{};
};

/// With a held crank on a flat rig F (for the modes) is at least the links'
/// weight under 9.80665 m/s².
LinkageScales linkage_scales(const LinkageModel& model, const CrankState& start);

/// Writes a start's modal coordinates η (m) and rates (m/s) of the coupler
/// [0] and rocker [1] into the scaled state y (positions at q's modal
/// indices, rates n further on); InputError for a non-finite entry or a
/// non-zero one on a rigid link or past the link's modes.
void scale_modal_start(const LinkageModel& model, const LinkageScales& scales,
                       const std::array<std::array<double, 4>, 2>& eta_m,
                       const std::array<std::array<double, 4>, 2>& rate_m_s, std::vector<double>& y);

/// The scaled state's component i by name: the coordinates q first ("theta3",
/// "crank_coupler d_x", "coupler eta2", …), then their rates (the same with
/// " rate"), then "books" for the quadratures after 2n.
std::string linkage_state_component(const LinkageModel& model, std::size_t i);

}  // namespace fourbar

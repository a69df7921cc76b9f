#pragma once
// The per-sample quantities a scene may request, with the work each needs,
// so that a run computes only what was asked for.

#include <span>
#include <string_view>
#include <vector>

namespace fourbar {

/// What has to be evaluated before a quantity can be read.
enum class Needs { crank, kinematics, loads, energy };

/// Every quantity the nominal model can write.
enum class Quantity {
  time, theta2, omega2, theta3, theta4, omega3, omega4, alpha3, alpha4, transmission,
  crank_torque, bearing_fx, bearing_fy, crankpin_fx, crankpin_fy, crank_pivot_fx, crank_pivot_fy,
  rocker_pivot_fx, rocker_pivot_fy, kinetic_energy, potential_energy
};

struct OutputSpec {
  Quantity quantity;
  std::string_view name;         ///< column name, with its unit
  Needs needs;
  std::string_view description;  ///< one line for --help and docs/reference.md
};

/// Every nominal-model output, in a stable order.
std::span<const OutputSpec> nominal_outputs();

/// The spec of `name`, or nullptr.
const OutputSpec* find_output(std::string_view name);

/// Outputs of the clearance model: the nominal quantities it computes
/// (`quantity`) and its own (`extra` ≠ none).
enum class ClearanceExtra { none, mode, gap, eta, contact_force, penetration };
struct ClearanceOutputSpec {
  std::string_view name;
  Quantity quantity;     ///< meaningful when extra == none
  ClearanceExtra extra;
  std::string_view description;
};

/// Every clearance-model output, in a stable order.
std::span<const ClearanceOutputSpec> clearance_outputs();
const ClearanceOutputSpec* find_clearance_output(std::string_view name);

}  // namespace fourbar

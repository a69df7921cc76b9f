#include "sim/outputs.hpp"

#include <array>

namespace fourbar {

namespace {

constexpr std::array kOutputs{
    OutputSpec{Quantity::time, "time_s", Needs::crank, "time since the start of the run"},
    OutputSpec{Quantity::theta2, "theta2_rad", Needs::crank, "crank angle θ2 from the ground line (continuous)"},
    OutputSpec{Quantity::omega2, "omega2_rad_s", Needs::crank, "crank speed ω2"},
    OutputSpec{Quantity::theta3, "theta3_rad", Needs::kinematics, "coupler angle θ3 (continuous)"},
    OutputSpec{Quantity::theta4, "theta4_rad", Needs::kinematics, "rocker angle θ4 (continuous)"},
    OutputSpec{Quantity::omega3, "omega3_rad_s", Needs::kinematics, "coupler angular velocity ω3"},
    OutputSpec{Quantity::omega4, "omega4_rad_s", Needs::kinematics, "rocker angular velocity ω4"},
    OutputSpec{Quantity::alpha3, "alpha3_rad_s2", Needs::kinematics, "coupler angular acceleration α3"},
    OutputSpec{Quantity::alpha4, "alpha4_rad_s2", Needs::kinematics, "rocker angular acceleration α4"},
    OutputSpec{Quantity::transmission, "transmission_deg", Needs::kinematics, "transmission angle between coupler and rocker"},
    OutputSpec{Quantity::crank_torque, "crank_torque_Nm", Needs::loads, "motor torque on the crank that holds the crank motion"},
    OutputSpec{Quantity::bearing_fx, "bearing_fx_N", Needs::loads, "coupler–rocker bearing: x force of the bushing on the pin"},
    OutputSpec{Quantity::bearing_fy, "bearing_fy_N", Needs::loads, "coupler–rocker bearing: y force of the bushing on the pin"},
    OutputSpec{Quantity::crankpin_fx, "crankpin_fx_N", Needs::loads, "crank–coupler joint: x force of the crank on the coupler"},
    OutputSpec{Quantity::crankpin_fy, "crankpin_fy_N", Needs::loads, "crank–coupler joint: y force of the crank on the coupler"},
    OutputSpec{Quantity::crank_pivot_fx, "crank_pivot_fx_N", Needs::loads, "x force of the ground on the crank at O2"},
    OutputSpec{Quantity::crank_pivot_fy, "crank_pivot_fy_N", Needs::loads, "y force of the ground on the crank at O2"},
    OutputSpec{Quantity::rocker_pivot_fx, "rocker_pivot_fx_N", Needs::loads, "x force of the ground on the rocker at O4"},
    OutputSpec{Quantity::rocker_pivot_fy, "rocker_pivot_fy_N", Needs::loads, "y force of the ground on the rocker at O4"},
    OutputSpec{Quantity::kinetic_energy, "kinetic_energy_J", Needs::energy, "kinetic energy of crank, coupler and rocker"},
    OutputSpec{Quantity::potential_energy, "potential_energy_J", Needs::energy, "gravitational potential energy (zero at the ground line)"},
};

constexpr std::array kClearanceOutputs{
    ClearanceOutputSpec{"time_s", Quantity::time, ClearanceExtra::none, "time since the start of the run"},
    ClearanceOutputSpec{"theta2_rad", Quantity::theta2, ClearanceExtra::none, "crank angle θ2 (continuous)"},
    ClearanceOutputSpec{"omega2_rad_s", Quantity::omega2, ClearanceExtra::none, "crank speed ω2"},
    ClearanceOutputSpec{"theta3_rad", Quantity::theta3, ClearanceExtra::none, "coupler angle θ3 (continuous)"},
    ClearanceOutputSpec{"theta4_rad", Quantity::theta4, ClearanceExtra::none, "rocker angle θ4 (continuous)"},
    ClearanceOutputSpec{"omega3_rad_s", Quantity::omega3, ClearanceExtra::none, "coupler angular velocity ω3"},
    ClearanceOutputSpec{"omega4_rad_s", Quantity::omega4, ClearanceExtra::none, "rocker angular velocity ω4"},
    ClearanceOutputSpec{"alpha3_rad_s2", Quantity::alpha3, ClearanceExtra::none, "coupler angular acceleration α3"},
    ClearanceOutputSpec{"alpha4_rad_s2", Quantity::alpha4, ClearanceExtra::none, "rocker angular acceleration α4"},
    ClearanceOutputSpec{"transmission_deg", Quantity::transmission, ClearanceExtra::none, "angle between coupler and rocker"},
    ClearanceOutputSpec{"crank_torque_Nm", Quantity::crank_torque, ClearanceExtra::none, "motor torque that holds the crank speed (also in free flight)"},
    ClearanceOutputSpec{"bearing_fx_N", Quantity::bearing_fx, ClearanceExtra::none, "x force of the bushing on the pin (0 in free flight)"},
    ClearanceOutputSpec{"bearing_fy_N", Quantity::bearing_fy, ClearanceExtra::none, "y force of the bushing on the pin (0 in free flight)"},
    ClearanceOutputSpec{"kinetic_energy_J", Quantity::kinetic_energy, ClearanceExtra::none, "kinetic energy of crank, coupler and rocker"},
    ClearanceOutputSpec{"potential_energy_J", Quantity::potential_energy, ClearanceExtra::none, "gravitational potential energy"},
    ClearanceOutputSpec{"mode", Quantity::time, ClearanceExtra::mode, "1 = following (pin on the bushing wall), 0 = free flight"},
    ClearanceOutputSpec{"gap_mm", Quantity::time, ClearanceExtra::gap, "clearance left between pin and bushing, ξ − |e| (0 in following)"},
    ClearanceOutputSpec{"eta_deg", Quantity::time, ClearanceExtra::eta, "direction η of the eccentricity, bushing centre to pin (continuous)"},
    ClearanceOutputSpec{"contact_force_N", Quantity::time, ClearanceExtra::contact_force, "normal contact force of the bushing on the pin: N in following, 0 in free flight (compliant: F_n(δ, δ̇))"},
    ClearanceOutputSpec{"penetration_mm", Quantity::time, ClearanceExtra::penetration, "penetration δ = |e| − ξ where > 0 (compliant contact; 0 to round-off in the three-mode model)"},
};

}  // namespace

std::span<const ClearanceOutputSpec> clearance_outputs() { return kClearanceOutputs; }

const ClearanceOutputSpec* find_clearance_output(std::string_view name) {
  for (const auto& o : kClearanceOutputs)
    if (o.name == name) return &o;
  return nullptr;
}

std::span<const OutputSpec> nominal_outputs() { return kOutputs; }

const OutputSpec* find_output(std::string_view name) {
  for (const auto& o : kOutputs)
    if (o.name == name) return &o;
  return nullptr;
}

}  // namespace fourbar

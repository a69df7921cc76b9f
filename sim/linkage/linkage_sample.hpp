#pragma once
// One sample of the linkage model's run: the links' motion, energies, the
// sensors' readings, the modes and each clearance joint's state, read from
// one full evaluation (forward_kinematics, pair_forces, solve_accelerations).

#include <array>
#include <vector>

#include "sim/drive/crank_motion.hpp"
#include "sim/linkage/linkage_dynamics.hpp"
#include "sim/linkage/linkage_sensor.hpp"

namespace fourbar {

/// One clearance joint's state in a sample.
struct JointSample {
  double gap_m = 0, penetration_m = 0, normal_force_N = 0, eta_rad = 0;
  Vec2 pin_force_N;
};

struct LinkageSample {
  double time_s = 0;
  CrankState crank;
  double theta3_rad = 0, theta4_rad = 0, omega3_rad_s = 0, omega4_rad_s = 0;
  double alpha3_rad_s2 = 0, alpha4_rad_s2 = 0, crank_torque_Nm = 0;
  double kinetic_energy_J = 0, potential_energy_J = 0;
  double strain_energy_J = 0;  ///< elastic links' ½ηᵀKη
  /// Modal coordinates η (m) of the coupler [0] and rocker [1], zero on a rigid link.
  std::array<std::array<double, 4>, 2> modal_m{};
  std::array<std::array<double, 4>, 2> modal_accel_m_s2{};  ///< η̈ of the coupler [0] and rocker [1]
  std::array<double, 2> midspan_deflection_m{};  ///< coupler, rocker (0 when rigid)
  std::vector<double> sensor_m_s2;               ///< tangential readings, set_sensors' order
  bool in_contact = false;  ///< any joint
  std::array<JointSample, kJoints> joint{};
};

/// The sample at the evaluated instant (c, w after the full pass); time_s
/// and crank are the caller's (absolute time, the drive's state).
LinkageSample linkage_sample(const LinkageModel& m, const LinkageCoordinates& c, const LinkageWorkspace& w,
                             const std::vector<LinkSensor>& sensors);

}  // namespace fourbar

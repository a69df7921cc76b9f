#pragma once
// The virtual rig's crank drive as a simulator's prescribed crank motion
// (sim/drive/crank_motion.hpp): the clearance and the linkage motion
// sources run their simulators on it.

#include "sim/drive/crank_motion.hpp"
#include "virtual_rig/motion_source.hpp"

namespace fourbar {

class DriveCrank final : public CrankMotion {
 public:
  explicit DriveCrank(const CrankDrive& d) : d_(d) {}
  CrankState at(double t) const override { return d_.at(t); }
  double time_at_angle(double angle_rad) const override { return d_.time_at_turned(angle_rad - d_.start_angle_rad); }

 private:
  const CrankDrive& d_;
};

}  // namespace fourbar

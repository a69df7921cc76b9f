#pragma once
// The result of one impact at the pin–bushing contact: the link rates after
// it, the impulses, the normal and tangential speeds before and after, the
// motor's impulse and the energy lost. Plain data: the three-mode impact law
// fills it (sim/three_mode/impact.hpp), the run records carry it
// (run_records.hpp).

#include "sim/record/link_motion.hpp"

namespace fourbar {

struct ImpactResult {
  LinkMotion after;
  double normal_impulse_Ns = 0;      ///< F ≥ 0 (pin pushed along −n)
  double tangential_impulse_Ns = 0;  ///< f on the pin along t = n⊥
  double normal_speed_before_m_s = 0, normal_speed_after_m_s = 0;
  double tangential_speed_before_m_s = 0, tangential_speed_after_m_s = 0;
  double motor_impulse_Nms = 0;      ///< τ̂ that holds ω2
  double energy_loss_J = 0;          ///< −½·(v⁺ + v⁻)·P: dissipated at the contact
  bool stuck = false;                ///< tangential slip stopped (rough / stick)
  bool degenerate = false;           ///< the requested law had no physical solution; smooth used
};

}  // namespace fourbar

#include "sim/linkage/linkage_scales.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.hpp"

namespace fourbar {

LinkageScales linkage_scales(const LinkageModel& model, const CrankState& c) {
  LinkageScales s;
  s.w = std::abs(c.speed_rad_s) > 0 ? std::abs(c.speed_rad_s) : 1.0;
  s.delta = model.all_ideal() ? 1e-3 : model.reference_clearance_m() / model.rig().coupler.length_m;
  s.energy = model.energy_scale_J(c.speed_rad_s);
  if (!(s.energy > 0)) s.energy = 1.0;
  s.force = model.force_scale_N(c.speed_rad_s);
  s.position.fill(1.0);
  for (const Placement& pl : model.placements())
    if (pl.offset_index >= 0)
      s.position[static_cast<std::size_t>(pl.offset_index)] = s.position[static_cast<std::size_t>(pl.offset_index) + 1] =
          model.joint(pl.joint).clearance_m;
  for (std::size_t i = 0; i < s.rate.size(); ++i) s.rate[i] = s.position[i] * s.w;
  const double modal_force =
      std::max(s.force, (model.rig().coupler.mass_kg + model.rig().rocker.mass_kg) * 9.80665);
  for (int b = 0; b < kBodies; ++b)
    if (const ElasticLink* link = model.elastic(b))
      for (int k = 0; k < link->modes(); ++k) {
        const auto i = static_cast<std::size_t>(model.modal_index(b) + k);
        const double stiffness = link->modal_stiffness(k, k), mass = link->modal_mass(k, k);
        s.position[i] = modal_force / stiffness;
        s.rate[i] = s.position[i] * std::sqrt(stiffness / mass);
      }
  return s;
}

void scale_modal_start(const LinkageModel& model, const LinkageScales& scales,
                       const std::array<std::array<double, 4>, 2>& eta_m,
                       const std::array<std::array<double, 4>, 2>& rate_m_s, std::vector<double>& y) {
  const auto n = static_cast<std::size_t>(model.coordinates());
  for (int b = 1; b < kBodies; ++b) {
    const ElasticLink* link = model.elastic(b);
    const int modes = link ? link->modes() : 0;
    for (int k = 0; k < 4; ++k) {
      const double e = eta_m[static_cast<std::size_t>(b - 1)][static_cast<std::size_t>(k)];
      const double r = rate_m_s[static_cast<std::size_t>(b - 1)][static_cast<std::size_t>(k)];
      const bool finite = std::isfinite(e) && std::isfinite(r);
      if (!finite || (k >= modes && (e != 0 || r != 0)))
        throw InputError(std::string("linkage start: modal coordinate ") + std::to_string(k + 1) + " of the " +
                         (b == 1 ? "coupler" : "rocker") + " is " +
                         (finite ? "given but the link has " + std::to_string(modes) + " modes" : "not finite") +
                         "; give eta and its rate only for an elastic link's modes");
      if (k >= modes) continue;
      const auto i = static_cast<std::size_t>(model.modal_index(b) + k);
      y[i] = e / scales.position[i];
      y[i + n] = r / scales.rate[i];
    }
  }
}

std::string linkage_state_component(const LinkageModel& m, std::size_t i) {
  const auto n = static_cast<std::size_t>(m.coordinates());
  if (i >= 2 * n) return "books";
  const std::size_t k = i % n;
  const std::string rate = i >= n ? " rate" : "";
  const char* link_names[] = {"crank", "coupler", "rocker"};
  for (const Placement& pl : m.placements()) {
    if (static_cast<std::size_t>(pl.angle_index) == k) return (pl.body == 1 ? "theta3" : "theta4") + rate;
    if (pl.offset_index < 0) continue;
    const auto first = static_cast<std::size_t>(pl.offset_index);
    if (k == first || k == first + 1)
      return std::string(to_string(static_cast<LinkJoint>(pl.joint))) + (k == first ? " d_x" : " d_y") + rate;
  }
  for (int b = 1; b < kBodies; ++b)
    if (const ElasticLink* link = m.elastic(b)) {
      const auto first = static_cast<std::size_t>(m.modal_index(b));
      if (k >= first && k < first + static_cast<std::size_t>(link->modes()))
        return std::string(link_names[b]) + " eta" + std::to_string(k - first + 1) + rate;
    }
  return "q" + std::to_string(k) + rate;
}

}  // namespace fourbar

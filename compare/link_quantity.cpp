#include "compare/link_quantity.hpp"

#include "common/units.hpp"

namespace fourbar {

std::string_view column_name(LinkQuantity q) {
  static constexpr std::array<std::string_view, 4> names{"alpha3_rad_s2", "omega3_rad_s", "alpha4_rad_s2",
                                                         "omega4_rad_s"};
  return names[index_of(q)];
}

std::string_view symbol(LinkQuantity q) {
  static constexpr std::array<std::string_view, 4> names{"α3", "ω3", "α4", "ω4"};
  return names[index_of(q)];
}

std::string_view unit(LinkQuantity q) { return is_acceleration(q) ? "rad/s²" : "rad/s"; }

std::string_view description(LinkQuantity q) {
  static constexpr std::array<std::string_view, 4> names{"coupler angular acceleration", "coupler angular velocity",
                                                         "rocker angular acceleration", "rocker angular velocity"};
  return names[index_of(q)];
}

bool is_acceleration(LinkQuantity q) { return q == LinkQuantity::alpha3 || q == LinkQuantity::alpha4; }

double CrankGrid::angle_rad(double k) const {
  return start_rad + direction * units::kTwoPi * k / static_cast<double>(grid_points_per_rev);
}

double CrankGrid::turned_deg(std::size_t k) const { return 360.0 * static_cast<double>(k) / static_cast<double>(grid_points_per_rev); }

}  // namespace fourbar

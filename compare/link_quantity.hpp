#pragma once
// The four link quantities that measurement and theory share (thesis ch. 8:
// "only the angular velocities and accelerations of the coupler and rocker
// links can be compared"), and the crank-angle grid they are compared on.

#include <array>
#include <cstddef>
#include <string_view>

namespace fourbar {

enum class LinkQuantity { alpha3 = 0, omega3 = 1, alpha4 = 2, omega4 = 3 };
inline constexpr std::array<LinkQuantity, 4> kLinkQuantities{LinkQuantity::alpha3, LinkQuantity::omega3,
                                                             LinkQuantity::alpha4, LinkQuantity::omega4};
inline constexpr std::size_t index_of(LinkQuantity q) { return static_cast<std::size_t>(q); }

/// Column stem with unit: "alpha3_rad_s2", "omega3_rad_s", ...
std::string_view column_name(LinkQuantity q);
/// Short symbol for tables and chart titles: "α3", "ω3", ...
std::string_view symbol(LinkQuantity q);
/// Unit for people: "rad/s²" or "rad/s".
std::string_view unit(LinkQuantity q);
/// "coupler angular acceleration", ...
std::string_view description(LinkQuantity q);
bool is_acceleration(LinkQuantity q);

/// N crank angles per revolution, θ_k = start + direction·2π·k/N
/// (direction +1 for a counter-clockwise crank, −1 clockwise).
struct CrankGrid {
  std::size_t grid_points_per_rev = 720;
  double start_rad = 0;
  double direction = 1;
  double angle_rad(double k) const;
  /// The crank angle turned from the grid start, in degrees (0 … 360).
  double turned_deg(std::size_t k) const;
};

}  // namespace fourbar

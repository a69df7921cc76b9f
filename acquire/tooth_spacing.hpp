#pragma once
// Tooth-spacing errors of a wheel (or line and A/B phase errors of an
// encoder), estimated from the recording itself.
//
// In every complete turn, a least-squares cubic t(φ) through the edges of
// that turn and its neighbours gives the time each edge would have at a
// smooth crank speed; the edge's deviation from it, times the speed, is the
// angle by which its tooth sits off its nominal place plus timing noise and
// whatever speed change within the turn the cubic does not follow. Averaged
// per position over many turns, noise and speed changes that are not locked
// to the turn average out; the tooth errors stay.
//
// What cannot be told apart: a speed change locked to the turn (a loaded
// crank slows down at the same angle every turn) and a wheel whose teeth are
// off by the same pattern give identical edge times. The once- and
// twice-per-turn part of the average (where a loaded four-bar's speed
// changes live, and where wheel eccentricity shows: an off-centre wheel
// advances and retards its teeth once per turn) is therefore reported, not
// corrected — it stays in the crank motion. The rest is the tooth-spacing
// error; it is used only when the manifest asks (correct_tooth_spacing).

#include <cstddef>
#include <vector>

#include "acquire/wheel_decode.hpp"

namespace fourbar {

/// Orders of the turn left to the crank motion (not corrected as tooth errors).
inline constexpr int kTurnLockedOrders = 2;

struct ToothSpacing {
  std::vector<double> error_rad;     ///< per position 0 … P−1, above kTurnLockedOrders; NaN where no tooth
  double rms_rad = 0;                ///< RMS of error_rad over the teeth
  double max_abs_rad = 0;
  double once_per_turn_rad = 0;      ///< amplitude of the order-1 part (eccentricity or turn-locked speed change)
  double twice_per_turn_rad = 0;     ///< amplitude of the order-2 part
  double standard_error_rad = 0;     ///< of each tooth's average (RMS over the teeth)
  std::size_t turns = 0;             ///< averaged
};

/// Needs at least one complete turn; with fewer than three the estimate is
/// mostly noise (standard_error_rad says how much).
ToothSpacing estimate_tooth_spacing(const NumberedEdges& edges);

}  // namespace fourbar

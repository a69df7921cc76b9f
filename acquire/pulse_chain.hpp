#pragma once
// Which crank-pulse edges are pulses: the chain of edges whose periods make
// the smoothest speed history, each edge left out at a fixed cost.
//
// There is no global or start-up period: every period is judged against its
// two neighbours in the chain only. The reference for a period d between
// neighbours a (before) and b (after) is the one constant angular
// acceleration gives, for which ω² grows linearly with the angle turned, so
// 1/d² is the mean of 1/a² and 1/b²: a run-up from standstill (periods
// 1 : 0.41 : 0.32 …) fits it as well as steady running. The misfit of d is
// ln(d / reference); the chain minimises Σ min(misfit², kMisfitCap) + kRemoveCost · (edges left
// out + kBreakCost · (breaks), found exactly by dynamic programming over the
// last three chosen edges (at most kMaxSkipped edges between two pulses).
//
// What that does: an echo or a bounce a little after a pulse, noise before
// it, a doubled mark on every turn split a period into two very unequal
// parts and are left out; the true pulses of a run-up or coast-down are kept
// however fast the period changes, because keeping all of them is smoother
// than any chain with edges left out. The first and last period of the chain
// have one neighbour and count with kBoundaryWeight.

#include <cstddef>
#include <span>
#include <vector>

namespace fourbar {

/// Cost of leaving an edge out, against misfit² of the periods it changes
/// (a spurious edge half-way through a steady period costs 0.53 to keep).
inline constexpr double kRemoveCost = 0.4;
/// misfit² counts at most this much (a period e ≈ 2.7 times off): a stall or a
/// run of lost pulses costs the same whatever its neighbours, so no true
/// pulse beside it is worth leaving out to soften it.
inline constexpr double kMisfitCap = 1.0;
/// A period may span up to this many turns (pulses missed in between), each
/// missed pulse costing kMissedCost: lost pulses do not make their
/// neighbours look spurious. Whether they are repaired is decided afterwards
/// (pulse_train.hpp).
inline constexpr int kMaxMissedTurns = 5;
inline constexpr double kMissedCost = 0.3;
/// Cost of breaking the chain (the period across the break judges nothing
/// and is no neighbour): a stall or a run of lost pulses longer than
/// kMaxMissedTurns does not make the pulses between two of them look
/// spurious. Whether a long period is a gap is decided afterwards.
inline constexpr double kBreakCost = 1.0;
/// Weight of the misfit² of the chain's first and last period (one neighbour).
inline constexpr double kBoundaryWeight = 0.25;
/// At most this many consecutive edges are left out between two pulses.
inline constexpr std::size_t kMaxSkipped = 4;

/// The reference period between neighbours a and b under constant angular
/// acceleration: (½(1/a² + 1/b²))^−½.
double constant_acceleration_period(double a_s, double b_s);

/// Indices of the edges that are pulses, increasing. `edges_s` increasing.
std::vector<std::size_t> smoothest_pulse_chain(std::span<const double> edges_s);

}  // namespace fourbar

// The clearance simulator's event detection: the witness functions sampled
// on the integrator's dense output (N + N_guard and the slip speed in the
// following mode, the penetration |e| − ξ in free flight), and the scans of
// one step for the first contact loss, slip event or impact.

#include <algorithm>
#include <optional>

#include <boost/math/tools/minima.hpp>

#include "sim/integrate/event_root.hpp"
#include "sim/three_mode/simulator_state.hpp"

namespace fourbar {

double ClearanceSimulator::Impl::follow_value(const FollowingMotion& f) const {
  double w = f.normal_force_N + scale.force_guard_N;
  if (wall.friction.mu > 0) {
    if (wall.friction.slip != 0) {
      if (wall.slip_armed) w = std::min(w, wall.friction.slip * f.slip_speed_m_s * wall.slip_force_per_speed);
    } else {
      w = std::min(w, wall.friction.mu * (f.normal_force_N + scale.force_guard_N) - std::abs(f.tangential_force_N));
    }
  }
  return w;
}

ClearanceSimulator::Impl::FreeSample ClearanceSimulator::Impl::free_witness(double time) {
  OdeState y;
  integ->interpolate(time, y);
  const BearingState b = model.bearing(crank_at(time), free_links(time, y));
  return {time, -b.gap_m, b.normal_speed_m_s};
}

ClearanceSimulator::Impl::FollowSample ClearanceSimulator::Impl::follow_witness(double time, bool check_drift) {
  OdeState y;
  integ->interpolate(time, y);
  const CrankState c = crank_at(time);
  const FollowingMotion f = model.following(c, eta_of(y), eta_rate_of(y), wall.friction);
  if (check_drift) monitor(model.bearing(c, f.links));
  if (!wall.slip_armed && wall.friction.slip * f.slip_speed_m_s > wall.slip_arm_speed_m_s) wall.slip_armed = true;
  return {time, follow_value(f), f.slip_speed_m_s};
}

std::optional<double> ClearanceSimulator::Impl::scan_free(double ta, double tb) {
  auto pen = [this](double x) { return free_witness(x).pen; };
  auto spd = [this](double x) { return free_witness(x).speed; };
  FreeSample prev = witness.free_prev;
  if (prev.t != ta) prev = free_witness(ta);
  if (seg.armed && witness.stage_filter && !settings.full_event_scan) {
    // As in scan_following: the pin stays inside by more than the spread
    // of the step's stage and end penetrations.
    const FreeSample end = free_witness(tb);
    const double lo = std::min({free_ode.pen_min, prev.pen, end.pen});
    const double hi = std::max({free_ode.pen_max, prev.pen, end.pen});
    if (-hi > hi - lo) {
      ++books.diag.filtered_steps;
      witness.free_prev = end;
      return std::nullopt;
    }
  }
  for (int i = 1; i <= kScanPoints; ++i) {
    const double ti = i == kScanPoints ? tb : ta + (tb - ta) * i / kScanPoints;
    const FreeSample cur = free_witness(ti);
    if (!seg.armed) {
      if (cur.pen < -scale.arm_depth_m) {
        seg.armed = true;
      } else if (cur.speed > 0) {
        // Past the deepest point of this flight: find it, then look ahead.
        double tmin = prev.t, pmin = prev.pen;
        if (prev.speed < 0) {
          tmin = locate_root(spd, prev.t, cur.t, prev.speed, cur.speed);
          pmin = pen(tmin);
        }
        if (cur.pen < 0) {
          seg.armed = true;  // coming back from inside: the crossing ahead is an impact
        } else if (pmin < -scale.arm_depth_m) {
          seg.armed = true;
          return locate_root(pen, tmin, cur.t, pmin, cur.pen);
        } else if (cur.pen > scale.arm_depth_m) {
          seg.armed = true;
          return tmin;  // the pin never left the wall beyond round-off: a touch
        }
        // Else still on the wall within round-off (|pen| ≤ arm depth), e.g.
        // just after a contact loss at N = −N_guard: a touch here would
        // restart the same state at the same time, so wait.
      }
      prev = cur;
      continue;
    }
    if (cur.pen >= 0) return locate_root(pen, prev.t, cur.t, prev.pen, cur.pen);
    if (prev.speed > 0 && cur.speed < 0) {
      // A local maximum of the penetration between samples: a grazing double root?
      const double tmax = locate_root(spd, prev.t, cur.t, prev.speed, cur.speed);
      const double pmax = pen(tmax);
      if (pmax >= 0) return locate_root(pen, prev.t, tmax, prev.pen, pmax);
    }
    prev = cur;
  }
  witness.free_prev = prev;
  return std::nullopt;
}

std::optional<double> ClearanceSimulator::Impl::scan_following(double ta, double tb) {
  auto w = [this](double x) { return follow_witness(x).w; };
  if (witness.follow_hist.empty() || witness.follow_hist.back().t != ta) {
    witness.follow_hist.clear();
    witness.follow_hist.push_back(follow_witness(ta));
  }
  if (witness.stage_filter && !settings.full_event_scan) {
    // The step's stage values and both ends stay positive by more than
    // their spread: w cannot reach zero inside (a parabola through them
    // dips at most 0.26 of the spread below the lowest), so the step end
    // is the only sample needed.
    const FollowSample end = follow_witness(tb, true);
    const double lo = std::min({following_ode.w_min, witness.follow_hist.back().w, end.w});
    const double hi = std::max({following_ode.w_max, witness.follow_hist.back().w, end.w});
    if (lo > hi - lo) {
      ++books.diag.filtered_steps;
      witness.follow_hist.push_back(end);
      if (witness.follow_hist.size() > 2) witness.follow_hist.erase(witness.follow_hist.begin());
      return std::nullopt;
    }
  }
  for (int i = 1; i <= kScanPoints; ++i) {
    const double ti = i == kScanPoints ? tb : ta + (tb - ta) * i / kScanPoints;
    const FollowSample cur = follow_witness(ti, i == kScanPoints);
    const FollowSample prev = witness.follow_hist.back();
    if (cur.w <= 0) return locate_root(w, prev.t, cur.t, prev.w, cur.w);
    if (witness.follow_hist.size() >= 2) {
      // Sampled local minimum: does a parabola through the three samples dip below zero?
      const FollowSample a = witness.follow_hist[witness.follow_hist.size() - 2];
      if (prev.w < a.w && prev.w < cur.w) {
        const double h1 = prev.t - a.t, h2 = cur.t - prev.t;
        const double d1 = (prev.w - a.w) / h1, d2 = (cur.w - prev.w) / h2;
        const double curv = 2 * (d2 - d1) / (h1 + h2);
        const double slope_mid = d1 + 0.5 * curv * h1;  // slope at prev
        const double dip = prev.w - slope_mid * slope_mid / (2 * curv);
        if (dip <= 0.5 * prev.w) {
          // Search only where the dense output is valid: the current step.
          const double lo = std::max(a.t, integ->previous_time());
          const double wlo = lo == a.t ? a.w : w(lo);
          const auto [tmin, wmin] = boost::math::tools::brent_find_minima(w, lo, cur.t, 40);
          if (wmin <= 0) return locate_root(w, lo, tmin, wlo, wmin);
        }
      }
    }
    witness.follow_hist.push_back(cur);
    if (witness.follow_hist.size() > 2) witness.follow_hist.erase(witness.follow_hist.begin());
  }
  return std::nullopt;
}

}  // namespace fourbar

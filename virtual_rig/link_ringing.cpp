#include "virtual_rig/link_ringing.hpp"

#include <algorithm>
#include <cmath>

#include "common/units.hpp"

namespace fourbar {

std::vector<BearingImpulse> bearing_impulses(const std::vector<ImpactRecord>& impacts) {
  std::vector<BearingImpulse> out;
  out.reserve(impacts.size());
  for (const ImpactRecord& r : impacts) {
    const double p = r.result.normal_impulse_Ns + r.settle_normal_impulse_Ns;
    if (!(p > 0)) continue;
    out.push_back({r.time_s, p * std::sin(r.eta_rad - r.theta3_rad), p * std::sin(r.eta_rad - r.theta4_rad)});
  }
  std::sort(out.begin(), out.end(), [](const BearingImpulse& a, const BearingImpulse& b) { return a.time_s < b.time_s; });
  return out;
}

LinkRinging::LinkRinging(std::vector<LinkMode> modes, std::vector<BearingImpulse> impulses)
    : modes_(std::move(modes)), impulses_(std::move(impulses)), state_(modes_.size()) {
  std::sort(impulses_.begin(), impulses_.end(), [](const BearingImpulse& a, const BearingImpulse& b) { return a.time_s < b.time_s; });
  // The state just after each impulse, for queries at any time.
  std::vector<State> st(modes_.size());
  after_impulse_.reserve(impulses_.size());
  for (std::size_t i = 0; i < impulses_.size(); ++i) {
    if (i > 0) propagate(modes_, st, impulses_[i].time_s - impulses_[i - 1].time_s);
    for (std::size_t k = 0; k < modes_.size(); ++k) {
      const LinkMode& m = modes_[k];
      const double across = m.link == RingingLink::coupler ? impulses_[i].across_coupler_Ns : impulses_[i].across_rocker_Ns;
      st[k].v += m.shape_at_bearing * across / m.modal_mass_kg;
    }
    after_impulse_.push_back(st);
  }
}

void LinkRinging::propagate(double dt) { propagate(modes_, state_, dt); }

void LinkRinging::propagate(const std::vector<LinkMode>& modes, std::vector<State>& state, double dt) {
  if (dt <= 0) return;
  for (std::size_t k = 0; k < modes.size(); ++k) {
    const LinkMode& m = modes[k];
    const double w = units::kTwoPi * m.frequency_hz, sigma = m.damping_ratio * w;
    const double wd = w * std::sqrt(std::max(1e-12, 1 - m.damping_ratio * m.damping_ratio));
    const double decay = std::exp(-sigma * dt), c = std::cos(wd * dt), s = std::sin(wd * dt);
    State& st = state[k];
    const double q = decay * (st.q * c + (st.v + sigma * st.q) / wd * s);
    const double v = decay * (st.v * c - (w * w * st.q + sigma * st.v) / wd * s);
    st = {q, v};
  }
}

void LinkRinging::advance_to(double t) {
  if (!started_) {
    // Impulses before the first time asked for happened long ago enough to
    // matter only through their ringing: start at the earliest one.
    time_s_ = impulses_.empty() ? t : std::min(t, impulses_.front().time_s);
    started_ = true;
  }
  while (next_ < impulses_.size() && impulses_[next_].time_s <= t) {
    const BearingImpulse& p = impulses_[next_++];
    propagate(p.time_s - time_s_);
    time_s_ = std::max(time_s_, p.time_s);
    for (std::size_t k = 0; k < modes_.size(); ++k) {
      const LinkMode& m = modes_[k];
      const double across = m.link == RingingLink::coupler ? p.across_coupler_Ns : p.across_rocker_Ns;
      state_[k].v += m.shape_at_bearing * across / m.modal_mass_kg;
    }
  }
  propagate(t - time_s_);
  time_s_ = std::max(time_s_, t);
}

double LinkRinging::sensor_acceleration(ChannelRole role) const { return acceleration(modes_, state_, role); }

double LinkRinging::sensor_acceleration_at(double t, ChannelRole role) const {
  const auto after = std::upper_bound(impulses_.begin(), impulses_.end(), t,
                                      [](double time_s, const BearingImpulse& p) { return time_s < p.time_s; });
  if (after == impulses_.begin()) return 0;  // no impulse yet: the links are at rest
  const auto i = static_cast<std::size_t>(after - impulses_.begin()) - 1;
  std::vector<State> st = after_impulse_[i];
  propagate(modes_, st, t - impulses_[i].time_s);
  return acceleration(modes_, st, role);
}

double LinkRinging::acceleration(const std::vector<LinkMode>& modes, const std::vector<State>& state, ChannelRole role) {
  if (!is_tangential(role)) return 0;
  const RingingLink link = is_on_coupler(role) ? RingingLink::coupler : RingingLink::rocker;
  double a = 0;
  for (std::size_t k = 0; k < modes.size(); ++k) {
    const LinkMode& m = modes[k];
    if (m.link != link) continue;
    const double w = units::kTwoPi * m.frequency_hz;
    a += m.shape_at_sensor * (-w * w * state[k].q - 2 * m.damping_ratio * w * state[k].v);
  }
  return a;
}

}  // namespace fourbar

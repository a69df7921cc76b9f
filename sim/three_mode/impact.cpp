#include "sim/three_mode/impact.hpp"

#include <cmath>

namespace fourbar {

namespace {

struct ContactFrame {
  Vec2 n, t, w3, w4;  // w3, w4: columns of W
  double Knn, Knt, Ktt;
};

ContactFrame contact_frame(const ClearanceModel& model, const CrankState& crank, const LinkMotion& m,
                           const BearingState& b) {
  const Rig& rig = model.rig();
  ContactFrame f;
  f.n = b.normal;
  f.t = b.normal.perp();
  f.w3 = rig.coupler.length_m * m.u3.perp();
  f.w4 = -(rig.rocker.length_m * m.u4 + b.eccentricity_m).perp();
  (void)crank;
  const double i3 = 1.0 / model.inertia_coupler_about_A(), i4 = 1.0 / model.inertia_rocker_about_O4();
  const double w3n = dot(f.w3, f.n), w3t = dot(f.w3, f.t), w4n = dot(f.w4, f.n), w4t = dot(f.w4, f.t);
  f.Knn = i3 * w3n * w3n + i4 * w4n * w4n;
  f.Knt = i3 * w3n * w3t + i4 * w4n * w4t;
  f.Ktt = i3 * w3t * w3t + i4 * w4t * w4t;
  return f;
}

}  // namespace

ImpactResult apply_impulse(const ClearanceModel& model, const CrankState& crank, const LinkMotion& before,
                           double F, double f) {
  const Rig& rig = model.rig();
  const BearingState b0 = model.bearing(crank, before);
  const ContactFrame cf = contact_frame(model, crank, before, b0);
  const Vec2 P = -F * cf.n + f * cf.t;
  ImpactResult r;
  r.normal_impulse_Ns = F;
  r.tangential_impulse_Ns = f;
  r.after = before;
  const double d3 = dot(cf.w3, P) / model.inertia_coupler_about_A();
  const double d4 = dot(cf.w4, P) / model.inertia_rocker_about_O4();
  r.after.omega3_rad_s += d3;
  r.after.omega4_rad_s += d4;
  const BearingState b1 = model.bearing(crank, r.after);
  r.normal_speed_before_m_s = b0.normal_speed_m_s;
  r.tangential_speed_before_m_s = b0.tangential_speed_m_s;
  r.normal_speed_after_m_s = b1.normal_speed_m_s;
  r.tangential_speed_after_m_s = b1.tangential_speed_m_s;
  // Motor impulse from the crank's momentum balance (THESIS-ERRATA, ch. 5).
  const Vec2 u2 = unit(crank.angle_rad);
  const double cos_b = dot(before.u3, u2);
  r.motor_impulse_Nms = rig.coupler.mass_kg * rig.crank.length_m * rig.coupler.mass_centre_m * cos_b * d3 -
                        dot(P, rig.crank.length_m * u2.perp());
  // Work of the contact impulse on the relative motion, with the sign of a loss.
  r.energy_loss_J = 0.5 * F * (r.normal_speed_after_m_s + r.normal_speed_before_m_s) -
                    0.5 * f * (r.tangential_speed_after_m_s + r.tangential_speed_before_m_s);
  return r;
}

ImpactResult resolve_impact(const ClearanceModel& model, const CrankState& crank, const LinkMotion& before,
                            const ImpactLaw& law) {
  const BearingState b = model.bearing(crank, before);
  const double vn = b.normal_speed_m_s, vt = b.tangential_speed_m_s;
  if (!(vn > 0)) return apply_impulse(model, crank, before, 0.0, 0.0);
  const ContactFrame cf = contact_frame(model, crank, before, b);
  const double e = law.restitution;
  const double smooth_F = (1 + e) * vn / cf.Knn;

  // Sticking: v_n⁺ = −e·v_n and v_t⁺ = 0.
  auto stick = [&](double& F, double& f) {
    const double det = cf.Knn * cf.Ktt - cf.Knt * cf.Knt;
    F = ((1 + e) * vn * cf.Ktt - cf.Knt * vt) / det;
    f = (cf.Knt * F - vt) / cf.Ktt;
  };
  double F = smooth_F, f = 0;
  bool stuck = false, degenerate = false;
  switch (law.contact) {
    case ContactLaw::smooth: break;
    case ContactLaw::rough:
      stick(F, f);
      stuck = true;
      break;
    case ContactLaw::stick_slip: {
      const double mu = law.friction_coefficient;
      stick(F, f);
      stuck = true;
      if (!(F >= 0 && std::abs(f) <= mu * F)) {
        // Sliding throughout the impact against the initial slip (eq. 5.3.3-5).
        const double sigma = vt > 0 ? 1.0 : vt < 0 ? -1.0 : 0.0;
        const double denom = cf.Knn + sigma * mu * cf.Knt;
        stuck = false;
        if (denom > 0) {
          F = (1 + e) * vn / denom;
          f = -sigma * mu * F;
        } else {
          F = -1;  // no sliding solution: treated below
        }
      }
      break;
    }
  }
  if (!(F >= 0)) {  // no physical solution of the requested law: fall back to smooth
    F = smooth_F;
    f = 0;
    stuck = false;
    degenerate = true;
  }
  ImpactResult r = apply_impulse(model, crank, before, F, f);
  r.stuck = stuck;
  r.degenerate = degenerate;
  return r;
}

}  // namespace fourbar

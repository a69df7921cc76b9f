#include "sim/linkage/linkage_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "common/error.hpp"
#include "sim/flex/elastic_body.hpp"
#include "sim/flex/rig_elastic_link.hpp"

namespace fourbar {

const char* to_string(LinkJoint j) {
  switch (j) {
    case LinkJoint::crank_coupler: return "crank_coupler";
    case LinkJoint::coupler_rocker: return "coupler_rocker";
    case LinkJoint::rocker_ground: return "rocker_ground";
  }
  return "?";
}

namespace {

BodyData body_of(const Link& l) { return {l.mass_kg, l.inertia_cg_kg_m2, l.length_m, {l.mass_centre_m, 0.0}}; }

constexpr int kCrank = static_cast<int>(LinkBody::crank), kCoupler = static_cast<int>(LinkBody::coupler),
              kRocker = static_cast<int>(LinkBody::rocker);

/// The three revolute joints, pin on the first body, bushing on the second,
/// each with the spec's clearance (checked: ≥ 0) and the film.
std::array<JointData, kJoints> linkage_joints(const Rig& rig, const LinkageSpec& spec) {
  const double l2 = rig.crank.length_m, l3 = rig.coupler.length_m, l4 = rig.rocker.length_m;
  std::array<JointData, kJoints> joints{};
  joints[0] = {LinkJoint::crank_coupler, {kCrank, {l2, 0}}, {kCoupler, {0, 0}}, spec.clearance_m[0], spec.film};
  joints[1] = {LinkJoint::coupler_rocker, {kCoupler, {l3, 0}}, {kRocker, {l4, 0}}, spec.clearance_m[1], spec.film};
  joints[2] = {LinkJoint::rocker_ground, {kRocker, {0, 0}}, {kGround, {rig.ground_length_m, 0}}, spec.clearance_m[2],
               spec.film};
  const char* keys[kJoints] = {"crank_coupler_radial_mm", "coupler_rocker_radial_mm", "rocker_ground_radial_mm"};
  for (int j = 0; j < kJoints; ++j) {
    JointData& jd = joints[static_cast<std::size_t>(j)];
    if (!(std::isfinite(jd.clearance_m) && jd.clearance_m >= 0))
      throw InputError(std::string("[linkage] ") + keys[j] + " must be >= 0 (0 = an ideal joint)");
    jd.film.clearance_m = jd.clearance_m;
  }
  return joints;
}

/// The tree (see the header): coupler and rocker placed by the two joints
/// other than the cut one, parent site first, child (placed body) second;
/// each clearance joint's offsets in joint order from coordinate 2 on.
/// Returns the next free coordinate.
int place_bodies(const std::array<JointData, kJoints>& joints, int cut, std::array<Placement, 2>& placements) {
  auto place = [&](int body, int joint, bool child_holds_pin, int angle_index) {
    const JointData& jd = joints[static_cast<std::size_t>(joint)];
    Placement p;
    p.body = body;
    p.joint = joint;
    p.parent = child_holds_pin ? jd.bushing : jd.pin;
    p.child = child_holds_pin ? jd.pin : jd.bushing;
    p.angle_index = angle_index;
    p.offset_sign = child_holds_pin ? 1.0 : -1.0;
    return p;
  };
  if (cut == 1 || cut == -1) {
    placements = {place(kCoupler, 0, false, 0), place(kRocker, 2, true, 1)};
  } else if (cut == 0) {
    placements = {place(kRocker, 2, true, 1), place(kCoupler, 1, true, 0)};
  } else {
    placements = {place(kCoupler, 0, false, 0), place(kRocker, 1, false, 1)};
  }
  int next_offset = 2;
  for (int j = 0; j < kJoints; ++j)
    for (Placement& p : placements)
      if (p.joint == j && joints[static_cast<std::size_t>(j)].clearance_m > 0) {
        p.offset_index = next_offset;
        next_offset += 2;
      }
  return next_offset;
}

/// Body b's elastic link from the rig's [<link>.elastic] table with the
/// spec's number of modes; InputError for a missing table, too many modes or
/// a mode that moves a joint.
ElasticLink linkage_elastic_link(const Rig& rig, const LinkageSpec& spec, int b) {
  const RigLink which = b == kCoupler ? RigLink::coupler : RigLink::rocker;
  std::optional<ElasticLinkSpec> es = rig_elastic_spec(rig, which);
  if (!es)
    throw InputError(std::string("[linkage] elastic_links names \"") + to_string(which) + "\" but the rig has no [" +
                     to_string(which) + ".elastic] table; add one (docs/flex.md) or remove the link");
  const int have = static_cast<int>(es->shapes.size());
  const int want = spec.elastic_modes > 0 ? spec.elastic_modes : have;
  if (want > have)
    throw InputError("[linkage] elastic_modes = " + std::to_string(want) + " but the rig's [" + to_string(which) +
                     ".elastic] gives " + std::to_string(have) + " modes; lower elastic_modes or raise modes");
  if (want > 4)
    throw InputError("[linkage] elastic_modes: at most 4 modes per link (the rig's [" + std::string(to_string(which)) +
                     ".elastic] gives " + std::to_string(have) + "); set elastic_modes <= 4");
  es->shapes.resize(static_cast<std::size_t>(want));
  if (es->measured_frequencies_Hz.size() > es->shapes.size()) es->measured_frequencies_Hz.resize(es->shapes.size());
  ElasticLink link = build_elastic_link(*es);
  // The joints sit at the link's ends; the deformed site positions must be
  // the rigid ones there (pinned–pinned modes vanish at both ends), else the
  // placement would need the deflection's Jacobian.
  for (double s_m : {0.0, link.length_m}) {
    const Vec2 d = deflection(link, s_m, Eigen::VectorXd::Ones(want));
    if (std::abs(d.x) + std::abs(d.y) > 1e-12 * link.length_m)
      throw InputError(std::string("[") + to_string(which) + ".elastic]: a mode moves a joint; only pinned-pinned modes");
  }
  return link;
}

}  // namespace

LinkageModel build_linkage(const Rig& rig, const LinkageSpec& spec) {
  LinkageModel m;
  m.rig_ = rig;
  m.spec_ = spec;
  m.bodies_ = {body_of(rig.crank), body_of(rig.coupler), body_of(rig.rocker)};
  m.joints_ = linkage_joints(rig, spec);
  for (int j = 0; j < kJoints; ++j) {
    const double xi = m.joints_[static_cast<std::size_t>(j)].clearance_m;
    if (xi > 0) m.clearance_joints_.push_back(j);
    m.xi_ref_ = std::max(m.xi_ref_, xi);
  }
  const bool any_elastic = spec.elastic[1] || spec.elastic[2];
  if (m.clearance_joints_.empty() && !any_elastic)
    throw InputError(
        "[linkage]: no joint has a clearance; give one of crank_coupler_radial_mm, coupler_rocker_radial_mm, "
        "rocker_ground_radial_mm > 0 (or use model = \"nominal\" for the ideal linkage)");
  if (!(spec.law.stiffness > 0))
    throw InputError("[linkage]: no contact stiffness; give contact_stiffness_N_per_m_n > 0");
  if (spec.film.viscosity_Pa_s > 0 && !(spec.film.radius_m > 0 && spec.film.length_m > 0))
    throw InputError("[linkage]: a lubricant needs the bearing's radius and length (rig [clearance] pin_radius_mm, "
                     "bearing_length_mm)");
  m.cut_ = m.joints_[1].clearance_m > 0 ? 1 : (m.joints_[0].clearance_m > 0 ? 0 : (m.joints_[2].clearance_m > 0 ? 2 : -1));
  int next = place_bodies(m.joints_, m.cut_, m.placements_);
  // Elastic links: modal coordinates after the offsets.
  for (int b : {kCoupler, kRocker}) {
    if (!spec.elastic[static_cast<std::size_t>(b)]) continue;
    const ElasticLink& link = m.elastic_[static_cast<std::size_t>(b)].emplace(linkage_elastic_link(rig, spec, b));
    m.modal_index_[static_cast<std::size_t>(b)] = next;
    next += link.modes();
  }
  if (next + 1 > kMaxFullCoordinates)
    throw InputError("[linkage] elastic_modes: too many coordinates (" + std::to_string(next) +
                     "); at most 4 modes per link");
  m.n_ = next;
  m.hysteresis_ = hysteresis_factor(spec.law.damping, spec.law.restitution, spec.law.exponent);
  return m;
}

double LinkageModel::force_scale_N(double w2) const {
  const double g = rig_.gravity_m_s2;
  return rig_.coupler.mass_kg * (g + rig_.crank.length_m * w2 * w2) + rig_.rocker.mass_kg * g + 1e-300;
}

double LinkageModel::energy_scale_J(double w2) const {
  // As ClearanceModel::energy_scale_J: crank and coupler-end motion at ω2 plus the potential energy range.
  const double m3 = rig_.coupler.mass_kg, l2 = rig_.crank.length_m;
  return 0.5 * (rig_.crank.inertia_about_joint() + m3 * l2 * l2) * w2 * w2 +
         rig_.gravity_m_s2 * (rig_.crank.mass_kg * rig_.crank.mass_centre_m + m3 * (l2 + rig_.coupler.mass_centre_m) +
                              rig_.rocker.mass_kg * rig_.rocker.mass_centre_m);
}

}  // namespace fourbar

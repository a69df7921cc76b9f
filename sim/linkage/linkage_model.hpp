#pragma once
// The planar linkage model: an immutable, validated description of bodies,
// joints and the tree that places them (SIM-DESIGN-NOTES §5, after Pinocchio's
// Model/Data and Exudyn's markers). Bodies are rigid; joints attach to named
// sites of bodies (a site is a point fixed in a body's frame), never to
// coordinates, so an elastic body can later replace a rigid one by moving its
// sites with its modes.
//
// Bodies: crank (prescribed through CrankMotion), coupler, rocker; the ground
// is body −1. Each body's frame has its origin at the link's first joint (O2,
// A, O4) and its x axis along the link; sites `proximal` (0, 0), `distal`
// (l, 0) and the mass centre (S, 0).
//
// Joints (revolute), each ideal or with a radial clearance ξ:
//   crank_coupler   pin: crank distal (A)       bushing: coupler proximal
//   coupler_rocker  pin: coupler distal (B)     bushing: rocker distal
//   rocker_ground   pin: rocker proximal (O4)   bushing: ground point (l1, 0)
// The eccentricity of a clearance joint is e = pin − bushing centre, |e| ≤ ξ
// in free flight. The crank–ground joint is ideal and carries the drive.
//
// Coordinates. The loop O2–A–B–O4 is cut at one clearance joint (the
// coupler–rocker joint if it has clearance, else the crank–coupler one, else
// the rocker–ground one); that joint closes the loop as a force element (a
// clearance pair) and needs no constraint rows. The other two joints place
// the coupler and rocker: an ideal joint adds the child's angle only, a
// clearance joint its angle and the two components of d = child site −
// parent site (d = ±e). q = (θ3, θ4, then d of each placing clearance joint
// in joint order): with clearance at B only, q = (θ3, θ4), the compliant
// model's coordinates. A rigid linkage without any clearance has no
// coordinate left (use model = "nominal"). An all-ideal linkage with an
// elastic link is accepted: the modes vanish at the joints, so the loop
// closes exactly as the rigid one and θ3, θ4 follow the nominal motion
// (prescribed like the crank's angle); q keeps (θ3, θ4) first and the modal
// coordinates η are its only free entries (cut_joint() is −1).

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "mechanism/rig.hpp"
#include "mechanism/vec2.hpp"
#include "sim/contact/contact_force.hpp"
#include "sim/contact/film_force.hpp"
#include "sim/flex/elastic_link.hpp"
#include "sim/integrate/linkage_integrator.hpp"

namespace fourbar {

enum class LinkBody { crank = 0, coupler = 1, rocker = 2 };
inline constexpr int kGround = -1;
inline constexpr int kBodies = 3;

enum class LinkJoint { crank_coupler = 0, coupler_rocker = 1, rocker_ground = 2 };
inline constexpr int kJoints = 3;
/// n + 1 at most: six joint coordinates, four modes on each of two links, the crank.
inline constexpr int kMaxFullCoordinates = 16;
/// "crank_coupler", "coupler_rocker", "rocker_ground" (impacts.csv's `joint`).
const char* to_string(LinkJoint j);

/// What a scene's [linkage] table decides (sim/scene.cpp reads it).
struct LinkageSpec {
  /// Radial clearance per joint (LinkJoint order); 0 = an ideal joint.
  std::array<double, kJoints> clearance_m{0, 0, 0};
  NormalForceLaw law;          ///< the compliant normal law (stiffness resolved)
  FrictionLaw friction;        ///< regularised Coulomb
  JournalFilm film;            ///< viscosity 0: dry; its clearance is set per joint
  double damping_floor_speed_m_s = 1e-5;
  double settle_speed_m_s = 1e-6;  ///< an onset faster than this is an impact
  double tolerance = 1e-10;        ///< CVODE relative and absolute, on the scaled state
  LinkageMethod method = LinkageMethod::bdf;  ///< the stepping method (linkage_integrator.hpp)
  /// Elastic bodies (LinkBody order; the crank stays rigid): the rig's
  /// [<link>.elastic] table as sim/flex's floating frame with pinned–pinned modes.
  std::array<bool, kBodies> elastic{false, false, false};
  int elastic_modes = 0;  ///< modes per elastic link; 0: the rig table's `modes`
};

/// A point fixed in a body (or the ground) frame.
struct Site {
  int body = kGround;
  Vec2 local_m;  ///< (along the link, normal to it)
};

struct BodyData {
  double mass_kg = 0, inertia_cg_kg_m2 = 0, length_m = 0;
  Vec2 centre_m;  ///< mass centre in the body frame
};

struct JointData {
  LinkJoint id{};
  Site pin, bushing;
  double clearance_m = 0;  ///< 0: ideal
  JournalFilm film;        ///< the spec's film with this joint's clearance
};

/// How a moving body is placed by its inboard joint.
struct Placement {
  int body = 0;            ///< coupler or rocker
  int joint = 0;           ///< the placing joint
  Site parent, child;      ///< the joint's sites on the parent (or ground) and on this body
  int angle_index = 0;     ///< index of θ in q
  int offset_index = -1;   ///< index of d_x (d_y next) in q; −1 for an ideal joint
  double offset_sign = 1;  ///< e = sign·d (+1 when the child holds the pin)
};

class LinkageModel {
 public:
  const Rig& rig() const { return rig_; }
  const LinkageSpec& spec() const { return spec_; }
  const BodyData& body(int b) const { return bodies_[static_cast<std::size_t>(b)]; }
  const JointData& joint(int j) const { return joints_[static_cast<std::size_t>(j)]; }
  /// Bodies placed in order (parents first): the coupler and the rocker.
  const std::array<Placement, 2>& placements() const { return placements_; }
  /// The joint that closes the loop (a clearance joint), −1 for an all-ideal linkage.
  int cut_joint() const { return cut_; }
  /// No clearance joint: θ3 and θ4 are prescribed by the nominal motion.
  bool all_ideal() const { return clearance_joints_.empty(); }
  /// The clearance joints in LinkJoint order (the witnesses, the books).
  const std::vector<int>& clearance_joints() const { return clearance_joints_; }
  /// Generalised coordinates n (the crank angle is z[n] in the full set).
  int coordinates() const { return n_; }
  /// The elastic link of a body, or nullptr for a rigid one. Its modal
  /// coordinates η sit in q from modal_index(b) on (after the joint offsets).
  const ElasticLink* elastic(int b) const {
    const auto& e = elastic_[static_cast<std::size_t>(b)];
    return e ? &*e : nullptr;
  }
  int modal_index(int b) const { return modal_index_[static_cast<std::size_t>(b)]; }
  bool any_elastic() const { return elastic_[1].has_value() || elastic_[2].has_value(); }
  /// Largest clearance: the angle scale is this over l3.
  double reference_clearance_m() const { return xi_ref_; }
  double hysteresis() const { return hysteresis_; }
  double force_scale_N(double crank_speed_rad_s) const;
  double energy_scale_J(double crank_speed_rad_s) const;

 private:
  friend LinkageModel build_linkage(const Rig&, const LinkageSpec&);
  Rig rig_;
  LinkageSpec spec_;
  std::array<BodyData, kBodies> bodies_{};
  std::array<JointData, kJoints> joints_{};
  std::array<Placement, 2> placements_{};
  std::vector<int> clearance_joints_;
  std::array<std::optional<ElasticLink>, kBodies> elastic_{};
  std::array<int, kBodies> modal_index_{-1, -1, -1};
  int cut_ = 0, n_ = 0;
  double xi_ref_ = 0, hysteresis_ = 0;
};

/// Builds and validates once; InputError (naming the [linkage] key) when no
/// joint has clearance and no link is elastic, a clearance is negative or not finite, the contact
/// stiffness is missing, or a lubricant lacks the bearing's radius or length;
/// an elastic link needs the rig's [<link>.elastic] table and at most its
/// `modes` modes.
LinkageModel build_linkage(const Rig& rig, const LinkageSpec& spec);

}  // namespace fourbar

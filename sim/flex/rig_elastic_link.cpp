#include "sim/flex/rig_elastic_link.hpp"

namespace fourbar {

const char* to_string(RigLink l) { return l == RigLink::coupler ? "coupler" : "rocker"; }

std::optional<ElasticLinkSpec> rig_elastic_spec(const Rig& rig, RigLink which) {
  const std::optional<LinkElasticity>& e = which == RigLink::coupler ? rig.coupler_elastic : rig.rocker_elastic;
  if (!e) return std::nullopt;
  const Link& link = which == RigLink::coupler ? rig.coupler : rig.rocker;
  ElasticLinkSpec spec;
  spec.name = (rig.source.empty() ? std::string("rig") : rig.source.string()) + " [" + to_string(which) + ".elastic]";
  spec.length_m = link.length_m;
  spec.mass_per_length_kg_m =
      e->density_kg_m3 && e->area_m2 ? *e->density_kg_m3 * *e->area_m2 : link.mass_kg / link.length_m;
  if (e->youngs_modulus_Pa && e->second_moment_m4)
    spec.bending_stiffness_N_m2 = *e->youngs_modulus_Pa * *e->second_moment_m4;
  if (e->youngs_modulus_Pa && e->area_m2) spec.axial_stiffness_N = *e->youngs_modulus_Pa * *e->area_m2;
  spec.depth_m = e->depth_m.value_or(0.0);
  for (int k = 1; k <= e->modes; ++k) spec.shapes.push_back({ShapeKind::lateral_sine, k});
  spec.damping_ratios = e->damping_ratios;
  spec.measured_frequencies_Hz = e->frequencies_Hz;
  spec.rigid = RigidInertia{link.mass_kg, link.mass_centre_m, link.inertia_about_joint()};
  return spec;
}

std::optional<ElasticLink> rig_elastic_link(const Rig& rig, RigLink which) {
  const std::optional<ElasticLinkSpec> spec = rig_elastic_spec(rig, which);
  if (!spec) return std::nullopt;
  return build_elastic_link(*spec);
}

}  // namespace fourbar

#pragma once
// A rig's elastic coupler or rocker (`[coupler.elastic]`, `[rocker.elastic]`)
// as an ElasticLink: pinned–pinned bending modes between the link's joints,
// the frame at its first joint (the crank pin A for the coupler, the pivot O4
// for the rocker), the rig's measured mass, centre and inertia as the rigid
// part, and the section's (or the tap test's) stiffness for the modes.

#include <optional>

#include "mechanism/rig.hpp"
#include "sim/flex/elastic_link.hpp"

namespace fourbar {

enum class RigLink { coupler, rocker };

const char* to_string(RigLink l);

/// The spec of the link's modes; nullopt when the rig gives it no
/// `[<link>.elastic]` table (a rigid link).
std::optional<ElasticLinkSpec> rig_elastic_spec(const Rig& rig, RigLink which);

/// rig_elastic_spec built; throws InputError naming the rig file and table.
std::optional<ElasticLink> rig_elastic_link(const Rig& rig, RigLink which);

}  // namespace fourbar

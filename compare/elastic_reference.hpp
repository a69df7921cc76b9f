#pragma once
// The elastic-link reference of a recording whose rig file has the links'
// modal data ([coupler.elastic] / [rocker.elastic]): the linkage model
// (sim/linkage) with those links elastic, the compliant contact at the
// coupler–rocker joint at the session theory's e (at most
// kReferenceMaxRestitution) and μ, run at the
// recording's operating point and read by the recording's own tangential
// accelerometers (compare/linkage_theory.hpp), for the link-vibration check
// (compare/link_vibration.hpp). Only the modes the check can see are kept:
// per link those below kReferenceModeShare × the checked range's top (at
// least one).

#include <array>
#include <optional>
#include <string>

#include "analyze/filter_design.hpp"
#include "analyze/sensor_mount.hpp"
#include "compare/matched_theory.hpp"
#include "compare/model_family.hpp"
#include "mechanism/rig.hpp"

namespace fourbar {

/// Modes above this multiple of the checked range's top are left out of the reference.
inline constexpr double kReferenceModeShare = 2.0;
/// The reference's restitution: the session theory's, at most this. At
/// e → 1 the compliant contact dissipates nothing and the rigid-link model
/// chatters without end; its broadband energy then covers the links'
/// vibration (measured on the linkage-model sessions at e = 1: no band where
/// the elastic model holds 4x the rigid-link one). At e = 0.5, 0.8, 0.9 the
/// position of the measurement between the two (compare/link_vibration.hpp)
/// barely moved (docs/verdict.md "Link vibration").
inline constexpr double kReferenceMaxRestitution = 0.9;
/// The reference's integrator tolerance (band energies, not a waveform).
inline constexpr double kReferenceTolerance = 1e-6;

struct ElasticReference {
  /// The linkage model with elastic links and with the same links rigid,
  /// through the recording's pass band; absent: not run.
  std::optional<MatchedTheory> theory, rigid_links;
  std::string not_run;                  ///< why not (no modal data: empty)
  std::string description;              ///< links, modes (Hz), contact stiffness
};

/// Where the reference runs: the recording's operating point, grid, pass
/// band and tangential accelerometers (as the report and the fit know them).
struct ElasticReferenceRun {
  const Rig* rig = nullptr;
  double clearance_m = 0;
  double crank_speed_rad_s = 0;
  CrankGrid grid;                                        ///< the measurement's
  FilterSpec filter;                                     ///< the α pass band as analysed
  std::array<std::optional<ResolvedMount>, 2> sensor;  ///< coupler [0], rocker [1] tangential
  std::string name;                                      ///< the recording's file name, for messages
};

/// `top_hz`: the family check's checked range.
ElasticReference elastic_reference(const ElasticReferenceRun& run, const TheorySettings& settings,
                                   const ModelFamilySettings& family, double top_hz);

}  // namespace fourbar

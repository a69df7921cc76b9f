#pragma once
// The elastic-link model as the fit's theory (issue 28 item 3; docs/fit.md
// "The elastic-link model"): the linkage model (sim/linkage) with the rig's
// elastic coupler and rocker and a compliant contact in the coupler–rocker
// joint (e → the contact's damping, μ → its regularised Coulomb friction),
// at the recording's operating point, from centred pins and `warmup` turns.
// What it gives for each link is what the recording's tangential
// accelerometer would read there (rigid frame + elastic deflection,
// sim/linkage/linkage_sensor.hpp), turned into α by analyze's own
// conversion (analyze/conversion.hpp) with the nominal link angle, as the
// mean over each cell of the target's grid (compare/linkage_theory.hpp: point
// values would fold the contact's energy above the grid's Nyquist order
// into the band energy), then the same pass bands and statistics as the
// three-mode model (statistics_of_theory).

#include "fit/fit_model.hpp"
#include "fit/recording_target.hpp"

namespace fourbar {

/// The compliant contact's stiffness the elastic model uses with `rig` at
/// `clearance_m`: the given one, else the rig bearing's. InputError naming
/// the rig file, the missing keys and the fix.
double elastic_fit_stiffness(const Rig& rig, const FitModel& model, double clearance_m);

/// InputError naming the rig file, what the elastic model needs that it
/// lacks (`[coupler.elastic]` / `[rocker.elastic]` modal data, the
/// bearing's stiffness keys) and the fix; also when `elastic_modes` asks for
/// more modes than a table gives. Builds the linkage model once to check it.
void check_elastic_fit_rig(const Rig& rig, const FitModel& model, double clearance_m);

/// Fills `target.sensor` from the recording's manifest: each fitted link's
/// tangential accelerometer (the channel analyze used), resolved on the rig.
void attach_sensors(RecordingTarget& target, const std::filesystem::path& manifest_file);

/// The elastic model's α over `turns` kept turns after `warmup` at `p`, on
/// `grid` (the target's analysis grid or its band's finer one), before any
/// pass band: what simulate_linkage_statistics and the model-family check
/// (family_judgement.hpp) start from.
MatchedTheory simulate_linkage_turns(const RecordingTarget& target, const ContactParameters& p, int warmup, int turns,
                                    double tolerance, const FitModel& model, const CrankGrid& grid);

/// The elastic model's statistics at `p` (see above).
SimulatedStatistics simulate_linkage_statistics(const RecordingTarget& target, const ContactParameters& p, int warmup,
                                                int turns, double tolerance, const FitModel& model);

}  // namespace fourbar

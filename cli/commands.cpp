#include <array>

#include "cli/command.hpp"

namespace fourbar::cli {

std::span<const Command> commands() {
  // In pipeline order: the main job first, then its stages, then the tools.
  static constexpr std::array table{
      Command{"report", "the main job: a session folder of recordings -> one HTML report, theory over measurement",
              run_report},
      Command{"inspect", "look inside a recording before there is a manifest; --manifest-template starts one",
              run_inspect},
      Command{"fit", "identify the bearing's restitution e and friction mu from a session's recordings", run_fit},
      Command{"acquire", "read a recording: calibrated channels, crank pulses, angle-tagged revolutions", run_acquire},
      Command{"analyze", "coupler and rocker angular acceleration and velocity from a recording, averaged",
              run_analyze},
      Command{"sim", "simulate a scene (nominal, clearance or linkage model) and write CSV + JSON", run_sim},
      Command{"sweep", "run the clearance model over a clearance x rpm x e x mu grid, one table", run_sweep},
      Command{"virtual-rig", "write the recording (and manifest, truth) the sensors would give for a scene",
              run_virtual_rig},
      Command{"rig", "check a rig file and report its class, assembly and transmission angles", run_rig},
      Command{"tap", "a link's mode frequencies and damping ratios from a hammer-tap recording, as rig-file lines",
              run_tap},
  };
  return table;
}

}  // namespace fourbar::cli

#include <array>

#include "cli/command.hpp"

namespace fourbar::cli {

std::span<const Command> commands() {
  static constexpr std::array table{
      Command{"sim", "simulate a scene (nominal mechanism) and write CSV + JSON", run_sim},
      Command{"rig", "check a rig file and report its class, assembly and transmission angles", run_rig},
  };
  return table;
}

}  // namespace fourbar::cli

#pragma once
// `fourbar sim --help`: the outputs and scene tables a scene may use.

#include <string>

namespace fourbar::cli {

/// The columns each model writes and the keys of [clearance], [compliant] and
/// [linkage], one aligned line each.
std::string sim_outputs_help();

}  // namespace fourbar::cli

#pragma once
// Bench support: the true contact parameters given on the command line as
// TRUE_E TRUE_CONTACT TRUE_MU (argv[2..4]) by the fit benches.

#include <string>

#include "fit/recording_target.hpp"

namespace fourbar::bench {

inline ContactParameters truth_from_args(char** argv) {
  ContactParameters truth;
  truth.restitution = std::stod(argv[2]);
  truth.contact = std::string(argv[3]) == "stick-slip" ? ContactLaw::stick_slip : ContactLaw::smooth;
  truth.friction_coefficient = std::stod(argv[4]);
  return truth;
}

}  // namespace fourbar::bench

#pragma once
// The report's section "Fitted bearing parameters" (a `fourbar fit` result,
// report/fit_record.hpp): the fitted values with their intervals and what is
// not identifiable, χ² at the fit and at the prior, measured vs the model at
// session.toml's prior vs the model at the fitted values (a, RMS difference,
// correlation, before → after), and the objective's profiles as small charts.

#include <sstream>

#include <nlohmann/json.hpp>

namespace fourbar {

/// <section id="fit"> for the (rounded) session record; nothing without "fit".
void fit_section(std::ostringstream& h, const nlohmann::json& data);

}  // namespace fourbar

#pragma once
// Which theory `fourbar fit` fits (docs/fit.md "The elastic-link model"):
// the three-mode clearance model (default), or the linkage model
// (sim/linkage, `model = "linkage"` in sim scenes) with the rig's elastic
// coupler and rocker, a compliant contact at the coupler–rocker joint and
// the accelerometers read on the elastic links (rigid + elastic).

#include <string>
#include <string_view>

#include "mechanism/rig.hpp"

namespace fourbar {

enum class FitModelKind { three_mode = 0, elastic = 1 };

struct FitModel {
  FitModelKind kind = FitModelKind::three_mode;
  /// Elastic model: pinned–pinned modes per elastic link (0: the rig
  /// table's `modes`).
  int elastic_modes = 0;
  /// Elastic model: the compliant contact's K in N/m^1.5 (0: from the
  /// rig's bearing, sim/compliant/contact_stiffness.hpp).
  double contact_stiffness_N_per_m_n = 0;
};

std::string_view name_of(FitModelKind k);
/// "three-mode" or "elastic" → the kind; InputError naming --model otherwise.
FitModelKind fit_model_kind(const std::string& text);

}  // namespace fourbar

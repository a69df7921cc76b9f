#pragma once
// Session level (thesis Figs 7.9–7.17 with 7.10/7.11): how the severity of
// the response changes with clearance at a fixed crank speed and with crank
// speed at a fixed clearance — measured (RMS of the fluctuation about the
// nominal response) beside simulated (impacts per turn n, ΣF, I_n = ΣF/n).

#include <optional>
#include <string>
#include <vector>

namespace fourbar {

struct SeverityPoint {
  std::string recording;
  double clearance_mm = 0;
  double speed_rpm = 0;
  std::optional<double> measured_alpha3_fluctuation_rms;  ///< RMS(α3 measured − nominal), rad/s²
  std::optional<double> measured_alpha4_fluctuation_rms;
  std::optional<double> simulated_alpha3_fluctuation_rms;  ///< RMS(α3 clearance model − nominal)
  double impacts_per_rev = 0;                 ///< n
  double sum_normal_impulse_per_rev_Ns = 0;   ///< ΣF
  std::optional<double> impact_index_Ns;      ///< I_n
  std::optional<double> magnification_alpha3;  ///< time-domain factor on α3
};

/// Points sharing one operating value (a crank speed or a clearance),
/// ordered by the other.
struct SeverityGroup {
  double value = 0;  ///< mean crank speed (rpm) or clearance (mm) of the group
  std::vector<SeverityPoint> points;
};

struct SeverityTables {
  std::vector<SeverityGroup> by_speed;      ///< each: one speed, points by rising clearance (Figs 7.9, 7.12–7.14, 7.10)
  std::vector<SeverityGroup> by_clearance;  ///< each: one clearance, points by rising speed (Figs 7.15–7.17, 7.11)
};

/// Groups speeds within `speed_tolerance` (relative, default 2 %) and
/// clearances within 1 % of each other.
SeverityTables severity_tables(std::vector<SeverityPoint> points, double speed_tolerance = 0.02);

}  // namespace fourbar

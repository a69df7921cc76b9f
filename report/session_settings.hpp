#pragma once
// A session folder and its optional `session.toml`: shared settings for the
// analysis and the matched theory of every recording in it, per-recording
// theory overrides, and a title. Read strictly (unknown keys are errors with
// a suggestion, values checked, file:line:key in every message).
//
//   title = "Coupler bearing, March series"      # report title (default: folder name)
//   notes = "..."
//   date = "2026-03-14"      # text, as the operator writes it; with operator, rig_id,
//   operator = "A. Tech"     # bearing: the session's record, on the report's
//   rig_id = "bench 2"       # first page (what a supervisor asks for)
//   bearing = "bush #7, bronze, 12 mm pin"
//   [analysis]    points_per_rev, low_hz, high_hz, mains_hz, mains_width_hz,
//                 window ("kaiser:8"), transition_hz, guard_revolutions,
//                 integration ("spectral" | "closed_trapezoid" | "trapezoid")
//   [theory]      model ("three-mode" | "compliant"), restitution,
//                 contact ("smooth" | "rough" | "stick-slip", three-mode),
//                 friction_coefficient, warmup_revolutions,
//                 averaged_revolutions, tolerance, max_order; with
//                 model = "compliant" the scene's compliant keys instead of
//                 contact (damping, contact_stiffness_N_per_m_n,
//                 contact_exponent, friction_*_speed_mm_s,
//                 damping_floor_speed_mm_s; stiffness from the rig's bearing
//                 when absent)
//   [model_family] band_width_hz, max_frequency_hz (compare/model_family.hpp;
//                 max_frequency_hz must stay below each recording's Nyquist
//                 frequency: check_band_limit)
//   [[recording]] file = "run3.flac", then any [theory] key for that recording

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analyze/pipeline.hpp"
#include "compare/matched_theory.hpp"
#include "compare/model_family.hpp"

namespace fourbar {

struct SessionSettings {
  std::filesystem::path file;  ///< session.toml (empty when the folder has none)
  std::string title;
  std::string notes;
  /// The session's record for the first page: date, operator, rig identity,
  /// bearing identity (empty when not given).
  std::string date, operator_name, rig_id, bearing;
  AnalyzeOptions analysis;     ///< keep_revolutions on (the spectral magnification needs every turn)
  TheorySettings theory;
  ModelFamilySettings model_family;  ///< [model_family]
  std::map<std::string, TheorySettings> theory_by_recording;  ///< by file name

  const TheorySettings& theory_for(const std::string& recording_file) const;
  /// Every setting with its value (for the report's settings table and the cache key).
  nlohmann::json to_json() const;
};

/// Reads `dir/session.toml` when present (defaults otherwise). InputError
/// naming file, line and key for a bad value or an unknown key.
SessionSettings load_session_settings(const std::filesystem::path& dir);

/// InputError (exit 2) naming session.toml's key when [model_family]
/// max_frequency_hz lies above the Nyquist frequency of `recording` sampled at `sample_rate_hz`.
void check_band_limit(const SessionSettings& settings, const std::string& recording, double sample_rate_hz);

struct SessionFiles {
  std::vector<std::filesystem::path> recordings;  ///< sorted by name
  std::vector<std::filesystem::path> orphan_manifests;  ///< REC.toml with no recording beside it
  std::vector<std::filesystem::path> other_files;  ///< neither a recording, a manifest, session.toml, *.truth.csv nor *.csv.json
};

/// The recordings in `dir` (top level only): files with a recording
/// extension (.wav .w64 .rf64 .flac .caf .aiff .aif .csv .tsv .txt), except
/// the virtual rig's `*.truth.csv`; a CSV's provenance `*.csv.json` is
/// neither a recording nor another file.
SessionFiles find_session_files(const std::filesystem::path& dir);

}  // namespace fourbar

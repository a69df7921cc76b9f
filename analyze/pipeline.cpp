#include "analyze/pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <sstream>

#include "analyze/chunked_analysis.hpp"
#include "analyze/window.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/units.hpp"

namespace fourbar {

const char* to_string(ConversionMethod m) { return m == ConversionMethod::full ? "full" : "thesis"; }

const char* to_string(IntegrationMethod m) {
  switch (m) {
    case IntegrationMethod::spectral: return "spectral";
    case IntegrationMethod::periodic: return "periodic";
    case IntegrationMethod::closed_trapezoid: return "closed-trapezoid";
    case IntegrationMethod::trapezoid: return "trapezoid";
  }
  return "?";
}

AnalyzeOptions AnalyzeOptions::thesis_method() {
  AnalyzeOptions o;
  o.conversion = ConversionMethod::thesis;
  o.integration = IntegrationMethod::trapezoid;
  o.filter.window = {WindowType::rectangular, 0};
  o.filter.transition_hz = 0.0;
  return o;
}

namespace {

void positive_if_set(const std::optional<double>& v, const char* option) {
  if (v && !(*v > 0 && std::isfinite(*v)))
    throw InputError(std::string("analyze: ") + option + " " + format_number(*v) + " must be a positive frequency in Hz");
}

}  // namespace

void validate_options(const AnalyzeOptions& o) {
  if (o.grid_points_per_rev != 0 && o.grid_points_per_rev < 4)
    throw InputError("analyze: --points " + std::to_string(o.grid_points_per_rev) + " must be at least 4 crank angles per revolution");
  positive_if_set(o.filter.low_hz, "--low-hz");
  positive_if_set(o.filter.high_hz, "--high-hz");
  if (o.filter.transition_hz && !(*o.filter.transition_hz >= 0 && std::isfinite(*o.filter.transition_hz)))
    throw InputError("analyze: --transition-hz " + format_number(*o.filter.transition_hz) + " must be >= 0 (0: ideal filter)");
  if (o.filter.mains_hz < 0 || !std::isfinite(o.filter.mains_hz))
    throw InputError("analyze: --mains-hz " + format_number(o.filter.mains_hz) + " must be 50, 60 (or any positive frequency), or 0 for none");
  validate_window(o.filter.window, "--window");
  if (o.filter.transition_hz && *o.filter.transition_hz == 0 && o.filter.window.type != WindowType::rectangular)
    throw InputError("analyze: --transition-hz 0 (the ideal bin-wise filter) takes --window rectangular, not " +
                     to_string(o.filter.window));
  if (o.spectrum_segment != 0 && o.spectrum_segment < 16)
    throw InputError("analyze: --spectrum-segment " + std::to_string(o.spectrum_segment) + " must be at least 16 samples");
}

RecordingAnalysis analyze_recording(const std::filesystem::path& recording, const std::filesystem::path& manifest_file,
                                    const AnalyzeOptions& options, RevolutionObserver* observer) {
  validate_options(options);
  OpenedRecording opened = open_with_manifest(recording, manifest_file);
  const Manifest& manifest = opened.manifest;

  RecordingAnalysis result;
  result.recording = recording;
  result.manifest_file = manifest.file;
  result.rig_file = manifest.rig_file;
  result.rig = manifest.rig;
  result.clearance_m = manifest.clearance_m;
  result.options = options;

  // The channels, checked against the rig before the long passes.
  const AnalysisChannels channels = analysis_channels(manifest);
  if (options.conversion == ConversionMethod::full)
    for (const auto& link : channels.links)
      for (const auto* ch : {&link.tangential, &link.normal}) try {
          if (*ch) resolve_mount(*manifest.rig, (*ch)->mount);
        } catch (const InputError& e) {
          throw InputError(manifest.file.string() + ": " + e.what() + " (keys position_mm, offset_mm)");
        }
  result.warnings = channels.warnings;
  result.clearance_from_rig = manifest.clearance_from_rig;
  if (manifest.clearance_from_rig)
    result.warnings.push_back(manifest.file.string() + ": clearance_mm = \"rig\": the rig file's " +
                              format_number(units::m_to_mm(manifest.clearance_m), 4) +
                              " mm is used as this run's clearance (the theory and the verdict rest on it); give the "
                              "measured radial clearance if this run's bearing differs");
  // The filter corners against the sample rate, as far as they are given.
  {
    const double fs = opened.reader->info().sample_rate_hz;
    const double nyquist = 0.5 * fs;
    for (const auto& [v, option] : {std::pair{options.filter.low_hz, "--low-hz"}, std::pair{options.filter.high_hz, "--high-hz"}})
      if (v && *v >= nyquist)
        throw InputError("analyze: " + std::string(option) + " " + format_number(*v) + " Hz lies at or above the Nyquist frequency " +
                         format_number(nyquist) + " Hz of " + recording.string() + " (sample rate " + format_number(fs) +
                         " Hz); give a corner below it");
    if (options.filter.mains_hz >= nyquist)
      throw InputError("analyze: --mains-hz " + format_number(options.filter.mains_hz) + " lies at or above the Nyquist frequency " +
                       format_number(nyquist) + " Hz of " + recording.string());
  }

  ChunkedAnalysis analysis(result, manifest, channels, observer);
  AcquireOptions acquire_options;
  acquire_options.progress = options.progress;
  acquire_options.excerpt_revolutions = options.excerpt_revolutions;
  acquire_options.threads = options.threads;
  acquire_options.range = options.range;
  result.acquisition = acquire(*opened.reader, manifest, acquire_options, analysis);
  analysis.finish();
  // The analysis resamples on its own grid (acquire made none): report that one.
  result.acquisition.grid_points_per_rev = static_cast<int>(result.grid_points_per_rev);
  result.warnings.insert(result.warnings.begin(), result.acquisition.warnings.begin(),
                         result.acquisition.warnings.end());
  if (options.setup_check) result.setup_check = check_setup(result, manifest);
  if (result.acquisition.wheel.positions_per_rev == 0 && !channels.links.empty() && result.mean_crank_speed_rad_s != 0 &&
      options.conversion == ConversionMethod::full) {
    const AccelerometerMount& mount = channels.links.front().tangential->mount;
    result.unseen_speed = unseen_speed_sensitivity(*manifest.rig, mount, result.mean_crank_speed_rad_s,
                                                   manifest.pulse_channel().crank_offset_rad);
    result.unseen_speed_link = mount.link;
  }
  return result;
}

}  // namespace fourbar

// The set-up check's detection and false-alarm rates on virtual-rig
// recordings of the thesis rig: every combination of motion (nominal,
// clearance 0.254 mm), crank speed, SNR and coupling (DC, AC 0.5 Hz), each
// analysed with the correct manifest and with each common mistake written
// into it. Prints the table docs/setup-check.md quotes, and (--cost) the check's
// cost against the analysis's on the same recordings.
//
//   build/bench/setup_check_matrix [--seeds S=3] [--revolutions R=12] [--coupler-only] [--verbose]
//
// --coupler-only: the manifest has only the coupler's tangential channel (the
// analysis's minimum), so the rocker and swap mistakes do not apply.
//
// The CI version (a smaller matrix) is tests/analyze/test_setup_check.cpp.

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>

#include "setup_mistakes.hpp"

using namespace fourbar;
using namespace fourbar::testing;

int main(int argc, char** argv) {
  int seeds = 3;
  double revolutions = 12;
  bool verbose = false, coupler_only = false;
  SetupCheckLimits limits;
  limits.min_confidence = 0;  // every candidate, to see the margins
  std::map<Mistake, double> conf_margin;  // mistake: lowest confidence of its finding; none: highest of any
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--seeds") && i + 1 < argc) seeds = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--revolutions") && i + 1 < argc) revolutions = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--verbose")) verbose = true;
    else if (!std::strcmp(argv[i], "--coupler-only")) coupler_only = true;
    else {
      std::fprintf(stderr, "usage: setup_check_matrix [--seeds S] [--revolutions R] [--coupler-only] [--verbose]\n");
      return 2;
    }
  }
  std::vector<Mistake> mistakes{Mistake::none};
  for (Mistake m : coupler_only ? coupler_only_mistakes() : all_mistakes()) mistakes.push_back(m);
  std::map<Mistake, std::pair<int, int>> counts;  // flagged, cases
  double analysis_s = 0, check_s = 0;
  double worst_scale = 0;  // correct manifests: largest |scale − 1| of a channel fitted on its own link
  int cases = 0;
  std::uint64_t seed = 100;
  for (bool clearance : {false, true})
    for (double rpm : {250.0, 350.0, 450.0, 600.0})
      for (double snr : {20.0, 30.0, 40.0})
        for (bool ac : {false, true})
          for (int s = 0; s < seeds; ++s) {
            VirtualSetup v(rpm);
            SetupCase c;
            c.rpm = rpm, c.clearance = clearance, c.snr_db = snr, c.ac_coupled = ac, c.revolutions = revolutions;
            c.coupler_only = coupler_only;
            c.seed = ++seed;
            const auto rec = write_setup_case(v, c, "rec.wav");
            for (Mistake m : mistakes) {
              AnalyzeOptions o;
              o.progress = false;
              o.setup_check = false;
              const auto manifest_file = manifest_with(rec, m);
              const auto t0 = std::chrono::steady_clock::now();
              const RecordingAnalysis a = analyze_recording(rec, manifest_file, o);
              const Manifest manifest = load_manifest(manifest_file);
              const auto t1 = std::chrono::steady_clock::now();
              const SetupCheck check = check_setup(a, manifest);
              const auto t2 = std::chrono::steady_clock::now();
              const SetupCheck all = check_setup(a, manifest, limits);
              double extreme = 0;
              // A mistake: the confidence of its finding; the correct manifest: of any candidate.
              for (const SetupFinding& f : (m == Mistake::none ? all : check).findings) {
                SetupCheck one;
                one.findings = {f};
                if (m == Mistake::none || flags(one, m)) extreme = std::max(extreme, f.confidence);
              }
              if (!conf_margin.count(m)) conf_margin[m] = extreme;
              conf_margin[m] = m == Mistake::none ? std::max(conf_margin[m], extreme) : std::min(conf_margin[m], extreme);
              analysis_s += std::chrono::duration<double>(t1 - t0).count();
              check_s += std::chrono::duration<double>(t2 - t1).count();
              ++cases;
              if (m == Mistake::none)
                for (const ChannelSetupEstimate& e : check.channels)
                  if (e.fitted_as == std::string(to_string(e.role))) worst_scale = std::max(worst_scale, std::abs(std::abs(e.scale) - 1));
              const bool hit = flags(check, m);
              counts[m].first += hit;
              counts[m].second += 1;
              const bool wrong = m == Mistake::none ? hit : !hit;
              if (verbose || wrong) {
                std::printf("%s %-9s %3.0f rpm %2.0f dB %s seed %llu | %-28s fit %.3f (manifest %.3f) offset %.1f dir %+.0f%s\n",
                            wrong ? "MISS" : "    ", clearance ? "clearance" : "nominal", rpm, snr, ac ? "AC" : "DC",
                            static_cast<unsigned long long>(c.seed), to_string(m), check.fit, check.fit_manifest,
                            check.crank_offset_deg, check.crank_direction, check.swapped ? " swapped" : "");
                for (const ChannelSetupEstimate& e : check.channels)
                  std::printf("        %-10s as %-19s scale %+.3f position %.1f mm (conf %.2f) fit %.3f manifest %.3f\n",
                              e.channel.c_str(), e.fitted_as.c_str(), e.scale, e.position_mm, e.position_confidence,
                              e.fit, e.fit_manifest);
                for (const SetupFinding& f : check.findings) std::printf("        finding: %s\n", f.message.c_str());
              }
            }
          }
  std::printf("\nset-up check on %d virtual-rig recordings x %zu manifests (%g revolutions each; nominal and clearance "
              "0.254 mm; 250/350/450/600 rpm; 20/30/40 dB SNR; DC and AC 0.5 Hz; %d seeds)\n\n",
              cases / static_cast<int>(mistakes.size()), mistakes.size(), revolutions, seeds);
  std::printf("| manifest | flagged | rate | confidence (lowest; correct: highest of any candidate) |\n|---|---|---|---|\n");
  for (Mistake m : mistakes)
    std::printf("| %s | %d / %d | %.1f %% | %.2f |\n", to_string(m), counts[m].first, counts[m].second,
                100.0 * counts[m].first / counts[m].second, conf_margin[m]);
  std::printf("\ncorrect manifests: largest |scale - 1| of a channel on its own link: %.4f\n", worst_scale);
  std::printf("\ncheck cost: %.4f s against %.3f s of analysis (%.2f %%)\n", check_s, analysis_s,
              100 * check_s / analysis_s);
  return 0;
}

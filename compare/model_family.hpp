#pragma once
// Does the measurement hold physics the model family lacks? The rigid
// clearance model has no link bending, no sensor resonance: energy the model
// does not have, concentrated in some frequency band, shows in the
// measurement's spectrum and in its turn-to-turn scatter, and a wrong model
// can then "match" a scatter that is not the clearance's.
//
// The check, on one link acceleration (α3, else α4), per turn:
//   d = turn − nominal (measured and model alike), its mean square per crank
//   order k by FFTW over the turn (Parseval: Σ_k P(k) = mean(d²)), averaged
//   over the whole record (turns one after another, Hann window: a ring that
//   does not fit a turn does not leak); bins grouped into bands of
//   band_width_hz from crank order kFirstCheckedOrder (order k at
//   k·f_crank Hz); per band the ratio r_b = E_measured(b) / E_model(b);
//   windows of kWindowBands adjacent bands, one band apart.
//   Impacts are near-impulses in α, so both sides have broadband spectra and
//   r_b changes only slowly with frequency whatever e is (measured: a
//   smooth fall of up to 20× over 100–900 Hz from another e and the
//   measurement chain's roll-off). Each window's reference r_ref is the
//   trend interpolated across it from its neighbours (kReferenceBands bands
//   on each side beyond its direct neighbours): the geometric mean of the
//   median ratio below and the median ratio above (one side's median at
//   the range's edges); its measured neighbours' level likewise. A window is unmodelled when its ratio
//   exceeds kExcessRatio·r_ref, its measured energy stands kMinProminence times
//   above its neighbours' (the measured spectrum itself peaks there), AND
//   its excess E_m − r_ref·E_s is at least kMinRmsShare of the measured
//   signal's RMS (as an RMS share). Adjacent
//   unmodelled bands form one finding: where (Hz), its peak, its strength
//   (√(excess / mean square of the measured signal)), and what it looks like
//   — a narrow resonance (excess within ±kNarrowShare of its peak frequency:
//   a link's bending mode or the sensor's mounted resonance) or broad
//   ringing (after impacts).
//
// Below the first unmodelled band (and below kCutShareOfPeak of its peak)
// the family is taken to hold: the turns, measured and model, are low-passed there (orders at or above it zeroed)
// and their turn-to-turn scatter compared again, a (scatter) below the band.
// docs/verdict.md "Model family" gives the reasons for each threshold.

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace fourbar {

/// A window's ratio over its neighbours' above which its energy is unmodelled
/// (5: 6 until 2026-12-03 missed structures at 5.6–6.0 whose prominence was
/// 6.2–10; on recordings without one no window with a prominence of 6 had a
/// ratio between 5 and 6, docs/verdict.md "A lower ratio threshold").
inline constexpr double kExcessRatio = 5.0;
/// Bands per window (windows one band apart).
inline constexpr std::size_t kWindowBands = 2;
/// … and its measured energy at least this many times its neighbours' (the
/// measured spectrum itself peaks there: a broad change of the ratio's
/// trend by another e does not, docs/verdict.md "Model family").
inline constexpr double kMinProminence = 6.0;
/// The agreement is judged below this share of the first finding's peak
/// frequency (or its band, whichever is lower): of a mode rung by impulses
/// at ζ = 0.02, 3.4 % of its energy up to 1.6 f lies below 0.75 f.
inline constexpr double kCutShareOfPeak = 0.75;
/// Windows also kWindowBands × 2, 4, … up to × this (their gap to the
/// neighbours and the neighbours' reach scaled alike): a lower-Q resonance
/// spans more bands than the narrowest window.
inline constexpr std::size_t kWindowScales = 4;
/// The neighbours: this many bands on each side beyond the window's direct neighbours.
inline constexpr std::size_t kReferenceBands = 4;
/// The check starts at this crank order: below it lies the rigid mechanism's
/// own response (the nominal band, the free flights), where another e
/// changes the spectrum's shape, not a structure the model lacks.
inline constexpr double kFirstCheckedOrder = 20;
/// The excess's RMS over the measured signal's RMS from which it is named.
inline constexpr double kMinRmsShare = 0.05;
/// Excess within ± this share of its peak frequency: a narrow resonance.
inline constexpr double kNarrowShare = 0.15;
/// A cut below this many crank orders leaves too little to judge the agreement on.
inline constexpr double kMinJudgedOrders = 10;

struct ModelFamilySettings {
  double band_width_hz = 20;  ///< [model_family] band_width_hz
  /// Highest frequency checked, Hz ([model_family] max_frequency_hz); 0: the
  /// grid's and the analysis filter's limit.
  double max_frequency_hz = 0;
  /// The compliant contact's stiffness (N/m^n) of the elastic-link reference
  /// (compare/link_vibration.hpp) when the rig file gives no bearing to
  /// compute it from ([model_family] contact_stiffness_N_per_m_n); 0: the rig's.
  double contact_stiffness_N_per_m_n = 0;
};

struct FamilyBand {
  double low_hz = 0, high_hz = 0;
  double measured_ms = 0, model_ms = 0;  ///< mean square of the deviation in the band
  double ratio = 0;                       ///< measured over model
  /// Of the window through this band that stands highest: its ratio over
  /// its neighbours' median ratio (`reference`), and its measured energy
  /// per band over its neighbours' median energy.
  double ratio_to_neighbours = 0, reference = 0, prominence = 0;
  bool unmodelled = false;
};

struct UnmodelledEnergy {
  std::string kind;          ///< "narrow resonance" or "broad ringing"
  double low_hz = 0, high_hz = 0, peak_hz = 0;
  double rms_share = 0;      ///< √(excess / mean square of the measured signal)
  double excess_ratio = 0;   ///< largest band ratio over the typical one
  /// Were this the first finding: where the agreement is judged (Hz), the
  /// turn-to-turn scatter of both sides below it, their ratio, or why it
  /// cannot be judged (a session may set a finding aside, see
  /// report/family_across_speeds.hpp, and the next one then decides).
  double judged_below_hz = 0;
  double measured_scatter_below = 0, model_scatter_below = 0;
  std::optional<double> a_scatter_below;
  std::string cannot_judge;
};

struct ModelFamilyCheck {
  bool checked = false;
  std::string not_checked;  ///< why not
  double crank_hz = 0, checked_up_to_hz = 0;
  double typical_ratio = 0;  ///< r_ref
  std::vector<FamilyBand> bands;
  std::vector<UnmodelledEnergy> unmodelled;  ///< lowest first
  /// Below the first unmodelled band: where the agreement is judged (Hz)
  /// and the turn-to-turn scatter of both sides there.
  std::optional<double> judged_below_hz;
  double measured_scatter_below = 0, model_scatter_below = 0;
  std::optional<double> a_scatter_below;  ///< model / measured scatter below the band
  std::string cannot_judge;  ///< set when the band leaves too little below it
};

/// `measured`, `model`: turns × N on the crank-angle grid; `nominal`: N.
/// `filter_high_hz`: the analysis' upper corner (0: none).
ModelFamilyCheck check_model_family(std::span<const double> measured, std::span<const double> model,
                                    std::span<const double> nominal, double crank_hz, double filter_high_hz,
                                    const ModelFamilySettings& settings);

/// The check's verdict fields (judged_below_hz, the scatters below, a,
/// cannot_judge) from its first finding, or cleared when it has none.
void judge_below_first_finding(ModelFamilyCheck& c);

/// Mean square of (turn − nominal) in each of `bands` (the check's own
/// spectrum of the whole record, Hann-windowed): a third side compared on the
/// check's bands (compare/link_vibration.hpp).
std::vector<double> band_mean_squares(std::span<const double> turns, std::span<const double> nominal, double crank_hz,
                                      std::span<const FamilyBand> bands);

/// Where the agreement is judged should `u` be the first finding (below its
/// band and below kCutShareOfPeak of its peak), the turn-to-turn scatter of
/// both sides low-passed there and their ratio, or why it cannot be judged.
void judge_below(UnmodelledEnergy& u, std::span<const double> measured, std::span<const double> model, std::size_t n,
                 double crank_hz);

/// Turns × N (consecutive turns) with every crank order at or above
/// `cut_order` removed, by one transform of the whole record.
std::vector<double> low_passed_turns(std::span<const double> turns, std::size_t n, double cut_order);

/// √(mean over angles of the variance over turns): the turn-to-turn scatter.
double turn_scatter(std::span<const double> turns, std::size_t n);

}  // namespace fourbar

#include "report/verdict.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <span>

#include "analyze/setup_finding.hpp"
#include "common/format.hpp"
#include "fit/response_statistics.hpp"

namespace fourbar {

namespace {

using nlohmann::json;

std::string num(double v, int digits = 2) { return format_number(v, digits); }
std::string pct(double share) { return format_number(100.0 * share, 2) + " %"; }

/// Turns to record for a quantity that falls as 1/√turns to go from `now` to `target`.
std::size_t turns_for(std::size_t turns, double now, double target) {
  return static_cast<std::size_t>(std::ceil(static_cast<double>(std::max<std::size_t>(turns, 1)) * (now / target) * (now / target)));
}

std::string turns_and_time(std::size_t turns, double rpm) {
  std::string s = std::to_string(turns) + " turns";
  if (rpm > 0) s += " (" + num(static_cast<double>(turns) / (rpm / 60.0), 2) + " s at " + num(rpm, 3) + " rpm)";
  return s;
}

VerdictLevel worst(VerdictLevel a, VerdictLevel b) {
  if (a == VerdictLevel::not_judged) return b;
  if (b == VerdictLevel::not_judged) return a;
  return static_cast<int>(a) > static_cast<int>(b) ? a : b;
}

VerdictPart setup_part(const VerdictInputs& in) {
  if (!in.findings.empty()) {
    const VerdictFinding& f = *std::max_element(in.findings.begin(), in.findings.end(),
                                                [](const auto& a, const auto& b) { return a.confidence < b.confidence; });
    std::string s = "The data contradict the manifest: " + finding_label(f.item, f.key) + (f.channel.empty() ? "" : " of " + f.channel) +
                    " — the manifest says " + f.manifest + ", the data say " + f.data + " (confidence " +
                    std::to_string(std::lround(100 * f.confidence)) + " %); change " + f.key;
    if (in.findings.size() > 1) s += " (and " + std::to_string(in.findings.size() - 1) + " more, listed in the set-up box)";
    return {VerdictLevel::problem, "check set-up", s + ". Until then every number below rests on a wrong manifest."};
  }
  if (!in.setup_checked)
    return {VerdictLevel::attention, "not checked",
            "The set-up check did not run" + (in.setup_not_checked.empty() ? std::string() : " (" + in.setup_not_checked + ")") +
                ": the results rest on the manifest unchecked."};
  return {VerdictLevel::good, "matches",
          "The data agree with the manifest (crank pulse angle, direction, channels, axis signs, calibration, positions)."};
}

double scatter_of(const VerdictInputs& in) { return in.nominal_rms > 0 ? in.spread_rms / in.nominal_rms : 0; }

/// The effect lives in the scatter between turns, not in the averaged curve:
/// the verdict then judges by a (scatter).
bool effect_is_chaotic(const VerdictInputs& in) {
  return in.effect_to_floor.value_or(0) < kEffectSeen && scatter_of(in) >= kScatterSeen && in.spread_rms > 0;
}

/// Chaotic, and the model at this clearance scatters too: the floor between
/// order lines of the averaged α3 is then the impacts' own scatter left in
/// the average (chance residues of chaotic turns), not noise.
bool floor_is_chaotic_scatter(const VerdictInputs& in) {
  return effect_is_chaotic(in) && in.nominal_rms > 0 && in.model_spread_rms / in.nominal_rms >= kScatterSeen;
}

VerdictPart measurement_part(const VerdictInputs& in) {
  struct Item {
    VerdictLevel level;
    std::string words, sentence;
  };
  std::vector<Item> items;
  const double rpm = in.speed_mean_rpm;
  std::string chaotic_note;  // what the floor is when it is the impacts' scatter
  if (in.revolutions >= kMinRevolutionsForFloor && floor_is_chaotic_scatter(in)) {
    const std::string floor = in.floor_rms > 0 && in.nominal_rms > 0 ? " (" + pct(in.floor_rms / in.nominal_rms) + ")" : std::string();
    chaotic_note = "The floor between order lines of the averaged α3" + floor +
                   " is the chaotic impacts' own scatter left in the average, not a measurement fault: the verdict judges by "
                   "a (scatter), whose standard error measures what these turns resolve.";
    if (in.scatter_relative_error) {
      const double rel = *in.scatter_relative_error;
      if (rel > kScatterErrorGood)
        items.push_back({rel > kScatterErrorProblem ? VerdictLevel::problem : VerdictLevel::attention, "a ± " + pct(rel),
                         "a (scatter) is uncertain by " + pct(rel) + " (standard error, " + std::to_string(in.revolutions) +
                             " turns): record about " + turns_and_time(turns_for(in.revolutions, rel, kScatterErrorGood), rpm) +
                             " to bring it to " + num(100 * kScatterErrorGood, 3) + " % (it falls about as 1/√turns)."});
    }
  } else if (in.revolutions < kMinRevolutionsForFloor) {
    items.push_back({VerdictLevel::problem, std::to_string(in.revolutions) + " turns",
                     "Only " + std::to_string(in.revolutions) + " turns averaged: no noise floor can be estimated; record at least " +
                         turns_and_time(kMinRevolutionsForFloor, rpm) + " (more lower the floor as 1/√turns)."});
  } else if (in.nominal_rms > 0 && in.floor_rms > 0) {
    const double rel = in.floor_rms / in.nominal_rms;
    if (rel > kFloorGood)
      items.push_back({rel > kFloorProblem ? VerdictLevel::problem : VerdictLevel::attention, "floor " + pct(rel),
                       "The averaged α3 is uncertain by " + pct(rel) + " of the nominal response (floor between order lines, " +
                           std::to_string(in.revolutions) + " turns): record about " +
                           turns_and_time(turns_for(in.revolutions, rel, kFloorGood), rpm) + " to bring it to " + pct(kFloorGood) +
                           " (it falls as 1/√turns)."});
  }
  const std::size_t all = in.revolutions + in.revolutions_clipped;
  if (in.revolutions_clipped > 0) {
    const double share = static_cast<double>(in.revolutions_clipped) / static_cast<double>(std::max<std::size_t>(all, 1));
    items.push_back({share > kClippedProblem ? VerdictLevel::problem : VerdictLevel::attention,
                     std::to_string(in.revolutions_clipped) + " clipped",
                     std::to_string(in.revolutions_clipped) + " of " + std::to_string(all) +
                         " turns clipped and left out: raise the clipping channel's input range or lower its gain."});
  }
  if (rpm > 0) {
    const double rel = in.speed_std_rpm / rpm;
    if (rel > kSpeedGood)
      items.push_back({rel > kSpeedProblem ? VerdictLevel::problem : VerdictLevel::attention, "speed ±" + pct(rel),
                       "The crank speed wanders by " + pct(rel) + " (std): the nominal α3 (∝ ω²) moves by about " + pct(2 * rel) +
                           " between turns; steady the drive (flywheel, speed control) or record shorter runs at one setting."});
  }
  VerdictPart p;
  p.level = VerdictLevel::good;
  for (const Item& i : items) p.level = worst(p.level, i.level);
  for (const Item& i : items) {
    p.words += (p.words.empty() ? "" : ", ") + i.words;
    p.sentence += (p.sentence.empty() ? "" : " ") + i.sentence;
  }
  if (items.empty()) {
    p.words = "ok";
    p.sentence = std::to_string(in.revolutions) + " turns averaged";
    if (!chaotic_note.empty() && in.scatter_relative_error)
      p.sentence += ", a (scatter) uncertain by " + pct(*in.scatter_relative_error) + " (standard error)";
    else if (chaotic_note.empty() && in.nominal_rms > 0 && in.floor_rms > 0)
      p.sentence += ", noise floor " + pct(in.floor_rms / in.nominal_rms) + " of the nominal α3";
    if (rpm > 0) p.sentence += ", crank speed steady to " + pct(in.speed_std_rpm / rpm);
    p.sentence += in.clipping_checked ? ", nothing clipped." : ".";
  }
  if (!in.clipping_checked) p.sentence += " Clipping was not checked (float or text data without adc_range_V in the manifest).";
  if (!chaotic_note.empty()) p.sentence += " " + chaotic_note;
  return p;
}

/// No clearance effect above the noise floor (the effect part's "none").
bool effect_none(const VerdictInputs& in) {
  return in.effect_to_floor.value_or(0) < kEffectNone && scatter_of(in) < kScatterNone;
}

VerdictPart effect_part(const VerdictInputs& in) {
  if (!in.effect_to_floor && !(in.nominal_rms > 0 && in.spread_rms > 0))
    return {VerdictLevel::not_judged, "not judged",
            "The clearance effect cannot be judged: no noise floor (too few turns) and no turn-to-turn scatter."};
  const double lines = in.effect_to_floor.value_or(0);
  const double scatter = scatter_of(in);
  const double model_lines = in.model_effect_to_floor.value_or(0);
  const double model_scatter = in.nominal_rms > 0 ? in.model_spread_rms / in.nominal_rms : 0;
  const std::string measured = "α3 order lines above order " + std::to_string(in.nominal_band_orders) + " at " + num(lines) +
                               "× the floor between them, turn-to-turn scatter " + pct(scatter) + " of the nominal response";
  const bool seen = lines >= kEffectSeen || scatter >= kScatterSeen;
  const bool none = effect_none(in);
  const bool expected = model_lines >= kEffectSeen || model_scatter >= kScatterSeen;
  if (seen)
    return {VerdictLevel::good, lines >= kEffectSeen ? "seen (lines " + num(lines) + "× floor)" : "seen (scatter " + pct(scatter) + ")",
            "A clearance effect is measured: " + measured + "."};
  if (none && expected)
    return {VerdictLevel::problem, "none, model expects one",
            "No clearance effect measurable above the noise floor (" + measured + "), but the clearance model at " +
                num(in.clearance_mm, 3) + " mm expects lines at " + num(model_lines) + "× the floor and " + pct(model_scatter) +
                " scatter: check clearance_mm in the manifest and the bearing (a tighter, lubricated or preloaded joint hides the clearance)."};
  if (none)
    return {VerdictLevel::good, "none",
            "No clearance effect measurable above the noise floor (" + measured + "); the model at " + num(in.clearance_mm, 3) +
                " mm expects none either."};
  std::string s = "A clearance effect barely above the noise floor (" + measured + ")";
  if (lines > 0 && in.revolutions > 0)
    s += ": record about " + turns_and_time(turns_for(in.revolutions, kEffectSeen, std::max(lines, 1e-9)), in.speed_mean_rpm) +
         " to raise the lines to " + num(kEffectSeen) + "× the floor (it falls as 1/√turns)";
  return {VerdictLevel::attention, "marginal (" + num(lines) + "× floor)", s + "."};
}

std::string fit_sentence(const VerdictInputs& in) {
  if (!in.fit) return {};
  const VerdictFit& f = *in.fit;
  std::string s = " The fit (" + f.file + ") gives e = " + num(f.restitution, 3) + " [" + num(f.restitution_low, 3) + ", " +
                  num(f.restitution_high, 3) + "]" + (f.friction ? ", μ = " + num(*f.friction, 3) : std::string()) + " (" +
                  f.contact + ")";
  if (!f.restitution_identifiable) s += ", but e is not identifiable from these recordings";
  if (f.magnification_fitted)
    s += "; with it a = " + num(*f.magnification_fitted, 3) +
         (f.magnification_fitted_standard_error ? " ± " + num(*f.magnification_fitted_standard_error, 2) : std::string()) +
         " for this recording";
  if (std::abs(f.restitution - in.restitution) > 0.01)
    s += "; set [theory] restitution = " + num(f.restitution, 3) + (f.friction ? " and friction_coefficient = " + num(*f.friction, 3) : std::string()) +
         " in session.toml to report with the fitted values";
  return s + ".";
}

/// The agreement sentence's clause on a (scatter)'s own error: whether the
/// turns recorded resolve a difference from 1, and how many would.
std::string scatter_error_clause(double a, double se, std::size_t turns) {
  const bool one_inside = std::abs(a - 1) <= 2 * se;
  std::string s = " a (scatter) has a standard error of " + num(se, 2) + " from " + std::to_string(turns) +
                  " measured turns and the model's turns (jackknife over turns)";
  if (one_inside && (a < kAgreeLow || a > kAgreeHigh))
    return s + ": 1 is within a ± 2 standard errors, so these turns do not resolve the difference; record more turns "
               "before changing the model.";
  if (!one_inside && a >= kAgreeLow && a <= kAgreeHigh)
    return s + ": a differs from 1 by more than 2 standard errors, though within " + pct(kAgreeHigh - 1) + ".";
  if (one_inside && 2 * se > kAgreeHigh - 1)
    return s + ": larger than the " + pct(kAgreeHigh - 1) + " this judgement allows, so agreement is not resolved either; "
               "record more turns to tell.";
  return s + ".";
}

/// The agreement sentence's clause when the measured turns repeat every few
/// turns; `differs` is set when the model's turns do not repeat at that lag.
std::string repeat_clause(const VerdictInputs& in, bool chaotic, bool& differs) {
  differs = false;
  if (!in.repeat) return {};
  const VerdictInputs::Repeat& r = *in.repeat;
  if (!r.confirmed)
    return " The measured turns may repeat every " + std::to_string(r.period) + " turns (turn i against turn i + " +
           std::to_string(r.period) + ": " + num(r.ratio, 2) + " of what irregular turns give, against " + num(r.neighbours, 2) +
           " for neighbouring turns), but the " + std::to_string(r.turns) +
           " turns it compares (each pulse-train segment's first and last two stay out) are too few to tell (at least " +
           std::to_string(2 * r.period + 4) + "): record more turns. If they do repeat, a compares a periodic motion "
           "with the model's and says little about the contact parameters (docs/verdict.md \"A periodic measured motion\").";
  std::string s = " The measured turns repeat every " + std::to_string(r.period) + " turns (turn i against turn i + " +
                  std::to_string(r.period) + ": " + num(r.ratio, 2) + " of what irregular turns give, against " +
                  num(r.neighbours, 2) + " for neighbouring turns), a periodic motion of the mechanism";
  if (!r.model_ratio)
    return s + "; the model's " + std::to_string(r.model_turns) + " turns are too few to tell whether it repeats (at least " +
           std::to_string(2 * r.period + 4) + "): set [theory] averaged_revolutions in session.toml.";
  if (*r.model_ratio < kTurnRepeatRatio) return s + "; the model's turns repeat at that lag too (" + num(*r.model_ratio, 2) + ").";
  differs = true;
  return s + "; the model's turns do not (" + num(*r.model_ratio, 2) + "): " +
         (chaotic ? "a (scatter) compares a periodic motion with an irregular one" : "a compares the averages of two different motions") +
         ", so its value, agreeing or not, says little about the contact parameters. A model can have such a motion beside an "
         "irregular one and not reach it from its start; the recording's own start decides which one the rig takes "
         "(docs/fit.md \"A periodic recording\").";
}

VerdictPart agreement_part(const VerdictInputs& in, std::optional<double>& a, std::optional<double>& a_se,
                           std::string& a_from) {
  const bool spectral = in.a_spectral && !in.orders_used.empty();
  const bool chaotic = effect_is_chaotic(in);
  std::string from;
  if (chaotic && in.model_revolutions > 0 && in.model_revolutions < kMinModelTurnsForScatter)
    return {VerdictLevel::attention, "too few model turns",
            "The clearance effect is chaotic (in the scatter between turns), so the model is compared by its own "
            "turn-to-turn scatter; the theory averaged " + std::to_string(in.model_revolutions) +
                (in.model_revolutions == 1 ? " turn" : " turns") + ", too few for one (at least " +
                std::to_string(kMinModelTurnsForScatter) + "): set [theory] averaged_revolutions = 20 in session.toml." +
                fit_sentence(in)};
  if (chaotic) {
    a = in.model_spread_rms / in.spread_rms;
    if (in.scatter_relative_error) a_se = *a * *in.scatter_relative_error;
    a_from = "scatter";
    from = "a (scatter) = model / measured turn-to-turn scatter of α3";
  } else if (spectral) {
    a = in.a_spectral;
    a_from = "spectral";
    from = "a (spectral) from orders ";
    for (std::size_t i = 0; i < in.orders_used.size(); ++i) from += (i ? ", " : "") + std::to_string(in.orders_used[i]);
  } else if (in.a_time) {
    a = in.a_time;
    a_from = "time";
    from = "a (time)";
  }
  if (!a) return {VerdictLevel::not_judged, "no a", "No magnification factor: the measurement equals the nominal response." + fit_sentence(in)};
  const std::string words = "a " + num(*a, 2) + (a_se ? " ± " + num(*a_se, 2) : std::string()) + " (" + a_from + ")";
  if (effect_none(in) || (!in.effect_to_floor && in.spread_rms == 0))
    return {VerdictLevel::not_judged, words + ", not meaningful",
            from + " = " + num(*a, 3) + " compares the model with noise: no clearance effect was measured." + fit_sentence(in)};
  VerdictPart p;
  p.words = words;
  p.level = (*a >= kAgreeLow && *a <= kAgreeHigh)                 ? VerdictLevel::good
            : (*a >= kAgreeProblemLow && *a <= kAgreeProblemHigh) ? VerdictLevel::attention
                                                                  : VerdictLevel::problem;
  p.sentence = from + " = " + num(*a, 3) + ": ";
  const std::string e = "e = " + num(in.restitution, 3);
  if (*a > kAgreeHigh)
    p.sentence += "the model is " + num(*a, 2) + "× more violent than the measurement; lower the restitution (" + e +
                  ") or the clearance if the manifest overstates it";
  else if (*a < kAgreeLow)
    p.sentence += "the model is gentler than the measurement (" + num(1.0 / *a, 2) + "× weaker); raise the restitution (" + e +
                  "), check clearance_mm (a larger real clearance hits harder), or look for rig vibration the model lacks";
  else
    p.sentence += "model and measurement agree within " + pct(kAgreeHigh - 1) + " (" + e + ", " + in.contact + ")";
  if (p.level != VerdictLevel::good && !in.fit) p.sentence += "; `fourbar fit SESSION_DIR` identifies e (and μ) from the session";
  p.sentence += ".";
  if (chaotic && a_se) p.sentence += scatter_error_clause(*a, *a_se, in.revolutions);
  if (chaotic)
    p.sentence += " The impacts are chaotic: the effect is in the scatter between turns, not in the averaged curve, so a (time)" +
                  (in.a_time ? " = " + num(*in.a_time, 3) : std::string()) + " and a (spectral)" +
                  (in.a_spectral ? " = " + num(*in.a_spectral, 3) : std::string()) + " compare chance residues of the averages.";
  else if (in.a_time && in.a_spectral && *in.a_spectral > 0 &&
           std::max(*in.a_time / *in.a_spectral, *in.a_spectral / *in.a_time) > kTimeSpectralApart)
    p.sentence += " a (time) = " + num(*in.a_time, 3) + " differs: it counts every order, also the nominal band (1 … " +
                  std::to_string(in.nominal_band_orders) + ") and mains hum, which the clearance model cannot hold.";
  bool differs = false;
  p.sentence += repeat_clause(in, chaotic, differs);
  if (differs) {
    p.level = worst(p.level, VerdictLevel::attention);
    p.words += ", turns repeat every " + std::to_string(in.repeat->period);
  }
  p.sentence += fit_sentence(in);
  return p;
}

double rms_of(const json& a) {
  if (!a.is_array() || a.empty()) return 0;
  double s = 0;
  for (const json& v : a) s += v.is_number() ? v.get<double>() * v.get<double>() : 0;
  return std::sqrt(s / static_cast<double>(a.size()));
}

const json& path(const json& j, std::initializer_list<const char*> keys) {
  static const json null;
  const json* p = &j;
  for (const char* k : keys) {
    if (!p->is_object() || !p->contains(k)) return null;
    p = &(*p)[k];
  }
  return *p;
}

std::optional<double> opt(const json& v) { return v.is_number() ? std::optional<double>(v.get<double>()) : std::nullopt; }
double num_or(const json& v, double d) { return v.is_number() ? v.get<double>() : d; }

}  // namespace

const char* to_string(VerdictLevel l) {
  switch (l) {
    case VerdictLevel::good: return "good";
    case VerdictLevel::attention: return "attention";
    case VerdictLevel::problem: return "problem";
    case VerdictLevel::not_judged: break;
  }
  return "not judged";
}

std::span<const VerdictPartInfo> verdict_parts() {
  static constexpr VerdictPartInfo kParts[] = {{"setup", "set-up", &Verdict::setup},
                                               {"measurement", "measurement", &Verdict::measurement},
                                               {"clearance_effect", "clearance effect", &Verdict::effect},
                                               {"model_family", "model family", &Verdict::family},
                                               {"model_agreement", "model agreement", &Verdict::agreement}};
  return kParts;
}

Verdict verdict_of(const VerdictInputs& in) {
  Verdict v;
  v.setup = setup_part(in);
  v.measurement = measurement_part(in);
  v.effect = effect_part(in);
  v.agreement = agreement_part(in, v.a, v.a_standard_error, v.a_from);
  v.family = family_part(in);
  judge_agreement_below_band(in, v);
  for (const VerdictPartInfo& p : verdict_parts()) v.overall = worst(v.overall, (v.*p.part).level);
  return v;
}

VerdictInputs verdict_inputs(const json& r, const json* fit, const std::string& fit_file) {
  VerdictInputs in;
  const json& sc = path(r, {"setup_check"});
  if (sc.is_object()) {
    in.setup_checked = !sc.contains("not_checked");
    if (!in.setup_checked && sc["not_checked"].is_string()) in.setup_not_checked = sc["not_checked"];
    for (const json& f : sc.value("findings", json::array()))
      in.findings.push_back({f.value("item", ""), f.value("channel", ""), f.value("key", ""), f.value("manifest", ""),
                             f.value("data", ""), f.value("confidence", 0.0)});
  }
  in.revolutions = static_cast<std::size_t>(num_or(path(r, {"operating_point", "revolutions_averaged"}), 0));
  in.clearance_mm = num_or(path(r, {"operating_point", "clearance_mm"}), 0);
  in.revolutions_clipped = static_cast<std::size_t>(num_or(path(r, {"acquisition", "revolutions_clipped"}), 0));
  const json& cc = path(r, {"acquisition", "clipping_checked"});
  in.clipping_checked = !cc.is_boolean() || cc.get<bool>();
  in.speed_mean_rpm = num_or(path(r, {"acquisition", "speed_rpm", "mean"}), num_or(path(r, {"operating_point", "speed_rpm"}), 0));
  in.speed_std_rpm = num_or(path(r, {"acquisition", "speed_rpm", "std"}), 0);
  const json& m = path(r, {"metrics", "alpha3_rad_s2"});
  const json& mg = path(m, {"magnification"});
  in.nominal_rms = num_or(path(m, {"nominal_rms"}), 0);
  in.floor_rms = num_or(path(mg, {"floor_rms"}), 0);
  in.effect_to_floor = opt(path(mg, {"effect_to_floor"}));
  in.model_effect_to_floor = opt(path(mg, {"model_effect_to_floor"}));
  in.nominal_band_orders = static_cast<int>(num_or(path(mg, {"nominal_band_orders"}), 0));
  in.a_time = opt(path(mg, {"time_domain"}));
  in.a_spectral = opt(path(mg, {"spectral"}));
  for (const json& k : path(mg, {"orders_used"}).is_array() ? path(mg, {"orders_used"}) : json::array()) in.orders_used.push_back(k.get<int>());
  in.spread_rms = rms_of(path(r, {"series", "alpha3_rad_s2", "measured_std"}));
  in.model_spread_rms = rms_of(path(r, {"series", "alpha3_rad_s2", "clearance_std"}));
  in.scatter_relative_error = opt(path(mg, {"scatter_relative_error"}));
  in.restitution = num_or(path(r, {"theory", "settings", "restitution"}), 0);
  in.model_revolutions = static_cast<std::size_t>(num_or(path(r, {"theory", "settings", "averaged_revolutions"}), 0));
  const json& contact = path(r, {"theory", "settings", "contact"});
  in.contact = contact.is_string() ? contact.get<std::string>() : "";
  in.family = verdict_family(r);
  const json& measured_repeat = path(m, {"turns_repeat", "measured"});
  const auto unconfirmed = static_cast<std::size_t>(num_or(path(measured_repeat, {"unconfirmed_period_turns"}), 0));
  const json& measured_lags = path(measured_repeat, {"by_lag"});
  if (static_cast<std::size_t>(num_or(path(measured_repeat, {"period_turns"}), 0)) < 2 && unconfirmed >= 2 &&
      measured_lags.is_array() && measured_lags.size() >= unconfirmed && measured_lags[unconfirmed - 1].is_number()) {
    VerdictInputs::Repeat rep;
    rep.period = unconfirmed;
    rep.confirmed = false;
    rep.ratio = measured_lags[unconfirmed - 1].get<double>();
    rep.neighbours = num_or(path(measured_repeat, {"neighbours"}), 1);
    rep.turns = static_cast<std::size_t>(num_or(path(measured_repeat, {"turns"}), 0));
    in.repeat = rep;
  }
  if (const auto period = static_cast<std::size_t>(num_or(path(measured_repeat, {"period_turns"}), 0)); period >= 2) {
    VerdictInputs::Repeat rep;
    rep.period = period;
    rep.ratio = num_or(path(measured_repeat, {"ratio"}), 1);
    rep.neighbours = num_or(path(measured_repeat, {"neighbours"}), 1);
    const json& model = path(m, {"turns_repeat", "model"});
    rep.model_turns = static_cast<std::size_t>(num_or(path(model, {"turns"}), 0));
    const json& lags = path(model, {"by_lag"});
    if (rep.model_turns >= 2 * period + 4 && lags.is_array() && lags.size() >= period && lags[period - 1].is_number())
      rep.model_ratio = lags[period - 1].get<double>();
    in.repeat = rep;
  }
  if (fit && fit->is_object() && path(*fit, {"parameters", "restitution", "value"}).is_number()) {
    VerdictFit f;
    f.file = fit_file;
    const json& e = path(*fit, {"parameters", "restitution"});
    f.restitution = e["value"].get<double>();
    f.restitution_low = num_or(path(e, {"low"}), f.restitution);
    f.restitution_high = num_or(path(e, {"high"}), f.restitution);
    f.restitution_identifiable = !path(e, {"identifiable"}).is_boolean() || path(e, {"identifiable"}).get<bool>();
    const json& fc = path(*fit, {"fitted", "contact"});
    f.contact = fc.is_string() ? fc.get<std::string>() : "";
    f.friction = opt(path(*fit, {"fitted", "friction_coefficient"}));
    const std::string name = r.value("name", "");
    for (const json& fr : path(*fit, {"recordings"}).is_array() ? path(*fit, {"recordings"}) : json::array())
      if (fr.value("file", "") == name) {
        f.magnification_fitted = opt(path(fr, {"magnification_fitted"}));
        f.magnification_fitted_standard_error = opt(path(fr, {"magnification_fitted_standard_error"}));
      }
    in.fit = f;
  }
  return in;
}

json verdict_json(const Verdict& v) {
  auto part = [](const VerdictPart& p) { return json{{"level", to_string(p.level)}, {"words", p.words}, {"sentence", p.sentence}}; };
  json j = {{"overall", to_string(v.overall)},
            {"a", v.a ? json(*v.a) : json(nullptr)},
            {"a_standard_error", v.a_standard_error ? json(*v.a_standard_error) : json(nullptr)},
            {"a_from", v.a_from}};
  for (const VerdictPartInfo& p : verdict_parts()) j[p.key] = part(v.*p.part);
  return j;
}

}  // namespace fourbar

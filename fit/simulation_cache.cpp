#include "fit/simulation_cache.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <cstring>
#include <ctime>
#include <mutex>
#include <stdexcept>

#include "cluster/case_queue.hpp"
#include "common/error.hpp"
#include "fit/linkage_statistics.hpp"

namespace fourbar {

namespace {

constexpr double kResolution = 1e-6;

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::int64_t quantised(double v) { return static_cast<std::int64_t>(std::llround(v / kResolution)); }

// Bytes: status (1) then either the error text or the statistics as doubles.
void put(std::string& out, double v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); }
double take(const std::string& in, std::size_t& at) {
  double v;
  std::memcpy(&v, in.data() + at, sizeof v);
  at += sizeof v;
  return v;
}

std::string encode(const CachedSimulation& c) {
  if (!c.error.empty()) return "E" + c.error;
  std::string out = "S";
  const SimulatedStatistics& s = c.statistics;
  put(out, s.impacts_per_rev), put(out, s.sum_normal_impulse_per_rev_Ns), put(out, s.turns);
  for (const auto& l : s.link) {
    put(out, l ? 1.0 : 0.0);
    if (!l) continue;
    put(out, static_cast<double>(l->turns));
    for (double v : l->value) put(out, v);
    for (double v : l->standard_error) put(out, v);
  }
  for (const auto& b : s.band) {
    put(out, b ? 1.0 : 0.0);
    if (b) put(out, b->excess), put(out, b->standard_error), put(out, b->floor);
  }
  for (const TurnRepeat& r : s.repeat) {
    put(out, static_cast<double>(r.period));
    for (double v : r.by_lag) put(out, v);
  }
  return out;
}

CachedSimulation decode(const std::string& in) {
  CachedSimulation c;
  if (in.empty() || in[0] == 'E') {
    c.error = in.empty() ? "no result" : in.substr(1);
    return c;
  }
  std::size_t at = 1;
  SimulatedStatistics& s = c.statistics;
  s.impacts_per_rev = take(in, at), s.sum_normal_impulse_per_rev_Ns = take(in, at);
  s.turns = static_cast<int>(take(in, at));
  for (auto& l : s.link) {
    if (take(in, at) == 0.0) continue;
    StatisticValues v;
    v.turns = static_cast<std::size_t>(take(in, at));
    for (double& x : v.value) x = take(in, at);
    for (double& x : v.standard_error) x = take(in, at);
    l = v;
  }
  for (auto& b : s.band) {
    if (take(in, at) == 0.0) continue;
    BandEnergy e;
    e.excess = take(in, at), e.standard_error = take(in, at), e.floor = take(in, at);
    b = e;
  }
  for (TurnRepeat& r : s.repeat) {
    r.period = static_cast<std::size_t>(take(in, at));
    for (double& v : r.by_lag) v = take(in, at);
  }
  return c;
}

/// What a rank needs to run one simulation: the recording's name, the
/// parameters as simulated and the settings, doubles in exact hexadecimal.
std::string describe(const std::string& name, const ContactParameters& p, const SimulationSettings& s) {
  char line[260];
  std::snprintf(line, sizeof line, "%a %d %a %d %d %a %d %d %a\n", p.restitution, static_cast<int>(p.contact),
                p.friction_coefficient, s.warmup_turns, s.simulated_turns, s.tolerance, static_cast<int>(s.model.kind),
                s.model.elastic_modes, s.model.contact_stiffness_N_per_m_n);
  return line + name;
}

}  // namespace

std::string SimulationCache::simulate_described(const std::vector<RecordingTarget>& targets,
                                                const std::string& description) {
  const auto eol = description.find('\n');
  ContactParameters p;
  SimulationSettings s;
  int contact = 0, kind = 0;
  if (eol == std::string::npos ||
      std::sscanf(description.c_str(), "%la %d %la %d %d %la %d %d %la", &p.restitution, &contact,
                  &p.friction_coefficient, &s.warmup_turns, &s.simulated_turns, &s.tolerance, &kind,
                  &s.model.elastic_modes, &s.model.contact_stiffness_N_per_m_n) != 9)
    throw RunError("fit: internal error: unreadable simulation case '" + description + "'");
  p.contact = static_cast<ContactLaw>(contact);
  s.model.kind = static_cast<FitModelKind>(kind);
  const std::string name = description.substr(eol + 1);
  const auto target = std::find_if(targets.begin(), targets.end(), [&](const RecordingTarget& t) { return t.name == name; });
  if (target == targets.end())
    throw RunError("fit: internal error: this rank has no recording named '" + name + "' to simulate");
  CachedSimulation c;
  try {
    c.statistics = s.model.kind == FitModelKind::elastic
                       ? simulate_linkage_statistics(*target, p, s.warmup_turns, s.simulated_turns, s.tolerance, s.model)
                       : simulate_statistics(*target, p, s.warmup_turns, s.simulated_turns, s.tolerance);
  } catch (const std::exception& e) {
    c.error = e.what();
    if (c.error.empty()) c.error = "failed";
  }
  return encode(c);
}

SimulationCache::SimulationCache(const std::vector<RecordingTarget>& targets, SimulationSettings settings)
    : targets_(targets), settings_(settings) {}

ContactParameters SimulationCache::canonical(const ContactParameters& p) {
  ContactParameters c;
  c.restitution = static_cast<double>(quantised(p.restitution)) * kResolution;
  c.friction_coefficient =
      p.contact == ContactLaw::stick_slip ? static_cast<double>(quantised(p.friction_coefficient)) * kResolution : 0.0;
  c.contact = c.friction_coefficient > 0 ? ContactLaw::stick_slip : ContactLaw::smooth;
  if (c.contact == ContactLaw::smooth) c.friction_coefficient = 0;
  return c;
}

SimulationCache::Key SimulationCache::key(std::size_t recording, const ContactParameters& p) {
  const ContactParameters c = canonical(p);
  return {recording, quantised(c.restitution), quantised(c.friction_coefficient)};
}

void SimulationCache::ensure(const std::vector<ContactParameters>& points) {
  std::vector<std::pair<std::size_t, ContactParameters>> todo;
  std::map<Key, bool> queued;
  for (const ContactParameters& p : points)
    for (std::size_t r = 0; r < targets_.size(); ++r) {
      const Key k = key(r, p);
      if (cache_.count(k) || queued.count(k)) continue;
      queued[k] = true;
      todo.emplace_back(r, canonical(p));
    }
  if (todo.empty()) return;
  std::vector<std::string> cases;
  for (const auto& [r, p] : todo) cases.push_back(describe(targets_[r].name, p, settings_));
  const auto t0 = std::chrono::steady_clock::now();
  std::mutex timing;
  std::map<std::string, double> cpu_of;  // description → its thread's CPU seconds
  const CaseQueueStats stats = run_described_cases(
      cases, settings_.threads,
      [&](const std::string& description) {
        const double c0 = thread_cpu_seconds();
        std::string bytes = simulate_described(targets_, description);
        const double used = thread_cpu_seconds() - c0;
        const std::lock_guard<std::mutex> lock(timing);
        cpu_of[description] = used;
        return bytes;
      },
      [&](std::size_t i, std::string&& bytes) {
        cache_[key(todo[i].first, todo[i].second)] = decode(bytes);
        if (settings_.on_simulation) settings_.on_simulation();
      });
  compute_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // Each case to the worker that is free first, in queue order.
  std::vector<double> free_at(std::max(1u, settings_.threads), 0.0);
  for (const std::string& c : cases) {
    const auto it = cpu_of.find(c);
    if (it == cpu_of.end()) continue;
    cpu_s_ += it->second;
    *std::min_element(free_at.begin(), free_at.end()) += it->second;
  }
  idle_wall_s_ += *std::max_element(free_at.begin(), free_at.end());
  simulations_ += static_cast<int>(todo.size());
  computed_here_ += static_cast<int>(stats.computed_here);
  turns_ += static_cast<long long>(todo.size()) * (settings_.warmup_turns + settings_.simulated_turns);
}

const CachedSimulation& SimulationCache::at(std::size_t recording, const ContactParameters& p) const {
  const auto it = cache_.find(key(recording, p));
  if (it == cache_.end()) throw RunError("fit: simulation asked for before it was run");
  return it->second;
}

}  // namespace fourbar

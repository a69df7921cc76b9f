#include "analyze/setup_finding.hpp"

#include <cmath>
#include <utility>

namespace fourbar {

std::string SetupCheck::status() const {
  if (!checked) return "not checked";
  return findings.empty() ? "ok" : "check set-up";
}

namespace {

std::string percent(double x) { return std::to_string(static_cast<int>(std::lround(100 * x))) + " %"; }

}  // namespace

std::string channel_key(const std::string& name, const std::string& key) {
  return "[[channel]] name=\"" + name + "\" " + key;
}

void add_finding(SetupCheck& out, std::string item, std::string channel, std::string key, std::string manifest,
                 std::string data, double confidence) {
  SetupFinding f{std::move(item), std::move(channel), std::move(key), std::move(manifest), std::move(data), confidence, {}};
  f.message = (f.channel.empty() ? std::string() : "channel '" + f.channel + "': ") + f.item + ": the manifest says " +
              f.manifest + ", the data say " + f.data + " (confidence " + percent(f.confidence) + "); change " + f.key;
  out.findings.push_back(std::move(f));
}

}  // namespace fourbar

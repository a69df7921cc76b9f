#pragma once
// A set-up check's finding as the technician reads it: which item, the
// manifest's value, the data's value, how sure, and the key to change.

#include <string>

#include "analyze/setup_check.hpp"

namespace fourbar {

/// `[[channel]] name="NAME" KEY`: how a finding names a channel's key.
std::string channel_key(const std::string& name, const std::string& key);

/// Appends the finding with its message ("channel 'X': item: the manifest
/// says …, the data say … (confidence N %); change KEY").
void add_finding(SetupCheck& out, std::string item, std::string channel, std::string key, std::string manifest,
                 std::string data, double confidence);

}  // namespace fourbar

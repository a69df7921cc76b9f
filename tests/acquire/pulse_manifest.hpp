#pragma once
// The smallest manifest the crank-pulse tests need: one crank_pulse channel.

#include "acquire/manifest.hpp"

namespace fourbar::testing {

/// A manifest ("synthetic.toml") whose only channel is the crank pulse at
/// `index` in the recording.
inline Manifest pulse_manifest(int index) {
  Manifest m;
  m.file = "synthetic.toml";
  ChannelSpec pulse;
  pulse.name = "crank_pulse";
  pulse.role = ChannelRole::crank_pulse;
  pulse.index = index;
  m.channels = {pulse};
  return m;
}

}  // namespace fourbar::testing

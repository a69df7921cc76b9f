#pragma once
// Test support: the error a rig and scene pair is refused with.

#include <gtest/gtest.h>

#include <string>

#include "common/error.hpp"
#include "sim/scene.hpp"
#include "support/temp_dir.hpp"

namespace fourbar::testing {

/// Writes `rig_text` as r.toml and `scene_text` as s.toml into `dir` and
/// loads the scene; the InputError's message, or a test failure and "" when
/// it is accepted.
inline std::string scene_error(TempDir& dir, const std::string& rig_text, const std::string& scene_text) {
  dir.write("r.toml", rig_text);
  try {
    load_scene(dir.write("s.toml", scene_text));
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted";
  return {};
}

/// `message` names `what`.
inline void expect_names(const std::string& message, const std::string& what) {
  EXPECT_NE(message.find(what), std::string::npos) << message;
}

}  // namespace fourbar::testing

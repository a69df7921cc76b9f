#pragma once
// The identity of the running program's build: the GNU build-id note the
// linker writes into the executable (a hash over its code and data). Two
// builds from different sources differ; the same build is the same. Caches
// key their results on it, so that a rebuilt fourbar with the same version
// number never serves results computed by the old code.

#include <string>

namespace fourbar {

/// Hex digits of the running executable's build-id; empty when it has none
/// (linked with --build-id=none), in which case callers fall back to kVersion.
const std::string& build_id();

}  // namespace fourbar

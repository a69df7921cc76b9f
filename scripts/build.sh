#!/usr/bin/env bash
# Configures and builds fourbar into build/ (Release with line-table debug
# info: -g1 gives stack traces and perf/callgrind source lines at about two
# thirds of the compile time of -g; configure build/ yourself with -g for a
# debugger that shows variables).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
  -DFOURBAR_WERROR=ON >/dev/null
cmake --build build --parallel "$(nproc)"

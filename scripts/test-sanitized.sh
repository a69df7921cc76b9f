#!/usr/bin/env bash
# Builds fourbar and its tests with AddressSanitizer + UndefinedBehaviorSanitizer
# (FOURBAR_SANITIZE=ON, g++) in build-asan/ and runs the CTest suite there,
# the fuzz regression replays included. Any sanitizer report fails the test
# it happens in. Warnings are not errors here: with -fsanitize, g++ 12
# reports false -Wmaybe-uninitialized in libstdc++'s <regex>; the normal
# build (scripts/build.sh) keeps -Werror.
#
#   ./scripts/test-sanitized.sh          the whole suite
#   ./scripts/test-sanitized.sh --ci     the subset CI runs (time budget): every
#                                        parser (fuzz corpus + regression
#                                        replays, test_acquire, test_common,
#                                        test_mechanism: the rig file) and the
#                                        clearance simulator (test_clearance)
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFOURBAR_SANITIZE=ON -DFOURBAR_WERROR=OFF \
  -DFOURBAR_BUILD_BENCH=OFF >/dev/null
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
if [ "${1:-}" = "--ci" ]; then
  targets=(replay_rig replay_scene replay_manifest replay_csv replay_audio replay_mat replay_csv_units test_common test_mechanism test_acquire test_clearance)
  cmake --build build-asan --parallel "$(nproc)" --target "${targets[@]}"
  ctest --test-dir build-asan --output-on-failure --parallel "$(nproc)" -R '^fuzz_replay_'
  for t in common/test_common mechanism/test_mechanism acquire/test_acquire sim/clearance/test_clearance; do
    "build-asan/tests/$t" --gtest_brief=1
  done
else
  cmake --build build-asan --parallel "$(nproc)"
  ctest --test-dir build-asan --output-on-failure --parallel "$(nproc)"
fi

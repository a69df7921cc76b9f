#!/usr/bin/env bash
# Builds fourbar and its tests with AddressSanitizer + UndefinedBehaviorSanitizer
# (FOURBAR_SANITIZE=ON, g++) in build-asan/ and runs the whole CTest suite
# there, the fuzz regression replays included. Any sanitizer report fails the
# test it happens in. Warnings are not errors here: with -fsanitize, g++ 12
# reports false -Wmaybe-uninitialized in libstdc++'s <regex>; the normal
# build (scripts/build.sh) keeps -Werror.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFOURBAR_SANITIZE=ON \
  -DFOURBAR_BUILD_BENCH=OFF >/dev/null
cmake --build build-asan --parallel "$(nproc)"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
ctest --test-dir build-asan --output-on-failure --parallel "$(nproc)"

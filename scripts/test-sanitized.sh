#!/usr/bin/env bash
# Builds fourbar and its tests with AddressSanitizer + UndefinedBehaviorSanitizer
# (FOURBAR_SANITIZE=ON, g++) in build-asan/ and runs the CTest suite there,
# the fuzz regression replays included. Any sanitizer report fails the test
# it happens in. Warnings are not errors here: with -fsanitize, g++ 12
# reports false -Wmaybe-uninitialized in libstdc++'s <regex>; the normal
# build (scripts/build.sh) keeps -Werror.
#
#   ./scripts/test-sanitized.sh          the whole suite
#   ./scripts/test-sanitized.sh --ci     what CI runs: every test the normal CI
#                                        runs except those labelled `slow` or
#                                        `skip_sanitized` (both still run in
#                                        the normal half). Labelled slow:
#     AnalyzePipeline.NoDriftOver10000Revolutions — 10 000 revolutions
#       streamed; the other AnalyzePipeline tests run the same code;
#     HtmlReport.DrawsEveryChartInHeadlessChromium,
#     SessionReport.PageDrawsInHeadlessChromium,
#     ReportFit.PageWithTheFitDrawsInHeadlessChromium,
#     HtmlPrint.SampleSessionDrawsAndPrintsOnA4AndLetterInHeadlessChromium,
#     HtmlPrint.OneRecordingSessionDrawsAndPrintsOnA4AndLetterInHeadlessChromium,
#     HtmlPrint.VerdictShownInHeadlessChromium — the time goes to headless
#       Chromium, which no sanitizer sees; the C++ writing the page runs in
#       the other report tests;
#     csv_in_pandas — the sample jobs read by pandas; their C++ runs in the
#       other CLI tests;
#     FitElastic.* — the elastic-link fit (about 30 s of CPU unsanitized);
#     ElasticLinkage.StiffModesApproachTheRigidLinkage — the elastic coupler
#       five times, up to E x 1e6;
#     independent_rig_report — the Python generator's session through
#       `fourbar report`.
#   Labelled skip_sanitized (not slow in the normal build, long under ASan):
#     FitCrossModel.CompliantSessionFittedWithTheImpactModelSaysTheModelFamilyDiffers
#       — 116 s under ASan; the fit and the compliant model run in the other
#       Fit* and compliant tests;
#     LinkageStress.* (3), Linkage.EnergyBalanceWithClearanceInAnyJoint — 87 s
#       together under ASan; the same linkage code runs in the other Linkage*
#       and ElasticLinkage tests;
#     layers, layers_detects_back_edges, file_sizes, doc_links,
#     independent_rig_selftest — scripts that run no compiled code.
#   (The list and the measured times: docs/robustness.md, "Sanitizers".)
set -euo pipefail
cd "$(dirname "$0")/.."
# -O1 -g1 (line tables: enough for the sanitizers' stack traces) compiles in
# about half the time of -O2 -g (report/html_report.cpp: 4.3 s against 9.3 s
# of CPU); the assertions stay off as in the normal build.
# Every target is compiled as unity batches of up to 16 files
# (CMAKE_UNITY_BUILD): under ASan + UBSan most of a unit's time goes to the
# instrumented code of the templates it instantiates (nlohmann-json,
# GoogleTest, the standard library), which a batch instantiates once
# (8 files of report/ at -O1: 83 s of user CPU one by one, 24.5 s as one
# batch; the 7 files of tests/virtual_rig at -O0: 36.7 s and 10.7 s). The
# test code is compiled at -O0 here (tests/CMakeLists.txt). A file's own
# helpers therefore have names of their own; helpers several files need
# live in one header (tests/support/, common/, ...).
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16 \
  -DFOURBAR_SANITIZE=ON -DFOURBAR_WERROR=OFF -DFOURBAR_BUILD_BENCH=OFF >/dev/null
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
cmake --build build-asan --parallel "$(nproc)"
if [ "${1:-}" = "--ci" ]; then
  ctest --test-dir build-asan --output-on-failure --parallel "$(nproc)" -LE '^(slow|skip_sanitized)$'
else
  ctest --test-dir build-asan --output-on-failure --parallel "$(nproc)"
fi

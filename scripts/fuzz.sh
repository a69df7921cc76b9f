#!/usr/bin/env bash
# Coverage-guided fuzzing of every fourbar input parser with libFuzzer,
# AddressSanitizer and UndefinedBehaviorSanitizer (clang from Debian).
#
#   ./scripts/fuzz.sh [SECONDS] [TARGET...]
#
# Builds the fuzz targets of tests/fuzz in build-fuzz/ (clang, FOURBAR_FUZZ=ON)
# and runs each target, one after the other in one process (one core), for
# SECONDS (default 60) from its seed corpus tests/fuzz/corpus/<target>/.
# New inputs go to build-fuzz/corpus/<target>/ (the seeds stay small);
# crashes of this run to build-fuzz/crashes/<target>/. A crash input belongs in
# tests/fuzz/regressions/<target>/ once fixed: CTest replays those.
# Prints one line per target: executions, corpus size, crashes. Exit 1 when
# any target crashed.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
targets=("$@")
[ "${#targets[@]}" -gt 0 ] || targets=(rig scene manifest csv audio mat csv_units)

cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER=clang++ -DFOURBAR_FUZZ=ON -DFOURBAR_BUILD_TESTS=OFF -DFOURBAR_BUILD_BENCH=OFF >/dev/null
ninja -C build-fuzz -j2 $(printf 'fuzz_%s ' "${targets[@]}") >/dev/null

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
status=0
summary=()
for t in "${targets[@]}"; do
  corpus="build-fuzz/corpus/$t" crashes="build-fuzz/crashes/$t" log="build-fuzz/fuzz_$t.log"
  rm -rf "$crashes"  # only this run's crashes are counted (fixed ones live in tests/fuzz/regressions/)
  mkdir -p "$corpus" "$crashes"
  set +e
  "build-fuzz/tests/fuzz/fuzz_$t" -max_total_time="$seconds" -max_len=8192 -rss_limit_mb=2048 \
    -timeout=10 -artifact_prefix="$crashes/" -print_final_stats=1 "$corpus" "tests/fuzz/corpus/$t" >"$log" 2>&1
  rc=$?
  set -e
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  found=$(find "$crashes" -type f | wc -l)
  units=$(find "$corpus" -type f | wc -l)
  line="$t: ${execs} execs in ${seconds} s, corpus ${units} inputs, ${found} crash files, exit ${rc}"
  summary+=("$line")
  echo "$line"
  if [ "$rc" -ne 0 ] || [ "$found" -gt 0 ]; then
    status=1
    grep -m3 -E 'ERROR|SUMMARY|runtime error|uncaught' "$log" || true
  fi
done
printf '%s\n' "${summary[@]}" > build-fuzz/summary.txt
exit "$status"

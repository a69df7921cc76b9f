#!/usr/bin/env bash
# Coverage-guided fuzzing of every fourbar input parser with libFuzzer,
# AddressSanitizer and UndefinedBehaviorSanitizer (clang from Debian).
#
#   ./scripts/fuzz.sh [SECONDS] [TARGET...]
#
# Builds the fuzz targets of tests/fuzz in build-fuzz/ (clang, FOURBAR_FUZZ=ON)
# and runs each target, one after the other in one process (one core), for
# SECONDS (default 60). A run starts from three corpora:
#   tests/fuzz/corpus/<target>/    hand-made seeds (replayed by CTest)
#   tests/fuzz/campaign/<target>/  the minimised corpus of every run so far
#                                  (committed, so each run starts where the
#                                  last stopped)
#   build-fuzz/corpus/<target>/    this machine's working corpus (new inputs)
# After the run, campaign/<target>/ is rebuilt with libFuzzer's -merge=1: the
# smallest set of inputs from campaign/ and build-fuzz/corpus/ that reaches
# every feature the seeds do not already reach. Commit it after a campaign.
# Crashes of this run go to build-fuzz/crashes/<target>/. A crash input belongs
# in tests/fuzz/regressions/<target>/ once fixed: CTest replays those.
# Prints one line per target: executions, final coverage (cov = edges,
# ft = features), corpus sizes, crashes; the lines also go to
# build-fuzz/summary.txt. Exit 1 when any target crashed.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
targets=("$@")
[ "${#targets[@]}" -gt 0 ] || targets=(rig scene manifest csv audio mat csv_units session tdms uff)

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "${launcher[@]}" \
  -DCMAKE_CXX_COMPILER=clang++ -DFOURBAR_FUZZ=ON -DFOURBAR_BUILD_TESTS=OFF -DFOURBAR_BUILD_BENCH=OFF >/dev/null
ninja -C build-fuzz -j2 $(printf 'fuzz_%s ' "${targets[@]}") >/dev/null

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
status=0
summary=()
for t in "${targets[@]}"; do
  bin="build-fuzz/tests/fuzz/fuzz_$t"
  seeds="tests/fuzz/corpus/$t" kept="tests/fuzz/campaign/$t"
  corpus="build-fuzz/corpus/$t" crashes="build-fuzz/crashes/$t" log="build-fuzz/fuzz_$t.log"
  rm -rf "$crashes"  # only this run's crashes are counted (fixed ones live in tests/fuzz/regressions/)
  mkdir -p "$corpus" "$crashes" "$kept"
  set +e
  "$bin" -max_total_time="$seconds" -max_len=8192 -rss_limit_mb=2048 \
    -timeout=10 -artifact_prefix="$crashes/" -print_final_stats=1 "$corpus" "$kept" "$seeds" >"$log" 2>&1
  rc=$?
  set -e
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  cov=$(grep -oE 'cov: [0-9]+ ft: [0-9]+' "$log" | tail -1 || true)
  found=$(find "$crashes" -type f | wc -l)

  # Minimise: start the merge from the seeds so that only inputs reaching
  # something the seeds do not are kept, then drop the seeds again.
  merged="build-fuzz/merge/$t"
  rm -rf "$merged" && mkdir -p "$merged"
  cp "$seeds"/* "$merged"/
  "$bin" -merge=1 -max_len=8192 -rss_limit_mb=2048 -timeout=10 "$merged" "$kept" "$corpus" \
    >"build-fuzz/merge_$t.log" 2>&1 || echo "$t: merge failed, see build-fuzz/merge_$t.log" >&2
  for s in "$seeds"/*; do rm -f "$merged/$(basename "$s")"; done
  if [ -n "$(ls -A "$merged")" ] || [ -z "$(ls -A "$kept")" ]; then
    rm -rf "$kept" && mv "$merged" "$kept"
  fi
  units=$(find "$corpus" -type f | wc -l)
  kept_units=$(find "$kept" -type f | wc -l)
  kept_size=$(du -sk --apparent-size "$kept" | cut -f1)
  line="$t: ${execs} execs in ${seconds} s, ${cov:-cov: ?}, corpus ${units} inputs (kept ${kept_units}, ${kept_size} KiB), ${found} crash files, exit ${rc}"
  summary+=("$line")
  echo "$line"
  if [ "$rc" -ne 0 ] || [ "$found" -gt 0 ]; then
    status=1
    grep -m3 -E 'ERROR|SUMMARY|runtime error|uncaught|timeout' "$log" || true
  fi
done
printf '%s\n' "${summary[@]}" > build-fuzz/summary.txt
exit "$status"

#!/usr/bin/env bash
# Times the main job on a session folder: `fourbar report` with an empty cache
# (everything computed, and the cache written) on every core and with
# --jobs 1 (the same options otherwise), then again with the cache (nothing
# recomputed). Prints the speed-up of every core over one job.
# Usage: bench/report_session.sh [SESSION_DIR] [RUNS]   (default data/session, 3)
# Prints each run's wall time and the best of each kind.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
session="${1:-$root/data/session}"
runs="${2:-3}"
fourbar="$root/build/cli/fourbar"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
now() { date +%s.%N; }
load() { cut -d' ' -f1-3 /proc/loadavg; }
load_before=$(load)
best_cold=1e9 best_warm=1e9 best_serial=1e9
for i in $(seq "$runs"); do
  rm -rf "$out/serial-cache"
  t0=$(now); "$fourbar" report "$session" --out "$out/serial/report.html" --cache "$out/serial-cache" --jobs 1 -q >/dev/null; t1=$(now)
  serial=$(awk "BEGIN{print $t1 - $t0}")
  best_serial=$(awk "BEGIN{print ($serial < $best_serial) ? $serial : $best_serial}")
  rm -rf "$out/cache"
  t0=$(now); "$fourbar" report "$session" --out "$out/report.html" --cache "$out/cache" -q >/dev/null; t1=$(now)
  "$fourbar" report "$session" --out "$out/report.html" --cache "$out/cache" -q >/dev/null; t2=$(now)
  cold=$(awk "BEGIN{print $t1 - $t0}"); warm=$(awk "BEGIN{print $t2 - $t1}")
  printf 'run %d: no cache %.3f s (--jobs 1: %.3f s), with cache %.3f s\n' "$i" "$cold" "$serial" "$warm"
  best_cold=$(awk "BEGIN{print ($cold < $best_cold) ? $cold : $best_cold}")
  best_warm=$(awk "BEGIN{print ($warm < $best_warm) ? $warm : $best_warm}")
done
printf 'best of %d: no cache %.3f s (target < 10 s), with cache %.3f s (target < 1 s); report %s bytes\n' \
  "$runs" "$best_cold" "$best_warm" "$(stat -c %s "$out/report.html")"
printf 'every core (%d) against --jobs 1: %.3f s / %.3f s = %.2fx faster\n' \
  "$(nproc)" "$best_cold" "$best_serial" "$(awk "BEGIN{print $best_serial / $best_cold}")"
# The line to quote (wall-clock ratio: meaningful only with the load beside it).
printf 'RATIO report cold, every core / --jobs 1: %.2fx (target >= 1.7); load average %s -> %s on %d cores\n' \
  "$(awk "BEGIN{print $best_serial / $best_cold}")" "$load_before" "$(load)" "$(nproc)"

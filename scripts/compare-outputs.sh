#!/usr/bin/env bash
# Refactoring check: runs two fourbar binaries over the same jobs on the
# repository's data (report on data/session, sim of three scenes, virtual-rig,
# analyze, acquire, rig, sweep) and compares every output file byte for byte,
# after masking what must differ (the output folder and checkout paths in the
# provenance lines). A change that only moves code must print "identical".
#
#   scripts/compare-outputs.sh OLD_FOURBAR NEW_FOURBAR [WORK_DIR]
#
# e.g. build the old revision with `git worktree add /tmp/old REV` and
# `cmake -S /tmp/old -B /tmp/old/build -G Ninja && cmake --build /tmp/old/build --target fourbar`,
# then `scripts/compare-outputs.sh /tmp/old/build/cli/fourbar build/cli/fourbar`.
# Exit status: 0 identical, 1 some output differs or a job failed, 2 usage.
set -uo pipefail
[ $# -ge 2 ] || { sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
old=$(realpath "$1") new=$(realpath "$2")
work=${3:-$(mktemp -d)}
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root" || exit 2

run_jobs() {  # FOURBAR OUT
  local f=$1 out=$2 failed=0
  rm -rf "$out" && mkdir -p "$out"
  "$f" report data/session --out "$out/report/report.html" >/dev/null 2>&1 || failed=1
  for s in thesis_nominal_350rpm thesis_clearance_350rpm_e05 wall_friction_steady_350rpm; do
    "$f" sim "data/scenes/$s.toml" --out "$out/sim_$s" >/dev/null 2>&1 || failed=1
  done
  "$f" virtual-rig data/scenes/thesis_virtual_rig_350rpm.toml --out "$out/vr.flac" >/dev/null 2>&1 || failed=1
  "$f" analyze data/session/thesis_350rpm_0254mm.flac --out "$out/analyze" >/dev/null 2>&1 || failed=1
  "$f" acquire data/session/thesis_350rpm_0254mm.flac --out "$out/acquire" >/dev/null 2>&1 || failed=1
  "$f" rig data/rigs/thesis.toml >"$out/rig.txt" 2>&1 || failed=1
  "$f" sweep data/scenes/experiment_grid_sweep.toml --out "$out/sweep.csv" >/dev/null 2>&1 || failed=1
  [ "$failed" -eq 0 ] || echo "compare-outputs: a job failed with $f (its outputs are compared anyway)"
  return "$failed"
}

# The report's cache key hashes the executable's build-id (common/build_id.hpp),
# which differs between any two builds by design: mask the key, and name each
# cache file by its content instead of by its key.
masked() { sed -E -e "s|$2|OUT|g" -e "s|$root|ROOT|g" -e 's/"cache_key": ?"[0-9a-f]{64}"/"cache_key":"KEY"/g' "$1"; }
name_cache_by_content() {  # OUT
  local f
  for f in "$1"/report/.fourbar-cache/*.json; do
    [ -f "$f" ] && mv "$f" "$1/report/.fourbar-cache/content-$(masked "$f" "$1" | sha256sum | cut -c1-16).json"
  done
}

rc=0
run_jobs "$old" "$work/old" || rc=1
run_jobs "$new" "$work/new" || rc=1
name_cache_by_content "$work/old"
name_cache_by_content "$work/new"
files=0
while IFS= read -r f; do
  files=$((files + 1))
  if [ ! -f "$work/new/$f" ]; then echo "missing in new: $f"; rc=1; continue; fi
  cmp -s <(masked "$work/old/$f" "$work/old") <(masked "$work/new/$f" "$work/new") || { echo "differs: $f"; rc=1; }
done < <(cd "$work/old" && find . -type f | sort)
extra=$(cd "$work/new" && find . -type f | sort | while read -r f; do [ -f "$work/old/$f" ] || echo "$f"; done)
[ -z "$extra" ] || { echo "only in new: $extra"; rc=1; }
if [ "$rc" -eq 0 ]; then echo "compare-outputs: identical ($files files in $work)"; else echo "compare-outputs: outputs differ (in $work)"; fi
exit "$rc"

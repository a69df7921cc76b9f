#!/usr/bin/env bash
# scripts/check-readme.py on planted faults: a README whose command no longer
# works, whose output excerpt no longer appears, with a shell block that
# carries no mark, and docs with a broken link or anchor. Each must fail,
# naming the fault; the unchanged small README must pass.
#   expect_drift_detected.sh SOURCE_DIR FOURBAR
set -uo pipefail
src=$1
fourbar=$2
check="$src/scripts/check-readme.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# A small README: the real opening block, one command and its excerpt.
head -n 6 "$src/README.md" > "$work/good.md"
cat >> "$work/good.md" <<'MD'

<!-- check: run -->
```sh
fourbar rig data/rigs/bench.toml
```
<!-- check: output -->
```text
  class:        crank-rocker
```
MD

expect() {  # expect NAME PATTERN command...: must exit 1 and print PATTERN
  local name=$1 pattern=$2; shift 2
  local out rc
  out=$("$@" 2>&1); rc=$?
  if [ "$rc" -ne 1 ] || ! grep -q -- "$pattern" <<<"$out"; then
    echo "FAIL $name: expected exit 1 and '$pattern', got exit $rc:"; echo "$out"; failures=$((failures + 1))
  else
    echo "ok   $name: $(grep -m1 -- "$pattern" <<<"$out")"
  fi
}

if out=$(python3 "$check" run "$src" "$fourbar" --readme "$work/good.md" 2>&1); then
  echo "ok   unchanged README passes"
else
  echo "FAIL the unchanged small README fails:"; echo "$out"; failures=$((failures + 1))
fi

sed 's|fourbar rig data/rigs/bench.toml|fourbar rig data/rigs/no_such_rig.toml|' "$work/good.md" > "$work/broken_command.md"
expect "broken command" "exited 2" python3 "$check" run "$src" "$fourbar" --readme "$work/broken_command.md"

sed 's|crank-rocker|double-crank|' "$work/good.md" > "$work/stale_excerpt.md"
expect "stale excerpt" "no longer shows" python3 "$check" run "$src" "$fourbar" --readme "$work/stale_excerpt.md"

sed 's|<!-- check: run -->||' "$work/good.md" > "$work/unmarked.md"
expect "unmarked block" "without a <!-- check" python3 "$check" run "$src" "$fourbar" --readme "$work/unmarked.md"

sed '5s|test.sh|tests.sh|' \
  "$work/good.md" > "$work/ci_drift.md"
expect "opening line CI does not run" ".ci/run does not run" python3 "$check" run "$src" "$fourbar" --readme "$work/ci_drift.md"

# Links: a tree with a README and docs/ holding a broken file link and anchor.
mkdir -p "$work/tree/docs"
printf '# t\n\n[ok](docs/a.md#a-heading) [gone](docs/missing.md)\n' > "$work/tree/README.md"
printf '# A heading\n\n[back](../README.md#t) [bad anchor](../README.md#nowhere) [out](../../x.md)\n' > "$work/tree/docs/a.md"
out=$(python3 "$check" links "$work/tree" 2>&1); rc=$?
for pattern in "docs/missing.md does not exist" "no heading '#nowhere'" "points outside the repository"; do
  if [ "$rc" -ne 1 ] || ! grep -q -- "$pattern" <<<"$out"; then
    echo "FAIL links: expected exit 1 and '$pattern', got exit $rc:"; echo "$out"; failures=$((failures + 1))
  else
    echo "ok   links: $(grep -m1 -- "$pattern" <<<"$out")"
  fi
done
if grep -q "a.md#a-heading\|README.md#t'" <<<"$out"; then
  echo "FAIL links: a good link was reported:"; echo "$out"; failures=$((failures + 1))
fi

exit $((failures > 0))

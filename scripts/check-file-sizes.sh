#!/usr/bin/env bash
# One concept per file: no source file of the stack's folders is over the
# line limit (docs/architecture.md). A file that grows past it holds two
# concepts; split it along its seams rather than raising the limit.
#
#   scripts/check-file-sizes.sh [ROOT]
#
# Prints each file over the limit and exits 1 if there is any, else 0.
set -uo pipefail
max_lines=500
folders=(common mechanism cluster acquire sim analyze virtual_rig compare fit report cli)
root=${1:-"$(cd "$(dirname "$0")/.." && pwd)"}
cd "$root" || exit 2
over=0
while read -r n file; do
  [ "$file" = total ] && continue
  if [ "$n" -gt "$max_lines" ]; then echo "$file: $n lines (limit $max_lines): split it along its seams"; over=$((over + 1)); fi
done < <(find "${folders[@]}" -type f \( -name '*.cpp' -o -name '*.hpp' \) -print0 2>/dev/null | xargs -0 wc -l)
[ "$over" -eq 0 ] || { echo "check-file-sizes: $over file(s) over $max_lines lines" >&2; exit 1; }
echo "check-file-sizes: every source file is at most $max_lines lines"

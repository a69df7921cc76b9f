#!/usr/bin/env bash
# Checks that the source folders form a stack with no back edges
# (docs/architecture.md): a file may include headers of its own folder and of
# folders on a LOWER layer only — never of a folder on its own layer (a
# beside-neighbour) or above. The same rule holds for the libraries each
# folder's CMakeLists.txt links. tests/ and bench/ may use every layer.
#
#   scripts/check-layers.sh [ROOT]     ROOT defaults to the repository
#
# Prints one line per violation (file:line: what, why) and exits 1 if there
# is any, 0 if the stack is clean, 2 on a usage error. CTest runs it on the
# repository (test `layers`) and on a tree with known back edges
# (test `layers_detects_back_edges`), so the checker itself is checked.
# Inside sim/ the same rule holds between its rooms (the second table).
set -uo pipefail

# The stack, bottom first: folder and layer. This table is the rule.
declare -A layer=(
  [common]=0
  [mechanism]=1 [cluster]=1
  [acquire]=2 [sim]=2
  [analyze]=3 [virtual_rig]=3
  [compare]=4
  [fit]=5
  [report]=6
  [cli]=7
)

# sim/'s rooms, bottom first (docs/architecture.md "Inside sim/"). A file
# directly in sim/ (scene.*, outputs.*) is in the room `scene`. A room may
# include its own files and those of rooms on a lower floor only.
declare -A sim_room=(
  [drive]=0 [integrate]=0 [flex]=0
  [contact]=1 [record]=1
  [three_mode]=2
  [compliant]=3 [linkage]=3
  [scene]=4
  [nominal]=5
  [run]=6
  [studies]=7
)

root=${1:-"$(cd "$(dirname "$0")/.." && pwd)"}
[ -d "$root" ] || { echo "check-layers: no folder $root" >&2; exit 2; }
cd "$root" || exit 2

violations=0
report() { echo "$1"; violations=$((violations + 1)); }

# Whether folder $1 may use folder $2.
allowed() { [ "$1" = "$2" ] || [ "${layer[$2]}" -lt "${layer[$1]}" ]; }

why() {
  if [ "${layer[$2]}" -eq "${layer[$1]}" ]; then echo "$2 stands beside $1 (layer ${layer[$1]})"
  else echo "$2 (layer ${layer[$2]}) is above $1 (layer ${layer[$1]})"; fi
}

# The room of a path inside sim/ ("sim/three_mode/model.hpp" → three_mode,
# "sim/scene.hpp" → scene).
# Sets `room` (no subshell: the checker runs this for every sim include).
room_of() {
  local rest=${1#sim/}
  if [ "${rest#*/}" = "$rest" ]; then room=scene; else room=${rest%%/*}; fi
}
room_why() {
  if [ "${sim_room[$2]}" -eq "${sim_room[$1]}" ]; then echo "sim/$2 stands beside sim/$1 (floor ${sim_room[$1]} of sim)"
  else echo "sim/$2 (floor ${sim_room[$2]} of sim) is above sim/$1 (floor ${sim_room[$1]})"; fi
}

# sim/'s rooms: every file is in a room of the table, every sim include allowed.
if [ -d sim ]; then
  while IFS= read -r file; do
    room_of "$file"
    [ -n "${sim_room[$room]+x}" ] || report "$file: sim/$room is not a room of sim's stack (add it to sim_room)"
  done < <(find sim -type f \( -name '*.hpp' -o -name '*.cpp' -o -name '*.h' \) | sort)
  while IFS=: read -r file line text; do
    inc=${text#*\"} inc=${inc%%\"*}
    [ "${inc%%/*}" = sim ] || continue
    room_of "$file"; from=$room
    room_of "$inc"; to=$room
    [ -n "${sim_room[$from]+x}" ] || continue
    if [ -z "${sim_room[$to]+x}" ]; then
      report "$file:$line: includes \"$inc\" from sim/$to, which is not a room of sim's stack"
    elif [ "$from" != "$to" ] && [ "${sim_room[$to]}" -ge "${sim_room[$from]}" ]; then
      report "$file:$line: includes \"$inc\": $(room_why "$from" "$to")"
    fi
  done < <(grep -rnE --include='*.hpp' --include='*.cpp' --include='*.h' \
             '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' sim 2>/dev/null)
fi

for folder in "${!layer[@]}"; do
  [ -d "$folder" ] || continue
  # Includes: every "x/..." include must name a known folder that is allowed.
  while IFS=: read -r file line text; do
    inc=$(sed -E 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"([^"]*)".*/\1/' <<<"$text")
    target=${inc%%/*}
    if [ "$target" = "$inc" ]; then
      report "$file:$line: includes \"$inc\" without its folder; write \"$folder/$inc\""
    elif [ -z "${layer[$target]+x}" ]; then
      report "$file:$line: includes \"$inc\" from $target/, which is not a source folder of the stack"
    elif ! allowed "$folder" "$target"; then
      report "$file:$line: includes \"$inc\": $(why "$folder" "$target")"
    fi
  done < <(grep -rnE --include='*.hpp' --include='*.cpp' --include='*.h' --include='*.in' \
             '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$folder" 2>/dev/null)
  # Libraries: fourbar_<folder> names in the folder's own CMakeLists.txt.
  cml="$folder/CMakeLists.txt"
  [ -f "$cml" ] || continue
  while IFS=: read -r line text; do
    for lib in $(grep -oE 'fourbar_[a-z_]+' <<<"$text"); do
      target=${lib#fourbar_}
      [ "$target" = warnings ] && continue
      [ -n "${layer[$target]+x}" ] || continue
      allowed "$folder" "$target" || report "$cml:$line: links $lib: $(why "$folder" "$target")"
    done
  done < <(grep -nE 'target_link_libraries|^[[:space:]]+(PUBLIC|PRIVATE|INTERFACE)?[[:space:]]*fourbar_' "$cml" |
             grep -vE '^[0-9]+:[[:space:]]*#')
done

if [ "$violations" -gt 0 ]; then
  echo "check-layers: $violations back edge(s) in $root; the stack is in docs/architecture.md" >&2
  exit 1
fi
echo "check-layers: no back edges (${#layer[@]} layers' folders and ${#sim_room[@]} rooms of sim checked in $root)"

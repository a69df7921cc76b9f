#!/usr/bin/env bash
# The layer checker on a tree with known back edges: it must exit 1 and name
# exactly the expected violations (tests/layers/expected_back_edges.txt), and
# pass the clean file in the same tree.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$("$here/../../scripts/check-layers.sh" "$here/back_edges" 2>/dev/null)
rc=$?
if [ "$rc" -ne 1 ]; then echo "expected exit 1, got $rc"; echo "$out"; exit 1; fi
if ! diff <(sort <<<"$out") <(sort "$here/expected_back_edges.txt"); then
  echo "the checker's findings differ from expected_back_edges.txt (< found, > expected)"; exit 1
fi
echo "check-layers found exactly the $(wc -l < "$here/expected_back_edges.txt") planted back edges"

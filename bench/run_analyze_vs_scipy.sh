#!/usr/bin/env bash
# The analyze chain in C++ against the same chain in numpy/scipy, on one
# synthetic 3-channel 25.6 kHz record: speed ratio and largest difference.
#   bench/run_analyze_vs_scipy.sh [SECONDS] [BUILD_DIR]
set -euo pipefail
seconds=${1:-60}
build=${2:-build}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$build/bench/bench_analyze_export" "$dir" "$seconds"
/usr/bin/python3 "$(dirname "$0")/compare_analyze_scipy.py" "$dir"

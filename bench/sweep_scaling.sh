#!/usr/bin/env bash
# Scaling of `fourbar sweep` over MPI ranks and threads, ratios in one run:
# a 24-point grid (2 clearances × 3 speeds × 4 e) of 50 counted turns each,
# with 1 and 2 MPI ranks (mpirun) and with 1 and 2 threads; every table must
# equal the 1-thread one. Then the measured cost per case and turn, and what
# a 10 000-case study of 1 000 turns each costs (docs/cluster.md).
# Usage: bench/sweep_scaling.sh [TURNS]   (default 50)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
turns="${1:-50}"
fourbar="$root/build/cli/fourbar"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cat >"$work/grid.toml" <<TOML
scene = "$root/data/scenes/experiment_clearance_base.toml"
radial_mm = [0.1016, 0.254]
crank_speed_rpm = [250, 350, 450]
restitution = [0.2, 0.4, 0.6, 0.8]
revolutions = $turns
skip_revolutions = 2
TOML
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# One machine: the ranks talk through shared memory (ob1 + vader), without
# Open MPI probing UCX and the network transports at start-up (MPI_Init
# 0.31 s -> 0.10 s per process on the 2-core development machine). Set
# OMPI_MCA_pml / OMPI_MCA_btl yourself to measure something else; on a
# cluster with InfiniBand leave them unset (UCX), see docs/cluster.md.
export OMPI_MCA_pml="${OMPI_MCA_pml:-ob1}" OMPI_MCA_btl="${OMPI_MCA_btl:-self,vader}"
now() { date +%s.%N; }
load() { cut -d' ' -f1-3 /proc/loadavg; }
load_before=$(load)
run() {  # label, command...; prints and records the wall time
  local label=$1; shift
  local t0 t1; t0=$(now); "$@" >/dev/null; t1=$(now)
  times[$label]=$(awk "BEGIN{print $t1 - $t0}")
  printf '%-10s %7.3f s\n' "$label" "${times[$label]}"
}
declare -A times
run threads1 "$fourbar" sweep "$work/grid.toml" --jobs 1 -q --out "$work/t1.csv"
run threads2 "$fourbar" sweep "$work/grid.toml" --jobs 2 -q --out "$work/t2.csv"
if command -v mpirun >/dev/null; then
  run ranks1 mpirun -np 1 "$fourbar" sweep "$work/grid.toml" -q --out "$work/r1.csv"
  run ranks2 mpirun --oversubscribe -np 2 "$fourbar" sweep "$work/grid.toml" -q --out "$work/r2.csv"
  # What mpirun itself costs (start the ranks, wait for them), paid once per
  # job whatever it computes: 2 ranks of a program without MPI.
  run launch mpirun --oversubscribe -np 2 true
fi
body() { grep -v '^#' "$1"; }
for f in "$work"/t2.csv "$work"/r1.csv "$work"/r2.csv; do
  [ -f "$f" ] || continue
  cmp -s <(body "$work/t1.csv") <(body "$f") || { echo "sweep_scaling: $(basename "$f") differs from the 1-thread table" >&2; exit 1; }
done
echo "tables identical: yes"
awk -v a="${times[threads1]}" -v b="${times[threads2]}" 'BEGIN{printf "2 threads vs 1: %.2fx\n", a / b}'
[ -n "${times[ranks2]:-}" ] && awk -v a="${times[ranks1]}" -v b="${times[ranks2]}" -v l="${times[launch]}" 'BEGIN{
  printf "2 ranks vs 1:   %.2fx\n", a / b
  printf "2 ranks vs 1 without mpirun'"'"'s own start (%.3f s, in both): %.2fx\n", l, (a - l) / (b - l) }'
# The line to quote (wall-clock ratio: meaningful only with the load beside it).
[ -n "${times[ranks2]:-}" ] && awk -v a="${times[ranks1]}" -v b="${times[ranks2]}" -v t="$turns" -v l0="$load_before" -v l1="$(load)" -v c="$(nproc)" \
  'BEGIN{ printf "RATIO sweep 24 x %d turns, 2 MPI ranks / 1: %.2fx (target >= 1.8); load average %s -> %s on %d cores\n", t, a / b, l0, l1, c }'
awk -v t="${times[threads1]}" -v turns="$turns" 'BEGIN{
  per_turn = t / (24 * (turns + 2));
  case_s = per_turn * 1002;
  printf "cost: %.2f ms per case-turn (one core); a 1000-turn case %.2f s\n", per_turn * 1e3, case_s;
  printf "10 000 cases x 1000 turns: %.1f core-hours; %.1f h on 2 cores, %.2f h on 1 node of 64 cores, %.2f h on 8 such nodes\n",
    1e4 * case_s / 3600, 1e4 * case_s / 3600 / 2, 1e4 * case_s / 3600 / 64, 1e4 * case_s / 3600 / 512 }'

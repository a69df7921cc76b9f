#!/usr/bin/env bash
# Cost of one `fourbar fit` of a session (issue 28: a 4-recording fit with
# the three-mode model in <= 60 s on 2 idle cores). Runs the fit with JOBS
# threads under /usr/bin/time and prints wall seconds, CPU seconds (user +
# sys: on a loaded machine only this compares), simulations, CPU per
# simulation, the idle-machine bound CPU / JOBS, the simulations' own CPU and
# an idle-machine wall estimate: the simulations list-scheduled on JOBS cores
# with their measured CPU times, plus the rest of the CPU as if serial
# (fit.json simulation_cpu_seconds, simulation_idle_wall_seconds).
#   bench/fit_speed.sh SESSION_DIR [FOURBAR] [JOBS] [EXTRA FIT OPTIONS...]
# SESSION_DIR: e.g. from bench/make_fit_session.sh (4 recordings, 12.8 kHz)
# or tests/independent_rig/make_session.py (25.6 kHz).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
session="$1"
fourbar="$(realpath "${2:-$root/build/cli/fourbar}")"
jobs="${3:-2}"
shift $(( $# < 3 ? $# : 3 ))
out="$(mktemp -d)"
/usr/bin/time -f "%e %U %S" -o "$out/time" "$fourbar" fit "$session" --out "$out/fit" --jobs "$jobs" -q "$@" \
  >"$out/log" 2>&1 || true
python3 - "$out/fit/fit.json" "$out/time" "$jobs" "$session" <<'PY'
import json, sys
path, timef, jobs, session = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
wall, user, sys_ = (float(x) for x in open(timef).read().split()[-3:])
cpu = user + sys_
try:
    j = json.load(open(path))
except Exception as ex:
    print(f"{session}: no fit.json ({ex})"); sys.exit(1)
n = len(j["recordings"])
sims = j["simulations"]
# The simulations' CPU (timed per simulation on its thread) and the wall
# time they would take on JOBS idle cores (each batch list-scheduled in queue
# order with those times); the rest of the CPU (analysis, the family check)
# counted as serial: an idle-machine estimate that the load cannot inflate.
sim_cpu = j.get("simulation_cpu_seconds", 0.0)
idle = j.get("simulation_idle_wall_seconds", 0.0) + max(cpu - sim_cpu, 0.0)
print(f"| {session} | {n} | {j['turns_per_simulation']} | {sims} | {wall:.0f} | {cpu:.0f} | {cpu / max(sims, 1):.2f} | {cpu / jobs:.0f} | {sim_cpu:.0f} | {idle:.0f} |")
PY
rm -rf "$out"

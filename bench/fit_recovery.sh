#!/usr/bin/env bash
# Recovery bench of `fourbar fit` (docs/fit.md):
# SYNTHETIC sessions made with known parameters (bench/make_fit_session.sh:
# 4 recordings, 250/350 rpm x 0.0254/0.254 mm, TURNS turns, 30 dB, a wrong
# prior e = 0.95 smooth in session.toml), e in {0.2, 0.5, 0.8} x contact
# {smooth, stick-slip mu 0.1, 0.3}; each fitted (PARALLEL fits at a time,
# JOBS threads each), then one table row per session: truth, fitted value
# [interval], truth inside?, chi2/term at the fit and at the prior, the
# magnification factor a ± its standard error per recording at the fit and
# at the prior, evaluations, simulations, wall time.
# The last lines count the intervals that hold the truth and the widest
# identifiable interval. FIT_OPTIONS="..." are passed to every fit.
# CASES="e0.2_0.3 e0.5_smooth ..." in the environment
# makes and fits only those sessions. With REFIT=0 sessions that already
# hold fit/fit.json are not fitted again (the table is made from their files).
#   bench/fit_recovery.sh [WORK_DIR] [FOURBAR] [TURNS] [JOBS] [PARALLEL]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
work="${1:-/tmp/fourbar-fit-recovery}"
fourbar="$(realpath "${2:-$root/build/cli/fourbar}")"
turns="${3:-25}" jobs="${4:-2}" parallel="${5:-1}"
mkdir -p "$work"
cases=()
seed=100
for e in 0.2 0.5 0.8; do
  for c in smooth 0.1 0.3; do
    seed=$((seed + 10))
    if [ "$c" = smooth ]; then contact=smooth mu=0; else contact=stick-slip mu=$c; fi
    name="e${e}_${c}"
    if [ -n "${CASES:-}" ] && [[ " $CASES " != *" $name "* ]]; then continue; fi
    [ -f "$work/$name/session.toml" ] || "$root/bench/make_fit_session.sh" "$work/$name" "$e" "$contact" "$mu" "$turns" 30 "$seed" "$fourbar"
    cases+=("$name $e $mu $contact")
  done
done
FIT_OPTIONS="${FIT_OPTIONS:-}"
export fourbar work jobs FIT_OPTIONS
refit="${REFIT:-1}"
export refit
printf '%s\n' "${cases[@]}" | xargs -P "$parallel" -L 1 bash -c \
  '[ "$refit" = 0 ] && [ -f "$work/$0/fit/fit.json" ] && exit 0
   rm -f "$work/$0/fit/fit.json"
   "$fourbar" fit "$work/$0" --out "$work/$0/fit" --jobs "$jobs" -q $FIT_OPTIONS >"$work/$0/fit.log" 2>&1 || true'
tally="$work/coverage.tally"
: >"$tally"
printf '| e | contact | fitted e [interval] | μ | fitted μ [interval] | e inside | μ inside | χ²/term fit (prior) | a fit (prior) | evaluations | simulations | s wall (CPU) |\n'
printf '|---|---|---|---|---|---|---|---|---|---|---|---|\n'
for c in "${cases[@]}"; do
  set -- $c
  python3 - "$work/$1/fit/fit.json" "$2" "$3" "$4" "$tally" <<'PY'
import json, sys
path, e, mu, contact, tally = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4], sys.argv[5]
try:
    j = json.load(open(path))
except Exception as ex:
    print(f"| {e} | {contact} | failed: {ex} |"); sys.exit()
p = j["parameters"]
def cell(name, truth):
    if name not in p: return "–", "–"
    q = p[name]
    ident = "" if q["identifiable"] else " not identifiable"
    if q.get("only_lower_bound"): ident = f" not identifiable: only ≥ {q['low']:.2f}"
    inside = q["low"] - 1e-9 <= truth <= q["high"] + 1e-9
    with open(tally, "a") as t:
        t.write(f"{name} {int(inside)} {int(q['identifiable'])} {q['high'] - q['low']:.4f} {abs(q['value'] - truth):.4f}\n")
    return f"{q['value']:.2f} [{q['low']:.2f}, {q['high']:.2f}]{ident}", "yes" if inside else "NO"
ce, ie = cell("restitution", e)
cm, im = cell("friction_coefficient", mu)
t = max(1, j["terms"])
def a_cell(r, key):
    if r.get(key) is None: return "–"
    se = r.get(key + "_standard_error")
    return f"{r[key]:.2f}" + (f"±{se:.2f}" if se is not None else "")
af = [a_cell(r, "magnification_fitted") for r in j["recordings"]]
ap = [a_cell(r, "magnification_prior") for r in j["recordings"]]
fmt = lambda v: "/".join(v)
print(f"| {e} | {contact} | {ce} | {mu} | {cm} | {ie} | {im} | {j['chi2']/t:.2f} ({j['chi2_prior']/t:.1f}) | {fmt(af)} ({fmt(ap)}) | {j['evaluations']} | {j['simulations']} | {j['seconds']:.0f} ({j.get('cpu_seconds', 0):.0f}) |")
PY
done
python3 - "$tally" <<'PY'
import sys
rows = [l.split() for l in open(sys.argv[1]) if l.strip()]
inside = sum(int(r[1]) for r in rows)
ident = [r for r in rows if r[2] == "1"]
print(f"\ntruth inside {inside} of {len(rows)} intervals ({100 * inside / max(1, len(rows)):.0f} %); "
      f"identifiable intervals at most {max((float(r[3]) for r in ident), default=0):.2f} wide; "
      f"identifiable values within 0.1 of the truth: {sum(float(r[4]) <= 0.1 + 1e-9 for r in ident)} of {len(ident)}")
PY

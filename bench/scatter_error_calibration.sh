#!/usr/bin/env bash
# Is the standard error of a (scatter) right? The report's a (scatter) =
# model / measured turn-to-turn scatter of α3 comes with a standard error
# (jackknife over turns, report/recording_job.cpp). Here the theory is the
# truth: the 9 SYNTHETIC sessions of the fit's recovery bench
# (bench/make_fit_session.sh: e in {0.2, 0.5, 0.8} x contact {smooth,
# stick-slip mu 0.1, 0.3}, 4 recordings each, TURNS turns, 30 dB) are
# reported with session.toml's theory set to the parameters that made them,
# so E[a] = 1 and z = (a - 1) / SE should have a spread of 1 and |z| < 2 in
# ~95 % of the recordings. Prints one row per recording and the summary.
# Sessions already in WORK_DIR (e.g. made by bench/fit_recovery.sh) are reused.
#   bench/scatter_error_calibration.sh [WORK_DIR] [FOURBAR] [TURNS]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
work="${1:-/tmp/fourbar-fit-recovery}"
fourbar="$(realpath "${2:-$root/build/cli/fourbar}")"
turns="${3:-25}"
mkdir -p "$work"
rows="$(mktemp)"
trap 'rm -f "$rows"' EXIT
seed=100
for e in 0.2 0.5 0.8; do
  for c in smooth 0.1 0.3; do
    seed=$((seed + 10))  # the seeds of bench/fit_recovery.sh
    if [ "$c" = smooth ]; then contact=smooth mu=0; else contact=stick-slip mu=$c; fi
    name="e${e}_${c}"
    [ -f "$work/$name/session.toml" ] || "$root/bench/make_fit_session.sh" "$work/$name" "$e" "$contact" "$mu" "$turns" 30 "$seed" "$fourbar"
    # A copy whose theory is the truth (the session's own session.toml holds a wrong prior).
    truth="$work/$name-truth"
    rm -rf "$truth"
    mkdir -p "$truth"
    cp "$work/$name"/*.flac "$work/$name"/*.toml "$truth/"
    [ -d "$work/$name/scenes" ] && cp -r "$work/$name/scenes" "$truth/"
    sed -i "s#$work/$name/#$truth/#g" "$truth"/*.toml
    {
      echo "title = \"SYNTHETIC: $name, theory at the truth\""
      echo "[theory]"
      echo "restitution = $e"
      echo "contact = \"$contact\""
      [ "$contact" = stick-slip ] && echo "friction_coefficient = $mu"
    } >"$truth/session.toml"
    "$fourbar" report "$truth" --out "$truth/out/report.html" --no-cache --no-fit -q >/dev/null 2>&1 || true
    python3 - "$truth/out/summary.json" "$name" >>"$rows" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
for r in s["recordings"]:
    v = r.get("verdict", {})
    if v.get("a_from") == "scatter" and v.get("a_standard_error"):
        print(sys.argv[2], r["name"], v["a"], v["a_standard_error"])
    else:
        print(sys.argv[2], r["name"], "not-scatter", v.get("a_from"))
PY
  done
done
python3 - "$rows" <<'PY'
import statistics as st, sys
z = []
print("%-12s %-26s %7s %7s %7s" % ("session", "recording", "a", "SE", "z"))
for line in open(sys.argv[1]):
    f = line.split()
    if f[2] == "not-scatter":
        print("%-12s %-26s judged by a (%s): left out" % (f[0], f[1], f[3]))
        continue
    a, se = float(f[2]), float(f[3])
    z.append((a - 1) / se)
    print("%-12s %-26s %7.3f %7.3f %7.2f" % (f[0], f[1], a, se, z[-1]))
n = len(z)
print("RATIO a (scatter) at the truth: %d recordings, z = (a - 1)/SE: spread %.2f (1 if the SE is right), median %.2f, "
      "|z| < 1 in %d (%.0f %%; 68 %% expected), |z| < 2 in %d (%.0f %%; 95 %% expected)"
      % (n, st.pstdev(z), st.median(z), sum(abs(x) < 1 for x in z), 100 * sum(abs(x) < 1 for x in z) / n,
         sum(abs(x) < 2 for x in z), 100 * sum(abs(x) < 2 for x in z) / n))
PY

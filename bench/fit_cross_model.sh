#!/usr/bin/env bash
# Cross-model check of `fourbar fit` (docs/fit.md "Cross-model"): SYNTHETIC
# sessions made by the COMPLIANT contact model (bench/make_fit_session.sh with
# MODEL=compliant: continuous force, damping calibrated to the restitution e,
# K = STIFFNESS N/m^1.5; 4 recordings 250/350 rpm x 0.0254/0.254 mm, TURNS
# turns, 30 dB), fitted with the three-mode impact model. Prints per session
# the compliant model's e, the effective e and mu the impact model finds,
# chi2 per statistic at the fit and at the prior, and the fit's notes (the
# model-family sentence when chi2/term > 4).
#   bench/fit_cross_model.sh [WORK_DIR] [FOURBAR] [TURNS] [JOBS] [E ...]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
work="${1:-/tmp/fourbar-fit-cross-model}"
fourbar="$(realpath "${2:-$root/build/cli/fourbar}")"
turns="${3:-25}" jobs="${4:-2}"
shift $(($# < 4 ? $# : 4))
es=("$@")
[ ${#es[@]} -gt 0 ] || es=(0.5)
mkdir -p "$work"
printf '| compliant e | K (N/m^1.5) | fitted e [interval] | fitted mu [interval] | chi2/term fit (prior) | a fit per recording | s wall (CPU) | notes |\n|---|---|---|---|---|---|---|---|\n'
seed=700
for e in "${es[@]}"; do
  seed=$((seed + 10))
  s="$work/compliant_e$e"
  [ -f "$s/session.toml" ] || MODEL=compliant "$root/bench/make_fit_session.sh" "$s" "$e" smooth 0 "$turns" 30 "$seed" "$fourbar"
  [ -f "$s/fit/fit.json" ] || "$fourbar" fit "$s" --out "$s/fit" --jobs "$jobs" -q >"$s/fit.log" 2>&1 || true
  python3 - "$s/fit/fit.json" "$e" "${STIFFNESS:-1e10}" <<'PY'
import json, sys
path, e, k = sys.argv[1], sys.argv[2], sys.argv[3]
try:
    j = json.load(open(path))
except Exception as ex:
    print(f"| {e} | {k} | failed: {ex} |"); sys.exit()
p = j["parameters"]
def cell(n):
    if n not in p: return "–"
    q = p[n]
    return f"{q['value']:.2f} [{q['low']:.2f}, {q['high']:.2f}]" + ("" if q["identifiable"] else " not identifiable")
t = max(1, j["terms"])
a = "/".join(f"{r['magnification_fitted']:.2f}" if "magnification_fitted" in r else "–" for r in j["recordings"])
print(f"| {e} | {k} | {cell('restitution')} | {cell('friction_coefficient')} | {j['chi2']/t:.2f} ({j['chi2_prior']/t:.1f}) | {a} | {j['seconds']:.0f} ({j.get('cpu_seconds', 0):.0f}) | {'; '.join(j['notes']) or '–'} |")
PY
done

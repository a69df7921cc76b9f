#!/usr/bin/env bash
# What a lubricant film does to the clearance response (docs/compliant.md
# "Lubricated bearing"): the thesis rig with a pin of R = 10 mm and a bearing
# length of 10 mm, 350 rpm, xi = 0.254 mm, e = 0.5, no friction,
# K = 1e10 N/m^1.5 (calibrated damping), TURNS turns after 2 from 0 deg, at
# tolerance TOL; dry and at each viscosity in VISCOSITIES (Pa s) with the
# film extent FILM. Per turn (mean over the turns): impacts (counted), sum of
# their impulses, contact losses, share of the time on the wall; over the
# run: the largest contact peak force, the largest |alpha3| and |alpha3 -
# nominal| at 1 deg samples, the film's dissipation per turn, integrator
# steps per turn, CPU seconds.
#   bench/lubricated_effect.sh [WORK_DIR] [FOURBAR] [TURNS] [TOL] [VISCOSITIES] [FILM]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
work="${1:-/tmp/fourbar-lubricated-effect}"
fourbar="$(realpath "${2:-$root/build/cli/fourbar}")"
turns="${3:-40}" tol="${4:-1e-9}" viscosities="${5:-0.01 0.1}" film="${6:-cavitated}"
mkdir -p "$work"
cases="dry $viscosities"
for v in $cases; do
  sed '/^radial_mm/a pin_radius_mm = 10\nbearing_length_mm = 10' "$root/data/rigs/thesis.toml" >"$work/rig_$v.toml"
  film_keys=""
  if [ "$v" != dry ]; then
    echo "lubricant_viscosity_Pa_s = $v" >>"$work/rig_$v.toml"
    film_keys="film = \"$film\""
  fi
  cat >"$work/$v.toml" <<SCENE
rig = "rig_$v.toml"
model = "clearance"
crank_speed_rpm = 350.0
revolutions = $((turns + 2))
samples_per_revolution = 360
outputs = ["time_s", "alpha3_rad_s2", "mode"]
[clearance]
model = "compliant"
contact_stiffness_N_per_m_n = 1e10
restitution = 0.5
tolerance = $tol
tables = ["impacts", "revolutions"]
$film_keys
SCENE
  /usr/bin/time -f "%U %S" -o "$work/$v.time" "$fourbar" sim "$work/$v.toml" --out "$work/out_$v" >"$work/$v.log"
done
python3 - "$work" "$turns" $cases <<'PY'
import csv, json, math, sys
work, turns, cases = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
def rows(path):
    with open(path) as f:
        return list(csv.DictReader(l for l in f if not l.startswith('#')))
def first_csv(d, want):
    import glob
    for p in sorted(glob.glob(f"{d}/*.csv")):
        with open(p) as f:
            head = next(l for l in f if not l.startswith('#'))
        if want in head.split(','): return p
    raise SystemExit(f"no csv with {want} in {d}")
out = {}
for c in cases:
    d = f"{work}/out_{c}"
    revs = [r for r in rows(f"{d}/revolutions.csv") if 2 <= int(r['revolution']) < turns + 2]
    assert len(revs) == turns, (c, len(revs))
    imp = [r for r in rows(f"{d}/impacts.csv") if 2 <= int(r['revolution']) < turns + 2]
    series = rows(first_csv(d, 'alpha3_rad_s2'))
    t0 = float(series[0]['time_s']); T = 60 / 350.0
    a3 = [abs(float(r['alpha3_rad_s2'])) for r in series if float(r['time_s']) - t0 >= 2 * T]
    s = json.load(open(f"{d}/summary.json"))['clearance']
    e = s.get('energy', {})
    u, sy = map(float, open(f"{work}/{c}.time").read().split())
    mean = lambda k: sum(float(r[k]) for r in revs) / turns
    out[c] = [mean('impacts'), mean('sum_normal_impulse_Ns'), mean('contact_losses'), mean('following_share'),
              max((float(r['peak_force_N']) for r in imp), default=0.0), max(a3),
              e.get('film_loss_J', 0.0) / (turns + 2), s.get('events', {}).get('integrator_steps', float('nan')) / (turns + 2), u + sy,
              e.get('residual_rel', float('nan'))]
names = ['dry' if c == 'dry' else f'μ = {c} Pa·s' for c in cases]
print('| over turns 3…%d | ' % (turns + 2) + ' | '.join(names) + ' |')
print('|---' * (len(cases) + 1) + '|')
labels = [('impacts per turn', '%.2f'), ('ΣF per turn (N·s)', '%.4f'), ('contact losses per turn', '%.2f'),
          ('share on the wall', '%.3f'), ('largest contact peak force (N)', '%.1f'), ('largest |α3| (rad/s²)', '%.0f'),
          ('film dissipation per turn (J)', '%.2e'), ('integrator steps per turn', '%.0f'), ('CPU (s)', '%.1f'),
          ('energy residual (rel.)', '%.1e')]
for i, (label, f) in enumerate(labels):
    print(f'| {label} | ' + ' | '.join(f % out[c][i] for c in cases) + ' |')
PY

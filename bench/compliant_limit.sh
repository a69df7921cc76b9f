#!/usr/bin/env bash
# Many-turn limit of the compliant contact model (docs/compliant.md): the
# thesis rig at 350 rpm, xi = 0.254 mm, e = 0.5, no friction, TURNS turns
# after 2 from 0 deg, for the three-mode model and the compliant model at
# K = 1e8 ... 1e13 N/m^1.5 (calibrated damping), each at tolerance TOL; then
# per-turn statistics: impacts with an impulse above 1e-3 N s, sum of impulses
# of the counted impacts, contact losses, time share in contact (following),
# as mean +- 95 % interval from batch means (5-turn batches, t quantile for
# the batch count: successive turns are correlated). One table per start
# crank angle in ANGLES (default "0"): the runs from different starts show
# how far a statistic over TURNS turns depends on where the run began.
#   bench/compliant_limit.sh [WORK_DIR] [FOURBAR] [TURNS] [TOL] [ANGLES] [MODELS]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
work="${1:-/tmp/fourbar-compliant-limit}"
fourbar="$(realpath "${2:-$root/build/cli/fourbar}")"
turns="${3:-160}" tol="${4:-1e-9}" angles="${5:-0}" models="${6:-three 1e8 1e9 1e10 1e11 1e12 1e13}"
mkdir -p "$work"
cp "$root/data/rigs/thesis.toml" "$work/rig.toml"
for angle in $angles; do
for m in $models; do
  if [ "$m" = three ]; then law='contact = "smooth"'; else law="model = \"compliant\"
contact_stiffness_N_per_m_n = $m"; fi
  cat >"$work/$m.toml" <<SCENE
rig = "rig.toml"
model = "clearance"
crank_speed_rpm = 350.0
start_angle_deg = $angle
revolutions = $((turns + 2))
samples_per_revolution = 36
outputs = ["time_s", "mode"]
[clearance]
$law
radial_mm = 0.254
restitution = 0.5
tolerance = $tol
tables = ["impacts", "revolutions"]
SCENE
  start=$(date +%s.%N)
  "$fourbar" sim "$work/$m.toml" --out "$work/out_$m" >"$work/$m.log"
  echo "$m from $angle deg: $(echo "$(date +%s.%N) - $start" | bc) s wall" >&2
done
echo "start angle $angle deg:"
python3 - "$work" "$turns" $models <<'PY'
import csv, math, statistics, sys
def t975(df):  # Student t quantile 0.975 (Cornish-Fisher expansion about z; 2.040 at df = 31)
    z = 1.959964
    return z + (z**3 + z) / (4 * df) + (5 * z**5 + 16 * z**3 + 3 * z) / (96 * df**2)
work, turns, models = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
def rows(path):
    with open(path) as f:
        return list(csv.DictReader(l for l in f if not l.startswith('#')))
def interval(v, b=5):
    means = [sum(v[i:i + b]) / b for i in range(0, len(v) - b + 1, b)]
    return sum(v) / len(v), t975(len(means) - 1) * statistics.stdev(means) / math.sqrt(len(means))
table = {}
for m in models:
    revs = [r for r in rows(f"{work}/out_{m}/revolutions.csv") if 2 <= int(r['revolution']) < turns + 2]
    assert len(revs) == turns, (m, len(revs))
    big = [0] * (turns + 2)
    for r in rows(f"{work}/out_{m}/impacts.csv"):
        k = int(r['revolution'])
        if 2 <= k < turns + 2 and float(r['normal_impulse_Ns']) > 1e-3: big[k] += 1
    table[m] = [interval(big[2:]), interval([float(r['sum_normal_impulse_Ns']) for r in revs]),
                interval([float(r['contact_losses']) for r in revs]),
                interval([float(r['following_share']) for r in revs])]
names = ['three-mode' if m == 'three' else 'K = ' + m for m in models]
print('| per turn | ' + ' | '.join(names) + ' |')
print('|---' * (len(models) + 1) + '|')
for i, (label, f) in enumerate([('impacts above 1e-3 N·s', '%.2f'), ('ΣF (N·s)', '%.3f'),
                                ('contact losses', '%.2f'), ('share in contact', '%.3f')]):
    print(f'| {label} | ' + ' | '.join((f + ' ± ' + f) % table[m][i] for m in models) + ' |')
PY
done

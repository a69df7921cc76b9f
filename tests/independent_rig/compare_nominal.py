#!/usr/bin/python3
"""Sanity check of geometry and sign conventions: this generator's rigid
kinematics (rig.py: circle intersection, 2×2 velocity/acceleration loops)
against fourbar's nominal output (`fourbar sim` of a nominal scene's
series.csv) at a few crank angles.

usage: compare_nominal.py SERIES.csv RIG.toml RPM [TOLERANCE]
Prints a table; exit 1 when a value differs by more than TOLERANCE
(relative to the quantity's RMS over the turn; default 1e-6).
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rig import load_rig, nominal_rates  # noqa: E402

COLUMNS = ["theta3_rad", "theta4_rad", "omega3_rad_s", "omega4_rad_s", "alpha3_rad_s2", "alpha4_rad_s2"]


def main(argv):
    series, rig_path, rpm = argv[0], argv[1], float(argv[2])
    tol = float(argv[3]) if len(argv) > 3 else 1e-6
    rig = load_rig(rig_path)
    w2 = rpm * 2 * math.pi / 60
    with open(series) as f:
        rows = [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]
    angle_key = "crank_deg" if "crank_deg" in rows[0] else "theta2_rad"
    rms = {c: math.sqrt(sum(float(r[c]) ** 2 for r in rows) / len(rows)) for c in COLUMNS}
    worst = 0.0
    print("crank_deg " + " ".join(f"{c:>28}" for c in COLUMNS))
    picks = [rows[i] for i in range(0, len(rows), max(1, len(rows) // 8))]
    for r in picks:
        th2 = math.radians(float(r[angle_key])) if angle_key == "crank_deg" else float(r[angle_key])
        mine = nominal_rates(rig, th2, w2, 0.0)
        cells = []
        for c, m in zip(COLUMNS, mine):
            theirs = float(r[c])
            if c.startswith("theta"):  # compare angles modulo 2π
                d = math.remainder(m - theirs, 2 * math.pi)
            else:
                d = m - theirs
            worst = max(worst, abs(d) / rms[c])
            cells.append(f"{m:12.6f} vs {theirs:12.6f}")
        print(f"{math.degrees(th2) % 360:9.2f} " + " ".join(f"{x:>28}" for x in cells))
    print(f"largest difference over the quantity's RMS: {worst:.2e} (tolerance {tol:.0e})")
    return 0 if worst <= tol else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

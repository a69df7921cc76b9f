#!/usr/bin/python3
"""Per-joint statistics of the three-clearance four-bar: Siconos's tutorial
run (FourBarLinkageWith3clearance, siconos-tutorials 4.4.0, its output file
simu_*.dat) beside fourbar's run of data/scenes/siconos_three_clearance.toml
(impacts.csv and summary.json of `fourbar sim`). Prints a Markdown table.

  bench/siconos_three_clearance_compare.py SIMU.dat FOURBAR_OUT_DIR

Siconos columns used (FourBarClearance.cpp): 0 time, 29/30/31 |e| of the
crank-coupler, coupler-rocker and rocker-ground joints. A joint is in contact
where |e| >= xi - tol (tol = 1e-6 m; rigid contact keeps |e| at xi); an
impact is a free-flight-to-contact transition whose approach speed (d|e|/dt
over the last whole free step, h = 0.1 ms) is above 1 mm/s, as the benchmark
counts them; contact is lost where contact turns to free flight (with e = 0
every contact is a sustained one). fourbar's "contact lost" are its contacts
that outlived their first compression-restitution cycle.

The tutorial writes every 500th step; for these statistics run it with every
step written (in FourBarClearance.cpp: (N/500) -> (N/1), (k%500) -> (k%1))."""
import csv
import json
import sys

import numpy as np

XI, TOL, SETTLE = 0.005, 1e-6, 1e-3
JOINTS = ["crank_coupler", "coupler_rocker", "rocker_ground"]


def siconos_stats(path):
    d = np.loadtxt(path)
    t = d[:, 0]
    out = {}
    for k, name in enumerate(JOINTS):
        e = d[:, 29 + k]
        contact = e >= XI - TOL
        dt = np.diff(t)
        free_time = float(np.sum(dt[~contact[:-1]]))
        impacts, lost = [], []
        for i in range(1, len(t)):
            if contact[i] and not contact[i - 1] and i >= 2:
                v = (e[i - 1] - e[i - 2]) / (t[i - 1] - t[i - 2])
                if v > SETTLE:
                    impacts.append((t[i], v))
            if contact[i - 1] and not contact[i]:
                lost.append(t[i])
        out[name] = dict(impacts=impacts, free=free_time / (t[-1] - t[0]), lost=lost,
                         pen=float(np.max(e - XI)) * 1e3)
    return out


def fourbar_stats(folder):
    with open(f"{folder}/summary.json") as f:
        lk = json.load(f)["linkage"]
    s = lk["joints"]
    st = lk["settings"]
    label = f"fourbar (K = {st['contact_stiffness_N_per_m_n']:.0e}, e = {st['restitution']})"
    rows = list(csv.DictReader(open(f"{folder}/impacts.csv")))
    out = {}
    for name in JOINTS:
        j = s[name]
        imp = [(float(r["time_s"]), float(r["approach_speed_m_s"])) for r in rows
               if r["joint"] == name and r["impact"] == "1"]
        out[name] = dict(impacts=imp, free=j["free_flight_share"], lost=[c["time_s"] for c in j["contact_lost_at"]],
                         pen=j["max_penetration_mm"])
    return out, label


def fmt_times(ts, n=4):
    s = ", ".join(f"{t:.3f}" for t in ts[:n])
    return s + (", ..." if len(ts) > n else "")


def main():
    a, (b, label_b) = siconos_stats(sys.argv[1]), fourbar_stats(sys.argv[2])
    print("| joint | model | impacts (> 1 mm/s) | first impacts: time s (approach m/s) | free-flight share | "
          "contact lost at (s) | largest penetration mm |")
    print("|---|---|---|---|---|---|---|")
    for name in JOINTS:
        for label, st in (("Siconos (rigid, e = 0)", a[name]), (label_b, b[name])):
            first = ", ".join(f"{t:.4f} ({v:.3f})" for t, v in st["impacts"][:3])
            print(f"| {name} | {label} | {len(st['impacts'])} | {first} | {st['free']:.3f} | "
                  f"{len(st['lost'])}: {fmt_times(st['lost'])} | {st['pen']:.2e} |")
    trajectories(sys.argv[1], sys.argv[2])


def trajectories(path, folder):
    """Link angles of fourbar's series.csv against Siconos's (columns 1-3: crank, coupler, rocker)."""
    d = np.loadtxt(path)
    rows = list(csv.DictReader(open(f"{folder}/series.csv")))
    t = np.array([float(r["time_s"]) for r in rows])
    print("\n| link angle | max abs difference rad | RMS difference rad |\n|---|---|---|")
    for name, col, key in (("crank", 1, "theta2_rad"), ("coupler", 2, "theta3_rad"), ("rocker", 3, "theta4_rad")):
        diff = np.array([float(r[key]) for r in rows]) - np.interp(t, d[:, 0], d[:, col])
        print(f"| {name} | {np.max(np.abs(diff)):.2e} | {np.sqrt(np.mean(diff ** 2)):.2e} |")


if __name__ == "__main__":
    main()

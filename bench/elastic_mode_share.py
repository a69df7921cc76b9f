#!/usr/bin/python3
"""Spectrum of the elastic speed case's sensors (issue 25): the share of each
frequency band in the RMS of the coupler and rocker mid-span sensors, from the
CSV of `build/bench/elastic_linkage_work_precision --share 4 40000 CSV` (the
tol-1e-12 reference sampled 40 000 times a turn). Bands are centred on the
links' eigenfrequencies (611, 2490, 5620, 10100 Hz for 4 modes a link).

    /usr/bin/python3 bench/elastic_mode_share.py CSV
"""
import sys

import numpy as np

d = np.genfromtxt(sys.argv[1], delimiter=",", names=True)
t = d["time_s"]
dt = t[1] - t[0]
bands = [(0, 300), (300, 1500), (1500, 4000), (4000, 8000), (8000, 14000), (14000, 30000), (30000, 1e9)]
for name in ["coupler_m_s2", "rocker_m_s2"]:
    x = d[name] - np.mean(d[name])
    p = np.abs(np.fft.rfft(x * np.hanning(len(x)))) ** 2
    f = np.fft.rfftfreq(len(x), dt)
    print(f"{name}: RMS {np.sqrt(np.mean(d[name] ** 2)):.4g} m/s^2; share of the (mean-free) RMS by band")
    for lo, hi in bands:
        m = (f >= lo) & (f < hi)
        print(f"  {lo:6.0f} - {min(hi, f[-1]):8.0f} Hz: {np.sqrt(p[m].sum() / p.sum()):.3e}")

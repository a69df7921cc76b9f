#!/usr/bin/python3
"""The analyze chain in numpy/scipy, on the record written by
bench_analyze_export, timed and compared with the C++ result.

    compare_analyze_scipy.py DIR

Same algorithms as analyze/ (not a library call for library call, but the
same mathematics): nominal kinematics, exact inverse of the sensor high-pass
with the model mean, conversion, Kaiser windowed-sinc band-pass with a 60 Hz
comb applied by one real FFT of the whole record (scipy.fft), cubic Lagrange
resampling onto the crank-angle grid, spectral periodic integration per
revolution, synchronous average. Prints the time of both, the speed ratio and
the largest difference of every output relative to its largest magnitude.
"""
import json
import sys
import time
from pathlib import Path

import numpy as np
import scipy.fft as sfft


def nominal(rig, theta2, w2, a2):
    """Closed-form pose, rates and crank-pin acceleration (mechanism/kinematics.cpp)."""
    l1, l2, l3, l4, branch = rig["l1"], rig["l2"], rig["l3"], rig["l4"], rig["branch"]
    u2x, u2y = np.cos(theta2), np.sin(theta2)
    vx, vy = l1 - l2 * u2x, -l2 * u2y
    r = np.hypot(vx, vy)
    cphi = np.clip((l3 * l3 + r * r - l4 * l4) / (2 * l3 * r), -1, 1)
    sphi = branch * np.sqrt(np.maximum(0, 1 - cphi * cphi))
    vhx, vhy = vx / r, vy / r
    u3x, u3y = cphi * vhx - sphi * vhy, sphi * vhx + cphi * vhy
    u4x, u4y = (l3 * u3x - vx) / l4, (l3 * u3y - vy) / l4
    cross = lambda ax, ay, bx, by: ax * by - ay * bx
    s34 = cross(u4x, u4y, u3x, u3y)
    s24 = cross(u4x, u4y, u2x, u2y)
    s23 = cross(u3x, u3y, u2x, u2y)
    w3 = -w2 * l2 * s24 / (l3 * s34)
    w4 = -w2 * l2 * s23 / (l4 * s34)
    kx = l2 * (a2 * -u2y - w2 * w2 * u2x) - l3 * w3 * w3 * u3x + l4 * w4 * w4 * u4x
    ky = l2 * (a2 * u2x - w2 * w2 * u2y) - l3 * w3 * w3 * u3y + l4 * w4 * w4 * u4y
    al3 = (kx * u4x + ky * u4y) / (l3 * s34)
    al4 = (kx * u3x + ky * u3y) / (l4 * s34)
    aAx = l2 * (a2 * -u2y - w2 * w2 * u2x)
    aAy = l2 * (a2 * u2x - w2 * w2 * u2y)
    return dict(coupler=(u3x, u3y, w3, al3, aAx, aAy), rocker=(u4x, u4y, w4, al4, 0 * aAx, 0 * aAy))


def reading(rig, m, ux, uy, w, al, ajx, ajy):
    nx, ny = -uy, ux
    w2 = w * w
    ax = ajx + m["r_m"] * (al * nx - w2 * ux) + m["h_m"] * (-al * ux - w2 * nx)
    ay = ajy + m["r_m"] * (al * ny - w2 * uy) + m["h_m"] * (-al * uy - w2 * ny)
    ay = ay + rig["g"]
    return m["sign"] * ((ax * nx + ay * ny) if m["axis"] == "tangential" else (ax * ux + ay * uy))


def restore(rig, m, kin, fs, y):
    if m["high_pass_corner_hz"] == 0:
        return y.copy()
    ux, uy, w, al, ajx, ajy = kin[m["link"]]
    n = y.size
    mean_alpha = ((w[-1] - w[0]) * fs + 0.5 * (al[0] + al[-1])) / n
    if m["axis"] == "tangential":
        al = np.full(n, mean_alpha)
    target = reading(rig, m, ux, uy, w, al, ajx, ajy).mean()
    a = 2 * np.pi * m["high_pass_corner_hz"] / fs
    decay, gain = np.exp(-a), -np.expm1(-a) / a
    x = np.empty(n)
    x[0] = 0
    np.cumsum((y[1:] - decay * y[:-1]) / gain, out=x[1:])
    return x + (target - x.mean())


def convert(rig, m, kin, x, link_alpha=None):
    ux, uy, w, al, ajx, ajy = kin[m["link"]]
    s, r, h = m["sign"], m["r_m"], m["h_m"]
    if m["axis"] == "tangential":
        nx, ny = -uy, ux
        return (s * x - (ajx * nx + ajy * ny) + h * w * w - rig["g"] * ny) / r
    return ((ajx * ux + ajy * uy) - h * (0 if link_alpha is None else link_alpha) + rig["g"] * uy - s * x) / r


def kernel(f, fs, lowpass_only):
    nyq = fs / 2
    bands = [(0.0, f["high_hz"])] if lowpass_only else [(f["low_hz"], f["high_hz"])]
    k = 1
    while k * f["mains_hz"] - 0.5 * f["mains_width_hz"] < nyq:
        lo, hi = k * f["mains_hz"] - 0.5 * f["mains_width_hz"], k * f["mains_hz"] + 0.5 * f["mains_width_hz"]
        cut = []
        for b in bands:
            if hi <= b[0] or lo >= b[1]:
                cut.append(b)
                continue
            if lo > b[0]:
                cut.append((b[0], lo))
            if hi < b[1]:
                cut.append((hi, b[1]))
        bands = cut
        k += 1
    beta = f["kaiser_beta"]
    width = 2 * np.sqrt(1 + (beta / np.pi) ** 2)
    half = max(int(np.ceil(0.5 * width * fs / f["transition_hz"])), 1)
    n = np.arange(-half, half + 1, dtype=float)

    def lp(b):
        x = 2 * b / fs
        out = np.empty_like(n)
        nz = n != 0
        out[nz] = np.sin(np.pi * x * n[nz]) / (np.pi * n[nz])
        out[~nz] = x
        return out

    h = sum(lp(hi) - lp(lo) for lo, hi in bands)
    return h * np.kaiser(2 * half + 1, beta)


def fft_filter(h, x):
    n, m = x.size, h.size // 2
    wrapped = np.zeros(n)
    np.add.at(wrapped, (np.arange(h.size) + n - m) % n, h)
    H = sfft.rfft(wrapped).real
    return sfft.irfft(sfft.rfft(x) * H, n)


def resampler(angle, N, start):
    first = int(np.ceil((angle[0] - start) / (2 * np.pi)))
    end = int(np.floor((angle[-1] - start) / (2 * np.pi)))
    revs = end - first
    idx = np.arange(revs * N)
    theta = start + 2 * np.pi * ((first + idx // N) + (idx % N) / N)
    j = np.minimum(np.searchsorted(angle, theta, side="right") - 1, angle.size - 3)
    b = np.clip(j - 1, 0, angle.size - 4)
    nodes = angle[b[:, None] + np.arange(4)]
    w = np.ones((theta.size, 4))
    for a in range(4):
        for c in range(4):
            if c != a:
                w[:, a] *= (theta - nodes[:, c]) / (nodes[:, a] - nodes[:, c])
    return revs, first, b, w


def resample(plan, x, N):
    revs, _, b, w = plan
    return np.einsum("ij,ij->i", w, x[b[:, None] + np.arange(4)]).reshape(revs, N)


def integrate(alpha, speed, turns):
    N = alpha.shape[1]
    G = sfft.rfft(alpha / speed, axis=1)
    G[:, 0] = 0
    G[:, 1:] /= 1j * np.arange(1, G.shape[1])
    if N % 2 == 0:
        G[:, N // 2] = 0
    w = sfft.irfft(G, N, axis=1)
    c = (turns - (w / speed).mean(axis=1)) / (1 / speed).mean(axis=1)
    return w + c[:, None]


def chain(meta, data):
    rig, fs, N, start = meta["rig"], meta["sample_rate_hz"], meta["points_per_rev"], meta["grid_start_rad"]
    angle, speed, accel = data[0], data[1], data[2]
    kin = nominal(rig, angle, speed, accel)
    band = kernel(meta["filter"], fs, False)
    low = kernel(meta["filter"], fs, True)
    plan = resampler(angle, N, start)
    speed_grid = resample(plan, speed, N)
    out = []
    alphas = {}
    for ch in (0, 1):
        m = meta["mounts"][ch]
        a = fft_filter(band, convert(rig, m, kin, restore(rig, m, kin, fs, data[3 + ch])))
        alphas[ch] = a
        ag = resample(plan, a, N)
        out += [ag, integrate(ag, speed_grid, 0.0)]  # both links rock: 0 turns per crank turn
    m = meta["mounts"][2]
    w2 = fft_filter(low, convert(rig, m, kin, restore(rig, m, kin, fs, data[5]), alphas[0]))
    out.append(resample(plan, w2, N))
    return out


def main():
    d = Path(sys.argv[1])
    meta = json.loads((d / "record.json").read_text())
    n = meta["frames"]
    data = np.fromfile(d / "record.f64", dtype="<f8").reshape(6, n)
    cpp_meta = json.loads((d / "cpp_result.json").read_text())
    best, first, out = float("inf"), None, None
    for _ in range(3):
        t0 = time.perf_counter()
        out = chain(meta, data)
        took = time.perf_counter() - t0
        first = took if first is None else first
        best = min(best, took)
    cpp = np.fromfile(d / "cpp_result.f64", dtype="<f8").reshape(5, -1)
    print(f"numpy {np.__version__} / scipy: {n} frames x 3 channels in {best:.3f} s ({n / best:.3g} frames/s; "
          f"best of 3, the first run {first:.3f} s)")
    print(f"C++ analyze chain:                 in {cpp_meta['seconds']:.3f} s; C++ is {best / cpp_meta['seconds']:.2f}x faster "
          f"(first runs: {first / cpp_meta['first_run_seconds']:.2f}x)")
    worst = 0.0
    for name, ours, theirs in zip(cpp_meta["arrays"], cpp, out):
        theirs = theirs.ravel()
        rel = np.max(np.abs(ours - theirs)) / np.max(np.abs(ours))
        worst = max(worst, rel)
        print(f"  {name:18s} max |C++ - numpy| / max |C++| = {rel:.2e}")
    print(f"largest relative difference {worst:.2e}")


if __name__ == "__main__":
    main()

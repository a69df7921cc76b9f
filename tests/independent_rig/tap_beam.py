#!/usr/bin/python3
"""CTest independent_rig_tap: `fourbar tap` on hammer taps of a finite-element
beam, written here from the physics (no code or model shared with fourbar's
virtual tap, which is a sum of damped sines).

The link: the thesis coupler as a steel bar 25 × 4 mm, 309 mm between the
pins, bending in the plane of the linkage (E 210 GPa, ρ 7850 kg/m³), pinned
at both joints as in the rig; 40 Hermite-cubic Euler–Bernoulli elements
(scipy.linalg.eigh of the consistent mass and stiffness); a 5 g accelerometer
at 0.45 L (its mass in the model, so the truth is the loaded beam's);
Rayleigh damping with ζ = 1 % at the first mode and 1.5 % at the second
(higher modes more: 3.1 %, 5.4 %). Every mode below the DAQ's band is in
the signal, not just the two fitted.

The tap: a half-sine force of 0.25 ms (a steel-tipped hammer) at 0.3 L, so
the peak acceleration comes during the force, not at a decay's start; the
response by modal superposition, each mode discretised exactly (zero-order
hold of the force) on a grid 8× the sample rate; the accelerometer chain
AC-coupled at 0.5 Hz; a sigma-delta DAQ's linear-phase FIR (Kaiser β 10,
delay compensated) decimating to 25.6 kHz; white noise at an SNR of the
ringing's first 20 ms RMS over the noise's; a 16-bit ADC at twice the peak.
0.1 s before the tap, 1 s in all, written as CSV (time_s, accel_m_s2).

Truth: the loaded beam's first two natural frequencies (undamped, from the
eigenproblem; the printed frequency is the natural one, ω_n, as the rig file
wants) and damping ratios. The issue's tolerances: frequency within 0.5 %,
damping ratio within 10 %, at 20, 30 and 40 dB, three noise seeds each,
`fourbar tap REC --modes 2`; and every truth within 3 printed uncertainties,
there, for the three modes the default finds at 60 dB (two seeds), and at
40 dB with 50 Hz hum at 3 % of the ringing's RMS (two seeds; the hum must be
named a steady tone); with a bouncing hammer (a second strike 1, 4 or 12 ms
later at 0.3–0.5 of the force: the bounce must be named) and an overloaded
recorder (range at 0.7 and 0.4 of the peak: the clip must be named), and no
single tap called either. Measured 2026-12-04: worst frequency error 1.5e-3 (the
third mode, with hum; the first two 3.2e-4), damping ratio 6.6 % (the third
mode, with hum; the first two 0.2 %), truths within 2.0 uncertainties.
Before the uncertainty included the later-start fit, the third mode at
60 dB lay 7 standard errors from its truth (docs/flex.md "Tap test").

usage: tap_beam.py FOURBAR_EXE WORK_DIR
       tap_beam.py --write FILE [--snr-db D] [--seed N]   (one recording; truth on stdout)
"""
import math
import os
import re
import shutil
import subprocess
import sys

try:
    import numpy as np
    import scipy.linalg
    import scipy.signal
except ImportError:
    print("independent_rig_tap: skipped: python3-scipy and python3-numpy (Debian) are not "
          f"installed for {sys.executable}; apt-get install python3-scipy")
    sys.exit(77)

LENGTH_M, WIDTH_M, THICK_M = 0.309, 25e-3, 4e-3
E_PA, RHO = 210e9, 7850.0
ELEMENTS = 40
SENSOR_AT, SENSOR_KG, HAMMER_AT = 0.45, 0.005, 0.30
ZETA_12 = (0.01, 0.015)
PULSE_S, PEAK_N = 0.25e-3, 50.0
FS, OVERSAMPLE, PRE_S, TOTAL_S = 25600.0, 8, 0.1, 1.0
HUM_HZ = 50.0
HIGHPASS_HZ = 0.5
FREQ_TOL, ZETA_TOL = 0.005, 0.10


def beam_modes():
    """(ω_n, mass-normalised shapes at the sensor and the hammer) of the pinned–pinned beam with the sensor's mass."""
    area, inertia = WIDTH_M * THICK_M, THICK_M * WIDTH_M ** 3 / 12   # in-plane: bending about the thickness axis
    ei, mu, h = E_PA * inertia, RHO * area, LENGTH_M / ELEMENTS
    k = ei / h ** 3 * np.array([[12, 6 * h, -12, 6 * h], [6 * h, 4 * h * h, -6 * h, 2 * h * h],
                                [-12, -6 * h, 12, -6 * h], [6 * h, 2 * h * h, -6 * h, 4 * h * h]])
    m = mu * h / 420 * np.array([[156, 22 * h, 54, -13 * h], [22 * h, 4 * h * h, 13 * h, -3 * h * h],
                                 [54, 13 * h, 156, -22 * h], [-13 * h, -3 * h * h, -22 * h, 4 * h * h]])
    n = 2 * (ELEMENTS + 1)
    kk, mm = np.zeros((n, n)), np.zeros((n, n))
    for e in range(ELEMENTS):
        s = slice(2 * e, 2 * e + 4)
        kk[s, s] += k
        mm[s, s] += m
    node = lambda x: int(round(x * ELEMENTS))  # noqa: E731
    mm[2 * node(SENSOR_AT), 2 * node(SENSOR_AT)] += SENSOR_KG
    free = [i for i in range(n) if i not in (0, 2 * ELEMENTS)]        # w = 0 at both pins
    w2, phi = scipy.linalg.eigh(kk[np.ix_(free, free)], mm[np.ix_(free, free)])
    full = np.zeros((n, len(free)))
    full[free, :] = phi
    return np.sqrt(w2), full[2 * node(SENSOR_AT), :], full[2 * node(HAMMER_AT), :]


def damping_ratios(omega):
    """Rayleigh α + β·ω² through ζ1, ζ2 at the first two modes."""
    w1, w2 = omega[0], omega[1]
    a = np.array([[1 / (2 * w1), w1 / 2], [1 / (2 * w2), w2 / 2]])
    alpha, beta = np.linalg.solve(a, np.array(ZETA_12))
    return alpha / (2 * omega) + beta * omega / 2


def recording(snr_db, seed, hum=0.0, bounce=None, clip=None):
    omega, at_sensor, at_hammer = beam_modes()
    zeta = damping_ratios(omega)
    fine = FS * OVERSAMPLE
    dt = 1.0 / fine
    t = np.arange(int(round(TOTAL_S * fine))) * dt
    tap = t - PRE_S
    force = np.where((tap >= 0) & (tap < PULSE_S), PEAK_N * np.sin(math.pi * np.clip(tap, 0, None) / PULSE_S), 0.0)
    if bounce:  # the hammer strikes again (delay_s later, a share of the force)
        delay_s, share = bounce
        later = tap - delay_s
        force = force + np.where((later >= 0) & (later < PULSE_S),
                                 share * PEAK_N * np.sin(math.pi * np.clip(later, 0, None) / PULSE_S), 0.0)
    accel = np.zeros_like(t)
    keep = omega < 2 * math.pi * 0.45 * FS           # modes the DAQ passes; the rest are filtered out anyway
    for w, z, ps, ph in zip(omega[keep], zeta[keep], at_sensor[keep], at_hammer[keep]):
        a = np.array([[0.0, 1.0], [-w * w, -2 * z * w]])
        b = np.array([[0.0], [ph]])
        c = np.array([[-w * w, -2 * z * w]])          # q̈ = f − 2ζω q̇ − ω² q, the force added below
        ad, bd, cd, dd, _ = scipy.signal.cont2discrete((a, b, c, np.array([[ph]])), dt, method="zoh")
        num, den = scipy.signal.ss2tf(ad, bd, cd, dd)
        accel += ps * scipy.signal.lfilter(num[0], den, force)
    bh, ah = scipy.signal.bilinear([1.0, 0.0], [1.0, 2 * math.pi * HIGHPASS_HZ], fine)
    accel = scipy.signal.lfilter(bh, ah, accel)
    taps = 8 * OVERSAMPLE * 16 + 1
    fir = scipy.signal.firwin(taps, 0.45 * FS, window=("kaiser", 10.0), fs=fine)
    delay = (taps - 1) // 2
    filtered = np.convolve(accel, fir)[delay:delay + len(accel)]
    samples = filtered[::OVERSAMPLE]
    start = int(round(PRE_S * FS))
    ringing_rms = float(np.sqrt(np.mean(samples[start:start + int(0.02 * FS)] ** 2)))
    rng = np.random.default_rng(seed)
    samples = samples + rng.normal(0.0, ringing_rms * 10 ** (-snr_db / 20), len(samples))
    samples = samples + hum * ringing_rms * math.sqrt(2) * np.sin(2 * math.pi * HUM_HZ * np.arange(len(samples)) / FS + 0.3)
    full_scale = (clip or 2) * np.max(np.abs(samples))   # clip < 1: the recorder overloads
    lsb = 2 * full_scale / 2 ** 16
    samples = np.clip(np.round(samples / lsb), -2 ** 15, 2 ** 15 - 1) * lsb
    truth = [(omega[i] / (2 * math.pi), zeta[i]) for i in range(2)]
    higher = [(omega[i] / (2 * math.pi), zeta[i]) for i in range(2, int(keep.sum()))]
    return samples, truth, higher


def write_csv(path, samples):
    with open(path, "w") as f:
        f.write("time_s,accel_m_s2\n")
        for i, x in enumerate(samples):
            f.write(f"{i / FS:.8f},{x:.9g}\n")


def printed_modes(text):
    """[(f, u_f, ζ, u_ζ)] from the "mode k: f ± u Hz, damping ratio ζ ± u" lines."""
    number = r"([-+0-9.eE]+)"
    return [tuple(float(g) for g in m.groups()) for m in re.finditer(
        rf"mode \d+: {number} ± {number} Hz, damping ratio {number} ± {number}", text)]


def judge(path, printed, truth, label):
    """Failures: an estimate outside the issue's tolerance, or a truth outside 3 printed uncertainties."""
    failures, line, worst = 0, [], (0.0, 0.0, 0.0)
    for k, ((f, uf, z, uz), (tf, tz)) in enumerate(zip(printed, truth)):
        ef, ez = abs(f / tf - 1), abs(z / tz - 1)
        nf, nz = abs(f - tf) / uf, abs(z - tz) / uz
        worst = (max(worst[0], ef), max(worst[1], ez), max(worst[2], nf, nz))
        line.append(f"mode {k + 1} {f:.2f} ± {uf:.2g} Hz ({ef:.1e}, {nf:.1f} u) zeta {z:.4f} ± {uz:.1g} "
                    f"({100 * ez:.1f} %, {nz:.1f} u)")
        if k < 2 and (ef > FREQ_TOL or ez > ZETA_TOL):
            print(f"FAIL: {path}: mode {k + 1}: {f} Hz, ζ {z} against {tf:.3f} Hz, ζ {tz:.4f} "
                  f"(tolerances {FREQ_TOL:.1%}, {ZETA_TOL:.0%})")
            failures += 1
        if nf > 3 or nz > 3:
            print(f"FAIL: {path}: mode {k + 1}: the truth ({tf:.3f} Hz, ζ {tz:.4f}) lies {nf:.1f} and {nz:.1f} "
                  f"printed uncertainties from {f} ± {uf} Hz, ζ {z} ± {uz}")
            failures += 1
    print(f"{label}: " + "; ".join(line))
    return failures, worst


def main(argv):
    if argv and argv[0] == "--write":
        snr = float(argv[argv.index("--snr-db") + 1]) if "--snr-db" in argv else 30.0
        seed = int(argv[argv.index("--seed") + 1]) if "--seed" in argv else 1
        samples, truth, higher = recording(snr, seed)
        write_csv(argv[1], samples)
        for k, (f, z) in enumerate(truth + higher, 1):
            print(f"mode {k}: {f:.4f} Hz, zeta {z:.5f}")
        return 0
    fourbar, work = argv[0], os.path.abspath(argv[1])
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    failures, worst = 0, (0.0, 0.0, 0.0)
    runs = [(snr, seed, ["--modes", "2"], 2, 0.0) for snr in (20, 30, 40) for seed in (1, 2, 3)]
    runs += [(60, seed, [], 3, 0.0) for seed in (1, 2)]   # the default: as many modes as the spectrum shows
    # Mains hum at 3 % of the ringing's RMS: the fit's hum component decays at
    # its bound, zero; the third mode came out at the fit's starting ζ 0.0100
    # ± 0.0003 (truth 0.030) until a rate at its bound was held there.
    runs = [r + (None,) for r in runs + [(40, seed, [], 3, 0.03) for seed in (1, 2)]]
    # A bouncing hammer: a second strike 1, 4 or 12 ms after the tap at 0.3–0.5
    # of its force. Fitted as a free decay, the 4 ms bounce gave "mode 2:
    # 603.8 Hz, ζ 0.117" (truth 2451.7 Hz, 0.015); the strike must be named.
    runs += [(30, 1, ["--modes", "2"], 2, 0.0, (0.001, 0.3)), (30, 2, ["--modes", "2"], 2, 0.0, (0.004, 0.4)),
             (40, 1, ["--modes", "2"], 2, 0.0, (0.012, 0.5))]
    runs = [r + (None,) for r in runs]
    # An overloaded recorder: its range at 0.7 and 0.4 of the tap's peak. The
    # clipped samples were taken for bounces of the hammer; at 0.2 the
    # second mode came out at 602 Hz. They must be named, the decay after
    # them fitted.
    runs += [(40, 1, ["--modes", "2"], 2, 0.0, None, 0.7), (40, 2, ["--modes", "2"], 2, 0.0, None, 0.4)]
    for snr, seed, modes, expect, hum, bounce, clip in runs:
        samples, truth, higher = recording(snr, seed, hum, bounce, clip)
        path = os.path.join(work, f"tap_{snr}dB_{seed}" + (f"_hum{hum:g}" if hum else "") +
                            (f"_bounce{1e3 * bounce[0]:g}ms" if bounce else "") +
                            (f"_clip{clip:g}" if clip else "") + ".csv")
        write_csv(path, samples)
        r = subprocess.run([fourbar, "tap", path] + modes, capture_output=True, text=True)
        printed = printed_modes(r.stdout)
        if r.returncode != 0 or len(printed) != expect:
            print(f"FAIL: fourbar tap {path} {' '.join(modes)} exited {r.returncode}, {len(printed)} modes "
                  f"({expect} expected): {r.stdout}{r.stderr}")
            failures += 1
            continue
        if bool(bounce) != ("struck again" in r.stdout):
            print(f"FAIL: fourbar tap {path}: " + ("the bounce is not named" if bounce else "a single tap is taken for a "
                  "bounce") + f": {r.stdout}")
            failures += 1
        if bool(clip) != ("clipped:" in r.stdout):
            print(f"FAIL: fourbar tap {path}: " + ("the clipping is not named" if clip else "an unclipped tap is "
                  "called clipped") + f": {r.stdout}")
            failures += 1
        if hum and "steady tone(s)" not in r.stdout:
            print(f"FAIL: fourbar tap {path}: the {HUM_HZ:g} Hz hum is not named as a steady tone: {r.stdout}")
            failures += 1
        label = (f"{snr} dB seed {seed} {' '.join(modes) or '(modes found)'}" + (f" hum {hum:.0%}" if hum else "") +
                 (f" bounce {1e3 * bounce[0]:g} ms" if bounce else "") + (f" clipped at {clip:g} of the peak" if clip else ""))
        f, w = judge(path, printed, truth + higher, label)
        failures += f
        worst = tuple(max(a, b) for a, b in zip(worst, w))
    print("truth: " + ", ".join(f"{f:.3f} Hz ζ {z:.4f}" for f, z in truth) +
          "; in the signal too: " + ", ".join(f"{f:.0f} Hz ζ {z:.3f}" for f, z in higher))
    print(f"worst frequency error {worst[0]:.2e}, worst damping-ratio error {100 * worst[1]:.1f} %, "
          f"truth at most {worst[2]:.1f} printed uncertainties away")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

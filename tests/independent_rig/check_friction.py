#!/usr/bin/python3
"""CTest independent_rig_friction: fourbar's linkage model with wall friction
against the independent generator, turn by turn.

With Coulomb friction μ = 0.2 in every contact the thesis rig (rigid links,
350 rpm, 0.254 mm at B, e = 0.5) settles into a periodic motion: the pin
rides the wall and leaves it about once a turn at a few mm/s. So the two
implementations are compared sample by sample on the mean turn, not by
statistics: each tangential accelerometer (the generator's positions),
band-passed 2–1000 Hz, cut into 58 turns at the crank pulse's mark, averaged.
fourbar's mean turn gets the manifest's AC coupling (first-order high-pass,
coupler 1 Hz, rocker 0.2 Hz: 9.7° and 2.0° of phase at the crank's
5.83 Hz) in the periodic steady state, as the generator's amplifier applies
it; then the relative RMS difference of the two mean turns.

What differs between the two: the contact's damping (the generator's
Hunt–Crossley χ found by root finding for e; fourbar's calibrated law), the
friction's regularisation (the generator's μ·v/√(v² + (0.1 mm/s)²); fourbar's
ramp from 0 to μ over 0–0.1 mm/s), the integrators, the DAQ's decimation.

Measured 2026-12-04 (seed 505, no crank wander): coupler 0.0165, rocker
0.0072. Without the AC coupling on fourbar's side 0.112 and 0.034; fourbar
at μ = 0.15 0.159 and 0.093, at μ = 0.25 0.102 and 0.042, without friction
0.49 and 0.21 (so the check can fail); e = 0.6 instead of 0.5 0.0175 and
0.0072 (this motion does not test restitution; check_elastic.py's chaotic
one does not test friction). Earlier, with a cruder alignment: fourbar's
ramp over 0.05 or 0.3 mm/s, a stick speed of 0.01 mm/s or tolerance 1e-10
moved the figures by < 0.001. Impacts a turn faster than 1 mm/s are
printed, not compared: fourbar's turn has a bounce at 3.92 mm/s (the
generator's median 3.6) and the pin's return to the wall 0.9° later at
1.14 mm/s, just over the count's threshold (generator 1.0 a turn, fourbar
2.0).

usage: check_friction.py FOURBAR_EXE WORK_DIR [SEED]
"""
import os
import shutil
import sys

try:
    import numpy as np
    import scipy.signal  # noqa: F401
except ImportError:
    print("independent_rig_friction: skipped: python3-scipy and python3-numpy (Debian) are not "
          f"installed for {sys.executable}; apt-get install python3-scipy")
    sys.exit(77)

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import linkage_compare as lc  # noqa: E402

RIG = os.path.join(HERE, "..", "..", "data", "rigs", "thesis.toml")
TURNS, WARMUP, RPM, CLEARANCE_MM, RESTITUTION, FRICTION = 60, 10, 350.0, 0.254, 0.5, 0.2
BAND_HZ = (2.0, 1000.0)
LIMIT = {"coupler": 0.04, "rocker": 0.02}   # relative RMS difference of the mean turns (measured 0.0165, 0.0072)


def ac_coupled_steady(turn, highpass_hz, turn_hz):
    """A periodic turn through a first-order high-pass at highpass_hz, in steady state."""
    spectrum = np.fft.rfft(turn)
    f = np.arange(len(spectrum)) * turn_hz
    return np.fft.irfft(spectrum * (1j * f / highpass_hz) / (1 + 1j * f / highpass_hz), len(turn))


def main(argv):
    fourbar, work = argv[0], os.path.abspath(argv[1])
    seed = argv[2] if len(argv) > 2 else "505"
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    session, _, rec, manifest, sensors, offset_deg = lc.make_generator_session(
        work, RIG, RPM, CLEARANCE_MM, TURNS, WARMUP, RESTITUTION,
        ["--friction", str(FRICTION), "--wander-pct", "0"], seed)
    channels = lc.tangential(manifest)
    gen = lc.generator_turns(session, rec, manifest, BAND_HZ, TURNS - 2)

    keys = {"coupler_rocker_radial_mm": CLEARANCE_MM, "restitution": RESTITUTION,
            "contact_stiffness_N_per_m_n": f"{rec['contact_stiffness_N_m1p5']:.10g}",
            "friction_coefficient": FRICTION, "friction_stick_speed_mm_s": 0.0, "friction_slip_speed_mm_s": 0.1,
            "tolerance": 1e-8}
    deg, columns, impacts = lc.fourbar_sim(fourbar, work, "friction", os.path.abspath(RIG), RPM, TURNS, WARMUP,
                                           keys, sensors)
    fs, turn_hz = lc.SAMPLES_PER_TURN * RPM / 60.0, RPM / 60.0
    print(f"thesis rig, rigid links, {RPM:g} rpm, {CLEARANCE_MM} mm, e = {RESTITUTION}, mu = {FRICTION}, seed {seed}; "
          f"mean of {TURNS - 2} turns, {BAND_HZ[0]:g}-{BAND_HZ[1]:g} Hz")
    print(f"impacts a turn (> 1 mm/s): generator {rec['impacts_per_turn']:.2f}, fourbar "
          f"{lc.impacts_per_turn(impacts, TURNS):.2f}; median impact speed generator "
          f"{rec['median_impact_speed_m_s'] * 1e3:.1f} mm/s (not compared)")
    failures = 0
    for link, x in columns.items():
        mean = np.mean(lc.fourbar_turns(deg, lc.band(x, fs, BAND_HZ), offset_deg, TURNS - 2), axis=0)
        mean = ac_coupled_steady(mean, channels[link]["highpass_hz"], turn_hz) if channels[link]["ac_coupled"] else mean
        reference = np.mean(gen[link], axis=0)
        rms = float(np.sqrt(np.mean(reference ** 2)))
        diff = float(np.sqrt(np.mean((mean - reference) ** 2))) / rms
        print(f"{link:8} mean turn RMS generator {rms:5.1f} m/s², fourbar {np.sqrt(np.mean(mean ** 2)):5.1f}; "
              f"relative RMS difference {diff:.4f} (limit {LIMIT[link]})")
        if not diff <= LIMIT[link]:
            print(f"  FAIL: {link}: fourbar's mean turn differs from the generator's by {diff:.3f} of its RMS")
            failures += 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

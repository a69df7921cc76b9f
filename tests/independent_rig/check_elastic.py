#!/usr/bin/python3
"""CTest independent_rig_elastic: fourbar's elastic linkage model against the
independent generator's two-way bending, on links where both describe the
same body.

The generator's links are uniform Euler–Bernoulli beams, pinned–free, with
the rig's rigid mass and inertia beside them and no inertia coupling between
the bending and the rotation: exact for a uniform bar (its pinned–free modes
are mass-orthogonal to the rotation about the pin), not for the thesis
rig's coupler and rocker, whose mass centres sit at 0.60 and 0.43 of their
length. fourbar's links take one mass per length for both (linear, with the
measured mass and centre). So the two are compared on the thesis rig with
uniform links (mass centre at L/2, inertia m·L²/12 about it): 350 rpm,
0.254 mm at B, e = 0.5, μ = 0, the generator's three pinned–free modes per
link (600 / 520 Hz first, ζ 2 %) given to fourbar as pinned–pinned
frequencies, as `fourbar tap` of such a link would (check_ringing.py), and
the generator's contact stiffness.

The motion is chaotic, so the runs are compared by statistics over 58 turns
after 11, not sample by sample: each tangential accelerometer's signal
band-passed to 2–1000 Hz (the analysis band), cut into turns by the crank
angle; its turn-to-turn scatter (RMS of each turn minus the turns' mean,
over the mean's RMS) and the mean turn's RMS. Measured 2026-12-04 (seed
505): generator coupler 1.334, rocker 0.496; fourbar elastic 1.271, 0.425
(ratios 0.95, 0.86; over four start angles 1.21–1.29 and 0.42–0.44);
fourbar with rigid links 2.103, 0.731 (1.58x, 1.47x: outside the bands, so
the check can fail). Impacts a turn are printed, not compared: they come in
bursts (generator 3.6–8.5 over seeds and crank wander, fourbar 2.4–4.4).
On the thesis rig's own links the two differ (30 turns: generator 1.42 /
0.71, fourbar 0.43–0.54 / 0.29–0.32): the generator's missing coupling
(docs/linkage-model.md, "Against the independent generator").

The generator runs with --snr-db 80 --hum-mV 0: physics, not the DAQ's noise.
Exit 77 (skipped) when this Python has no scipy.

usage: check_elastic.py FOURBAR_EXE WORK_DIR [SEED]
"""
import math
import os
import re
import shutil
import sys

try:
    import numpy as np
    import scipy.signal  # noqa: F401
except ImportError:
    print("independent_rig_elastic: skipped: python3-scipy and python3-numpy (Debian) are not "
          f"installed for {sys.executable}; apt-get install python3-scipy")
    sys.exit(77)
import tomllib

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import linkage_compare as lc  # noqa: E402
RIG = os.path.join(HERE, "..", "..", "data", "rigs", "thesis.toml")
TURNS, WARMUP, RPM, CLEARANCE_MM, RESTITUTION = 60, 10, 350.0, 0.254, 0.5
BAND_HZ = (2.0, 1000.0)
# Accepted ratio fourbar / generator (measured over 58 turns: fourbar's four
# start angles 1.21–1.29 and 0.42–0.44; rigid links 1.58x and 1.47x off).
SCATTER_BAND = {"coupler": (0.8, 1.25), "rocker": (0.7, 1.4)}
MEAN_RMS_BAND = (0.8, 1.25)


def uniform_rig(path_out):
    """The thesis rig with its coupler and rocker as uniform bars."""
    with open(RIG, "rb") as f:
        rig = tomllib.load(f)
    section, out = None, []
    with open(RIG) as f:
        for line in f:
            m = re.match(r"\s*\[([^\]]+)\]", line)
            if m:
                section = m.group(1).strip()
            key = line.split("=")[0].strip()
            if section in ("coupler", "rocker") and key in ("mass_centre_mm", "inertia_kg_mm2"):
                length, mass = rig[section]["length_mm"], rig[section]["mass_kg"]
                value = length / 2 if key == "mass_centre_mm" else mass * length * length / 12
                line = f"{key} = {value:.6f}   # uniform bar (check_elastic.py)\n"
            out.append(line)
    with open(path_out, "w") as f:
        f.writelines(out)


def statistics(turns):
    """(turn-to-turn scatter over the mean turn's RMS, the mean turn's RMS)."""
    a = np.array(turns)
    mean = a.mean(axis=0)
    mean_rms = float(np.sqrt(np.mean(mean ** 2)))
    return float(np.sqrt(np.mean((a - mean) ** 2))) / mean_rms, mean_rms


def fourbar_stats(fourbar, work, name, rig_file, elastic, stiffness, sensors, offset_deg):
    keys = {"coupler_rocker_radial_mm": CLEARANCE_MM, "restitution": RESTITUTION,
            "contact_stiffness_N_per_m_n": f"{stiffness:.10g}", "friction_coefficient": 0.0, "tolerance": 1e-8}
    if elastic:
        keys.update({"elastic_links": '["coupler", "rocker"]', "elastic_modes": 3})
    deg, columns, impacts = lc.fourbar_sim(fourbar, work, name, rig_file, RPM, TURNS, WARMUP, keys, sensors)
    fs = lc.SAMPLES_PER_TURN * RPM / 60.0
    stats = {link: statistics(lc.fourbar_turns(deg, lc.band(x, fs, BAND_HZ), offset_deg, TURNS - 2))
             for link, x in columns.items()}
    return stats, lc.impacts_per_turn(impacts, TURNS)


def main(argv):
    fourbar, work = argv[0], os.path.abspath(argv[1])
    seed = argv[2] if len(argv) > 2 else "505"
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    rig_uniform = os.path.join(work, "rig_uniform.toml")
    uniform_rig(rig_uniform)
    session, args, rec, manifest, sensors, offset_deg = lc.make_generator_session(
        work, rig_uniform, RPM, CLEARANCE_MM, TURNS, WARMUP, RESTITUTION,
        ["--vibration", "--vibration-coupling", "two-way"], seed)

    from links import pinned_free_roots  # noqa: E402
    b1 = pinned_free_roots(1)[0]
    rig_elastic = os.path.join(work, "rig_uniform_elastic.toml")
    shutil.copy(rig_uniform, rig_elastic)
    with open(rig_elastic, "a") as f:
        for link, f1 in (("coupler", args["coupler_mode_hz"]), ("rocker", args["rocker_mode_hz"])):
            freqs = [round(f1 * (k * math.pi / b1) ** 2, 2) for k in range(1, args["modes"] + 1)]
            f.write(f"\n[{link}.elastic]\nmode_frequencies_Hz = {freqs}\n"
                    f"damping_ratios = {[args['damping_ratio']] * args['modes']}\n")

    gen = {link: statistics(turns)
           for link, turns in lc.generator_turns(session, rec, manifest, BAND_HZ, TURNS - 2).items()}
    stiffness = rec["contact_stiffness_N_m1p5"]
    elastic, elastic_impacts = fourbar_stats(fourbar, work, "elastic", rig_elastic, True, stiffness, sensors, offset_deg)
    rigid, rigid_impacts = fourbar_stats(fourbar, work, "rigid", rig_uniform, False, stiffness, sensors, offset_deg)

    print(f"uniform links, {RPM:g} rpm, {CLEARANCE_MM} mm, e = {RESTITUTION}, seed {seed}, {TURNS} turns after {WARMUP}; "
          f"sensors band-passed {BAND_HZ[0]:g}-{BAND_HZ[1]:g} Hz")
    print(f"impacts a turn (> 1 mm/s): generator {rec['impacts_per_turn']:.2f}, fourbar elastic {elastic_impacts:.2f}, "
          f"fourbar rigid {rigid_impacts:.2f} (not compared: bursts, 3.6-8.5 over the generator's seeds)")
    print(f"{'sensor':8} {'generator':>18} {'fourbar elastic':>18} {'ratio':>6} {'fourbar rigid':>16} {'ratio':>6}")
    failures = 0
    for link in ("coupler", "rocker"):
        (gs, gr), (es, er), (rs, rr) = gen[link], elastic[link], rigid[link]
        print(f"{link:8} scatter {gs:6.3f} rms {gr:5.1f}   {es:6.3f} rms {er:5.1f}  {es / gs:6.2f}   "
              f"{rs:6.3f} rms {rr:5.1f} {rs / gs:6.2f}")
        lo, hi = SCATTER_BAND[link]
        if not lo <= es / gs <= hi:
            print(f"  FAIL: {link} turn-to-turn scatter: fourbar {es:.3f} against the generator's {gs:.3f} "
                  f"(ratio {es / gs:.2f}, accepted {lo}-{hi})")
            failures += 1
        if not MEAN_RMS_BAND[0] <= er / gr <= MEAN_RMS_BAND[1]:
            print(f"  FAIL: {link} mean turn's RMS: fourbar {er:.1f} against the generator's {gr:.1f} m/s²")
            failures += 1
    if all(SCATTER_BAND[k][0] <= rigid[k][0] / gen[k][0] <= SCATTER_BAND[k][1] for k in gen):
        print("  FAIL: fourbar with rigid links is inside the bands too: the check cannot tell elastic links")
        failures += 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

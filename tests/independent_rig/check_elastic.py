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
505): generator coupler 1.333, rocker 0.496; fourbar elastic 1.273, 0.424
(ratios 0.96, 0.86; over four start angles 1.21–1.29 and 0.42–0.44);
fourbar with rigid links 2.101, 0.731 (1.58x, 1.47x: outside the bands, so
the check can fail). Impacts a turn are printed, not compared: they come in
bursts (generator 3.6–8.5 over seeds and crank wander, fourbar 2.4–4.4).
On the thesis rig's own links the two differ (30 turns: generator 1.42 /
0.71, fourbar 0.43–0.54 / 0.29–0.32): the generator's missing coupling
(docs/linkage-model.md, "Against the independent generator").

The generator runs with --snr-db 80 --hum-mV 0: physics, not the DAQ's noise.
Exit 77 (skipped) when this Python has no scipy.

usage: check_elastic.py FOURBAR_EXE WORK_DIR [SEED]
"""
import csv
import json
import math
import os
import re
import shutil
import subprocess
import sys

try:
    import numpy as np
    import scipy.io.wavfile
    import scipy.signal
except ImportError:
    print("independent_rig_elastic: skipped: python3-scipy and python3-numpy (Debian) are not "
          f"installed for {sys.executable}; apt-get install python3-scipy")
    sys.exit(77)
import tomllib

HERE = os.path.dirname(os.path.abspath(__file__))
RIG = os.path.join(HERE, "..", "..", "data", "rigs", "thesis.toml")
TURNS, WARMUP, RPM, CLEARANCE_MM, RESTITUTION = 60, 10, 350.0, 0.254, 0.5
SAMPLES_PER_TURN = 3600          # fourbar's series: 21 kHz at 350 rpm
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


def band(x, fs):
    sos = scipy.signal.butter(4, BAND_HZ, "bandpass", fs=fs, output="sos")
    return scipy.signal.sosfiltfilt(sos, x)


def statistics(turns):
    a = np.array(turns)
    mean = a.mean(axis=0)
    mean_rms = float(np.sqrt(np.mean(mean ** 2)))
    return float(np.sqrt(np.mean((a - mean) ** 2))) / mean_rms, mean_rms


def generator_stats(session, manifest):
    fs, data = scipy.io.wavfile.read(os.path.join(session, manifest["_wav"]))
    volts = data.astype(float) / 2 ** 31 * manifest["full_scale_V"]   # 24-bit WAV read left-justified
    channels = {c["role"]: c for c in manifest["channel"]}
    pulse = volts[:, channels["crank_pulse"]["index"]]
    mid = 0.5 * (pulse.max() + pulse.min())
    falling = np.where((pulse[:-1] > mid) & (pulse[1:] <= mid))[0]
    out = {}
    for link in ("coupler", "rocker"):
        c = channels[f"{link}_tangential"]
        x = band(volts[:, c["index"]] * 1000.0 / (c["sensitivity_mV_per_m_s2"] * c["gain"]), fs)
        grid = np.arange(len(x))
        turns = [np.interp(np.linspace(a, b, 720, endpoint=False), grid, x)
                 for a, b in zip(falling[:-1], falling[1:])]
        out[link] = statistics(turns[1:TURNS - 1])   # the same turns as fourbar's, away from the filter's ends
    return out


def fourbar_run(fourbar, work, name, rig_file, elastic, stiffness, sensors):
    scene = os.path.join(work, f"{name}.toml")
    links = 'elastic_links = ["coupler", "rocker"]\nelastic_modes = 3\n' if elastic else ""
    with open(scene, "w") as f:
        f.write(f'rig = "{rig_file}"\nmodel = "linkage"\ncrank_speed_rpm = {RPM}\nstart_angle_deg = 0.0\n'
                f'revolutions = {TURNS}\nsamples_per_revolution = {SAMPLES_PER_TURN}\n'
                f'outputs = ["time_s"]\n\n[linkage]\ncoupler_rocker_radial_mm = {CLEARANCE_MM}\n{links}'
                f'restitution = {RESTITUTION}\ncontact_stiffness_N_per_m_n = {stiffness:.10g}\n'
                f'friction_coefficient = 0.0\ntolerance = 1e-8\n'
                f'coupler_sensors_mm = [{sensors["coupler"][0]}, {sensors["coupler"][1]}]\n'
                f'rocker_sensors_mm = [{sensors["rocker"][0]}, {sensors["rocker"][1]}]\n')
    out = os.path.join(work, f"out_{name}")
    rc = subprocess.run([fourbar, "sim", scene, "--out", out, "--warmup-turns", str(WARMUP)],
                        stdout=subprocess.DEVNULL).returncode
    if rc != 0:
        raise SystemExit(f"fourbar sim {scene} exited {rc}")
    with open(os.path.join(out, "series.csv")) as f:
        rows = list(csv.reader(f))
    head, body = rows[0], np.array(rows[1:], dtype=float)
    t, deg = body[:, head.index("time_s")], body[:, head.index("crank_deg")]
    fs = 1.0 / float(np.median(np.diff(t)))
    stats = {}
    for link in ("coupler", "rocker"):
        d, h = sensors[link]
        column = next(c for c in head if c.startswith(f"{link}_acc_"))
        x = band(body[:, head.index(column)], fs)
        angle = deg - deg[0]
        turns = [np.interp(k * 360.0 + np.arange(720) * 0.5, angle, x) for k in range(1, TURNS - 1)]
        stats[link] = statistics(turns)
    with open(os.path.join(out, "impacts.csv")) as f:
        impacts = [r for r in csv.DictReader(f)
                   if float(r["time_s"]) >= t[0] and float(r["approach_speed_m_s"]) > 1e-3]
    return stats, len(impacts) / TURNS


def main(argv):
    fourbar, work = argv[0], os.path.abspath(argv[1])
    seed = argv[2] if len(argv) > 2 else "505"
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    rig_uniform = os.path.join(work, "rig_uniform.toml")
    uniform_rig(rig_uniform)
    session = os.path.join(work, "generator")
    subprocess.run([sys.executable, "-W", "ignore", os.path.join(HERE, "make_session.py"), "--out", session,
                    "--rig", rig_uniform, "--recording", f"{RPM:g}:{CLEARANCE_MM}", "--turns", str(TURNS),
                    "--warmup-turns", str(WARMUP), "--restitution", str(RESTITUTION), "--prior", "truth",
                    "--vibration", "--vibration-coupling", "two-way", "--snr-db", "80", "--hum-mV", "0",
                    "--seed", seed], check=True)
    with open(os.path.join(session, "truth", "truth.json")) as f:
        truth = json.load(f)
    args = truth["arguments"]
    name, rec = next(iter(truth["recordings"].items()))
    with open(os.path.join(session, os.path.splitext(rec["file"])[0] + ".toml"), "rb") as f:
        manifest = tomllib.load(f)
    manifest["_wav"] = rec["file"]
    sensors = {}
    for c in manifest["channel"]:
        for link in ("coupler", "rocker"):
            if c["role"] == f"{link}_tangential":
                sensors[link] = (c["position_mm"], c["offset_mm"])

    sys.path.insert(0, HERE)
    from links import pinned_free_roots  # noqa: E402
    b1 = pinned_free_roots(1)[0]
    rig_elastic = os.path.join(work, "rig_uniform_elastic.toml")
    shutil.copy(rig_uniform, rig_elastic)
    with open(rig_elastic, "a") as f:
        for link, f1 in (("coupler", args["coupler_mode_hz"]), ("rocker", args["rocker_mode_hz"])):
            freqs = [round(f1 * (k * math.pi / b1) ** 2, 2) for k in range(1, args["modes"] + 1)]
            f.write(f"\n[{link}.elastic]\nmode_frequencies_Hz = {freqs}\n"
                    f"damping_ratios = {[args['damping_ratio']] * args['modes']}\n")

    gen = generator_stats(session, manifest)
    stiffness = rec["contact_stiffness_N_m1p5"]
    elastic, elastic_impacts = fourbar_run(fourbar, work, "elastic", rig_elastic, True, stiffness, sensors)
    rigid, rigid_impacts = fourbar_run(fourbar, work, "rigid", rig_uniform, False, stiffness, sensors)

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

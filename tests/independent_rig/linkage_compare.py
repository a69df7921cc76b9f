"""What check_elastic.py and check_friction.py share: a generator session's
tangential accelerometers cut into crank turns, and `fourbar sim` of the
linkage model on the same rig cut alike.

Turns are 720 points each (0.5°). The generator's start at its crank
pulse's falling edge (the manifest's crank_offset_deg past the zero, the
RC's 10 µs lag is 0.02° at 350 rpm), located to a fraction of a sample;
fourbar's at the same crank angle. Signals are in m/s² (the manifest's
sensitivity and gain undone).
"""
import csv
import json
import os
import subprocess
import sys
import tomllib

import numpy as np
import scipy.io.wavfile
import scipy.signal

LINKS = ("coupler", "rocker")
POINTS = 720
SAMPLES_PER_TURN = 3600   # fourbar_sim's series: 21 kHz at 350 rpm


def band(x, fs, band_hz):
    """Zero-phase Butterworth band-pass (4th order each way)."""
    sos = scipy.signal.butter(4, band_hz, "bandpass", fs=fs, output="sos")
    return scipy.signal.sosfiltfilt(sos, x)


def read_session(session):
    """(truth's arguments, its one recording's truth, the manifest) of a one-recording session."""
    with open(os.path.join(session, "truth", "truth.json")) as f:
        truth = json.load(f)
    rec = next(iter(truth["recordings"].values()))
    with open(os.path.join(session, os.path.splitext(rec["file"])[0] + ".toml"), "rb") as f:
        manifest = tomllib.load(f)
    return truth["arguments"], rec, manifest


def make_generator_session(work, rig, rpm, clearance_mm, turns, warmup, restitution, extra, seed):
    """Runs make_session.py into WORK/generator (one recording, the true prior,
    80 dB SNR and no hum: physics, not the DAQ's noise); returns (session,
    truth's arguments, the recording's truth, manifest, {link: (position_mm,
    offset_mm)} of the tangential sensors, the crank pulse's crank_offset_deg)."""
    session = os.path.join(work, "generator")
    subprocess.run([sys.executable, "-W", "ignore", os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                                  "make_session.py"),
                    "--out", session, "--rig", rig, "--recording", f"{rpm:g}:{clearance_mm}", "--turns", str(turns),
                    "--warmup-turns", str(warmup), "--restitution", str(restitution), "--prior", "truth",
                    "--snr-db", "80", "--hum-mV", "0", "--seed", str(seed)] + extra, check=True)
    args, rec, manifest = read_session(session)
    sensors = {link: (c["position_mm"], c["offset_mm"]) for link, c in tangential(manifest).items()}
    offset_deg = next(c for c in manifest["channel"] if c["role"] == "crank_pulse")["crank_offset_deg"]
    return session, args, rec, manifest, sensors, offset_deg


def tangential(manifest):
    """{link: the manifest's tangential channel of that link}."""
    return {link: next(c for c in manifest["channel"] if c["role"] == f"{link}_tangential") for link in LINKS}


def generator_turns(session, rec, manifest, band_hz, count):
    """{link: `count` turns of its band-passed signal}, from the second whole turn on."""
    fs, data = scipy.io.wavfile.read(os.path.join(session, rec["file"]))
    volts = data.astype(float) / 2 ** 31 * manifest["full_scale_V"]   # 24-bit WAV read left-justified
    pulse = volts[:, next(c["index"] for c in manifest["channel"] if c["role"] == "crank_pulse")]
    mid = 0.5 * (pulse.max() + pulse.min())
    i = np.where((pulse[:-1] > mid) & (pulse[1:] <= mid))[0]
    edges = i + (pulse[i] - mid) / (pulse[i] - pulse[i + 1])
    if len(edges) < count + 2:
        raise SystemExit(f"FAIL: {session}: {len(edges) - 1} turns between crank pulses, {count + 1} needed")
    out = {}
    for link, c in tangential(manifest).items():
        x = band(volts[:, c["index"]] * 1000.0 / (c["sensitivity_mV_per_m_s2"] * c["gain"]), fs, band_hz)
        grid = np.arange(len(x))
        out[link] = [np.interp(np.linspace(a, b, POINTS, endpoint=False), grid, x)
                     for a, b in zip(edges[1:count + 1], edges[2:count + 2])]
    return out


def fourbar_sim(fourbar, work, name, rig_file, rpm, turns, warmup, linkage_keys, sensors):
    """Runs `fourbar sim` of a linkage scene (SAMPLES_PER_TURN, constant
    speed); returns (crank_deg, {link: sensor column}, impacts after the warm-up)."""
    scene = os.path.join(work, f"{name}.toml")
    keys = "".join(f"{k} = {v}\n" for k, v in linkage_keys.items())
    with open(scene, "w") as f:
        f.write(f'rig = "{rig_file}"\nmodel = "linkage"\ncrank_speed_rpm = {rpm}\nstart_angle_deg = 0.0\n'
                f'revolutions = {turns}\nsamples_per_revolution = {SAMPLES_PER_TURN}\noutputs = ["time_s"]\n\n[linkage]\n{keys}'
                f'coupler_sensors_mm = [{sensors["coupler"][0]}, {sensors["coupler"][1]}]\n'
                f'rocker_sensors_mm = [{sensors["rocker"][0]}, {sensors["rocker"][1]}]\n')
    out = os.path.join(work, f"out_{name}")
    rc = subprocess.run([fourbar, "sim", scene, "--out", out, "--warmup-turns", str(warmup)],
                        stdout=subprocess.DEVNULL).returncode
    if rc != 0:
        raise SystemExit(f"fourbar sim {scene} exited {rc}")
    with open(os.path.join(out, "series.csv")) as f:
        rows = list(csv.reader(f))
    head, body = rows[0], np.array(rows[1:], dtype=float)
    columns = {link: body[:, head.index(next(c for c in head if c.startswith(f"{link}_acc_")))] for link in LINKS}
    t0 = body[0, head.index("time_s")]
    with open(os.path.join(out, "impacts.csv")) as f:
        impacts = [r for r in csv.DictReader(f) if float(r["time_s"]) >= t0]
    return body[:, head.index("crank_deg")], columns, impacts


def fourbar_turns(deg, x, offset_deg, count):
    """`count` turns of x, each from offset_deg past a whole turn, from the second whole turn on."""
    first = np.ceil((deg[0] - offset_deg) / 360.0) * 360.0 + offset_deg
    return [np.interp(first + k * 360.0 + np.arange(POINTS) * 360.0 / POINTS, deg, x) for k in range(1, count + 1)]


def impacts_per_turn(impacts, turns, faster_than_m_s=1e-3):
    return sum(float(r["approach_speed_m_s"]) > faster_than_m_s for r in impacts) / turns

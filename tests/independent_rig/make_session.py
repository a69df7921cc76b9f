#!/usr/bin/python3
"""Writes a session folder that `fourbar report` and `fourbar fit` read as is:
recordings (24-bit WAV), each with its manifest, session.toml with a chosen
prior, the rig file (rig/) and the truth (truth/truth.json).

An independent generator: see README.md in this folder for how its physics,
sensors and DAQ differ from fourbar's virtual rig.
"""
import argparse
import json
import math
import os
import shutil
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bearing import ClearanceLinkage, Contact, CrankMotion  # noqa: E402
from links import BeamModes  # noqa: E402
from rig import load_rig  # noqa: E402
from sensors import (Daq, Pulse, Sensor, adc, condition, hum, pulse_fine,  # noqa: E402
                     rigid_specific_force, to_samples)
from writers import write_manifest, write_session_toml, write_wav24  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_RIG = os.path.normpath(os.path.join(HERE, "..", "..", "data", "rigs", "thesis.toml"))


def default_sensors(args):
    """Where this generator's lab put its sensors (not the sample session's)."""
    common = dict(sensitivity_mV_per_m_s2=args.sensitivity, gain=args.gain,
                  resonance_hz=args.sensor_resonance_hz, resonance_q=args.sensor_resonance_q)
    return [
        Sensor("cpl_t", "coupler_tangential", 0.280, 0.015, 1, highpass_hz=1.0, **common),
        Sensor("cpl_n", "coupler_normal", 0.280, 0.015, -1, highpass_hz=1.0, **common),
        Sensor("rkr_t", "rocker_tangential", 0.295, -0.012, 1, highpass_hz=0.2, **common),
    ]


def band_rms(x, fs, hi_hz, lo_hz=0.5):
    spec = np.fft.rfft(x - x.mean())
    f = np.fft.rfftfreq(len(x), 1.0 / fs)
    spec[(f > hi_hz) | (f < lo_hz)] = 0.0
    return float(np.sqrt(np.mean(np.fft.irfft(spec, len(x)) ** 2)))


def one_recording(args, rig, rpm, clearance_m, index, out_dir):
    rng = np.random.default_rng(args.seed * 1000 + index)
    daq = Daq(sample_rate_hz=args.sample_rate, oversample=args.oversample, adc_bits=args.adc_bits,
              snr_db=args.snr_db, hum_mV=args.hum_mV, anti_alias=args.anti_alias,
              multiplexed_skew_s=args.skew_us * 1e-6)
    fs, fs_fine = daq.sample_rate_hz, daq.sample_rate_hz * daq.oversample
    h = 1.0 / fs_fine
    crank = CrankMotion(rpm, args.wander_pct, args.wander_period_s,
                        theta0_rad=rng.uniform(0, 2 * math.pi))
    contact = Contact(args.restitution, args.friction, pin_radius_m=args.pin_radius_mm * 1e-3,
                      friction_at=args.friction_at)
    modes = {
        "coupler": BeamModes(rig.coupler.length_m, rig.coupler.mass_kg, args.coupler_mode_hz,
                             args.damping_ratio, args.modes),
        "rocker": BeamModes(rig.rocker.length_m, rig.rocker.mass_kg, args.rocker_mode_hz,
                            args.damping_ratio, args.modes),
    }
    two_way = args.vibration and args.vibration_coupling == "two-way"
    model = ClearanceLinkage(rig, clearance_m, contact, crank,
                             beams=(modes["coupler"], modes["rocker"]) if two_way else None)
    period = 60.0 / rpm
    t_rec = args.warmup_turns * period
    preroll = max(args.preroll_s, 0.0)
    duration = (args.turns + 1.5) * period
    n_out = int(round(duration * fs))
    n_pre = int(round(preroll * fs))
    t0 = t_rec - n_pre / fs
    nodes = t0 + np.arange((n_pre + n_out) * daq.oversample + 1) * h
    started = time.time()
    y, _ = model.run(model.initial_state(), 0.0, t0)
    impacts_before = model.stats.impacts
    contacts_before = model.stats.contacts
    model.stats.approach_speeds.clear()
    y, states = model.run(y, t0, nodes[-1], nodes=nodes)
    sim_s = time.time() - started

    # interval means on the fine grid
    mid = 0.5 * (nodes[1:] + nodes[:-1])
    th3 = 0.5 * (states[1:, 0] + states[:-1, 0])
    th4 = 0.5 * (states[1:, 1] + states[:-1, 1])
    w3 = 0.5 * (states[1:, 2] + states[:-1, 2])
    w4 = 0.5 * (states[1:, 3] + states[:-1, 3])
    a3 = np.diff(states[:, 2]) / h
    a4 = np.diff(states[:, 3]) / h
    fx = np.diff(states[:, 4]) / h          # force on the coupler's pin
    fy = np.diff(states[:, 5]) / h
    th2, w2, a2 = crank.state(mid)
    f_cpl = -np.sin(th3) * fx + np.cos(th3) * fy      # across the coupler at its end
    f_rkr = np.sin(th4) * fx - np.cos(th4) * fy       # −F across the rocker
    sensors = default_sensors(args)
    g = rig.gravity_m_s2
    columns, twin_columns, stats_sensors = [], [], {}
    clipped = 0
    skip = n_pre
    for ch, s in enumerate(sensors):
        th, w, a = (th3, w3, a3) if s.link == "coupler" else (th4, w4, a4)
        rigid = rigid_specific_force(s, g, th2, w2, a2, rig.crank.length_m, th, w, a)
        bend = np.zeros_like(rigid)
        if s.tangential and two_way:
            # Σ φ_k(x)·q̈_k from the integrated modes (interval means, as α3, α4)
            n_c = modes["coupler"].count
            i0 = 6 if s.link == "coupler" else 6 + 2 * n_c
            n = modes[s.link].count
            bend = np.diff(states[:, i0 + n:i0 + 2 * n], axis=0) @ modes[s.link].shape(s.position_m) / h
        elif s.tangential and args.vibration:
            force = f_cpl if s.link == "coupler" else f_rkr
            bend = modes[s.link].acceleration(force, h, s.position_m)
        v_rigid = to_samples(condition(rigid, s, fs_fine), daq, ch)[skip:skip + n_out]
        v_bend = to_samples(condition(bend, s, fs_fine), daq, ch)[skip:skip + n_out] if args.vibration else 0 * v_rigid
        t_out = t_rec + np.arange(n_out) / fs + ch * daq.multiplexed_skew_s
        mains, white = hum(t_out, daq, rng), rng.normal(0.0, 10 ** (-daq.snr_db / 20), n_out)
        for v, cols in ((v_rigid + v_bend, columns), (v_rigid, twin_columns)):
            rms = float(np.sqrt(np.mean((v - v.mean()) ** 2)))
            q, clipped_here = adc(v + mains + rms * white, daq)
            cols.append(q)
            clipped = clipped_here if cols is columns else clipped
        r_full = float(np.sqrt(np.mean((v_rigid - v_rigid.mean()) ** 2)))
        b_full = float(np.sqrt(np.mean((v_bend - np.mean(v_bend)) ** 2)))
        stats_sensors[s.name] = {
            "role": s.role, "clipped_samples": clipped,
            "rigid_rms_V": r_full, "vibration_rms_V": b_full,
            "vibration_over_rigid_rms": b_full / r_full,
            "vibration_over_rigid_rms_below_1kHz": band_rms(v_bend, fs, 1000.0) / band_rms(v_rigid, fs, 1000.0)
            if args.vibration else 0.0,
        }
    pulse = Pulse(math.radians(args.pulse_angle_deg))
    p_fine, _falls = pulse_fine(nodes[:-1], crank, pulse)
    p = to_samples(p_fine, daq, len(sensors))[skip:skip + n_out]
    p += rng.normal(0.0, pulse.noise_mV * 1e-3, n_out)
    q, _ = adc(p, daq)
    columns.append(q)
    twin_columns.append(q)

    name = f"indep_{int(round(rpm))}rpm_{clearance_m * 1e3:.4f}mm".replace(".", "p")
    for folder, cols in ((out_dir, columns), (args.twin_out, twin_columns)):
        if folder is None:
            continue
        write_wav24(os.path.join(folder, name + ".wav"), np.stack(cols, axis=1), fs, daq.full_scale_V)
        write_manifest(os.path.join(folder, name + ".toml"), args, rig_rel="rig/" + os.path.basename(rig.path),
                       clearance_m=clearance_m, sensors=sensors, daq=daq, pulse=pulse)
    turns_recorded = duration / period
    speeds = np.array(model.stats.approach_speeds)
    return name, {
        "file": name + ".wav", "crank_speed_rpm": rpm, "clearance_mm": clearance_m * 1e3,
        "simulated_s": nodes[-1], "warmup_s": t_rec, "recorded_s": n_out / fs,
        "impacts_per_turn": (model.stats.impacts - impacts_before) / (turns_recorded + preroll / period),
        "contacts_per_turn": (model.stats.contacts - contacts_before) / (turns_recorded + preroll / period),
        "median_impact_speed_m_s": float(np.median(speeds)) if len(speeds) else 0.0,
        "max_impact_speed_m_s": float(speeds.max()) if len(speeds) else 0.0,
        "sensors": stats_sensors, "contact_stiffness_N_m1p5": model.K, "damping_factor_chi": model.chi,
        "compute_s": round(time.time() - started, 1), "integration_s": round(sim_s, 1),
    }


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", required=True, help="session folder to write (made; files in it replaced)")
    p.add_argument("--rig", default=DEFAULT_RIG)
    p.add_argument("--recording", action="append", metavar="RPM:CLEARANCE_MM",
                   help="one recording (repeat); default 250 and 350 rpm × 0.0254 and 0.254 mm")
    p.add_argument("--turns", type=float, default=25.0, help="crank turns recorded (default 25)")
    p.add_argument("--warmup-turns", type=float, default=20.0)
    p.add_argument("--preroll-s", type=float, default=1.6,
                   help="sensor chain run before the recording starts (AC coupling settles; inside the warm-up)")
    p.add_argument("--restitution", type=float, default=0.5)
    p.add_argument("--friction", type=float, default=0.0, help="Coulomb μ in every contact (0: smooth)")
    p.add_argument("--friction-at", choices=["always", "impacts"], default="always",
                   help='"always": μ acts in every contact; "impacts": only during an impact, as the thesis (not while the pin stays on the wall)')
    p.add_argument("--pin-radius-mm", type=float, default=0.0,
                   help="pin radius in the friction's slip speed and moments (0: a point pin, as the thesis)")
    p.add_argument("--prior", default="truth", help='session.toml [theory]: "truth" or e.g. "e=1" or "e=0.5,mu=0.2"')
    p.add_argument("--vibration", action="store_true", help="add the links' bending modes")
    p.add_argument("--vibration-coupling", choices=["one-way", "two-way"], default="one-way",
                   help='"one-way": the bearing force drives the modes, the bending does not move the bushing '
                        '(energy not paid by the contact: energy_budget.py); "two-way": the free ends\' '
                        'deflection is in the contact (bearing.py), the contact pays for the ringing')
    p.add_argument("--twin-out", help="also write the same session without the vibration (same motion and noise) here")
    p.add_argument("--coupler-mode-hz", type=float, default=600.0)
    p.add_argument("--rocker-mode-hz", type=float, default=520.0)
    p.add_argument("--damping-ratio", type=float, default=0.02)
    p.add_argument("--modes", type=int, default=3)
    p.add_argument("--sample-rate", type=int, default=25600)
    p.add_argument("--oversample", type=int, default=8)
    p.add_argument("--adc-bits", type=int, default=16)
    p.add_argument("--snr-db", type=float, default=30.0)
    p.add_argument("--hum-mV", type=float, default=1.5)
    p.add_argument("--sensitivity", type=float, default=1.0, help="mV per m/s² (B&K 4371 + 2635 at 1 mV/pC)")
    p.add_argument("--gain", type=float, default=1.0)
    p.add_argument("--sensor-resonance-hz", type=float, default=0.0,
                   help="every accelerometer's mounted resonance (0: none); not written in the manifests")
    p.add_argument("--sensor-resonance-q", type=float, default=30.0, help="its quality factor")
    p.add_argument("--anti-alias", default="sigma-delta", help='"sigma-delta" or "butterworth:ORDER:CORNER_HZ"')
    p.add_argument("--skew-us", type=float, default=0.0, help="multiplexed ADC: channel k sampled k·skew late")
    p.add_argument("--wander-pct", type=float, default=0.3)
    p.add_argument("--wander-period-s", type=float, default=2.7)
    p.add_argument("--pulse-angle-deg", type=float, default=12.0)
    p.add_argument("--seed", type=int, default=1)
    args = p.parse_args(argv)
    if args.vibration_coupling == "two-way" and not args.vibration:
        p.error("--vibration-coupling two-way couples the links' bending modes, which only --vibration adds; "
                "give --vibration as well (or leave the coupling out for rigid links)")
    if args.sensor_resonance_hz < 0 or args.sensor_resonance_q <= 0:
        p.error("--sensor-resonance-hz must be 0 (none) or above and --sensor-resonance-q above 0 "
                f"(got {args.sensor_resonance_hz} Hz, Q {args.sensor_resonance_q})")
    return args


def main(argv):
    args = parse_args(argv)
    rig = load_rig(args.rig)
    for folder in (args.out, args.twin_out):
        if folder is None:
            continue
        os.makedirs(os.path.join(folder, "rig"), exist_ok=True)
        os.makedirs(os.path.join(folder, "truth"), exist_ok=True)
        shutil.copyfile(args.rig, os.path.join(folder, "rig", os.path.basename(args.rig)))
    recs = args.recording or ["250:0.0254", "250:0.254", "350:0.0254", "350:0.254"]
    truth = {"generator": "tests/independent_rig/make_session.py", "arguments": vars(args), "recordings": {}}
    for i, spec in enumerate(recs):
        rpm, cl = (float(x) for x in spec.split(":"))
        name, info = one_recording(args, rig, rpm, cl * 1e-3, i, args.out)
        truth["recordings"][name] = info
        print(f"{name}: {info['impacts_per_turn']:.1f} impacts/turn, "
              f"vibration/rigid {[round(s['vibration_over_rigid_rms'], 2) for s in info['sensors'].values()]}, "
              f"{info['compute_s']} s", file=sys.stderr)
    write_session_toml(os.path.join(args.out, "session.toml"), args)
    with open(os.path.join(args.out, "truth", "truth.json"), "w") as f:
        json.dump(truth, f, indent=1)
    if args.twin_out:
        args.vibration = False
        write_session_toml(os.path.join(args.twin_out, "session.toml"), args)
        truth["arguments"] = vars(args)
        truth["twin_of"] = args.out
        for info in truth["recordings"].values():
            for sensor in info["sensors"].values():
                sensor["vibration_rms_V"] = sensor["vibration_over_rigid_rms"] = 0.0
                sensor["vibration_over_rigid_rms_below_1kHz"] = 0.0
        with open(os.path.join(args.twin_out, "truth", "truth.json"), "w") as f:
            json.dump(truth, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

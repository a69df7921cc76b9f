"""The files fourbar reads: a 24-bit WAV (Python's wave module), each
recording's manifest (docs/acquire.md's keys) and session.toml
(docs/report.md's keys)."""
import math
import wave

import numpy as np


def write_wav24(path, volts, fs, full_scale_V):
    """volts: samples × channels; ±full_scale_V is digital full scale."""
    full = 2 ** 23
    ints = np.clip(np.round(volts / full_scale_V * full), -full, full - 1).astype("<i4")
    raw = ints.reshape(-1).view(np.uint8).reshape(-1, 4)[:, :3].tobytes()
    with wave.open(path, "wb") as w:
        w.setnchannels(volts.shape[1])
        w.setsampwidth(3)
        w.setframerate(int(fs))
        w.writeframes(raw)


def _num(x):
    return repr(float(x))


def write_manifest(path, args, rig_rel, clearance_m, sensors, daq, pulse):
    lines = [
        "# Recording manifest (keys: docs/acquire.md). SYNTHETIC: written by",
        "# tests/independent_rig/make_session.py (compliant-contact clearance model,",
        "# not fourbar's virtual rig); the truth is in truth/truth.json.",
        f'rig = "{rig_rel}"',
        f"clearance_mm = {_num(clearance_m * 1e3)}",
        f"full_scale_V = {_num(daq.full_scale_V)}",
        'crank_direction = "ccw"',
        f'notes = "independent generator, seed {args.seed}"',
    ]
    for i, s in enumerate(sensors):
        lines += ["", "[[channel]]", f"index = {i}", f'name = "{s.name}"', f'role = "{s.role}"',
                  f"sensitivity_mV_per_m_s2 = {_num(s.sensitivity_mV_per_m_s2)}", f"gain = {_num(s.gain)}",
                  f"axis_sign = {s.axis_sign}", f"position_mm = {_num(s.position_m * 1e3)}",
                  f"offset_mm = {_num(s.offset_m * 1e3)}"]
        if s.highpass_hz > 0:
            lines += ["ac_coupled = true", f"highpass_hz = {_num(s.highpass_hz)}"]
        else:
            lines += ["ac_coupled = false"]
    lines += ["", "[[channel]]", f"index = {len(sensors)}", 'name = "tacho"', 'role = "crank_pulse"',
              'polarity = "falling"', f"crank_offset_deg = {_num(round(math.degrees(pulse.angle_rad), 9))}", ""]
    with open(path, "w") as f:
        f.write("\n".join(lines))


def prior_of(args):
    """(e, μ or None) for session.toml's [theory]."""
    if args.prior == "truth":
        return args.restitution, (args.friction if args.friction > 0 else None)
    e, mu = None, None
    for part in args.prior.split(","):
        key, value = part.split("=")
        if key.strip() == "e":
            e = float(value)
        elif key.strip() == "mu":
            mu = float(value)
        else:
            raise SystemExit(f"--prior: unknown key {key} (use e=…,mu=…)")
    if e is None:
        raise SystemExit("--prior needs e=…")
    return e, mu


def write_session_toml(path, args):
    e, mu = prior_of(args)
    truth = f"e = {args.restitution}, " + (f"stick-slip mu = {args.friction}" if args.friction > 0 else "smooth")
    lines = [
        "# SYNTHETIC session from tests/independent_rig/make_session.py (keys: docs/report.md).",
        f'title = "Independent generator: truth {truth}; prior {args.prior}"',
        f'notes = "compliant-contact clearance model{", link bending modes" if args.vibration else ""}; '
        f'truth in truth/truth.json"',
        "",
        "[analysis]",
        "mains_hz = 50",
        "",
        "[theory]",
        f"restitution = {e}",
    ]
    if mu is not None:
        lines += ['contact = "stick-slip"', f"friction_coefficient = {mu}"]
    else:
        lines += ['contact = "smooth"']
    lines += ["warmup_revolutions = 20", "averaged_revolutions = 20", ""]
    with open(path, "w") as f:
        f.write("\n".join(lines))

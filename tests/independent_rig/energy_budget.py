#!/usr/bin/env python3
"""The energy budget of make_session.py's link vibration (--vibration).

The generator drives each link's pinned–free bending modes one way with the
bearing force across the link (links.py): the bending does not move the
bushing, so the contact never pays for the energy the modes receive. This
script runs the generator's own clearance model (bearing.py) and measures,
over the same stretch a session records,

  * E_modes: the work the bearing force does on the modes,
    Σ_k ∫ φ_k(L)·F⊥(t)·q̇_k dt (what the modal damping then dissipates), and
  * E_rel: the relative kinetic energy the impacts bring,
    Σ_i ½·m_eff·v_i² over the impacts (approach speed v_i, m_eff the
    pair's effective mass at B, I_A/L3² and I_O4/L4² in series),

and prints their ratio next to the short-impact estimate
m_eff·(1 + e)²·Σ_k φ_k(L)² a link (an impulse J = m_eff·(1 + e)·v much
shorter than a modal period gives mode k the energy ½·(φ_k(L)·J)²). In a
model whose energy balances, E_modes cannot exceed the energy the impacts
lose, (1 − e²)·E_rel; a ratio above that means the generator's ringing is
stronger than any rig's with these impacts could be.

  python3 tests/independent_rig/energy_budget.py [--rpm 350] [--clearance-mm 0.254]
      [--restitution 0.5] [--turns 10] [--seed 505]
"""
import argparse
import math
import os
import sys

import numpy as np
from scipy.signal import lsim

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bearing import ClearanceLinkage, Contact, CrankMotion  # noqa: E402
from links import BeamModes  # noqa: E402
from rig import load_rig  # noqa: E402


def modal_work(force_N, dt_s, modes: BeamModes) -> tuple[float, float]:
    """Σ_k ∫ φ_k(L)·F(t)·q̇_k dt for the force held over each step (exact for
    the held force: φ_k(L)·F_n·(q_k,n+1 − q_k,n)), and the modal damping's
    dissipation Σ_k ∫ 2ζω_k·q̇_k² dt beside it (equal but for the modes'
    energy change over the record)."""
    tip = modes.shape(modes.length_m)
    w = 2.0 * math.pi * modes.frequencies_hz()
    t = np.arange(len(force_N) + 1) * dt_s
    f = np.concatenate([force_N, [0.0]])
    work = dissipated = 0.0
    for k in range(modes.count):
        a = np.array([[0.0, 1.0], [-w[k] ** 2, -2.0 * modes.damping_ratio * w[k]]])
        b = np.array([[0.0], [tip[k]]])
        _, _, x = lsim((a, b, np.eye(2), np.zeros((2, 1))), f, t, interp=False)
        work += float(np.sum(tip[k] * force_N * np.diff(x[:, 0])))
        dissipated += float(np.sum(2.0 * modes.damping_ratio * w[k] * x[:, 1] ** 2) * dt_s)
    return work, dissipated


def main() -> int:
    here = os.path.dirname(os.path.abspath(__file__))
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--rig", default=os.path.join(here, "..", "..", "data", "rigs", "thesis.toml"))
    p.add_argument("--rpm", type=float, default=350.0)
    p.add_argument("--clearance-mm", type=float, default=0.254)
    p.add_argument("--restitution", type=float, default=0.5)
    p.add_argument("--turns", type=float, default=10.0)
    p.add_argument("--warmup-turns", type=float, default=20.0)
    p.add_argument("--coupler-mode-hz", type=float, default=600.0)
    p.add_argument("--rocker-mode-hz", type=float, default=520.0)
    p.add_argument("--damping-ratio", type=float, default=0.02)
    p.add_argument("--modes", type=int, default=3)
    p.add_argument("--rate-hz", type=float, default=204800.0, help="force sampling (the generator's fine grid)")
    p.add_argument("--seed", type=int, default=505)
    args = p.parse_args()
    if not (args.turns > 0 and args.rpm > 0 and args.clearance_mm > 0 and 0 < args.restitution <= 1):
        print("energy_budget.py: --turns, --rpm, --clearance-mm must be > 0 and --restitution in (0, 1]",
              file=sys.stderr)
        return 2

    rig = load_rig(args.rig)
    rng = np.random.default_rng(args.seed)
    crank = CrankMotion(args.rpm, theta0_rad=rng.uniform(0, 2 * math.pi))
    model = ClearanceLinkage(rig, args.clearance_mm * 1e-3, Contact(args.restitution), crank)
    period = 60.0 / args.rpm
    t0, t1 = args.warmup_turns * period, (args.warmup_turns + args.turns) * period
    y, _ = model.run(model.initial_state(), 0.0, t0)
    model.stats.approach_speeds.clear()
    dt = 1.0 / args.rate_hz
    nodes = t0 + np.arange(int(round((t1 - t0) / dt)) + 1) * dt
    y, states = model.run(y, t0, nodes[-1], nodes=nodes)
    th3 = 0.5 * (states[1:, 0] + states[:-1, 0])
    th4 = 0.5 * (states[1:, 1] + states[:-1, 1])
    fx, fy = np.diff(states[:, 4]) / dt, np.diff(states[:, 5]) / dt
    f_cpl = -np.sin(th3) * fx + np.cos(th3) * fy
    f_rkr = np.sin(th4) * fx - np.cos(th4) * fy

    cp, rk = rig.coupler, rig.rocker
    m_c = cp.inertia_about_joint_kg_m2 / cp.length_m ** 2
    m_r = rk.inertia_about_joint_kg_m2 / rk.length_m ** 2
    m_eff = 1.0 / (1.0 / m_c + 1.0 / m_r)
    speeds = np.array(model.stats.approach_speeds)
    e_rel = float(np.sum(0.5 * m_eff * speeds ** 2))
    e = args.restitution
    print(f"{args.turns:g} turns at {args.rpm:g} rpm, clearance {args.clearance_mm:g} mm, e = {e:g}: "
          f"{len(speeds)} impacts, median approach {np.median(speeds) if len(speeds) else 0:.4f} m/s; "
          f"m_eff at B {m_eff:.4f} kg (coupler {m_c:.4f}, rocker {m_r:.4f})")
    print(f"relative kinetic energy the impacts bring, E_rel = {e_rel:.4e} J; "
          f"an energy-balanced impact loses at most (1 - e^2)·E_rel = {(1 - e * e) * e_rel:.4e} J")
    total = 0.0
    for name, link, f1, force in (("coupler", cp, args.coupler_mode_hz, f_cpl),
                                  ("rocker", rk, args.rocker_mode_hz, f_rkr)):
        modes = BeamModes(link.length_m, link.mass_kg, f1, args.damping_ratio, args.modes)
        work, dissipated = modal_work(force, dt, modes)
        estimate = m_eff * (1 + e) ** 2 * float(np.sum(modes.shape(link.length_m) ** 2))
        total += work
        print(f"{name}: modes {np.round(modes.frequencies_hz(), 1).tolist()} Hz, work on them {work:.4e} J "
              f"= {work / e_rel:.2f} E_rel (modal damping {dissipated:.4e} J; short-impact estimate "
              f"{estimate:.2f} E_rel)")
    print(f"both links: {total / e_rel:.2f} E_rel, {total / ((1 - e * e) * e_rel):.2f}× what the impacts can lose")
    return 0


if __name__ == "__main__":
    sys.exit(main())

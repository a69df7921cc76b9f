#!/usr/bin/python3
"""CTest independent_rig_selftest: the generator's parts against closed
forms (exit 1 on a failure, 77 without scipy).

- the contact law rebounds with the e it was calibrated for;
- free flight: α3 = m3·S3·[l2·ω2²·sin(θ2−θ3) − g·cos θ3] / I_A3 (thesis
  4.1-20 as corrected) and α4 = −m4·g·S4·cos θ4 / I_O4;
- a pin pressed into the wall: the rocker's moment equals (C4 − O4) × F_n·n;
- the bending modes ring at the pinned–free beam's frequencies;
- two-way bending: the free ends' deflection enters the contact, whose
  power on the links' relative motion is then the modes' (energy paid by
  the contact, which the one-way drive does not do: energy_budget.py);
- the crank pulse's falling edge crosses mid-level at the marked angle
  (within the RC's ln 2·τ lag).
"""
import math
import os
import sys

try:
    import numpy as np
except ImportError:
    print("independent_rig_selftest: skipped: no numpy/scipy for", sys.executable)
    sys.exit(77)
try:
    import scipy  # noqa: F401
except ImportError:
    print("independent_rig_selftest: skipped: no scipy for", sys.executable)
    sys.exit(77)

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from bearing import ClearanceLinkage, Contact, CrankMotion, damping_factor, restitution_of  # noqa: E402
from links import BeamModes  # noqa: E402
from rig import load_rig, nominal_rates  # noqa: E402
from sensors import Pulse, pulse_fine  # noqa: E402

failures = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what)
    if not ok:
        failures.append(what)


rig = load_rig(os.path.join(HERE, "..", "..", "data", "rigs", "thesis.toml"))

for e in (0.2, 0.5, 0.8):
    got = restitution_of(damping_factor(e))
    check(abs(got - e) < 1e-6, f"contact law rebounds with e = {e}: {got:.9f}")

crank = CrankMotion(350.0)
model = ClearanceLinkage(rig, 0.254e-3, Contact(0.5), crank)
t = 0.0123
th2, w2, _a2 = crank.state(t)
t3, t4, w3, w4, _, _ = nominal_rates(rig, th2, w2, 0.0)
y = [t3, t4, w3, w4, 0.0, 0.0]           # pin at the bushing centre: no contact
d = model.rhs(t, y)
cp, rk, g = rig.coupler, rig.rocker, rig.gravity_m_s2
a3 = cp.mass_kg * cp.mass_centre_m * (rig.crank.length_m * w2 ** 2 * math.sin(th2 - t3) - g * math.cos(t3)) \
    / cp.inertia_about_joint_kg_m2
a4 = -rk.mass_kg * g * rk.mass_centre_m * math.cos(t4) / rk.inertia_about_joint_kg_m2
check(abs(d[2] - a3) < 1e-9 * abs(a3), f"free-flight α3 = {d[2]:.6f} (thesis 4.1-20: {a3:.6f})")
check(abs(d[3] - a4) < 1e-9 * abs(a4), f"free-flight α4 = {d[3]:.6f} (closed form: {a4:.6f})")

# press the rocker's bushing so the pin penetrates by 1 µm along the rocker
y2 = list(y)
y2[1] = t4 + (0.254e-3 + 1e-6) / rk.length_m  # bushing swung across: |d| ≈ ξ + 1 µm
y2[3] = w4 = 0.0
y2[2] = 0.0
b, vb, cc, vc, _a, _ = model.geometry(t, y2)
fx, fy, nx, ny = model.contact_force(b, vb, cc, vc, 0.0, 0.0)
dx, dy = b[0] - cc[0], b[1] - cc[1]
r = math.hypot(dx, dy)
delta = r - 0.254e-3
ddot = ((vb[0] - vc[0]) * dx + (vb[1] - vc[1]) * dy) / r
fn = model.K * delta ** 1.5 * max(1 + model.chi * ddot / model.v0, 0.0)
check(abs(math.hypot(fx, fy) - fn) < 1e-9 * fn, f"contact force |F| = {math.hypot(fx, fy):.4f} N = K·δ^1.5·(1+χδ̇/v0)")
d2 = model.rhs(t, y2)
qx, qy = rk.length_m * math.cos(y2[1]) + 0.254e-3 * nx, rk.length_m * math.sin(y2[1]) + 0.254e-3 * ny
m4 = -(qx * fy - qy * fx) - rk.mass_kg * g * rk.mass_centre_m * math.cos(y2[1])
check(abs(d2[3] * rk.inertia_about_joint_kg_m2 - m4) < 1e-9 * abs(m4), "rocker moment of the contact force")

# two-way bending: the free ends' deflection is in the contact, and the
# contact's power on the relative motion is the modes' (links at rest):
# F·(v_B − v_A − v_C) = Σ φ_k(L)·(F·n3)·q̇_k + Σ φ_k(L)·(−F·n4)·q̇_k
beams = (BeamModes(cp.length_m, cp.mass_kg, 600.0, 0.02), BeamModes(rk.length_m, rk.mass_kg, 520.0, 0.02))
two = ClearanceLinkage(rig, 0.254e-3, Contact(0.5), crank, beams=beams)
y3 = np.zeros(two.size)
y3[:6] = y2
rng = np.random.default_rng(3)
n_c, n_r = beams[0].count, beams[1].count
y3[6:6 + n_c] = rng.normal(0, 2e-9, n_c)                        # q (tip deflections ~1e-8 m)
y3[6 + n_c:6 + 2 * n_c] = rng.normal(0, 2e-3, n_c)              # q̇
y3[6 + 2 * n_c:6 + 2 * n_c + n_r] = rng.normal(0, 2e-9, n_r)
y3[6 + 2 * n_c + n_r:] = rng.normal(0, 2e-3, n_r)
b3, vb3, cc3, vc3, _a, (c3, s3, c4, s4) = two.geometry(t, y3)
w3_tip = float(np.dot(two.tip_c, y3[6:6 + n_c]))
check(abs(b3[0] - (b[0] - w3_tip * s3)) < 1e-15 and abs(b3[1] - (b[1] + w3_tip * c3)) < 1e-15,
      f"two-way: the coupler's end moved {w3_tip * 1e9:.2f} nm across the link")
fx3, fy3, _nx, _ny = two.contact_force(b3, vb3, cc3, vc3, 0.0, 0.0)
l2 = rig.crank.length_m
va = (-l2 * w2 * math.sin(th2), l2 * w2 * math.cos(th2))
p_contact = fx3 * (vb3[0] - va[0] - vc3[0]) + fy3 * (vb3[1] - va[1] - vc3[1])
d3 = two.rhs(t, y3)
f3, f4 = -s3 * fx3 + c3 * fy3, s4 * fx3 - c4 * fy3
p_modes = f3 * float(np.dot(two.tip_c, y3[6 + n_c:6 + 2 * n_c])) + \
    f4 * float(np.dot(two.tip_r, y3[6 + 2 * n_c + n_r:]))
check(abs(p_contact - p_modes) < 1e-9 * abs(p_modes) and abs(p_modes) > 0,
      f"two-way: the contact's power {p_contact:.6e} W is the modes' {p_modes:.6e} W (one way would give 0)")
i_r = 6 + 2 * n_c
want = -2 * 0.02 * two.w_r * y3[i_r + n_r:] - two.w_r ** 2 * y3[i_r:i_r + n_r] + two.tip_r * f4
check(np.allclose(d3[i_r + n_r:], want, rtol=1e-12, atol=0), "two-way: the rocker's modes driven by −F·n4")

modes = BeamModes(cp.length_m, cp.mass_kg, 600.0, 0.01)
fs = 204800.0
force = np.zeros(int(fs * 0.5))
force[10] = fs * 1e-3                      # 1 mN·s in one step
acc = modes.acceleration(force, 1 / fs, 0.28)
spec = np.abs(np.fft.rfft(acc * np.hanning(len(acc))))
freq = np.fft.rfftfreq(len(acc), 1 / fs)
peaks = [freq[np.argmax(np.where(abs(freq - f0) < 0.2 * f0, spec, 0))] for f0 in modes.frequencies_hz()]
check(all(abs(p - f0) < 3.0 for p, f0 in zip(peaks, modes.frequencies_hz())),
      f"bending modes ring at {[round(p) for p in peaks]} Hz (beam: {[round(f) for f in modes.frequencies_hz()]})")

pulse = Pulse(math.radians(12.0))
tt = np.arange(0, 0.5, 1 / fs)
v, falls = pulse_fine(tt, crank, pulse)
mid = 0.5 * (pulse.high_V + pulse.low_V)
k = np.flatnonzero((v[:-1] > mid) & (v[1:] <= mid))
t_cross = tt[k] + (v[k] - mid) / (v[k] - v[k + 1]) / fs
lag = [tc - falls[np.argmin(abs(falls - tc))] for tc in t_cross]
want = pulse.edge_tau_s * math.log((pulse.high_V - pulse.low_V) / (mid - pulse.low_V))
check(len(lag) >= 2 and all(abs(x - want) < 0.5e-6 for x in lag),
      f"falling edges cross mid-level {np.mean(lag) * 1e6:.2f} µs after the mark (RC: {want * 1e6:.2f} µs)")

sys.exit(1 if failures else 0)

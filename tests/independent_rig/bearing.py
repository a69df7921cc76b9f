"""The linkage with a clearance at the coupler–rocker bearing, the contact
compliant (no impact mode): one set of equations for free flight, bounces
and persistent contact, integrated with scipy's solve_ivp.

Degrees of freedom: the crank's motion is prescribed (the motor and flywheel
hold its speed, thesis ch. 4-5), so the coupler is a pendulum pinned at the
moving crank pin A and the rocker one pinned at O4: q = (θ3, θ4). Euler's
equation about each link's pin (derived here, cf. THESIS-ERRATA 4.1-20):

  I_A3·α3 = −m3·S3·(n3·a_A) − m3·g·S3·cos θ3 + (P_pin − A) × F
  I_O4·α4 = −m4·g·S4·cos θ4 + (P_bush − O4) × (−F)

F is the force of the bushing on the pin. The eccentricity d = B3 − C4
(bushing centre to pin centre), penetration δ = |d| − ξ, normal n = d/|d|:

  F_n = K·δ^1.5·(1 + χ·δ̇/v0)⁺   (Hunt–Crossley form; v0 the approach speed
        at the contact's onset, at least v_floor; no adhesion)
  F   = −F_n·n + f·t,  t = n turned +90°,
  f   = −μ·F_n·v_t/√(v_t² + v_reg²)   (regularised Coulomb, acting in every
        contact, bounce or persistent)

χ is calibrated so that a free two-body collision under this law rebounds
with exactly the restitution e (the dimensionless law x'' = −x^1.5·(1+χx')⁺
has no other parameter, so one χ serves every mass and speed).

Bending, two way (`beams`, make_session.py --vibration-coupling two-way):
each link's pinned–free modes (links.py, mass-normalised φ_k, ω_k, ζ) move
its free end across the link by w = Σ φ_k(L)·q_k, so the pin centre is
B = A + L3·u3 + w3·n3 and the bushing centre C = O4 + L4·u4 + w4·n4
(n = u turned +90°), and the contact force drives the modes it depends on:

  q̈_k + 2ζω_k·q̇_k + ω_k²·q_k = φ_k(L)·(F·n3)   (coupler; the rocker: −F·n4)

The contact's power F·(v_B − v_C) is then the rigid links' plus the modes'
(the modes are orthogonal to the rigid rotation about the pin), so the
energy the modes ring with is paid by the contact. Left out, as small
against the contact's: the bending's rotary and centrifugal coupling with
the link's rotation and the crank pin's acceleration driving the coupler's
modes; the Euler equations keep the rigid moment arms.
"""
from dataclasses import dataclass, field
import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from rig import Rig, nominal_rates


@dataclass
class Contact:
    restitution: float
    friction: float = 0.0            # Coulomb μ (0: smooth)
    stiffness_N_m15: float = 0.0     # K; 0: from the pin/bushing materials
    pin_radius_m: float = 0.0        # 0: a point pin (the thesis's contact geometry)
    v_floor_m_s: float = 1e-3        # least approach speed in the damping term
    v_reg_m_s: float = 1e-4          # friction regularisation speed
    friction_at: str = "always"      # "always": every contact; "impacts": as the thesis's
                                     # stick-slip model, during an impact's compression and
                                     # restitution only (not while the pin then stays on the wall)


def hertz_stiffness(clearance_m: float, pin_radius_m: float = 6.35e-3) -> float:
    """K of the cylindrical-joint Hertz law used by Lankarani and Flores:
    K = 4/(3π(σp+σb))·√(Rp·Rb/(Rb−Rp)), σ = (1−ν²)/(πE); a steel pin in an
    oil-impregnated brass bushing (thesis sec. 7.1), ½-inch pin."""
    sig_p = (1 - 0.29 ** 2) / (math.pi * 207e9)
    sig_b = (1 - 0.34 ** 2) / (math.pi * 100e9)
    rb = pin_radius_m + clearance_m
    return 4.0 / (3.0 * math.pi * (sig_p + sig_b)) * math.sqrt(pin_radius_m * rb / clearance_m)


def restitution_of(chi: float) -> float:
    """Rebound/approach speed of x'' = −x^1.5·(1 + χ·x')⁺, x(0) = 0, x'(0) = 1."""
    def rhs(_t, s):
        return [s[1], -max(s[0], 0.0) ** 1.5 * max(1.0 + chi * s[1], 0.0)]

    def out(_t, s):
        return s[0]
    out.terminal, out.direction = True, -1
    sol = solve_ivp(rhs, (0.0, 1e3), [0.0, 1.0], method="DOP853", events=out,
                    rtol=1e-10, atol=1e-12, first_step=1e-6, max_step=0.05)
    return -sol.y_events[0][0][1]


def damping_factor(restitution: float) -> float:
    """χ such that restitution_of(χ) = e."""
    if restitution >= 1.0:
        return 0.0
    if not 0.0 < restitution:
        raise SystemExit("restitution must be in (0, 1]")
    return brentq(lambda c: restitution_of(c) - restitution, 0.0, 1e3, xtol=1e-7)


class CrankMotion:
    """ω2(t) = ω0·(1 + ε·sin(2πt/T)): a slow speed wander the pulses follow."""

    def __init__(self, rpm: float, wander_pct: float = 0.0, wander_period_s: float = 3.0,
                 theta0_rad: float = 0.0):
        self.w0 = rpm * 2.0 * math.pi / 60.0
        self.eps = wander_pct / 100.0
        self.k = 2.0 * math.pi / wander_period_s
        self.theta0 = theta0_rad

    def state(self, t):
        if isinstance(t, float):
            s, c = math.sin(self.k * t), math.cos(self.k * t)
        else:
            s, c = np.sin(self.k * t), np.cos(self.k * t)
        theta = self.theta0 + self.w0 * t + self.w0 * self.eps * (1.0 - c) / self.k
        return theta, self.w0 * (1.0 + self.eps * s), self.w0 * self.eps * self.k * c

    def time_of_angle(self, theta):
        """t with θ2(t) = theta (monotone: Newton from the mean speed)."""
        t = (theta - self.theta0) / self.w0
        for _ in range(6):
            th, w, _a = self.state(t)
            t = t - (th - theta) / w
        return t


@dataclass
class Stats:
    contacts: int = 0
    impacts: int = 0                  # contacts entered faster than 1 mm/s
    max_approach_m_s: float = 0.0
    approach_speeds: list = field(default_factory=list)


class ClearanceLinkage:
    def __init__(self, rig: Rig, clearance_m: float, contact: Contact, crank: CrankMotion, beams=None):
        """beams: None (rigid links) or (coupler, rocker) BeamModes driven two way."""
        self.rig, self.xi, self.c, self.crank = rig, clearance_m, contact, crank
        self.beams = beams
        if beams is None:
            self.nc = self.nr = 0
        else:
            self.nc, self.nr = beams[0].count, beams[1].count
            self.tip_c = beams[0].shape(beams[0].length_m)
            self.tip_r = beams[1].shape(beams[1].length_m)
            self.w_c = 2.0 * math.pi * beams[0].frequencies_hz()
            self.w_r = 2.0 * math.pi * beams[1].frequencies_hz()
        self.size = 6 + 2 * (self.nc + self.nr)
        self.K = contact.stiffness_N_m15 or hertz_stiffness(clearance_m)
        self.chi = damping_factor(contact.restitution)
        self.v0 = contact.v_floor_m_s
        self.stats = Stats()
        self.fric_active = True
        if contact.friction_at not in ("always", "impacts"):
            raise SystemExit('friction_at must be "always" or "impacts"')
        cp, rk = rig.coupler, rig.rocker
        self.IA3, self.IO4 = cp.inertia_about_joint_kg_m2, rk.inertia_about_joint_kg_m2

    def geometry(self, t, y):
        """Pin and bushing centres and velocities, the crank pin's acceleration."""
        r = self.rig
        l1, l2, l3, l4 = r.ground_m, r.crank.length_m, r.coupler.length_m, r.rocker.length_m
        th2, w2, a2 = self.crank.state(t)
        c2, s2 = math.cos(th2), math.sin(th2)
        c3, s3 = math.cos(y[0]), math.sin(y[0])
        c4, s4 = math.cos(y[1]), math.sin(y[1])
        b = (l2 * c2 + l3 * c3, l2 * s2 + l3 * s3)
        vb = (-l2 * w2 * s2 - l3 * y[2] * s3, l2 * w2 * c2 + l3 * y[2] * c3)
        cc = (l1 + l4 * c4, l4 * s4)
        vc = (-l4 * y[3] * s4, l4 * y[3] * c4)
        if self.nc:
            # the free ends' deflection across the links, w·n, and its rate ẇ·n − w·θ̇·u
            nc, nr = self.nc, self.nr
            w3 = float(np.dot(self.tip_c, y[6:6 + nc]))
            w3d = float(np.dot(self.tip_c, y[6 + nc:6 + 2 * nc]))
            r0 = 6 + 2 * nc
            w4 = float(np.dot(self.tip_r, y[r0:r0 + nr]))
            w4d = float(np.dot(self.tip_r, y[r0 + nr:r0 + 2 * nr]))
            b = (b[0] - w3 * s3, b[1] + w3 * c3)
            vb = (vb[0] - w3d * s3 - w3 * y[2] * c3, vb[1] + w3d * c3 - w3 * y[2] * s3)
            cc = (cc[0] - w4 * s4, cc[1] + w4 * c4)
            vc = (vc[0] - w4d * s4 - w4 * y[3] * c4, vc[1] + w4d * c4 - w4 * y[3] * s4)
        a_a = (l2 * (-a2 * s2 - w2 * w2 * c2), l2 * (a2 * c2 - w2 * w2 * s2))
        return b, vb, cc, vc, a_a, (c3, s3, c4, s4)

    def contact_force(self, b, vb, cc, vc, w3, w4):
        dx, dy = b[0] - cc[0], b[1] - cc[1]
        r = math.hypot(dx, dy)
        delta = r - self.xi
        if delta <= 0.0:
            return 0.0, 0.0, 0.0, 0.0
        nx, ny = dx / r, dy / r
        rvx, rvy = vb[0] - vc[0], vb[1] - vc[1]
        ddot = nx * rvx + ny * rvy
        # numpy's power: a rejected trial stage of the explicit free-flight
        # step can carry a huge δ (two-way modes ringing at kHz); inf then
        # fails the step's error test instead of raising OverflowError
        fn = self.K * float(np.float64(delta) ** 1.5) * max(1.0 + self.chi * ddot / self.v0, 0.0)
        f = 0.0
        if self.c.friction > 0.0 and self.fric_active:
            rp = self.c.pin_radius_m
            vt = -ny * rvx + nx * rvy + rp * w3 - (rp + self.xi) * w4
            f = -self.c.friction * fn * vt / math.sqrt(vt * vt + self.c.v_reg_m_s ** 2)
        return -fn * nx - f * ny, -fn * ny + f * nx, nx, ny

    def rhs(self, t, y):
        r = self.rig
        cp, rk, g = r.coupler, r.rocker, r.gravity_m_s2
        b, vb, cc, vc, a_a, (c3, s3, c4, s4) = self.geometry(t, y)
        fx, fy, nx, ny = self.contact_force(b, vb, cc, vc, y[2], y[3])
        rp = self.c.pin_radius_m
        # moment arms: pin contact point from A, bushing contact point from O4
        px, py = cp.length_m * c3 + rp * nx, cp.length_m * s3 + rp * ny
        qx, qy = rk.length_m * c4 + (rp + self.xi) * nx, rk.length_m * s4 + (rp + self.xi) * ny
        n3_a = -s3 * a_a[0] + c3 * a_a[1]
        t3 = -cp.mass_kg * cp.mass_centre_m * (n3_a + g * c3) + (px * fy - py * fx)
        t4 = -rk.mass_kg * g * rk.mass_centre_m * c4 - (qx * fy - qy * fx)
        if not self.nc:
            return [y[2], y[3], t3 / self.IA3, t4 / self.IO4, fx, fy]
        out = np.empty(self.size)
        out[:6] = (y[2], y[3], t3 / self.IA3, t4 / self.IO4, fx, fy)
        f3 = -s3 * fx + c3 * fy           # across the coupler, on its pin
        f4 = s4 * fx - c4 * fy            # across the rocker, on its bushing (−F)
        i = 6
        for n, tip, w, zeta, f in ((self.nc, self.tip_c, self.w_c, self.beams[0].damping_ratio, f3),
                                   (self.nr, self.tip_r, self.w_r, self.beams[1].damping_ratio, f4)):
            q, qd = y[i:i + n], y[i + n:i + 2 * n]
            out[i:i + n] = qd
            out[i + n:i + 2 * n] = -2.0 * zeta * w * qd - w * w * q + tip * f
            i += 2 * n
        return out

    def gap_event(self, t, y):
        b, _vb, cc, _vc, _a, _ = self.geometry(t, y)
        return math.hypot(b[0] - cc[0], b[1] - cc[1]) - self.xi

    def approach_speed(self, t, y):
        b, vb, cc, vc, _a, _ = self.geometry(t, y)
        dx, dy = b[0] - cc[0], b[1] - cc[1]
        r = math.hypot(dx, dy)
        return ((vb[0] - vc[0]) * dx + (vb[1] - vc[1]) * dy) / r

    def initial_state(self):
        """The nominal motion at t = 0, the pin at the bushing's centre."""
        th2, w2, a2 = self.crank.state(0.0)
        t3, t4, w3, w4, _a3, _a4 = nominal_rates(self.rig, th2, w2, a2)
        y = np.zeros(self.size)
        y[:4] = (t3, t4, w3, w4)
        return y

    def run(self, y, t0, t1, nodes=None, rtol=1e-8):
        """Integrates from t0 to t1; returns the end state and, when nodes
        (sorted times in [t0, t1]) are given, the state at each (rows)."""
        out = None if nodes is None else np.empty((len(nodes), self.size))
        parts = [[1e-12, 1e-12, 1e-9, 1e-9, 1e-10, 1e-10]]
        for n in (self.nc, self.nr):    # mass-normalised q ~ tip deflection/4, q̇ ~ ω·q
            parts += [np.full(n, 1e-13), np.full(n, 1e-10)]
        atol = np.concatenate(parts)
        t = t0
        inside = self.gap_event(t, y) > 0.0
        k = 0
        new_phase = True
        while t < t1:
            # a hysteresis of 1e-11 m keeps each phase's start off its own root
            band = 1e-11 if inside else -1e-11

            def ev(tt, yy, band=band):
                return self.gap_event(tt, yy) + band
            ev.terminal, ev.direction = True, (-1.0 if inside else 1.0)
            if inside and new_phase:
                v = self.approach_speed(t, y)
                self.v0 = max(v, self.c.v_floor_m_s)
                self.stats.contacts += 1
                if v > 1e-3:
                    self.stats.impacts += 1
                    self.stats.approach_speeds.append(v)
                self.stats.max_approach_m_s = max(self.stats.max_approach_m_s, v)
                self.fric_active = self.c.friction_at == "always" or v > 1e-3
            events = [ev]
            if inside and self.fric_active and self.c.friction_at == "impacts" and self.c.friction > 0.0:
                def restituted(tt, yy):      # δ̇ back from receding to 0: the pin stays on the wall
                    return self.approach_speed(tt, yy)
                restituted.terminal, restituted.direction = True, 1.0
                events.append(restituted)
            try:
                sol = solve_ivp(self.rhs, (t, t1), y, method="LSODA" if inside else "DOP853",
                                events=events, dense_output=out is not None, rtol=rtol, atol=atol,
                                max_step=np.inf if inside else 1e-3)
            except ValueError:  # scipy's event bracketing failed at a grazing touch: step past it
                sol = solve_ivp(self.rhs, (t, min(t + 1e-6, t1)), y, method="LSODA",
                                dense_output=out is not None, rtol=rtol, atol=atol)
                sol.status = 1 if (self.gap_event(sol.t[-1], sol.y[:, -1]) > 0.0) != inside else 0
            if sol.status < 0:
                raise RuntimeError(sol.message)
            t_end = sol.t[-1]
            if out is not None:
                k2 = np.searchsorted(nodes, t_end, side="right")
                if k2 > k:
                    out[k:k2] = sol.sol(nodes[k:k2]).T
                k = k2
            y = sol.y[:, -1].copy()
            t = t_end
            new_phase = False
            if sol.status == 1:
                if len(events) > 1 and sol.t_events is not None and len(sol.t_events[1]):
                    self.fric_active = False   # the impact is over; the pin follows the wall
                else:
                    inside = not inside
                    new_phase = True
        if out is not None and k < len(nodes):
            out[k:] = y
        return y, out

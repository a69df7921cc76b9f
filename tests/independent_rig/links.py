"""Bending vibration of the coupler and the rocker, driven by the bearing force.

Each link is a uniform Euler–Bernoulli beam pinned at its first joint (the
crank pin A, the pivot O4) and free at the bearing end, in the frame that
turns with the link: the rigid rotation about the pin is the pinned–free
beam's zero-frequency mode, the bending modes are the others
(tan βL = tanh βL: βL = 3.9266, 7.0686, 10.2102, …; f_k ∝ (β_kL)²). The
stiffness is chosen by the first mode's frequency. The bearing force's
component across the link at the free end drives the modes (one way: the
bending does not move the bushing, so it does not change the contact);
each mode has viscous damping ratio ζ:

  q̈_k + 2ζω_k·q̇_k + ω_k²·q_k = φ_k(L)·F⊥(t),  ∫ μ φ_k² dx = 1

and a tangential accelerometer at x reads Σ φ_k(x)·q̈_k on top of the rigid
link's acceleration (an axial one reads nothing of it).
"""
from dataclasses import dataclass
import math

import numpy as np
from scipy.optimize import brentq
from scipy.signal import cont2discrete, lfilter


def pinned_free_roots(count: int) -> list[float]:
    """β_k·L of a pinned–free beam: roots of tan x = tanh x above 0."""
    roots = []
    for k in range(1, count + 1):
        lo, hi = k * math.pi + 1e-6, k * math.pi + math.pi / 2 - 1e-6
        roots.append(brentq(lambda x: math.tan(x) - math.tanh(x), lo, hi))
    return roots


@dataclass(frozen=True)
class BeamModes:
    length_m: float
    mass_kg: float
    first_mode_hz: float
    damping_ratio: float
    count: int = 3

    def frequencies_hz(self) -> np.ndarray:
        b = np.array(pinned_free_roots(self.count))
        return self.first_mode_hz * (b / b[0]) ** 2

    def shape(self, x_m: float) -> np.ndarray:
        """Mass-normalised φ_k(x), k = 1 … count (uniform line density)."""
        ll, mu = self.length_m, self.mass_kg / self.length_m
        out = []
        xs = np.linspace(0.0, ll, 4001)
        for bl in pinned_free_roots(self.count):
            beta = bl / ll

            def phi(x):
                return np.sin(beta * x) + math.sin(bl) / math.sinh(bl) * np.sinh(beta * x)
            norm = math.sqrt(mu * np.trapz(phi(xs) ** 2, xs))
            out.append(float(phi(x_m)) / norm)
        return np.array(out)

    def acceleration(self, force_across_N: np.ndarray, dt_s: float, x_sensor_m: float) -> np.ndarray:
        """Mean bending acceleration at x over each step, for the force across
        the link at its free end held over each step (exact discretisation)."""
        w = 2.0 * math.pi * self.frequencies_hz()
        tip, here = self.shape(self.length_m), self.shape(x_sensor_m)
        total = np.zeros(len(force_across_N) + 1)
        for k in range(self.count):
            a = np.array([[0.0, 1.0], [-w[k] ** 2, -2.0 * self.damping_ratio * w[k]]])
            b = np.array([[0.0], [tip[k]]])
            c = np.array([[0.0, 1.0]])            # output: the modal velocity
            ad, bd, cd, dd, _ = cont2discrete((a, b, c, np.zeros((1, 1))), dt_s, method="zoh")
            # transfer function of the discrete system (velocity after each step)
            num, den = _ss2tf(ad, bd, cd, dd)
            vel = lfilter(num, den, np.concatenate([force_across_N, [0.0]]))
            total += here[k] * vel
        return np.diff(total) / dt_s


def _ss2tf(a, b, c, d):
    from scipy.signal import ss2tf
    num, den = ss2tf(a, b, c, d)
    return num[0], den

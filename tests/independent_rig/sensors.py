"""What the accelerometers, the conditioning amplifier and the DAQ make of the
motion: specific force at each sensor (rigid links plus bending), the
sensor's mounted resonance, sensitivity and gain, AC coupling, mains hum,
noise, the DAQ's anti-alias filter (an ideal delay-compensated
sigma-delta decimator, or an analog Butterworth with its phase), the skew
of a multiplexed ADC, clipping and quantisation; and the crank pulse.

Everything is computed on a fine grid (rate × oversample); accelerations
are means over each fine step (velocity differences), so an impact's short
force pulse keeps its area.
"""
from dataclasses import dataclass, field
import math

import numpy as np
from scipy.signal import bilinear, butter, lfilter, lfilter_zi, resample_poly


@dataclass
class Sensor:
    name: str
    role: str                      # coupler_tangential, coupler_normal, rocker_tangential, rocker_normal
    position_m: float              # along the link from its first joint
    offset_m: float = 0.0          # across the link, + on the counter-clockwise side
    axis_sign: int = 1
    sensitivity_mV_per_m_s2: float = 1.0
    gain: float = 1.0
    highpass_hz: float = 0.0       # 0: DC-coupled
    resonance_hz: float = 0.0      # mounted resonance (0: none)
    resonance_q: float = 30.0

    @property
    def link(self) -> str:
        return self.role.split("_")[0]

    @property
    def tangential(self) -> bool:
        return self.role.endswith("tangential")


@dataclass
class Daq:
    sample_rate_hz: int = 25600
    oversample: int = 16
    full_scale_V: float = 10.0
    adc_bits: int = 16
    snr_db: float = 30.0
    hum_hz: float = 49.97
    hum_mV: float = 1.5
    hum_harmonics: list = field(default_factory=lambda: [1.0, 0.4, 0.15])
    anti_alias: str = "sigma-delta"   # or "butterworth:ORDER:CORNER_HZ"
    multiplexed_skew_s: float = 0.0   # channel k sampled k·skew after channel 0


@dataclass
class Pulse:
    angle_rad: float                  # crank angle at the marking (falling) edge
    width_rad: float = math.radians(8.0)
    high_V: float = 5.0
    low_V: float = 0.2
    edge_tau_s: float = 15e-6         # the pickup's output RC
    noise_mV: float = 5.0


def rigid_specific_force(s: Sensor, g: float, th2, w2, a2, l2, th, w, a):
    """Specific force (acceleration minus gravity) along the sensor's +n
    (tangential) or +u (normal) axis of its link, rigid links."""
    c, sn = np.cos(th), np.sin(th)
    if s.link == "coupler":   # the link turns about the crank pin A
        ax = l2 * (-a2 * np.sin(th2) - w2 * w2 * np.cos(th2))
        ay = l2 * (a2 * np.cos(th2) - w2 * w2 * np.sin(th2))
    else:                     # about the fixed pivot O4
        ax = ay = 0.0
    p, o = s.position_m, s.offset_m
    if s.tangential:
        return (-sn * ax + c * ay) + a * p - w * w * o + g * c
    return (c * ax + sn * ay) - w * w * p - a * o + g * sn


def second_order_lowpass(x, f0, q, fs):
    w0 = 2 * math.pi * f0
    b, a = bilinear([w0 * w0], [1.0, w0 / q, w0 * w0], fs=fs)
    return lfilter(b, a, x, zi=lfilter_zi(b, a) * x[0])[0]


def first_order_highpass(x, fc, fs):
    """RC high-pass (bilinear); started at steady state for the first value's
    level held forever (its output then starts at zero)."""
    b, a = bilinear([1.0, 0.0], [1.0, 2 * math.pi * fc], fs=fs)
    return lfilter(b, a, x, zi=lfilter_zi(b, a) * x[0])[0]


def condition(x_m_s2, s: Sensor, fs_fine):
    """Sensor resonance, sensitivity × gain, AC coupling: volts on the fine grid."""
    if s.resonance_hz > 0.0:
        x_m_s2 = second_order_lowpass(x_m_s2, s.resonance_hz, s.resonance_q, fs_fine)
    v = s.axis_sign * x_m_s2 * s.sensitivity_mV_per_m_s2 * s.gain * 1e-3
    if s.highpass_hz > 0.0:
        v = first_order_highpass(v, s.highpass_hz, fs_fine)
    return v


def pulse_fine(t_fine, crank, p: Pulse):
    """Pickup output: high, falling to low at the marked angle for width_rad of
    crank; each switch an exact RC exponential from the previous level."""
    th0, _w, _a = crank.state(float(t_fine[0]))
    th1, _w, _a = crank.state(float(t_fine[-1]))
    k0 = math.floor((th0 - p.angle_rad) / (2 * math.pi)) - 1
    k1 = math.ceil((th1 - p.angle_rad) / (2 * math.pi)) + 1
    times, levels = [], []
    for k in range(k0, k1 + 1):
        times += [crank.time_of_angle(p.angle_rad + 2 * math.pi * k),
                  crank.time_of_angle(p.angle_rad + p.width_rad + 2 * math.pi * k)]
        levels += [p.low_V, p.high_V]
    times, levels = np.array(times), np.array(levels)
    i = np.searchsorted(times, t_fine, side="right") - 1   # the last switch (k0 - 1 turns back: i >= 0)
    new, old = levels[i], np.where(levels[i] == p.low_V, p.high_V, p.low_V)
    v = new + (old - new) * np.exp(-(t_fine - times[i]) / p.edge_tau_s)
    return v, times[::2]


def hum(t, daq: Daq, rng):
    out = np.zeros_like(t)
    for h, rel in enumerate(daq.hum_harmonics, start=1):
        out += daq.hum_mV * 1e-3 * rel * np.sin(2 * math.pi * h * daq.hum_hz * t + rng.uniform(0, 2 * math.pi))
    return out


def to_samples(v_fine, daq: Daq, channel_index: int):
    """Anti-alias filter and sampling of one channel's fine-grid volts."""
    r = daq.oversample
    fs_fine = daq.sample_rate_hz * r
    shift = int(round(channel_index * daq.multiplexed_skew_s * fs_fine))
    if daq.anti_alias == "sigma-delta":
        # linear-phase FIR, its delay compensated (as a sigma-delta DAQ reports)
        y = resample_poly(v_fine, 1, r, window=("kaiser", 10.0))
        if shift:
            y_shift = resample_poly(np.concatenate([v_fine[shift:], np.repeat(v_fine[-1], shift)]), 1, r,
                                    window=("kaiser", 10.0))
            y = y_shift
        return y
    kind, order, corner = daq.anti_alias.split(":")
    if kind != "butterworth":
        raise SystemExit(f"unknown anti-alias filter {daq.anti_alias}")
    b, a = butter(int(order), float(corner), fs=fs_fine)
    y = lfilter(b, a, v_fine, zi=lfilter_zi(b, a) * v_fine[0])[0]
    return y[shift::r][: len(v_fine) // r]


def adc(v, daq: Daq):
    """Clip at ±full scale and quantise to adc_bits; returns volts and the clipped count."""
    fs = daq.full_scale_V
    clipped = int(np.count_nonzero(np.abs(v) >= fs))
    v = np.clip(v, -fs, fs * (1 - 2.0 ** (1 - daq.adc_bits)))
    lsb = 2 * fs / 2 ** daq.adc_bits
    return np.round(v / lsb) * lsb, clipped

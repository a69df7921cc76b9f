#!/usr/bin/env bash
# Makes the sample session data/session/: SYNTHETIC recordings of the thesis
# rig written by `fourbar virtual-rig` from the clearance model (e = 0.5,
# smooth impacts) at 250 and 350 rpm with radial clearances 0.0254 and
# 0.254 mm (0.001 and 0.010 in, thesis ch. 7), 4 s each, FLAC 24-bit at
# 12.8 kHz, with sensor noise, mains hum and a ±0.5 % crank-speed wander.
# Every manifest says "SYNTHETIC" in its notes. Usage:
#   scripts/make-sample-session.sh [FOURBAR] [OUT_DIR]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
fourbar="$(realpath "${1:-$root/build/cli/fourbar}")"
out="${2:-$root/data/session}"
mkdir -p "$out" && out="$(realpath "$out")"
mkdir -p "$out"
scenes="$out/scenes"   # kept beside the recordings: they say exactly what made them
rig="$(realpath --relative-to="$scenes" "$root/data/rigs/thesis.toml")"
mkdir -p "$scenes"

seed=11
for rpm in 250 350; do
  for clearance in 0.0254 0.254; do
    name="thesis_${rpm}rpm_$(echo "$clearance" | tr -d .)mm"
    seed=$((seed + 1))
    cat >"$scenes/$name.toml" <<SCENE
# SYNTHETIC sample recording: thesis rig, clearance model, $rpm rpm, radial clearance $clearance mm.
rig = "$rig"
model = "clearance"
crank_speed_rpm = $rpm
start_angle_deg = 0.0
outputs = ["alpha3_rad_s2", "alpha4_rad_s2"]

[clearance]
radial_mm = $clearance
restitution = 0.5
contact = "smooth"
tolerance = 1e-8

[recording]
sample_rate_hz = 12800
duration_s = 4.0
sample_format = "pcm24"
full_scale_V = 10.0
noise_snr_db = 40.0
hum_frequency_hz = 50.0
hum_mV = 2.0
hum_harmonics = [1.0, 0.3]
speed_fluctuation_pct = 0.5
speed_fluctuation_period_s = 3.0
seed = $seed
warmup_revolutions = 20
notes = "SYNTHETIC: made by scripts/make-sample-session.sh with the virtual rig (clearance model, e = 0.5, smooth), not a lab measurement"

[recording.pulse]
name = "crank_pulse"
angle_deg = 0.0
width_deg = 10.0
rise_us = 150.0
jitter_us = 2.0

[[recording.sensor]]
name = "coupler_t"
role = "coupler_tangential"
position_mm = 289.0
offset_mm = 12.0
axis_sign = 1
sensitivity_mV_per_m_s2 = 1.0
gain = 2.0
ac_coupled = true
highpass_hz = 0.5

[[recording.sensor]]
name = "coupler_n"
role = "coupler_normal"
position_mm = 289.0
offset_mm = 12.0
axis_sign = -1
sensitivity_mV_per_m_s2 = 1.0
gain = 2.0
ac_coupled = true
highpass_hz = 0.5

[[recording.sensor]]
name = "rocker_t"
role = "rocker_tangential"
position_mm = 292.0
offset_mm = 10.0
axis_sign = 1
volts_per_unit = 0.002
SCENE
    (cd "$out" && "$fourbar" virtual-rig "scenes/$name.toml" --out "$name.flac" --no-truth)
  done
done
du -ch "$out"/*.flac | tail -1

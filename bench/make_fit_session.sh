#!/usr/bin/env bash
# Makes a SYNTHETIC session with known contact parameters for the fit's
# identifiability study and recovery bench: 4 recordings of the thesis rig
# (250 and 350 rpm × 0.0254 and 0.254 mm radial clearance) written by
# `fourbar virtual-rig` from the clearance model, TURNS turns each at SNR_DB,
# 12.8 kHz, coupler and rocker tangential accelerometers; session.toml holds
# a deliberately wrong prior (e = 0.95, smooth). Usage:
#   bench/make_fit_session.sh OUT_DIR RESTITUTION CONTACT MU [TURNS] [SNR_DB] [SEED] [FOURBAR]
# CONTACT is smooth or stick-slip (MU is ignored for smooth). With
# MODEL=compliant in the environment the recordings come from the compliant
# contact model instead (continuous force, damping calibrated to e, stiffness
# K = STIFFNESS N/m^1.5, default 1e10; CONTACT stick-slip gives its wall
# friction MU).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$1" e="$2" contact="$3" mu="$4"
turns="${5:-25}" snr="${6:-30}" seed="${7:-1}"
fourbar="$(realpath "${8:-$root/build/cli/fourbar}")"
mkdir -p "$out/scenes" && out="$(realpath "$out")"
rig="$(realpath --relative-to="$out/scenes" "$root/data/rigs/thesis.toml")"
model="${MODEL:-three-mode}"
friction=""
[ "$contact" = stick-slip ] && friction="friction_coefficient = $mu"
law="contact = \"$contact\""
[ "$model" = compliant ] && law="model = \"compliant\"
contact_stiffness_N_per_m_n = ${STIFFNESS:-1e10}"
for rpm in 250 350; do
  for clearance in 0.0254 0.254; do
    name="rec_${rpm}rpm_$(echo "$clearance" | tr -d .)mm"
    seed=$((seed + 1))
    cat >"$out/scenes/$name.toml" <<SCENE
# SYNTHETIC: clearance model ($model) e = $e, $contact ${friction}, $rpm rpm, radial clearance $clearance mm.
rig = "$rig"
model = "clearance"
crank_speed_rpm = $rpm
start_angle_deg = 0.0
outputs = ["alpha3_rad_s2"]

[clearance]
radial_mm = $clearance
restitution = $e
$law
$friction
tolerance = 1e-8

[recording]
sample_rate_hz = 12800
revolutions = $turns
sample_format = "pcm24"
noise_snr_db = $snr
seed = $seed
warmup_revolutions = 20
notes = "SYNTHETIC: bench/make_fit_session.sh, $model model, e = $e, $contact $friction"

[recording.pulse]
angle_deg = 0.0

[[recording.sensor]]
name = "coupler_t"
role = "coupler_tangential"
position_mm = 289.0
volts_per_unit = 0.002

[[recording.sensor]]
name = "rocker_t"
role = "rocker_tangential"
position_mm = 292.0
volts_per_unit = 0.002
SCENE
    (cd "$out" && "$fourbar" virtual-rig "scenes/$name.toml" --out "$name.flac" --no-truth >/dev/null)
  done
done
cat >"$out/session.toml" <<TOML
title = "SYNTHETIC fit session: $model model, e = $e, $contact $friction"
[theory]
restitution = 0.95
contact = "smooth"
TOML

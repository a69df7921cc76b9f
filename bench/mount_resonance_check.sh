#!/usr/bin/env bash
# Measures the model-family check (compare/model_family.hpp, docs/verdict.md
# "Wider windows for lower-Q resonances") on rigid-rig recordings with an
# accelerometer mount resonance the manifest does not report: the virtual
# rig's clearance model (thesis rig, 0.254 mm, true e = 0.8, smooth, 25
# turns at 30 dB) records the coupler's sensor through a second-order
# resonance (sensor_resonance_Hz / _Q), then the keys are taken out of the
# manifest, as when the calibration sheet is not at hand; session.toml's
# prior is e = 1. 450 and 800 Hz × Q 5, 10, 20 × 250 and 350 rpm: one line
# per recording with the report's model-family and model-agreement cells
# ("good: holds" is a miss).
#
# Usage: bench/mount_resonance_check.sh OUT_DIR [FOURBAR]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$1"
fourbar="$(realpath "${2:-$root/build/cli/fourbar}")"
mkdir -p "$out" && out="$(realpath "$out")"
missed=0 total=0
for hz in 450 800; do
  for q in 5 10 20; do
    for rpm in 250 350; do
      d="$out/r${hz}_q${q}_${rpm}"
      mkdir -p "$d/make" "$d/session"
      cat >"$d/make/rec.toml" <<EOT
rig = "$root/data/rigs/thesis.toml"
model = "clearance"
crank_speed_rpm = $rpm
outputs = ["alpha3_rad_s2"]
[clearance]
radial_mm = 0.254
restitution = 0.8
contact = "smooth"
[recording]
sample_rate_hz = 12800
revolutions = 25
noise_snr_db = 30.0
seed = 11
[recording.pulse]
angle_deg = 0.0
[[recording.sensor]]
name = "coupler_t"
role = "coupler_tangential"
position_mm = 289.0
volts_per_unit = 0.002
sensor_resonance_Hz = $hz
sensor_resonance_Q = $q
[[recording.sensor]]
name = "rocker_t"
role = "rocker_tangential"
position_mm = 292.0
volts_per_unit = 0.002
EOT
      printf '[theory]\nrestitution = 1.0\ncontact = "smooth"\n' >"$d/session/session.toml"
      "$fourbar" virtual-rig "$d/make/rec.toml" --no-truth --out "$d/session/rec.flac" >/dev/null 2>&1
      sed -i '/sensor_resonance_/d' "$d/session/rec.toml"
      "$fourbar" report "$d/session" --out "$d/report/report.html" --no-cache >"$d/report.txt" 2>&1
      line="$(python3 -c "
import json, sys
r = json.load(open('$d/report/summary.json'))['recordings'][0]['verdict']
print(r['model_family']['level'] + ': ' + r['model_family']['words'] + '  |  agreement ' + r['model_agreement']['level'] + ': ' + r['model_agreement']['words'])
")"
      total=$((total + 1))
      case "$line" in good:\ holds*) missed=$((missed + 1)) ;; esac
      printf '%4s Hz  Q %2s  %s rpm  model family %s\n' "$hz" "$q" "$rpm" "$line"
    done
  done
done
echo "mount resonance not reported in the manifest: $total recordings, missed ('good: holds') in $missed"

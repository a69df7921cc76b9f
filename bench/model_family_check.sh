#!/usr/bin/env bash
# Measures the model-family check (compare/model_family.hpp, docs/verdict.md
# "Model family") on SYNTHETIC sessions: the virtual rig's clearance model
# with true e = 0.8 (smooth), four recordings per session (250 and 350 rpm ×
# 0.1016 and 0.254 mm radial clearance), TURNS turns at 30 dB SNR with 50 Hz
# mains hum, and session.toml's WRONG prior e = 1. Each session is made
# twice with the same seeds and start angle (session s starts its crank at
# 45·(s − 1)°, so that each session's chaotic motion differs): once rigid, once with the links' bending modes
# rung by the bearing impulses ([[recording.link_mode]]: coupler 600 Hz,
# rocker 720 Hz, ζ = 0.02, modal mass MODAL_MASS_KG). Then `fourbar report`
# on each, and per recording: the ringing's RMS share of the rigid signal
# (virtual-rig's own figure), the unmodelled band the report names, the
# model-agreement level and a.
#
# Usage: bench/model_family_check.sh OUT_DIR [SESSIONS] [TURNS] [MODAL_MASS_KG] [FOURBAR]
# (defaults 2 sessions = 8 recordings per condition, 25 turns, 0.05 kg;
# FIRST_SESSION=3 in the environment makes sessions 3, 4, …: other start
# angles, a hold-out for thresholds set on sessions 1 and 2; CONDITIONS="1"
# makes only the ringing sessions, "0" only the rigid ones — the rigid ones
# do not depend on MODAL_MASS_KG).
# Prints one line per recording and the rates the issue asks for:
#   with ringing ≥ 50 % of the rigid RMS: agreement never "good", band named;
#   without ringing: no band named (false alarms).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$1" sessions="${2:-2}" turns="${3:-25}" mass="${4:-0.05}"
fourbar="$(realpath "${5:-$root/build/cli/fourbar}")"
mkdir -p "$out" && out="$(realpath "$out")"
rig="$root/data/rigs/thesis.toml"
motion="${MOTION:-clearance}"
case "$motion" in
  clearance) sensor_mm="${SENSOR_MM:-289.0 292.0}" ;;
  linkage) rig="$root/data/rigs/thesis_elastic.toml" sensor_mm="${SENSOR_MM:-154.5 156.0}" ;;
  *) echo "MOTION must be clearance or linkage" >&2; exit 2 ;;
esac
read -r coupler_mm rocker_mm <<<"$sensor_mm"

make_session() {  # DIR SEED RINGING(0|1) START_DEG
  local dir="$1" seed="$2" ringing="$3" start="$4"
  mkdir -p "$dir/scenes"
  for rpm in 250 350; do
    for clearance in 0.1016 0.254; do
      local name="rec_${rpm}rpm_$(echo "$clearance" | tr -d .)mm"
      seed=$((seed + 1))
      {
        cat <<SCENE
# SYNTHETIC: $motion model e = 0.8 smooth, $rpm rpm, $clearance mm; link ringing: $ringing.
rig = "$rig"
model = "$motion"
crank_speed_rpm = $rpm
start_angle_deg = $start
outputs = ["alpha3_rad_s2"]
SCENE
        if [ "$motion" = clearance ]; then
          cat <<SCENE

[clearance]
radial_mm = $clearance
restitution = 0.8
contact = "smooth"
tolerance = 1e-8
SCENE
        else  # the elastic links' vibration from the linkage model itself (ringing = 1), or rigid links
          cat <<SCENE

[linkage]
coupler_rocker_radial_mm = $clearance
restitution = 0.8
contact_stiffness_N_per_m_n = ${CONTACT_STIFFNESS:-4.1e10}
tolerance = ${LINKAGE_TOLERANCE:-1e-7}
$([ "$ringing" = 1 ] && printf 'elastic_links = ["coupler", "rocker"]\nelastic_modes = %s' "${ELASTIC_MODES:-2}")
SCENE
        fi
        cat <<SCENE

[recording]
sample_rate_hz = 12800
revolutions = $turns
sample_format = "pcm24"
noise_snr_db = 30
hum_mV = 2.0
seed = $seed
warmup_revolutions = 20

[recording.pulse]
angle_deg = 0.0

[[recording.sensor]]
name = "coupler_t"
role = "coupler_tangential"
position_mm = $coupler_mm
volts_per_unit = 0.002

[[recording.sensor]]
name = "rocker_t"
role = "rocker_tangential"
position_mm = $rocker_mm
volts_per_unit = 0.002
SCENE
        if [ "$ringing" = 1 ] && [ "$motion" = clearance ]; then
          cat <<MODES

[[recording.link_mode]]
link = "coupler"
frequency_hz = 600
damping_ratio = 0.02
modal_mass_kg = $mass

[[recording.link_mode]]
link = "rocker"
frequency_hz = 720
damping_ratio = 0.02
modal_mass_kg = $mass
MODES
        fi
      } >"$dir/scenes/$name.toml"
      (cd "$dir" && "$fourbar" virtual-rig "scenes/$name.toml" --out "$name.flac" --no-truth -q) >"$dir/../$(basename "$dir")_$name.virtual-rig.log"
    done
  done
  printf 'title = "SYNTHETIC model-family check, true e = 0.8, prior e = 1"\n[theory]\nrestitution = 1.0\ncontact = "smooth"\n' >"$dir/session.toml"
  "$fourbar" report "$dir" --out "$dir/report/report.html" -q >/dev/null 2>"$dir/report.stderr" || true
}

for s in $(seq "${FIRST_SESSION:-1}" $((${FIRST_SESSION:-1} + sessions - 1))); do
  for ringing in ${CONDITIONS:-0 1}; do
    make_session "$out/s${s}_ringing$ringing" $((100 * s)) "$ringing" $((45 * (s - 1)))
  done
done

python3 - "$out" <<'PY'
import json, glob, os, re, sys
out = sys.argv[1]
rows = []
for summary in sorted(glob.glob(os.path.join(out, "s*_ringing*", "report", "summary.json"))):
    d = os.path.dirname(os.path.dirname(summary))
    ringing = d.endswith("ringing1")
    for r in json.load(open(summary))["recordings"]:
        name = r["name"]
        txt = open(d + "_" + os.path.splitext(name)[0] + ".virtual-rig.log").read()
        share = re.search(r"link ringing on coupler_t: ([0-9.e+-]+) %", txt)
        share = float(share.group(1)) / 100 if share else 0.0
        v = r.get("verdict", {})
        mf = r.get("model_family", {})
        named = mf.get("unmodelled", [])
        # The highest window in the coupler mode's neighbourhood (ringing) or anywhere (rigid):
        # its ratio over its neighbours' and its measured prominence (compare/model_family.hpp).
        bands = [b for b in mf.get("bands", []) if not ringing or 540 <= 0.5 * (b["low_hz"] + b["high_hz"]) <= 660]
        top = max(bands, key=lambda b: min(b["ratio_to_neighbours"], b["prominence"]), default=None)
        stand = f'{top["ratio_to_neighbours"]:5.1f} x / {top["prominence"]:5.1f} x at {top["low_hz"]:.0f} Hz' if top else "-"
        rows.append((os.path.basename(d), name, ringing, share, named, v.get("model_agreement", {}).get("level"),
                     v.get("model_agreement", {}).get("words"), v.get("a"), stand))
for d, name, ringing, share, named, level, words, a, stand in rows:
    band = "; ".join(f'{u["kind"]} {u["low_hz"]:.0f}-{u["high_hz"]:.0f} Hz ({100*u["rms_share"]:.0f} %)' for u in named) or "none"
    print(f"{d:16s} {name:22s} ringing {100*share:5.1f} %  named: {band:40s} window {stand}  agreement: {level} ({words})")
strong = [r for r in rows if r[2] and r[3] >= 0.5]
rigid = [r for r in rows if not r[2]]
print(f"\nringing >= 50 % of the rigid RMS: {len(strong)} recordings; band named in {sum(1 for r in strong if r[4])}; "
      f"agreement 'good' in {sum(1 for r in strong if r[5] == 'good')}")
print(f"without ringing: {len(rigid)} recordings; band named (false alarm) in {sum(1 for r in rigid if r[4])}; "
      f"agreement 'good' in {sum(1 for r in rigid if r[5] == 'good')}")
PY

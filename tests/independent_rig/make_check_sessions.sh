#!/bin/sh
# Makes issue 28's check sessions with the independent generator into DIR
# (default /tmp/indep), each with the true prior unless said: smooth
# e = 0.2, 0.5, 0.8; stick-slip e = 0.5 with μ = 0.1, 0.2; e = 0.8 smooth
# with link vibration and the wrong prior e = 1, and its twin without the
# vibration (same motion and noise); stick-slip e = 0.5 with μ = 0.1, 0.2
# acting at impacts only (stickimp_*, the thesis's choice); with FULL=1 also stick-slip e = 0.2, 0.8
# with μ = 0.1, 0.2, and e = 0.5 through a sensor resonance (6 kHz), an
# analog anti-alias filter (4th-order Butterworth, 8 kHz) and a multiplexed
# ADC's skew (9.8 µs per channel). Two recordings each (250 and 350 rpm at
# 0.254 mm; clean_e05 four, at 0.0254 mm too; RECS="250:0.254 350:0.254 ..." to change), 25 turns; JOBS
# sessions at a time (default 2). About 4 CPU minutes per recording.
set -eu
dir=${1:-/tmp/indep}
jobs=${JOBS:-2}
recs=${RECS:-"250:0.254 350:0.254"}
here=$(dirname "$0")
py=/usr/bin/python3
mkdir -p "$dir"
rec_args=""
for r in $recs; do rec_args="$rec_args --recording $r"; done
run() {
    name=$1; shift
    if [ -f "$dir/$name/truth/truth.json" ]; then echo "$name: exists"; return; fi
    these=$rec_args
    case "$*" in *--recording*) these="" ;; esac   # the session names its own recordings
    # shellcheck disable=SC2086
    nice "$py" "$here/make_session.py" --out "$dir/$name" $these "$@" > "$dir/$name.log" 2>&1 \
        && echo "$name: made" || { echo "$name: FAILED (see $dir/$name.log)"; return 1; }
}
{
    echo "vib_e08_prior1 --restitution 0.8 --vibration --prior e=1 --seed 81 --twin-out $dir/novib_e08_prior1"
    echo "clean_e08 --restitution 0.8 --seed 8"
    echo "stick_e05_mu02 --restitution 0.5 --friction 0.2 --seed 52"
    echo "clean_e02 --restitution 0.2 --seed 2"
    echo "stick_e05_mu01 --restitution 0.5 --friction 0.1 --seed 51"
    echo "clean_e05 --restitution 0.5 --seed 5 --recording 250:0.0254 --recording 250:0.254 --recording 350:0.0254 --recording 350:0.254"
    echo "stickimp_e05_mu01 --restitution 0.5 --friction 0.1 --friction-at impacts --seed 601"
    echo "stickimp_e05_mu02 --restitution 0.5 --friction 0.2 --friction-at impacts --seed 602"
    if [ "${FULL:-0}" = 1 ]; then
        echo "stick_e02_mu01 --restitution 0.2 --friction 0.1 --seed 21"
        echo "stick_e02_mu02 --restitution 0.2 --friction 0.2 --seed 22"
        echo "stick_e08_mu01 --restitution 0.8 --friction 0.1 --seed 81"
        echo "stick_e08_mu02 --restitution 0.8 --friction 0.2 --seed 82"
        echo "chain_e05 --restitution 0.5 --seed 55 --sensor-resonance-hz 6000 --anti-alias butterworth:4:8000 --skew-us 9.765625"
    fi
} | {
    n=0
    while read -r line; do
        # shellcheck disable=SC2086
        run $line &
        n=$((n + 1))
        if [ "$n" -ge "$jobs" ]; then wait; n=0; fi
    done
    wait
}

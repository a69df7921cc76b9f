#!/usr/bin/python3
"""Runs `fourbar report` (and, with --fit, `fourbar fit`) on sessions made by
make_check_sessions.sh and prints what fourbar says against the truth: per
recording the verdict's set-up, clearance-effect and model-agreement levels
with a (± SE), the generator's vibration/rigid RMS ratio; per session the
fitted e and μ with intervals and identifiability, χ²/term.

usage: run_baseline.py FOURBAR_EXE SESSIONS_DIR [--fit] [NAME ...]
Outputs go to SESSIONS_DIR/out/NAME/ (report.html, summary.json, fit/).
"""
import json
import os
import subprocess
import sys
import time


def report(fourbar, session, out):
    html = os.path.join(out, "report.html")
    t = time.time()
    rc = subprocess.run([fourbar, "report", session, "--out", html, "--no-cache", "--no-fit", "-q"],
                        capture_output=True, text=True)
    if rc.returncode not in (0, 1):
        print(rc.stderr)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f), time.time() - t


def fit(fourbar, session, out):
    t = time.time()
    rc = subprocess.run([fourbar, "fit", session, "--out", os.path.join(out, "fit"), "-q"],
                        capture_output=True, text=True)
    path = os.path.join(out, "fit", "fit.json")
    if not os.path.exists(path):
        return None, rc.stdout + rc.stderr, time.time() - t
    with open(path) as f:
        return json.load(f), rc.stdout, time.time() - t


def param(p):
    if p is None:
        return "–"
    ident = "" if p.get("identifiable") else " not identifiable"
    return f"{p['value']:.3g} [{p['low']:.3g}, {p['high']:.3g}]{ident}"


def main(argv):
    fourbar, root = argv[0], argv[1]
    do_fit = "--fit" in argv
    names = [a for a in argv[2:] if not a.startswith("--")] or sorted(
        d for d in os.listdir(root) if os.path.isfile(os.path.join(root, d, "truth", "truth.json")))
    for name in names:
        session = os.path.join(root, name)
        with open(os.path.join(session, "truth", "truth.json")) as f:
            truth = json.load(f)
        out = os.path.join(root, "out", name)
        os.makedirs(out, exist_ok=True)
        summary, secs = report(fourbar, session, out)
        targs = truth["arguments"]
        print(f"## {name}: truth e = {targs['restitution']}, μ = {targs['friction']}, "
              f"vibration {targs['vibration']}, prior {targs['prior']} (report {secs:.0f} s)")
        for rec in summary["recordings"]:
            v = rec.get("verdict", {})
            key = os.path.splitext(os.path.basename(rec.get("file", rec.get("name", ""))))[0]
            tr = truth["recordings"].get(key, {})
            vib = [round(s["vibration_over_rigid_rms"], 2) for s in tr.get("sensors", {}).values()
                   if s["role"].endswith("tangential")]
            if not v:
                print(f"| {key} | failed: {rec.get('error', '?')} |")
                continue
            se = v.get("a_standard_error")
            a = v.get("a")
            print(f"| {key} | {v['setup']['level']} | {v['clearance_effect']['level']}: "
                  f"{v['clearance_effect']['words']} | {v['model_agreement']['level']} | "
                  f"{'–' if a is None else f'{a:.2f}'} ± {'–' if se is None else f'{se:.2f}'} "
                  f"({v.get('a_from')}) | {tr.get('impacts_per_turn', 0):.1f} | {vib} |")
        if do_fit:
            fj, text, fsecs = fit(fourbar, session, out)
            if fj is None:
                print(f"fit: no fit.json ({fsecs:.0f} s): {text.strip()[:300]}")
                continue
            par = fj["parameters"]
            mu = par.get("friction_coefficient")
            terms = fj.get("terms") or 1
            print(f"fit ({fsecs:.0f} s): e = {param(par.get('restitution'))}; μ = {param(mu)}; "
                  f"contact {par.get('contact', {}).get('value')}; χ²/term {fj['chi2'] / terms:.2f} "
                  f"(prior {fj['chi2_prior'] / terms:.2f})")
        sys.stdout.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

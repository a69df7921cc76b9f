#!/usr/bin/python3
"""Fit recovery on the independent generator's sessions (issue 28): runs
`fourbar fit` on each session (PARALLEL at a time, --jobs JOBS each, extra
fit options after --) and prints one row per session: the truth, fitted e
and μ with their intervals and identifiability, whether the truth is inside
and within ±0.1, χ²/term, the band and the modelling offsets at the fit, the
model-family verdict, wall and CPU seconds; then the tallies the issue asks
for: e and μ within ±0.1 where called identifiable, the truth inside the
reported intervals, sessions with vibration that report anything identifiable.

usage: fit_recovery.py FOURBAR SESSIONS_DIR [--jobs N] [--parallel P] [--refit] [--table-only] [NAME ...] [-- FIT OPTIONS]
Fits go to SESSIONS_DIR/fit_out/NAME/ (fit.json, log, time); without
--refit a session whose fit.json exists is not fitted again.
"""
import json
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor


def run_fit(fourbar, session, out, jobs, extra):
    os.makedirs(out, exist_ok=True)
    cmd = ["nice", "/usr/bin/time", "-f", "%e %U %S", "-o", os.path.join(out, "time"), fourbar, "fit", session,
           "--out", out, "--jobs", str(jobs), "-q"] + extra
    with open(os.path.join(out, "log"), "w") as log:
        subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT)


def cell(p, truth):
    if p is None:
        return "–", None, None
    ident = p.get("identifiable", False)
    lb = " only ≥ %.2f" % p["low"] if p.get("only_lower_bound") else ""
    inside = p["low"] - 1e-9 <= truth <= p["high"] + 1e-9
    close = abs(p["value"] - truth) <= 0.1 + 1e-9
    text = f"{p['value']:.2f} [{p['low']:.2f}, {p['high']:.2f}]{'' if ident else ' not identifiable'}{lb}"
    return text, inside, (close if ident else None)


def main(argv):
    extra = []
    if "--" in argv:
        extra = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    fourbar, root = argv[0], argv[1]
    jobs, parallel, refit, table_only, names = 2, 1, False, False, []
    i = 2
    while i < len(argv):
        a = argv[i]
        if a == "--jobs":
            jobs = int(argv[i + 1]); i += 2; continue
        if a == "--parallel":
            parallel = int(argv[i + 1]); i += 2; continue
        if a == "--refit":
            refit = True; i += 1; continue
        if a == "--table-only":
            table_only = True; i += 1; continue
        names.append(a); i += 1
    if not names:
        names = sorted(d for d in os.listdir(root) if os.path.isfile(os.path.join(root, d, "truth", "truth.json")))
    outs = {n: os.path.join(root, "fit_out", n) for n in names}
    todo = [] if table_only else [n for n in names if refit or not os.path.isfile(os.path.join(outs[n], "fit.json"))]
    with ThreadPoolExecutor(max_workers=parallel) as pool:
        for n in todo:
            pool.submit(run_fit, fourbar, os.path.join(root, n), outs[n], jobs, extra)
    print("| session | truth e, μ (friction at) | vibration | fitted e [interval] | e inside, ±0.1 | fitted μ [interval] | "
          "μ inside, ±0.1 | χ²/term (prior) | offsets at fit (band, spread) | family | s wall (CPU) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    tally = {"inside": 0, "intervals": 0, "close": 0, "identifiable": 0, "vib_identifiable": 0, "vib": 0}
    for n in names:
        with open(os.path.join(root, n, "truth", "truth.json")) as f:
            targs = json.load(f)["arguments"]
        e_true, mu_true, vib = targs["restitution"], targs["friction"], targs["vibration"]
        at = targs.get("friction_at", "always") if mu_true else "–"
        path = os.path.join(outs[n], "fit.json")
        t = "?"
        times = open(os.path.join(outs[n], "time")).read().split() if os.path.isfile(os.path.join(outs[n], "time")) else []
        if len(times) >= 3:
            w, u, s = (float(x) for x in times[-3:])
            t = f"{w:.0f} ({u + s:.0f})"
        if not os.path.isfile(path):
            log = open(os.path.join(outs[n], "log")).read().strip().splitlines() if os.path.isfile(os.path.join(outs[n], "log")) else ["?"]
            what = "no fit: " + log[-1][:160] if len(times) >= 3 else "not finished"
            print(f"| {n} | {e_true}, {mu_true} ({at}) | {vib} | {what} | | | | | | | {t} |")
            continue
        j = json.load(open(path))
        par = j["parameters"]
        et, ei, ec = cell(par.get("restitution"), e_true)
        mt, mi, mc = cell(par.get("friction_coefficient"), mu_true)
        for inside, close, p in ((ei, ec, par.get("restitution")), (mi, mc, par.get("friction_coefficient"))):
            if p is None:
                continue
            if vib:
                tally["vib"] += 1
                tally["vib_identifiable"] += 1 if p.get("identifiable") else 0
                continue
            tally["intervals"] += 1
            tally["inside"] += 1 if inside else 0
            if close is not None:
                tally["identifiable"] += 1
                tally["close"] += 1 if close else 0
        terms = j.get("terms") or 1
        off = j.get("modelling_offsets", {})
        offs = ", ".join(f"{off[k]['offset_at_fit']:+.2f}" for k in ("band_excess", "spread") if k in off) or "–"
        fam = j.get("model_family", {}).get("verdict", "?")
        yn = lambda v: "–" if v is None else ("yes" if v else "**no**")
        print(f"| {n} | {e_true}, {mu_true} ({at}) | {vib} | {et} | {yn(ei)}, {yn(ec)} | {mt} | {yn(mi)}, {yn(mc)} | "
              f"{j['chi2'] / terms:.2f} ({j['chi2_prior'] / terms:.2f}) | {offs} | {fam} | {t} |")
    print(f"\n# without vibration: truth inside {tally['inside']} of {tally['intervals']} intervals; "
          f"within ±0.1 in {tally['close']} of {tally['identifiable']} identifiable parameters; "
          f"with vibration: {tally['vib_identifiable']} of {tally['vib']} parameters identifiable")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

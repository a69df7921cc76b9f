#!/usr/bin/python3
"""CTest independent_rig_report: a small clean session from the independent
generator (no link vibration, the true prior e = 0.5, smooth), then
`fourbar report`: the set-up check must pass ("good") and the model
agreement must not be "problem" for every recording. Exit 77 (skipped)
when this Python has no scipy.

usage: check_report.py FOURBAR_EXE WORK_DIR
"""
import json
import os
import shutil
import subprocess
import sys

try:
    import scipy  # noqa: F401
    import numpy  # noqa: F401
except ImportError:
    print("independent_rig_report: skipped: python3-scipy and python3-numpy (Debian) are not "
          f"installed for {sys.executable}; apt-get install python3-scipy")
    sys.exit(77)

HERE = os.path.dirname(os.path.abspath(__file__))


def main(argv):
    fourbar, work = argv[0], argv[1]
    session = os.path.join(work, "session")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    gen = [sys.executable, os.path.join(HERE, "make_session.py"), "--out", session,
           "--recording", "350:0.254", "--turns", "16", "--warmup-turns", "20",
           "--restitution", "0.5", "--prior", "truth", "--seed", "3"]
    subprocess.run(gen, check=True)
    out = os.path.join(work, "report", "report.html")
    rc = subprocess.run([fourbar, "report", session, "--out", out, "--no-cache", "--no-fit", "-q"]).returncode
    if rc != 0:
        print(f"fourbar report exited {rc}")
        return 1
    with open(os.path.join(os.path.dirname(out), "summary.json")) as f:
        summary = json.load(f)
    failures = 0
    for rec in summary["recordings"]:
        v = rec["verdict"]
        name = rec.get("name", rec.get("file", "?"))
        setup, agree = v["setup"], v["model_agreement"]
        print(f"{name}: set-up {setup['level']} ({setup['words']}); model agreement "
              f"{agree['level']} ({agree['words']}); a = {v.get('a')} ± {v.get('a_standard_error')} "
              f"({v.get('a_from')})")
        if setup["level"] != "good":
            print(f"  FAIL: the set-up check should pass on the generator's manifest: {setup['sentence']}")
            failures += 1
        if agree["level"] == "problem":
            print(f"  FAIL: model agreement 'problem' for the true prior: {agree['sentence']}")
            failures += 1
    if not summary["recordings"]:
        print("FAIL: no recording in summary.json")
        failures += 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

#!/usr/bin/python3
"""Every CSV fourbar writes opens in pandas with plain read_csv.

Runs the sample jobs (report on data/session, sim of four scenes with their
tables, virtual-rig writing a CSV recording and its truth, analyze with
--per-revolution, acquire, sweep), then reads every *.csv they wrote with
pandas.read_csv and no options: it must parse, its header must be the first
line of the file (no '#' lines above it) and hold the expected names, and
every column that holds numbers must come out as a float or int dtype (not
object). Each CSV's provenance must be in the JSON beside it. Then
--csv-comments must give back the '#' lines, and fourbar must read its own
CSV recording in both forms.

  csv_in_pandas.py FOURBAR SOURCE_DIR
"""
import json
import os
import re
import subprocess
import sys
import tempfile

try:
    import pandas as pd
    from pandas.api.types import is_numeric_dtype
except ImportError:
    sys.exit("csv_in_pandas: python3-pandas is missing; install it (scripts/install-deps.sh)")

fourbar, source = sys.argv[1], sys.argv[2]
failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL: " + msg)


def run(*args, cwd=None):
    r = subprocess.run([fourbar, *args], cwd=cwd or source, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("csv_in_pandas: fourbar %s failed (%d): %s" % (" ".join(args), r.returncode, r.stderr))
    return r


# Columns that hold text; every other column must read as numbers.
TEXT_COLUMNS = {"status", "error", "recording", "id", "file", "direction", "setup_check", "verdict", "a_kind",
                "verdict_setup", "verdict_measurement", "verdict_clearance_effect", "verdict_model_family",
                "verdict_model_agreement"}

# The header of every CSV whose columns do not depend on the scene or recording.
EXPECTED = {
    "sweep.csv": "radial_mm,crank_speed_rpm,restitution,friction_coefficient,impacts_per_rev,"
                 "impacts_per_rev_standard_error,sum_normal_impulse_per_rev_Ns,"
                 "sum_normal_impulse_per_rev_standard_error_Ns,impact_index_Ns,contact_losses_per_rev,following_share,"
                 "energy_residual_rel,max_penetration_rel,status,error",
    "revolution_list.csv": "revolution,start_time_s,period_s,speed_rpm,segment,repaired,clipped",
    "pulses.csv": "time_s,segment,status",
    "session_severity.csv": "clearance_mm,speed_rpm,measured_alpha3_fluctuation_rms_rad_s2,"
                            "measured_alpha4_fluctuation_rms_rad_s2,simulated_alpha3_fluctuation_rms_rad_s2,"
                            "impacts_per_rev,sum_normal_impulse_per_rev_Ns,impact_index_Ns,magnification_alpha3,"
                            "recording,status",
    "summary.csv": "id,file,status,verdict,a,a_standard_error,a_kind,verdict_setup,verdict_measurement,"
                   "verdict_clearance_effect,verdict_model_family,verdict_model_agreement,speed_rpm,speed_std_rpm,clearance_mm,direction,revolutions_averaged,"
                   "revolutions_clipped,a_time,a_spectral,alpha3_measured_fluctuation_rms_rad_s2,"
                   "alpha3_model_fluctuation_rms_rad_s2,alpha3_rms_difference_model_rad_s2,"
                   "alpha3_rms_difference_nominal_rad_s2,alpha3_correlation_model,alpha3_correlation_nominal,"
                   "alpha4_a_time,alpha4_correlation_model,model_impacts_per_rev,"
                   "model_sum_normal_impulse_per_rev_Ns,model_impact_index_Ns,setup_check,setup_findings,"
                   "warnings,error",
    "impacts.csv@sim_clearance": "crank_deg,time_s,revolution,normal_impulse_Ns,tangential_impulse_Ns,eta_deg,"
                                 "approach_speed_m_s,rebound_speed_m_s,slip_speed_before_m_s,slip_speed_after_m_s,"
                                 "stuck,energy_loss_J,motor_impulse_Nms,mode_after",
    "impacts.csv@sim_compliant": "crank_deg,time_s,revolution,normal_impulse_Ns,contact_impulse_Ns,"
                                 "tangential_impulse_Ns,eta_deg,approach_speed_m_s,rebound_speed_m_s,peak_force_N,"
                                 "contact_duration_s,max_penetration_mm,energy_loss_J,mode_after",
    "revolutions.csv@sim_clearance": "crank_deg,revolution,impacts,sum_normal_impulse_Ns,impact_index_Ns,"
                                     "contact_losses,following_share,free_flight_share,alpha3_deviation_rms_rad_s2",
    "_impacts.csv@series": "crank_deg,revolution,normal_impulse_Ns,pin_deg,bushing_deg,global_deg",
}

# A column name: lower-case words and digits joined by '_', a unit such as Ns
# or Hz keeping its capitals.
NAME = re.compile(r"^[A-Za-z][A-Za-z0-9]*(_[A-Za-z0-9]+)*$")


def expected_header(rel):
    base = os.path.basename(rel)
    folder = os.path.basename(os.path.dirname(rel))
    for key in (base + "@" + folder, base):
        if key in EXPECTED:
            return EXPECTED[key]
    if folder == "series" and base.endswith("_impacts.csv"):
        return EXPECTED["_impacts.csv@series"]
    return None


def check_csv(path, rel, json_beside):
    with open(path, encoding="utf-8") as f:
        first = f.readline().rstrip("\n")
        second = f.readline()
    if first.startswith("#"):
        fail("%s: starts with a '#' line" % rel)
        return
    try:
        df = pd.read_csv(path)
    except Exception as e:  # any parse error
        fail("%s: pandas.read_csv: %s" % (rel, e))
        return
    names = list(df.columns)
    if ",".join(names) != first:
        fail("%s: pandas header %s is not the file's first line %s" % (rel, names, first))
    want = expected_header(rel)
    if want is not None and first != want:
        fail("%s: header\n  %s\nexpected\n  %s" % (rel, first, want))
    for n in names:
        if not NAME.match(n):
            fail("%s: column name %r is not a plain name with its unit" % (rel, n))
    if second and len(df) == 0:
        fail("%s: rows in the file but none in pandas" % rel)
    numeric = 0
    for n in names:
        # A table without rows (a scene without impacts) has no values to type:
        # pandas gives its columns dtype object whatever the file.
        if n in TEXT_COLUMNS or len(df) == 0:
            continue
        if not is_numeric_dtype(df[n]):
            bad = df[n][pd.to_numeric(df[n], errors="coerce").isna() & df[n].notna()].head(3).tolist()
            fail("%s: column %s reads as %s, not numbers (e.g. %s)" % (rel, n, df[n].dtype, bad))
        else:
            numeric += 1
    if not os.path.exists(json_beside):
        fail("%s: no JSON with its provenance beside it (%s)" % (rel, os.path.relpath(json_beside, os.path.dirname(path))))
    else:
        with open(json_beside, encoding="utf-8") as f:
            j = json.load(f)
        prov = j.get("provenance", j if "tool" in j else None)
        if not prov or prov.get("tool") != "fourbar" or "version" not in prov:
            fail("%s: %s has no provenance (tool, version)" % (rel, os.path.basename(json_beside)))
    return len(df), numeric


def provenance_json(path, out):
    """Where a CSV's provenance is: NAME.csv.json, else the summary.json of its
    folder or of the report folder above series/."""
    sidecar = path + ".json"
    if os.path.exists(sidecar):
        return sidecar
    d = os.path.dirname(path)
    if os.path.basename(d) == "series":
        d = os.path.dirname(d)
    return os.path.join(d, "summary.json")


with tempfile.TemporaryDirectory(prefix="fourbar-csv-") as out:
    run("report", "data/session", "--out", os.path.join(out, "report", "report.html"), "--no-cache", "-q")
    sims = {"sim_nominal": "thesis_nominal_350rpm", "sim_clearance": "thesis_clearance_350rpm_e05",
            "sim_friction": "wall_friction_steady_350rpm", "sim_compliant": "thesis_compliant_350rpm_e05"}
    for folder, scene in sims.items():
        run("sim", os.path.join("data", "scenes", scene + ".toml"), "--out", os.path.join(out, folder))
    run("analyze", "data/session/thesis_350rpm_0254mm.flac", "--per-revolution", "--out", os.path.join(out, "analyze"))
    run("acquire", "data/session/thesis_350rpm_0254mm.flac", "--out", os.path.join(out, "acquire"))
    run("sweep", "data/scenes/experiment_grid_sweep.toml", "-q", "--out", os.path.join(out, "sweep", "sweep.csv"))

    # A CSV recording (the scene's audio sample format left out), with its truth.
    with open(os.path.join(source, "data", "scenes", "thesis_virtual_rig_350rpm.toml"), encoding="utf-8") as f:
        scene = f.read()
    rig = os.path.join(source, "data", "rigs", "thesis.toml")
    scene = scene.replace('rig = "../rigs/thesis.toml"', 'rig = "%s"' % rig)
    scene = re.sub(r'(?m)^sample_format = .*\n', "", scene)
    scene = re.sub(r'(?m)^revolutions = 20$', "revolutions = 3", scene)
    scene = re.sub(r'(?m)^sample_rate_hz = 25600$', "sample_rate_hz = 5000", scene)
    os.makedirs(os.path.join(out, "vr"))
    scene_file = os.path.join(out, "vr_scene.toml")
    with open(scene_file, "w", encoding="utf-8") as f:
        f.write(scene)
    run("virtual-rig", scene_file, "--out", os.path.join(out, "vr", "REC.csv"))
    # fourbar reads back its own CSV recording without '#' lines.
    run("acquire", os.path.join(out, "vr", "REC.csv"), "--out", os.path.join(out, "vr_acquire"))

    found = sorted(os.path.relpath(os.path.join(d, f), out)
                   for d, _, files in os.walk(out) for f in files if f.endswith(".csv"))
    must = ["report/summary.csv", "report/session_severity.csv", "sweep/sweep.csv", "vr/REC.csv",
            "vr/REC.truth.csv", "acquire/samples.csv", "acquire/revolutions.csv", "acquire/revolution_list.csv",
            "acquire/pulses.csv", "analyze/averaged.csv", "analyze/spectra.csv", "analyze/per_revolution.csv",
            "sim_clearance/impacts.csv", "sim_clearance/revolutions.csv", "sim_compliant/impacts.csv",
            "sim_nominal/series.csv", "report/series/thesis_350rpm_0254mm.csv",
            "report/series/thesis_350rpm_0254mm_orders.csv", "report/series/thesis_350rpm_0254mm_impacts.csv"]
    for m in must:
        if m not in found:
            fail("%s was not written" % m)
    rows = 0
    for rel in found:
        path = os.path.join(out, rel)
        r = check_csv(path, rel, provenance_json(path, out))
        if r:
            rows += r[0]
            print("ok %-50s %8d rows, %3d numeric columns" % (rel, r[0], r[1]))

    # summary.csv: one row per recording, the values of summary.json.
    if os.path.exists(os.path.join(out, "report", "summary.csv")):
        summary = pd.read_csv(os.path.join(out, "report", "summary.csv"))
        exact = pd.read_csv(os.path.join(out, "report", "summary.csv"), float_precision="round_trip")
        with open(os.path.join(out, "report", "summary.json"), encoding="utf-8") as f:
            recs = json.load(f)["recordings"]
        if list(summary["file"]) != [r["name"] for r in recs]:
            fail("summary.csv: files %s, summary.json %s" % (list(summary["file"]), [r["name"] for r in recs]))
        else:
            for i, r in enumerate(recs):
                a = r["metrics"]["alpha3_rad_s2"]
                pairs = [("speed_rpm", r["operating_point"]["speed_rpm"]),
                         ("revolutions_averaged", r["operating_point"]["revolutions_averaged"]),
                         ("a_time", a["magnification"]["time_domain"]), ("a_spectral", a["magnification"]["spectral"]),
                         ("alpha3_correlation_model", a["correlation_simulated"]),
                         ("alpha3_rms_difference_model_rad_s2", a["rms_difference_simulated"])]
                for col, want in pairs:
                    # pandas' default float parser may miss the last bit; the exact
                    # round trip is tested in C++ (tests/common/test_number_text.cpp).
                    if want is None:  # no value (e.g. no order usable for a spectral a): an empty cell
                        if not pd.isna(summary[col][i]):
                            fail("summary.csv row %d %s = %r, summary.json null" % (i, col, summary[col][i]))
                        continue
                    if not abs(summary[col][i] - want) <= 1e-15 * abs(want):
                        fail("summary.csv row %d %s = %r, summary.json %r" % (i, col, summary[col][i], want))
                if summary["status"][i] != r["status"] or summary["setup_check"][i] != r["setup_check"]["status"]:
                    fail("summary.csv row %d: status or set-up check differ from summary.json" % i)
                # The verdict: its level, every part's level, the a it judges by with its error and kind.
                v = r["verdict"]
                if summary["verdict"][i] != v["overall"]:
                    fail("summary.csv row %d verdict %r, summary.json %r" % (i, summary["verdict"][i], v["overall"]))
                for part in ("setup", "measurement", "clearance_effect", "model_agreement"):
                    if summary["verdict_" + part][i] != v[part]["level"]:
                        fail("summary.csv row %d verdict_%s %r, summary.json %r" % (i, part, summary["verdict_" + part][i],
                                                                                    v[part]["level"]))
                if summary["a_kind"][i] != v["a_from"]:
                    fail("summary.csv row %d a_kind %r, summary.json %r" % (i, summary["a_kind"][i], v["a_from"]))
                # Exactly, read with pandas' round-trip float parser (its default
                # parser may miss the last bits).
                for col, key in (("a", "a"), ("a_standard_error", "a_standard_error")):
                    want = v[key]
                    if want is None or exact[col][i] != want:
                        fail("summary.csv row %d %s = %r, summary.json %r" % (i, col, exact[col][i], want))
                if not 0 < summary["a_standard_error"][i] < summary["a"][i]:
                    fail("summary.csv row %d: a %r with standard error %r" % (i, summary["a"][i], summary["a_standard_error"][i]))
            # A chaotic clearance effect's scatter is not a measurement fault:
            # on the sample session no part of any verdict is a problem.
            for part in ("verdict", "verdict_setup", "verdict_measurement", "verdict_clearance_effect",
                         "verdict_model_family", "verdict_model_agreement"):
                if "problem" in list(summary[part]):
                    fail("summary.csv: the sample session has a %s 'problem': %s" % (part, list(summary[part])))
        severity = pd.read_csv(os.path.join(out, "report", "session_severity.csv"))
        if sorted(set(severity["status"])) != ["ok"]:
            fail("session_severity.csv status %s, want ok for every sample recording" % list(severity["status"]))
        # The manifests' clearances as they write them (not 0.025400000000000002).
        for rel in ("report/summary.csv", "report/session_severity.csv"):
            text = pd.read_csv(os.path.join(out, rel), dtype=str)
            cells = sorted(set(text["clearance_mm"]))
            if cells != ["0.0254", "0.254"]:
                fail("%s: clearance_mm cells %s, want the manifests' 0.0254 and 0.254" % (rel, cells))

    # --csv-comments: today's '#' lines above the header, then the same table.
    run("sim", os.path.join("data", "scenes", "thesis_clearance_350rpm_e05.toml"), "--csv-comments",
        "--out", os.path.join(out, "commented"))
    run("virtual-rig", scene_file, "--csv-comments", "--out", os.path.join(out, "vr_commented", "REC.csv"))
    run("sweep", "data/scenes/experiment_grid_sweep.toml", "-q", "--csv-comments",
        "--out", os.path.join(out, "sweep_commented", "sweep.csv"))
    run("report", "data/session", "--out", os.path.join(out, "report_commented", "report.html"), "--csv-comments", "-q")
    run("analyze", "data/session/thesis_350rpm_0254mm.flac", "--csv-comments", "--out",
        os.path.join(out, "analyze_commented"))
    run("acquire", "data/session/thesis_350rpm_0254mm.flac", "--csv-comments", "--out",
        os.path.join(out, "acquire_commented"))
    same_as = {"commented/series.csv": "sim_clearance/series.csv", "commented/impacts.csv": "sim_clearance/impacts.csv",
               "vr_commented/REC.csv": "vr/REC.csv", "vr_commented/REC.truth.csv": "vr/REC.truth.csv",
               "sweep_commented/sweep.csv": "sweep/sweep.csv",
               "report_commented/summary.csv": "report/summary.csv",
               "report_commented/series/thesis_350rpm_0254mm.csv": "report/series/thesis_350rpm_0254mm.csv",
               "analyze_commented/averaged.csv": "analyze/averaged.csv",
               "acquire_commented/pulses.csv": "acquire/pulses.csv"}
    for rel, plain_rel in same_as.items():
        path = os.path.join(out, rel)
        with open(path, encoding="utf-8") as f:
            first = f.readline()
        if not first.startswith("# made by fourbar"):
            fail("%s with --csv-comments: first line %r" % (rel, first))
        if not pd.read_csv(path, comment="#").equals(pd.read_csv(os.path.join(out, plain_rel))):
            fail("%s: with --csv-comments the table differs from %s" % (rel, plain_rel))
    if not os.path.exists(os.path.join(out, "sweep_commented", "sweep.csv.json")):
        fail("sweep --csv-comments: no sweep.csv.json (the JSON is written either way)")
    run("acquire", os.path.join(out, "vr_commented", "REC.csv"), "--out", os.path.join(out, "vr_commented_acquire"))
    a = pd.read_csv(os.path.join(out, "vr_acquire", "revolutions.csv"))
    b = pd.read_csv(os.path.join(out, "vr_commented_acquire", "revolutions.csv"))
    if not a.equals(b):
        fail("acquire reads the CSV recording differently with and without its '#' lines")

print("csv_in_pandas: %d CSV files, %d rows read by pandas %s; %d failures"
      % (len(found), rows, pd.__version__, len(failures)))
sys.exit(1 if failures else 0)

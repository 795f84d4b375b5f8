"""scripts/bilayer_results.py (docs/sweeps.md), the reader of results for
notebooks, against the files it reads:
  - a sweep of scripts/sweep over Example 1 (partial_closure.prm, 16 cells,
    Loads/Constants c = 1e-3 mu1 and c = 2e-3 mu1, and a point bilayer
    refuses): load() gives a Sweep whose table columns are sweep.csv's as
    numbers (the failed point's values NaN, the varied values as text),
    whose energy and G are each run's summary.json numbers, and whose runs
    are the points' Runs (None for the failed point);
  - a run: its summary and cycles are summary.json's; its table columns
    are table.csv's (the dofs whole numbers, the energy the cycles'); its
    interface CSV is read only when asked for, and its columns are the
    file's; used_parameters.prm is its text;
  - a growth run (growth_full_opening.prm): growth.csv's columns are
    summary.json's growth steps (load factor, energy, G of tip 1);
  - the command line prints an overview of a sweep and of a run (exit 0)
    and one line, exit 1, for a folder that holds neither.
Skipped (77) where this Python has no numpy.
Usage: python3 results_reader.py BILAYER SOURCE_DIR"""
import csv
import json
import math
import os
import subprocess
import sys
import tempfile

bilayer, source = sys.argv[1:3]
try:
    import numpy as np
except ImportError:
    print("numpy is missing: skipped")
    sys.exit(77)
sys.path.insert(0, os.path.join(source, "scripts"))
import bilayer_results  # noqa: E402

READER = os.path.join(source, "scripts", "bilayer_results.py")
failures = 0


def check(what, ok):
    global failures
    print("%s: %s" % (what, "yes" if ok else "NO"))
    failures += 0 if ok else 1


def same(values, expected):
    """Equal arrays, None and NaN alike."""
    expected = [math.nan if e is None else e for e in expected]
    return len(values) == len(expected) and all(
        (math.isnan(a) and math.isnan(b)) or a == b for a, b in zip(values, expected))


def check_sweep(folder):
    sweep = bilayer_results.load(folder)
    check("a Sweep of 3 points over Loads/Constants, Materials/Layer 1/Young's modulus",
          isinstance(sweep, bilayer_results.Sweep) and sweep.table.rows == 3 and
          sweep.entries == ["Loads/Constants", "Materials/Layer 1/Young's modulus"])
    with open(os.path.join(folder, "sweep.csv")) as f:
        rows = list(csv.DictReader(f))
    check("the varied values as text, the exit statuses whole numbers",
          list(sweep.table["Loads/Constants"]) == [r["Loads/Constants"] for r in rows] and
          sweep.table["exit"].dtype == np.int64 and list(sweep.table["exit"]) == [0, 1, 0])
    summaries = [None if r is None else r.summary for r in sweep.runs]
    check("runs: point 2 failed (None), the others Runs", summaries[1] is None and
          all(isinstance(sweep.runs[i], bilayer_results.Run) for i in (0, 2)))
    for i in (0, 2):
        with open(os.path.join(folder, rows[i]["folder"], "summary.json")) as f:
            summary = json.load(f)
        last = summary["cycles"][-1]
        check("point %d: the run's summary is summary.json" % (i + 1), summaries[i] == summary)
        check("point %d: energy, dofs, G and dG of each tip are summary.json's" % (i + 1),
              sweep.table["energy"][i] == last["energy"] and sweep.table["dofs"][i] == last["dofs"]
              and all(sweep.table["G_tip%d" % t][i] == tip["G"] and
                      sweep.table["dG_tip%d" % t][i] == tip["G_error"]
                      for t, tip in enumerate(last["crack_tips"], 1)))
    check("the failed point's energy and G are NaN",
          math.isnan(sweep.table["energy"][1]) and math.isnan(sweep.table["G_tip1"][1]))
    check("read as a dict too", sweep["table"] is sweep.table and "runs" in sweep.keys())
    return sweep.runs[0].path


def check_run(folder):
    run = bilayer_results.load(folder)
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    check("a Run: summary and cycles are summary.json's",
          isinstance(run, bilayer_results.Run) and run.summary == summary and
          run.cycles == summary["cycles"] and run["cycles"] is run.cycles)
    with open(os.path.join(folder, "table.csv")) as f:
        table = list(csv.DictReader(l for l in f if not l.startswith("#")))
    check("table: table.csv's columns, one entry per cycle",
          run.table.names == list(table[0]) and run.table.rows == len(summary["cycles"]))
    check("table: the dofs whole numbers, the energy the cycles'",
          run.table["dofs"].dtype == np.int64 and
          list(run.table["dofs"]) == [c["dofs"] for c in summary["cycles"]] and
          same(run.table["energy"], [c["energy"] for c in summary["cycles"]]))
    check("the interface CSV not read before it is asked for",
          list(run.interface) == [0] and not run.interface.read)
    with open(os.path.join(folder, "interface-00.csv")) as f:
        rows = list(csv.DictReader(l for l in f if not l.startswith("#")))
    columns = run.interface[0]
    check("interface[0]: the columns and numbers of interface-00.csv",
          columns.names == list(rows[0]) and columns.rows == len(rows) and
          all(same(columns[k], [float(r[k]) for r in rows]) for k in ("x", "jump_normal", "s")))
    with open(os.path.join(folder, "used_parameters.prm")) as f:
        check("parameters: used_parameters.prm", run.parameters == f.read())
    check("no growth.csv: growth None", run.growth is None)


def check_growth(tmp):
    folder = os.path.join(tmp, "growth")
    subprocess.run([bilayer, os.path.join(source, "parameter_files", "growth_full_opening.prm"),
                    "--set", "Output/Output directory=" + folder, "--set", "Output/Write VTU=false"],
                   check=True, stdout=subprocess.DEVNULL)
    run = bilayer_results.load(folder)
    steps = run.summary["growth"]["steps"]
    check("growth: growth.csv's load factor, energy and G of tip 1 are the growth steps'",
          run.growth.rows == len(steps) and
          same(run.growth["load_factor"], [s["load_factor"] for s in steps]) and
          same(run.growth["energy"], [s["energy"] for s in steps]) and
          same(run.growth["tip1_G"], [s["tips"][0]["G"] for s in steps]))


def overview(folder):
    p = subprocess.run([sys.executable, READER, folder], stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, text=True)
    return p.returncode, p.stdout, p.stderr


with tempfile.TemporaryDirectory() as tmp:
    folder = os.path.join(tmp, "sweep")
    p = subprocess.run(
        [sys.executable, os.path.join(source, "scripts", "sweep"),
         os.path.join(source, "parameter_files", "partial_closure.prm"), "--bilayer", bilayer,
         "--set", "Output/Write VTU=false", "--set", "Mesh/Cells along Sigma=16", "--zip",
         "--vary", "Loads/Constants=c = 1e-3*mu1,c = 1e-3*mu1,c = 2e-3*mu1",
         "--vary", "Materials/Layer 1/Young's modulus=200,-5,200", "--output", folder],
        stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    check("the sweep: exit 1 (one point refused)", p.returncode == 1)
    run_folder = check_sweep(folder)
    check_run(run_folder)
    check_growth(tmp)
    code, out, err = overview(folder)
    check("overview of the sweep: exit 0, its points", code == 0 and out.startswith("sweep: ") and
          "3 points" in out and len(out.splitlines()) <= 24)
    code, out, err = overview(run_folder)
    check("overview of a run: exit 0, its tips", code == 0 and out.startswith("run: ") and
          "tip 2" in out)
    code, out, err = overview(tmp)
    check("a folder of neither: one line, exit 1",
          code == 1 and out == "" and len(err.splitlines()) == 1 and "summary.json" in err)

print("%d failures" % failures)
sys.exit(1 if failures else 0)

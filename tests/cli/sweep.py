"""scripts/sweep (docs/sweeps.md) on Example 1 (partial_closure.prm, 16 and
32 cells along Sigma, the crack faces free to interpenetrate: a linear
problem; a uniform pressure c on the top of layer 1; Uzawa with the
scale-invariant relative stopping rule):
  - a 2 x 2 grid of Loads/Constants (c = 1e-3 mu1, c = 2e-3 mu1) and
    Mesh/Cells along Sigma (16, 32), two points at a time: sweep.csv and
    sweep.md have the four points in grid order with their values; on each
    mesh doubling the loads multiplies the energy, and G, dG, G_I, G_II of
    each tip by 4 (the problem is linear: u scales with the load, Pi and G
    with its square) and leaves the dofs as they are; the phase angle is
    atan(sqrt(G_II / G_I)) in degrees at both loads; the
    energy is negative (Pi = -1/2 l(u) at equilibrium); where summary.json
    has boundary_parts, Fx_<part>, Fy_<part>, ux_<part>, uy_<part> are its
    numbers, double with the loads, the top's force is the resultant
    (0, -2 c) of the pressure on its length 2, and the forces of all parts
    balance (no body force); where it has none, no such column;
  - the plot of G_tip1 against the cells: a PNG and a PDF, one curve of two
    points with error bars per value of c;
  - the same sweep again runs nothing (every point kept: summary.json and
    the markers untouched); with another --set it is refused (exit 1) and
    changes nothing;
  - three zipped points, one refused by bilayer (Young's modulus -5: exit 1)
    and one whose checks fail (3 iterations: exit 2): the sweep exits 1,
    the table holds each exit status and first error line, the failed
    points' stderr.txt the line, the good point its values; a rerun keeps
    the good point and reruns the two others;
  - bad input: --zip over lists of two lengths, an unknown entry, a range
    of count 0 are one line "sweep: error: ..." and exit 2; an --output
    holding a file of the user is refused (exit 1) and the file kept.
Skipped (77) without gnuplot.
Usage: python3 sweep.py BILAYER SOURCE_DIR"""
import csv
import glob
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

bilayer, source = sys.argv[1:3]
if shutil.which("gnuplot") is None:
    print("gnuplot is missing: skipped")
    sys.exit(77)
SWEEP = os.path.join(source, "scripts", "sweep")
SCENE = os.path.join(source, "parameter_files", "partial_closure.prm")
BASE = ["--set", "Output/Write VTU=false", "--set", "Contact/Non-penetration on the crack=false",
        "--set", "Solver/Stopping rule=relative", "--set", "Loads/Layer 1/Traction on top side=0; -c"]
GRID = ["--vary", "Loads/Constants=c = 1e-3*mu1,c = 2e-3*mu1",
        "--vary", "Mesh/Cells along Sigma=16,32"]
MU1 = 200 / (2 * (1 + 0.28))   # the shear modulus of layer 1 (c = 1e-3 mu1)
failures = 0


def check(what, ok):
    global failures
    print("%s: %s" % (what, "yes" if ok else "NO"))
    failures += 0 if ok else 1


def sweep(*args):
    p = subprocess.run([sys.executable, SWEEP, SCENE, "--bilayer", bilayer] + list(args),
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    return p.returncode, p.stdout, p.stderr


def rows_of(folder):
    with open(os.path.join(folder, "sweep.csv")) as f:
        return list(csv.DictReader(f))


def num(row, key):
    """A cell of ROW as a number (NaN where empty or missing)."""
    text = row.get(key) or ""
    return float(text) if text else math.nan


def close(a, b, tol):
    return abs(a - b) <= tol * max(abs(a), abs(b), 1e-300)


def stamps(folder):
    return {p: os.stat(p).st_mtime_ns for p in glob.glob(os.path.join(folder, "runs", "*", "*")) +
            glob.glob(os.path.join(folder, "runs", "*", ".sweep-point"))}


def check_parts(rows, summaries):
    """The boundary-part columns against summary.json and the mechanics."""
    parts = [p["name"] for p in summaries[0]["cycles"][-1].get("boundary_parts", [])]
    if not parts:
        check("no boundary_parts in summary.json: no force columns",
              not any(k.startswith(("Fx_", "uy_")) for k in rows[0]))
        return
    ok = True
    for row, s in zip(rows, summaries):
        for part in s["cycles"][-1]["boundary_parts"]:
            for col, key, i in (("Fx", "force", 0), ("Fy", "force", 1),
                                ("ux", "mean_displacement", 0), ("uy", "mean_displacement", 1)):
                ok = ok and num(row, "%s_%s" % (col, part["name"])) == part[key][i]
    check("Fx, Fy, ux, uy of the parts %s: summary.json's numbers" % ", ".join(parts), ok)
    for n in ("16", "32"):
        one, two = [r for r in rows if r["Mesh/Cells along Sigma"] == n]
        scale = max(abs(num(one, k)) for k in one if k.startswith(("Fx_", "Fy_")))
        uscale = max(abs(num(one, k)) for k in one if k.startswith(("ux_", "uy_")))
        doubled = all(abs(num(two, k) - 2 * num(one, k)) <=
                      1e-8 * (scale if k.startswith("F") else uscale)
                      for k in one if k.startswith(("Fx_", "Fy_", "ux_", "uy_")))
        check("%s cells: forces and mean displacements double with the loads" % n, doubled)
        for row, c in ((one, 1e-3 * MU1), (two, 2e-3 * MU1)):
            check("%s cells, c = %.6g: the top's force is (0, -2 c)" % (n, c),
                  abs(num(row, "Fx_top")) <= 1e-12 and close(num(row, "Fy_top"), -2 * c, 1e-10))
            for axis in ("Fx", "Fy"):
                total = sum(num(row, "%s_%s" % (axis, p)) for p in parts)
                check("%s cells, c = %.6g: the parts' %s balance (sum %.2e)" % (n, c, axis, total),
                      abs(total) <= 1e-8 * scale * (2 if row is two else 1))


def check_grid(folder):
    rows = rows_of(folder)
    check("sweep.csv: 4 rows", len(rows) == 4)
    expected = [(c, n) for c in ("c = 1e-3*mu1", "c = 2e-3*mu1") for n in ("16", "32")]
    check("the points in grid order with their values",
          [(r["Loads/Constants"], r["Mesh/Cells along Sigma"]) for r in rows] == expected and
          [r["point"] for r in rows] == ["1", "2", "3", "4"])
    check("every point exit 0, converged, accepted, wall time > 0",
          all(r["exit"] == "0" and r["converged"] == "1" and r["accepted"] == "1" and
              num(r, "wall_s") > 0 for r in rows))
    summaries = []
    for r in rows:
        with open(os.path.join(folder, r["folder"], "summary.json")) as f:
            summaries.append(json.load(f))
    check("energy and G_tip1 are the last cycle's of summary.json",
          all(num(r, "energy") == s["cycles"][-1]["energy"] and
              num(r, "G_tip1") == s["cycles"][-1]["crack_tips"][0]["G"]
              for r, s in zip(rows, summaries)))
    for n in ("16", "32"):
        one, two = [r for r in rows if r["Mesh/Cells along Sigma"] == n]
        check("%s cells: the energy is negative and 4 times as large with 2 c (ratio %.12g)" % (
            n, num(two, "energy") / num(one, "energy")),
            num(one, "energy") < 0 and close(num(two, "energy"), 4 * num(one, "energy"), 1e-8))
        for t in (1, 2):
            g1, g2 = num(one, "G_tip%d" % t), num(two, "G_tip%d" % t)
            check("%s cells, tip %d: G and dG 4 times as large with 2 c (G ratio %.12g)" % (
                n, t, g2 / g1), close(g2, 4 * g1, 1e-6) and
                close(num(two, "dG_tip%d" % t), 4 * num(one, "dG_tip%d" % t), 1e-6))
            check("%s cells, tip %d: G_I and G_II 4 times as large with 2 c" % (n, t),
                  all(abs(num(two, k % t) - 4 * num(one, k % t)) <= 1e-6 * g2
                      for k in ("G_I_tip%d", "G_II_tip%d")))
            psi = [math.degrees(math.atan2(math.sqrt(num(r, "G_II_tip%d" % t)),
                                           math.sqrt(num(r, "G_I_tip%d" % t)))) for r in (one, two)]
            check("%s cells, tip %d: psi = atan(sqrt(G_II / G_I)) = %.6g deg, with 2 c too" % (
                n, t, psi[0]), all(abs(num(r, "psi_tip%d" % t) - p) <= 1e-6
                                  for r, p in zip((one, two), psi)))
        check("%s cells: the same dofs" % n, one["dofs"] == two["dofs"])
    check("32 cells have more dofs than 16", int(rows[1]["dofs"]) > int(rows[0]["dofs"]))
    with open(os.path.join(folder, "sweep.md")) as f:
        md = [l for l in f.read().splitlines() if l.startswith("|")]
    check("sweep.md: a header, a rule and 4 rows, no error column",
          len(md) == 6 and "Loads/Constants" in md[0] and "error" not in md[0])
    check_parts(rows, summaries)


def check_plot(folder):
    png, pdf = (os.path.join(folder, "sweep-G_tip1." + e) for e in ("png", "pdf"))
    check("sweep-G_tip1.png and .pdf written",
          os.path.isfile(png) and open(png, "rb").read(8) == b"\x89PNG\r\n\x1a\n" and
          os.path.isfile(pdf) and open(pdf, "rb").read(5) == b"%PDF-")
    with open(os.path.join(folder, "sweep-G_tip1.dat")) as f:
        blocks = [b for b in f.read().split("\n\n\n") if b.strip()]
    points = [[l.split() for l in b.splitlines() if l and not l.startswith("#")] for b in blocks]
    check("the figure's data: one curve per c, two points each with an error bar",
          len(points) == 2 and all(len(p) == 2 and all(len(x) == 3 for x in p) for p in points))


def check_rerun(folder):
    before = stamps(folder)
    code, out, err = sweep(*(BASE + GRID + ["--output", folder]))
    check("the same sweep again: exit 0, 0 ran, 4 kept",
          code == 0 and "4 points: 0 ran, 4 kept" in out and out.count("] kept") == 4)
    check("... nothing of the points rewritten", stamps(folder) == before)
    code, out, err = sweep(*(BASE + GRID + ["--output", folder, "--set", "Solver/Tolerance=1e-7"]))
    check("with another --set: refused, exit 1, one line naming the other command",
          code == 1 and err.startswith("sweep: ") and "another command" in err and
          len(err.strip().splitlines()) == 1 and "start" not in out)
    check("... nothing of the points changed", stamps(folder) == before)


def check_failures(folder):
    zipped = ["--zip", "--vary", "Materials/Layer 1/Young's modulus=200,-5,200",
              "--vary", "Solver/Maximum iterations=100000,100000,3"]
    args = ["--set", "Output/Write VTU=false", "--set", "Mesh/Cells along Sigma=16"] + zipped + \
        ["--output", folder]
    code, out, err = sweep(*args)
    rows = rows_of(folder)
    check("a failing point: exit 1, 3 rows", code == 1 and len(rows) == 3)
    check("... the good point kept with its values",
          rows[0]["exit"] == "0" and rows[0]["energy"] != "" and rows[0]["error"] == "" and
          os.path.isfile(os.path.join(folder, rows[0]["folder"], "summary.json")))
    check("... Young's modulus -5: exit 1 and bilayer's error line",
          rows[1]["exit"] == "1" and rows[1]["error"].startswith("bilayer: error:") and
          "Young's modulus" in rows[1]["error"] and rows[1]["energy"] == "")
    check("... 3 iterations: exit 2 and the failed checks' line",
          rows[2]["exit"] == "2" and "FAILED" in rows[2]["error"] and rows[2]["G_tip1"] == "")
    with open(os.path.join(folder, rows[1]["folder"], "stderr.txt")) as f:
        check("... the failed point's stderr.txt holds the line", rows[1]["error"] in f.read())
    check("... stderr names the failed points", "2 of 3 points failed" in err)
    code, out, err = sweep(*args)
    check("rerun: the good point kept, the failed ones run again, exit 1",
          code == 1 and "3 points: 2 ran, 1 kept (finished before), 2 failed" in out)


def check_refusals(tmp):
    for what, args in (
            ("--zip over lists of two lengths", ["--zip", "--vary", "Loads/Constants=c = 1,c = 2",
                                                 "--vary", "Mesh/Cells along Sigma=8,16,32"]),
            ("an unknown entry", ["--vary", "Loads/Load factr=1,2"]),
            ("a range of count 0", ["--vary", "Mesh/Cells along Sigma=8:16:0"])):
        code, out, err = sweep(*(args + ["--output", os.path.join(tmp, "never")]))
        check("%s: exit 2, one line 'sweep: error:'" % what,
              code == 2 and err.startswith("sweep: error: ") and len(err.splitlines()) == 1 and
              not os.path.exists(os.path.join(tmp, "never")))
    user = os.path.join(tmp, "user")
    os.mkdir(user)
    with open(os.path.join(user, "notes.txt"), "w") as f:
        f.write("mine\n")
    code, out, err = sweep("--vary", "Mesh/Cells along Sigma=8", "--output", user)
    check("an --output of the user's: exit 1, one line, the file kept",
          code == 1 and err.startswith("sweep: ") and len(err.splitlines()) == 1 and
          sorted(os.listdir(user)) == ["notes.txt"] and open(os.path.join(user, "notes.txt")).read()
          == "mine\n")


with tempfile.TemporaryDirectory() as tmp:
    grid = os.path.join(tmp, "grid")
    code, out, err = sweep(*(BASE + GRID + ["--output", grid, "--jobs", "2",
                                            "--plot", "G_tip1", "--against",
                                            "Mesh/Cells along Sigma"]))
    check("the 2 x 2 grid: exit 0 (%s)" % (err.strip().splitlines() or ["no message"])[-1],
          code == 0)
    check("... a start and an end line per point",
          out.count("] start") == 4 and out.count("] done") == 4)
    if code == 0:
        check_grid(grid)
        check_plot(grid)
        check_rerun(grid)
    check_failures(os.path.join(tmp, "failing"))
    check_refusals(tmp)

print("%d failures" % failures)
sys.exit(1 if failures else 0)

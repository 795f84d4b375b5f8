"""What the study scripts of scripts/ compute from bilayer's results
(standard library only). The Python scripts import it from their own
directory (`import study_lib`):

    extrapolate(dofs, energies) -> (Pi_ref, b) or None
                           Richardson/Aitken extrapolation of three
                           energies Pi_k = Pi_ref + C N_k^-b (b solved for)
    loglog_fit(xs, ys) -> (slope, intercept)
                           the least-squares line of log y against log x
    summary(directory)     summary.json of a result directory, parsed
    cycles(directory)      its list of cycles
    interface_path(directory, cycle)
                           the interface CSV of a cycle (interface-NN.csv)
    interface_rows(path)   the rows of an interface CSV as dicts of strings
                           (its '#' lines skipped)
    table_rows(directory)  the rows of table.csv as dicts of strings

Reading a folder the user names (any folder: bilayer's or not), each
exiting 1 with one line "SCRIPT: ..." where it cannot, never a traceback:
    results_folder(path, script, what)
                           the absolute path of an existing, readable folder
    read_json(path, script, required)
                           a JSON object (a dict) from a file; None where
                           the file is missing and not required
    read_csv(path, script, columns)
                           (rows as dicts of strings, header) of a CSV file
                           ('#' lines skipped) whose header has COLUMNS and
                           every row as many cells as the header
    cell_number(row, column, path, script)
                           a cell of read_csv() as a float: empty, null, nan
                           are NaN, text that is no finite number exits 1
    sequence_settings(method, refinement, degree, cycles, tolerance)
                           the settings of one mesh sequence of
                           scripts/work_precision (from 8 cells along Sigma)
    reference_energy(prm, directory) -> (Pi_ref, b, cycles)
                           Pi_ref of a scene as scripts/work_precision finds
                           it: its adaptive Q2 sequence (active set, KKT
                           1e-10, 26 cycles) extrapolated through its last
                           three cycles

Run as a program (for the bash scripts of scripts/, which carry no Python):
    python3 scripts/study_lib.py work DIR LABEL WARM
        two lines of the run in DIR (scripts/adaptive_study): the dofs, and
        the outer iterations and solves of each cycle
    python3 scripts/study_lib.py processes SERIAL PARALLEL NP
        one line comparing the run PARALLEL on NP processes with the run
        SERIAL (scripts/gmsh_mpi): relative energy difference per cycle,
        equal iteration counts, bit-identical interface CSV files
    python3 scripts/study_lib.py example DIR
        one line of the last cycle of the run in DIR (scripts/run_examples)
"""
import csv
import filecmp
import json
import math
import os
import subprocess
import sys

import bilayer_run

# The sequence whose last three cycles give Pi_ref (scripts/work_precision,
# scripts/bench_fine_mesh): adaptive Q2, active set, KKT tolerance 1e-10.
REFERENCE = {"method": "active set", "refinement": "adaptive", "degree": 2, "cycles": 26,
             "tolerance": "1e-10"}


def extrapolate(dofs, energies):
    """(Pi_ref, b) from Pi_k = Pi_ref + C N_k^-b through three cycles
    (N_k = DOFS, Pi_k = ENERGIES), b solved for by bisection in
    [1e-3, 20]; None where the dofs do not grow or the energies do not
    converge monotonically (no b > 0 fits)."""
    (n1, n2, n3), (e1, e2, e3) = dofs, energies
    if not n1 < n2 < n3 or (e1 - e2) * (e2 - e3) <= 0:
        return None
    q = (e1 - e2) / (e2 - e3)
    # g(b) = (N1^-b - N2^-b) / (N2^-b - N3^-b) grows with b, from
    # log(N2/N1) / log(N3/N2) at b = 0.
    g = lambda b: (n1 ** -b - n2 ** -b) / (n2 ** -b - n3 ** -b)
    lo, hi = 1e-3, 20.0
    if not g(lo) < q < g(hi):
        return None
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if g(mid) < q else (lo, mid)
    b = 0.5 * (lo + hi)
    c = (e2 - e3) / (n2 ** -b - n3 ** -b)
    return e3 - c * n3 ** -b, b


def loglog_fit(xs, ys):
    """(slope, intercept) of the least-squares line log y = slope log x +
    intercept (y ~ x^slope); the slope is nan where all x are equal."""
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    sxx = sum((a - mx) ** 2 for a in lx)
    slope = sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sxx if sxx > 0 else float("nan")
    return slope, my - slope * mx


def summary(directory):
    """summary.json of the result directory DIRECTORY, parsed (a dict);
    exits 1 with one line where it is missing or not a JSON object."""
    return read_json(os.path.join(directory, "summary.json"), os.path.basename(sys.argv[0]))


def cycles(directory):
    """The cycles of summary.json in DIRECTORY (a list of dicts); exits 1
    with one line where it has none."""
    c = summary(directory).get("cycles")
    if not isinstance(c, list) or not c or not all(isinstance(x, dict) for x in c):
        _refuse(os.path.basename(sys.argv[0]), "%s has no list of cycles: not a summary.json "
                "of bilayer" % os.path.join(directory, "summary.json"))
    return c


def interface_path(directory, cycle):
    """The interface CSV of CYCLE in DIRECTORY."""
    return os.path.join(directory, "interface-%02d.csv" % cycle)


def interface_rows(path):
    """The rows of the interface CSV PATH as dicts {column: text}; its
    comment lines ('#': the tips, the crack pieces) are skipped."""
    with open(path) as f:
        return list(csv.DictReader(l for l in f if not l.startswith("#")))


def table_rows(directory):
    """The rows of table.csv in DIRECTORY as dicts {column: text}; its
    comment lines ('#': the crack tips) are skipped."""
    with open(os.path.join(directory, "table.csv")) as f:
        return list(csv.DictReader(l for l in f if not l.startswith("#")))


def _refuse(script, message):
    sys.exit("%s: %s" % (script, message))


def results_folder(path, script, what="the results folder"):
    """The absolute path of the folder PATH (WHAT in messages); exits 1
    with one line where it is empty, missing, not a folder or not
    readable."""
    if not path:
        _refuse(script, "%s is an empty string: name a folder" % what)
    full = os.path.abspath(path)
    if not os.path.exists(full):
        _refuse(script, "%s %s does not exist" % (what, path))
    if not os.path.isdir(full):
        _refuse(script, "%s %s is not a folder (give a bilayer output directory)" % (what, path))
    try:
        os.listdir(full)
    except OSError as e:
        _refuse(script, "%s %s cannot be read: %s" % (what, path, e.strerror or e))
    return full


def _read_text(path, script, what):
    """The text of the regular file PATH; exits 1 with one line where it
    is not a readable UTF-8 file."""
    if os.path.isdir(path):
        _refuse(script, "%s is a folder, not %s" % (path, what))
    if not os.path.isfile(path):
        _refuse(script, "%s is not a regular file (%s)" % (path, what))
    try:
        with open(path, encoding="utf-8") as f:
            return f.read()
    except UnicodeDecodeError as e:
        _refuse(script, "%s is not a text file (byte %d is not UTF-8): not %s" % (
            path, e.start, what))
    except OSError as e:
        _refuse(script, "%s cannot be read: %s" % (path, e.strerror or e))


def read_json(path, script, required=True, what="a summary.json of bilayer"):
    """The JSON object (a dict) in the file PATH; None where PATH does not
    exist and REQUIRED is false. Exits 1 with one line where it is not a
    readable file, not JSON, or not an object."""
    if not os.path.lexists(path):
        if required:
            _refuse(script, "no %s (%s)" % (os.path.basename(path), path))
        return None
    data = _read_text(path, script, what)
    try:
        value = json.loads(data)
    except ValueError as e:
        _refuse(script, "%s is not JSON (%s): not %s" % (
            path, " ".join(str(e).split())[:120], what))
    except RecursionError:
        _refuse(script, "%s nests too deep: not %s" % (path, what))
    if not isinstance(value, dict):
        _refuse(script, "%s holds a JSON %s, not an object: not %s" % (
            path, type(value).__name__.replace("NoneType", "null"), what))
    return value


def read_csv(path, script, columns=(), what="a CSV file of bilayer"):
    """(rows, header) of the CSV file PATH, its '#' lines skipped: rows
    as dicts {column: text} with the 1-based line of the file in
    row["#line"]. Exits 1 with one line where the file is missing or not
    readable text, has no header, lacks one of COLUMNS, repeats a column,
    or has a row whose cell count differs from the header's."""
    if not os.path.lexists(path):
        _refuse(script, "no %s (%s)" % (os.path.basename(path), path))
    lines = []
    for number, line in enumerate(_read_text(path, script, what).splitlines(), 1):
        if not line.startswith("#") and line.strip():
            lines.append((number, line))
    try:
        table = list(csv.reader([l for _, l in lines]))
    except csv.Error as e:
        _refuse(script, "%s is not a CSV file (%s): not %s" % (path, e, what))
    if not table:
        _refuse(script, "%s has no header line: not %s" % (path, what))
    header = [h.strip() for h in table[0]]
    missing = [c for c in columns if c not in header]
    if missing:
        _refuse(script, "%s has no column %s (its columns: %s): not %s" % (
            path, ", ".join(missing), ", ".join(header)[:200] or "none", what))
    if len(set(header)) != len(header):
        _refuse(script, "%s repeats a column of its header: not %s" % (path, what))
    rows = []
    for (number, _), cells in zip(lines[1:], table[1:]):
        if len(cells) != len(header):
            _refuse(script, "%s line %d has %d cells where the header has %d: not %s" % (
                path, number, len(cells), len(header), what))
        row = dict(zip(header, cells))
        row["#line"] = number
        rows.append(row)
    return rows, header


def cell_number(row, column, path, script):
    """ROW[COLUMN] of read_csv() as a float: empty, null and nan are NaN
    (bilayer writes a number that is not finite as null); exits 1 with one
    line naming the file, the line and the column where the text is not a
    number or an infinite one."""
    text = (row.get(column) or "").strip()
    if text in ("", "null", "nan"):
        return float("nan")
    try:
        value = float(text)
    except ValueError:
        value = None
    if value is None or math.isinf(value):
        _refuse(script, "%s line %s: %s = %r is not a finite number (not bilayer's)" % (
            path, row.get("#line", "?"), column, text[:40]))
    return value


def sequence_settings(method, refinement, degree, cycles, tolerance):
    """The settings of one mesh sequence of scripts/work_precision: from 8
    cells along Sigma, METHOD with theta = auto and warm starts, stopped at
    the relative KKT residual TOLERANCE, CYCLES cycles of REFINEMENT, DEGREE
    on both layers, no VTU."""
    return {
        "Mesh/Cells along Sigma": "8",
        "Mesh/Number of cycles": str(cycles),
        "Mesh/Refinement": refinement,
        "Mesh/Polynomial degree of layer 1": str(degree),
        "Mesh/Polynomial degree of layer 2": str(degree),
        "Solver/Method": method,
        "Solver/Uzawa step theta": "auto",
        "Solver/Stopping rule": "kkt",
        "Solver/Tolerance": tolerance,
        "Solver/Warm start": "true",
        "Output/Write VTU": "false",
        "Output/Progress interval": "0",
        "Output/Terminal output": "checks",
    }


def reference_energy(prm, directory, cycles=REFERENCE["cycles"]):
    """(Pi_ref, b, the cycles of summary.json) of the scene PRM: the
    REFERENCE sequence run into DIRECTORY and extrapolated through its last
    three cycles (Pi_k = Pi_ref + C N_k^-b); exits 1 with one line where
    the run fails or its energies do not converge monotonically."""
    settings = sequence_settings(REFERENCE["method"], REFERENCE["refinement"],
                                 REFERENCE["degree"], cycles, REFERENCE["tolerance"])
    run = bilayer_run.run(prm, settings, directory, stdout=subprocess.DEVNULL, stderr=None)
    if run.returncode != 0 or run.summary is None:
        sys.exit("%s: the reference sequence of %s failed (exit %d; its results: %s)" % (
            os.path.basename(sys.argv[0]), prm, run.returncode, run.directory or directory))
    sequence = run.summary["cycles"]
    fit = extrapolate([c["dofs"] for c in sequence[-3:]], [c["energy"] for c in sequence[-3:]])
    if fit is None:
        sys.exit("%s: the reference sequence of %s is not monotone enough to extrapolate" % (
            os.path.basename(sys.argv[0]), prm))
    return fit + (sequence,)


def solves(cycle):
    """The subdomain solves of a cycle, those of the preconditioner
    included."""
    return cycle["subdomain_solves"] + cycle["preconditioner_solves"]


def print_work(directory, label, warm):
    """scripts/adaptive_study: the dofs, outer iterations and solves of
    each cycle of the run in DIRECTORY."""
    d = cycles(directory)
    print("%-10s warm start %-5s  dofs %s" % (label, warm, " ".join(str(c["dofs"]) for c in d)))
    print("%-10s warm start %-5s  iterations %s  solves %s  (total %d)" % (
        label, warm, " ".join(str(c["iterations"]) for c in d),
        " ".join(str(solves(c)) for c in d), sum(solves(c) for c in d)))


def print_processes(serial, parallel, processes):
    """scripts/gmsh_mpi: the run PARALLEL on PROCESSES processes against
    the run SERIAL."""
    a, b = cycles(serial), cycles(parallel)
    print("%s processes: relative energy difference per cycle %s; iterations equal: %s; "
          "interface CSV identical: %s" % (
              processes,
              ", ".join("%.1e" % (abs(x["energy"] - y["energy"]) / abs(x["energy"]))
                        for x, y in zip(a, b)),
              "yes" if all(x["iterations"] == y["iterations"] for x, y in zip(a, b)) else "NO",
              "yes" if all(filecmp.cmp(interface_path(serial, c), interface_path(parallel, c),
                                       False) for c in range(len(a))) else "no"))


def print_example(directory):
    """scripts/run_examples: the last cycle of the run in DIRECTORY."""
    d = summary(directory)
    c = cycles(directory)[-1]
    print("%-24s %6d %7d %14.6e %10.2e %10.2e %8.3f %8.3f" % (
        d["scene"], c["iterations"], c["subdomain_solves"], c["energy"],
        c["constraint_violation"], c["max_penetration"],
        c["wall_seconds"]["setup"], c["wall_seconds"]["solve"]))


def main(argv):
    """The command-line interface for the bash scripts (see the module's
    docstring)."""
    if len(argv) == 4 and argv[0] == "work":
        print_work(*argv[1:])
    elif len(argv) == 4 and argv[0] == "processes":
        print_processes(*argv[1:])
    elif len(argv) == 2 and argv[0] == "example":
        print_example(argv[1])
    else:
        print("study_lib.py: usage: study_lib.py work DIR LABEL WARM | processes SERIAL "
              "PARALLEL NP | example DIR", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    bilayer_run.guard(lambda: main(sys.argv[1:]), "study_lib.py")

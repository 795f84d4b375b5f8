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
    """summary.json of the result directory DIRECTORY, parsed."""
    with open(os.path.join(directory, "summary.json")) as f:
        return json.load(f)


def cycles(directory):
    """The cycles of summary.json in DIRECTORY (a list of dicts)."""
    return summary(directory)["cycles"]


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
    c = d["cycles"][-1]
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
        sys.exit("usage: study_lib.py work DIR LABEL WARM | processes SERIAL PARALLEL NP | "
                 "example DIR")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

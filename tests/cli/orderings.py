"""Solver/Ordering (docs/performance.md, "Orderings"): the fill-reducing
ordering of the subproblems' Cholesky factorisations changes the order of
elimination, not the linear systems, so
  - the energy, G and the largest opening of Example 1 agree to round-off
    (1e-10 relative) under minimum degree, nested dissection and fewest
    flops, each run accepted;
  - summary.json's factors name the ordering asked for, with flops and
    entries of a Cholesky factor: entries >= the subproblem's dofs (the
    diagonal) and flops >= entries (CHOLMOD's count, the sum of the squared
    column counts of L);
  - fewest flops keeps, subproblem by subproblem, the ordering with fewer
    flops of the other two runs, with exactly their flops and entries (the
    analyses are deterministic).
The factorisations' OpenMP loops (CHOLMOD's scatter of each update into
independent columns of L, include/bilayer/core/build_info.h) change no
operation on any entry, so
  - a run with them in teams of one (the default where each task's BLAS
    has one thread, reported as build.threads.factorisation_loops = 1) and
    a run with them as the OpenMP library sets them
    (BILAYER_OPENMP_LOOPS=library: factorisation_loops = 0) give the same
    energy and G bit for bit.
Example 1 (partial_closure.prm), Q1, 64 cells along Sigma (every
subproblem above the 4000 dofs from which fewest flops tries both), one
cycle, active set.
Usage: python3 orderings.py BILAYER PARAMETER_FILE_DIRECTORY"""
import json
import os
import subprocess
import sys
import tempfile

bilayer, scenes = sys.argv[1:3]
failures = 0


def check(what, ok):
    global failures
    print("%s: %s" % (what, "yes" if ok else "NO"))
    failures += 0 if ok else 1


def run(directory, ordering, env=None, whole=False):
    args = [bilayer, os.path.join(scenes, "partial_closure.prm"),
            "--set", "Output/Output directory=" + directory,
            "--set", "Output/Terminal output=checks", "--set", "Output/Write VTU=false",
            "--set", "Output/Write interface CSV=false", "--set", "Mesh/Number of cycles=1",
            "--set", "Mesh/Refinement=global", "--set", "Mesh/Cells along Sigma=64",
            "--set", "Solver/Method=active set", "--set", "Solver/Ordering=" + ordering]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL,
                   env=dict(os.environ, **(env or {})))
    summary = json.load(open(os.path.join(directory, "summary.json")))
    return summary if whole else summary["cycles"][-1]


with tempfile.TemporaryDirectory() as tmp:
    runs = {}
    for ordering in ("minimum degree", "nested dissection", "fewest flops"):
        runs[ordering] = run(os.path.join(tmp, ordering.replace(" ", "_")), ordering)
    loops = {}
    for name, env in (("teams of one", {"BILAYER_BLAS_THREADS": "1"}),
                      ("library", {"BILAYER_BLAS_THREADS": "1",
                                   "BILAYER_OPENMP_LOOPS": "library"})):
        loops[name] = run(os.path.join(tmp, "loops_" + name.replace(" ", "_")),
                          "minimum degree", env, whole=True)

md, nd, ff = runs["minimum degree"], runs["nested dissection"], runs["fewest flops"]
for name, c in runs.items():
    check("%s: accepted" % name, c["accepted"])
    names = [s.strip() for s in c["factors"]["ordering"].split(",")]
    if name != "fewest flops":
        check("%s: every factor ordered so (%s)" % (name, c["factors"]["ordering"]),
              names == [name] * 4)
    n_sub = c["dofs"] / 4.0
    check("%s: entries >= dofs, flops >= entries" % name,
          all(e >= 0.9 * n_sub and f >= e
              for e, f in zip(c["factors"]["entries"], c["factors"]["flops"])))
    rel = abs(c["energy"] - md["energy"]) / abs(md["energy"])
    check("%s: energy equal to minimum degree's (%.1e relative)" % (name, rel), rel <= 1e-10)
    for t, (a, b) in enumerate(zip(c["crack_tips"], md["crack_tips"])):
        rel_g = abs(a["G"] - b["G"]) / max(abs(b["G"]) for b in md["crack_tips"])
        check("%s: G of tip %d equal to minimum degree's (%.1e)" % (name, t + 1, rel_g),
              rel_g <= 1e-8)

check("nested dissection: fewer flops than minimum degree on some subproblem",
      any(a < b for a, b in zip(nd["factors"]["flops"], md["factors"]["flops"])))
chosen = [s.strip() for s in ff["factors"]["ordering"].split(",")]
for s in range(4):
    best = md if md["factors"]["flops"][s] <= nd["factors"]["flops"][s] else nd
    best_name = "minimum degree" if best is md else "nested dissection"
    check("fewest flops, subproblem %d: %s with its flops and entries" % (s + 1, best_name),
          chosen[s] == best_name and ff["factors"]["flops"][s] == best["factors"]["flops"][s]
          and ff["factors"]["entries"][s] == best["factors"]["entries"][s])

one, library = loops["teams of one"], loops["library"]
check("OpenMP loops: teams of one with one BLAS thread per call, the library's "
      "teams under BILAYER_OPENMP_LOOPS=library (%s, %s)"
      % (one["build"]["threads"], library["build"]["threads"]),
      one["build"]["threads"]["blas"] == 1
      and one["build"]["threads"]["factorisation_loops"] == 1
      and library["build"]["threads"]["factorisation_loops"] == 0)
a, b = one["cycles"][-1], library["cycles"][-1]
check("OpenMP loops: the same energy and G bit for bit (%r, %r)" % (a["energy"], b["energy"]),
      a["energy"] == b["energy"]
      and [t["G"] for t in a["crack_tips"]] == [t["G"] for t in b["crack_tips"]])

print("failures: %d" % failures)
sys.exit(1 if failures else 0)

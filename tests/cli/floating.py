#!/usr/bin/env python3
"""Floating subproblems and free specimens from the command line
(docs/floating.md), on Example 1 (parameter_files/partial_closure.prm, 8
cells along Sigma, one cycle):

  - Omega+ floating (Geometry/Clamped sides = bottom, the bottom traction
    off: both layers of Omega+ held through Sigma alone) and the free
    specimen (nothing clamped; Example 1's tractions, whose resultant force
    and moment vanish): each run by the active-set method, by the paper's
    Uzawa iteration and by FISTA (theta = auto, stopping rule kkt, relative
    KKT residual 1e-9), all accepted; the three energies agree to 1e-6
    relative and G at each tip to 1e-6 of the largest G (the same discrete
    problem; the solvers' tolerances);
  - summary.json names the floating subproblems (u+ and v+; all four for
    the free specimen, marked free), their anchors carry at most 1e-11 of
    the load scale (the balance's target; the acceptance tolerance is
    1e-6), and the reactions including the anchors balance the applied
    loads to the round-off bound plus 1e-10 of the forces;
  - dcb_growth.prm's double cantilever beam free and held by its clamp at
    the far end (the toughness raised beyond x = 20, where the crack
    arrests): every growth step agrees to 1e-8 (dcb_without_clamp());
  - under mpirun -np 2 the floating scene is refused in one line naming
    the floating subproblem and the one process, exit 1, nothing written.
Usage: floating.py BILAYER PARTIAL_CLOSURE_PRM
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

failures = []


def check(label, passed):
    print("%s: %s" % (label, "yes" if passed else "NO"))
    if not passed:
        failures.append(label)


def run(command, out, settings):
    args = list(command) + ["--set", "Output/Output directory=" + out,
                            "--set", "Mesh/Number of cycles=1",
                            "--set", "Mesh/Cells along Sigma=8",
                            "--set", "Output/Write VTU=false",
                            "--set", "Output/Write interface CSV=false"]
    for key, value in settings.items():
        args += ["--set", "%s=%s" % (key, value)]
    # (mpirun as root and on more processes than cores.)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    result = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            universal_newlines=True, env=env)
    return result.returncode, result.stdout, result.stderr


SOLVERS = {
    "active set": {"Solver/Method": "active set", "Solver/Tolerance": "1e-9"},
    "uzawa": {"Solver/Method": "uzawa", "Solver/Uzawa step theta": "auto",
              "Solver/Stopping rule": "kkt", "Solver/Tolerance": "1e-9"},
    "accelerated": {"Solver/Method": "accelerated",
                    "Solver/Uzawa step theta": "auto",
                    "Solver/Stopping rule": "kkt", "Solver/Tolerance": "1e-9"},
}
SCENES = {
    "Omega+ floating": ({"Geometry/Clamped sides": "bottom",
                         "Loads/Layer 1/Traction on bottom side": "0; 0"},
                        ["u+", "v+"], False),
    "free specimen": ({"Geometry/Clamped sides": ""},
                      ["u-", "u+", "v-", "v+"], True),
}


def growth_rows(directory):
    with open(os.path.join(directory, "growth.csv")) as f:
        return list(csv.DictReader(l for l in f if not l.startswith("#")))


def dcb_without_clamp(bilayer, prm, work):
    """The double cantilever beam of dcb_growth.prm (its arms pulled apart
    at the left end by +-P, balanced in force and moment) held by its clamp
    at the right end and free, the toughness raised 100-fold beyond x = 20
    so that the crack arrests there (a ligament of 20 arm heights): the
    clamp carries no force and the stresses decay within a few arm heights
    of the tip (Saint-Venant), so every growth step's load factor, crack
    length, energy and G agree to 1e-8."""
    runs = {}
    for name, clamped in (("clamped", "right"), ("free", "")):
        out = os.path.join(work, "dcb_" + name)
        args = [bilayer, prm, "--set", "Output/Output directory=" + out,
                "--set", "Output/Write VTU=false",
                "--set", "Output/Write interface CSV=false",
                "--set", "Geometry/Clamped sides=" + clamped,
                "--set", "Fracture/Toughness=0.01*(x < 20 ? 1 : 100)"]
        rc = subprocess.call(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        if rc != 0 or not os.path.exists(os.path.join(out, "growth.csv")):
            check("dcb_growth.prm %s: accepted (exit %d)" % (name, rc), False)
            return
        runs[name] = growth_rows(out)
    a, b = runs["clamped"], runs["free"]
    same = len(a) == len(b) and all(
        x["crack_length"] == y["crack_length"] and
        abs(float(x["load_factor"]) - float(y["load_factor"])) <=
        1e-8 * abs(float(x["load_factor"])) and
        abs(float(x["energy"]) - float(y["energy"])) <= 1e-8 * abs(float(x["energy"])) and
        abs(float(x["tip1_G"]) - float(y["tip1_G"])) <= 1e-8 * abs(float(x["tip1_G"]))
        for x, y in zip(a, b))
    grew = float(a[-1]["crack_length"]) >= 19
    check("dcb_growth.prm free and clamped at the far end: %d growth steps, load "
          "factor, crack length, energy and G agree to 1e-8" % len(a), same and grew)


def main():
    bilayer, prm = sys.argv[1], sys.argv[2]
    work = tempfile.mkdtemp(prefix="bilayer_floating_")
    try:
        for scene, (settings, names, free) in SCENES.items():
            cycles = {}
            for solver, choice in SOLVERS.items():
                out = os.path.join(work, (scene + " " + solver).replace(" ", "_"))
                rc, _, err = run([bilayer, prm], out, dict(settings, **choice))
                summary = os.path.join(out, "summary.json")
                if rc != 0 or not os.path.exists(summary):
                    check("%s, %s: accepted (exit %d: %s)"
                          % (scene, solver, rc, err.strip()[-300:]), False)
                    continue
                cycles[solver] = json.load(open(summary))["cycles"][-1]
            if len(cycles) != len(SOLVERS):
                continue
            check("%s: accepted by the three solvers" % scene,
                  all(c["accepted"] for c in cycles.values()))
            energies = [c["energy"] for c in cycles.values()]
            check("%s: the three energies agree to 1e-6" % scene,
                  max(energies) - min(energies) <= 1e-6 * max(abs(e) for e in energies))
            tips = [[t["G"] for t in c["crack_tips"]] for c in cycles.values()]
            largest = max(abs(g) for t in tips for g in t)
            check("%s: G at each tip agrees to 1e-6 of the largest G" % scene,
                  all(len(t) == len(tips[0]) for t in tips) and
                  all(abs(t[k] - tips[0][k]) <= 1e-6 * largest
                      for t in tips for k in range(len(t))))
            floating = [c.get("floating", {}) for c in cycles.values()]
            check("%s: floating subproblems named (%s)%s"
                  % (scene, ", ".join(names), ", free specimen" if free else ""),
                  all(f.get("subproblems") == names and
                      f.get("free_specimen") == free for f in floating))
            check("%s: anchors carry at most 1e-11 of the load scale" % scene,
                  all(f.get("out_of_balance", 1) <= 1e-11 for f in floating))
            balanced = True
            for c in cycles.values():
                b = c["force_balance"]
                scale = b["force_scale"]
                residual = math.hypot(b["applied"][0] + b["reactions"][0],
                                      b["applied"][1] + b["reactions"][1])
                balanced = balanced and residual <= b["roundoff"] + 1e-10 * scale
            check("%s: reactions with the anchors balance the loads" % scene,
                  balanced)

        dcb_without_clamp(bilayer, os.path.join(os.path.dirname(prm), "dcb_growth.prm"),
                          work)

        if shutil.which("mpirun"):
            out = os.path.join(work, "mpi")
            rc, _, err = run(["mpirun", "-np", "2", bilayer, prm], out,
                             SCENES["Omega+ floating"][0])
            lines = [l for l in err.splitlines() if l.startswith("bilayer: error:")]
            check("mpirun -np 2: refused in one line naming the one process, "
                  "exit 1, nothing written",
                  rc == 1 and len(set(lines)) == 1 and
                  "floating subproblems are solved in runs of one process" in lines[0]
                  and not os.path.exists(out))
        else:
            check("mpirun found (apt-get install openmpi-bin)", False)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

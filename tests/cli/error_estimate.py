"""The global error estimate eta (summary.json, table.csv, table.txt) against
the error it estimates, e_h = (2 |Pi_h - Pi|)^1/2 in the energy norm:
  - a uniform stress state that closes the crack (uniform_stress.prm: a
    linear exact solution, which Q1 reproduces): the Kelly part of eta
    vanishes to rounding (eta <= 1e-8 e_scale, e_scale = (2 |Pi|)^1/2);
  - Example 1, Q1, four uniform cycles (active set): Pi from the last three
    energies by extrapolation (Pi_h - Pi ~ C N^-r); the efficiency index
    eta / e_h of cycles 0-2 lies in [0.3, 3] and varies by less than 20 %,
    and eta falls at the rate of e_h (observed h-rates within 0.1);
  - eta is in every cycle of summary.json, a column of table.csv with the
    same numbers, and a column "eta" of table.txt.
Usage: python3 error_estimate.py BILAYER PARAMETER_FILE_DIRECTORY TEST_DIRECTORY"""
import csv
import json
import math
import os
import subprocess
import sys
import tempfile

bilayer, scenes, here = sys.argv[1:4]
failures = 0


def check(what, ok):
    global failures
    print("%s: %s" % (what, "yes" if ok else "NO"))
    failures += 0 if ok else 1


def run(prm, directory, *settings):
    args = [bilayer, prm, "--set", "Output/Output directory=" + directory,
            "--set", "Output/Terminal output=checks", "--set", "Output/Write VTU=false"]
    for s in settings:
        args += ["--set", s]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    return json.load(open(os.path.join(directory, "summary.json")))["cycles"]


with tempfile.TemporaryDirectory() as work:
    cycles = run(os.path.join(here, "uniform_stress.prm"), os.path.join(work, "uniform"),
                 "Mesh/Interface terms in the estimator=false")
    for c in cycles:
        e_scale = math.sqrt(2 * abs(c["energy"]))
        check("uniform stress, cycle %d: Kelly part of eta %.1e <= 1e-8 x %.1e"
              % (c["cycle"], c["eta"], e_scale), c["eta"] <= 1e-8 * e_scale)

    directory = os.path.join(work, "example1")
    cycles = run(os.path.join(scenes, "partial_closure.prm"), directory,
                 "Solver/Method=active set", "Mesh/Number of cycles=4")
    E = [c["energy"] for c in cycles]
    N = [c["dofs"] for c in cycles]
    # Pi_h - Pi = C N^-r through the last three cycles: with q = N ratio
    # (4 here), d1 = E1 - E2 = C N1^-r (1 - q^-r), d2 = E2 - E3 = d1 q^-r.
    d1, d2 = E[1] - E[2], E[2] - E[3]
    ratio = d2 / d1
    reference = E[3] - d2 * ratio / (1 - ratio)
    errors = [math.sqrt(2 * abs(e - reference)) for e in E[:3]]
    efficiency = [c["eta"] / e for c, e in zip(cycles, errors)]
    print("Example 1: Pi extrapolated %.10e; efficiency %s" %
          (reference, " ".join("%.3f" % x for x in efficiency)))
    check("Example 1: efficiency index in [0.3, 3]", all(0.3 <= x <= 3 for x in efficiency))
    check("Example 1: efficiency varies by < 20 %", max(efficiency) / min(efficiency) < 1.2)
    h = [max(c["h_max_minus"], c["h_max_plus"]) for c in cycles]
    for i in (1, 2):
        rate_e = math.log(errors[i - 1] / errors[i]) / math.log(h[i - 1] / h[i])
        rate_eta = math.log(cycles[i - 1]["eta"] / cycles[i]["eta"]) / math.log(h[i - 1] / h[i])
        check("Example 1, cycles %d-%d: h-rates of e_h %.3f and eta %.3f within 0.1"
              % (i - 1, i, rate_e, rate_eta), abs(rate_e - rate_eta) <= 0.1)
    rows = list(csv.DictReader(l for l in open(os.path.join(directory, "table.csv"))
                               if not l.startswith("#")))
    check("table.csv has eta, as in summary.json",
          len(rows) == len(cycles) and
          all(abs(float(r["eta"]) - c["eta"]) <= 1e-12 * c["eta"] for r, c in zip(rows, cycles)))
    header = next(l for l in open(os.path.join(directory, "table.txt")) if not l.startswith("#"))
    check("table.txt has a column eta", "| eta" in header)
sys.exit(1 if failures else 0)

#!/usr/bin/env python3
"""The forces on the boundary parts (summary.json "boundary_parts",
"force_balance"; growth.csv's force columns) against equilibrium and beam
theory.

Every shipped scene (parameter_files/*.prm) runs with one mesh cycle (a
growth scene runs all its steps, a cohesive scene under path following its
first 10), without VTU or interface files, and
els.prm with 4 adaptive cycles (hanging nodes, on the clamped end too), and
on every state:
  - the run is accepted (its own check of the balance among the checks);
  - the reactions of the clamped parts balance the applied loads: the
    resultant of the reactions plus that of the load vector is below the
    round-off bound of the sums (machine epsilon times
    sum |K_ij| |w_j| + |F_i| + |c_i|) plus 1e-10 of the forces;
  - "reactions" is the sum of the forces of the clamped parts;
  - where no layer has a body force, the load vector's resultant equals the
    sum of the traction forces of the parts that are not clamped (two
    computations: the assembled load vector, and the traction integrated
    on the parts' faces) to the round-off bound plus 1e-10 of the forces.
The double cantilever beam (dcb_growth.prm: one layer, (0, 40) x (-1, 1),
E = 1, nu = 0.3, plane strain, the right end clamped, the shear traction
+-P/h on the left end of each arm, P = 1e-3 times the load factor lambda),
at every step whose ligament is at least two arm heights:
  - the force on the left end in the upper region (Omega+) is lambda P to
    1e-12 and in the lower one -lambda P, the reaction of the clamp zero to
    the state's round-off bound plus 1e-9 of lambda P (the arms pull in
    opposite directions);
  - the opening delta = uy(left end, Omega+) - uy(left end, Omega-) from the
    parts' mean displacements within 2 % of beam theory with the root
    rotation (Kanninen): delta = 8 P (a + chi h)^3 / (E' h^3), chi =
    6^(-1/4), E' = E / (1 - nu^2) (tests/dcb_beam_theory.cc);
  - delta P0 (P0 = 1e-3) equals growth.csv's conjugate displacement (F_1, w)
    to 1e-9: the traction is uniform on each arm's end, so the work of the
    unit load is P0 times the difference of the mean displacements.
Usage: reactions.py BILAYER PARAMETER_FILES
"""
import concurrent.futures
import csv
import glob
import json
import math
import os
import subprocess
import sys
import tempfile

failures = []


def check(label, passed):
    print("%s: %s" % (label, "yes" if passed else "NO"))
    if not passed:
        failures.append(label)


def run(bilayer, prm, out, cycles=1):
    with open(out + ".log", "w") as log:
        return subprocess.call(
            [bilayer, prm,
             "--set", "Output/Output directory=" + out,
             "--set", "Mesh/Number of cycles=%d" % cycles,
             "--set", "Output/Write VTU=false",
             "--set", "Output/Write interface CSV=false",
             "--set", "Cohesive/Steps=10"],
            stdout=log, stderr=subprocess.STDOUT)


def has_body_force(directory):
    """Whether used_parameters.prm gives a layer a body force."""
    for line in open(os.path.join(directory, "used_parameters.prm")):
        key, _, value = line.strip().partition("=")
        if key.strip() == "set Body force" and any(
                x.strip() not in ("0", "0.0", "") for x in value.split(";")):
            return True
    return False


def balance_holds(cycle, body_force):
    """The three balance checks of one state; the worst relative value."""
    balance = cycle["force_balance"]
    parts = cycle["boundary_parts"]
    applied, reactions = balance["applied"], balance["reactions"]
    # The forces' scale: every layer's and every region's share.
    scale = math.hypot(*applied) + sum(
        math.hypot(*f) for p in parts
        for f in p["layer_forces"] + [r["force"] for r in p["regions"]])
    residual = math.hypot(applied[0] + reactions[0], applied[1] + reactions[1])
    ok = residual <= balance["roundoff"] + 1e-10 * scale
    clamped = [sum(p["force"][k] for p in parts if p["clamped"]) for k in (0, 1)]
    ok = ok and all(abs(clamped[k] - reactions[k])
                    <= balance["roundoff"] + 1e-12 * scale for k in (0, 1))
    if not body_force:
        tractions = [sum(p["force"][k] for p in parts if not p["clamped"])
                     for k in (0, 1)]
        ok = ok and all(abs(tractions[k] - applied[k])
                        <= balance["roundoff"] + 1e-10 * scale for k in (0, 1))
    return ok


def check_scene(name, directory, rc):
    if rc != 0 or not os.path.exists(os.path.join(directory, "summary.json")):
        check("%s: accepted (exit %d)" % (name, rc), False)
        return
    summary = json.load(open(os.path.join(directory, "summary.json")))
    body_force = has_body_force(directory)
    states = summary["cycles"]
    balanced = [balance_holds(c, body_force) for c in states]
    check("%s: %d state(s) accepted, reactions balance the loads%s"
          % (name, len(states),
             "" if body_force else ", load resultant = traction forces"),
          all(c["accepted"] for c in states) and all(balanced)
          and len(states) > 0)


def check_dcb(directory):
    E, nu, h, P0 = 1.0, 0.3, 1.0, 1e-3
    E_prime = E / (1 - nu * nu)
    chi = 6 ** -0.25
    rows = list(csv.DictReader(
        l for l in open(os.path.join(directory, "growth.csv"))
        if not l.startswith("#")))
    states = json.load(open(os.path.join(directory, "summary.json")))["cycles"]
    worst, forces_ok, work_ok, n = 0.0, True, True, 0
    for row in rows:
        a = float(row["crack_length"])
        if 40 - a < 2 * h:
            continue
        n += 1
        lam = float(row["load_factor"])
        upper, lower = float(row["Fy_left_r2"]), float(row["Fy_left_r1"])
        clamp = math.hypot(float(row["Fx_right"]), float(row["Fy_right"]))
        forces_ok = forces_ok and abs(upper - lam * P0) <= 1e-12 * lam * P0 \
            and abs(lower + lam * P0) <= 1e-12 * lam * P0 \
            and clamp <= states[int(row["step"])]["force_balance"]["roundoff"] \
            + 1e-9 * lam * P0
        delta = float(row["uy_left_r2"]) - float(row["uy_left_r1"])
        beam = 8 * lam * P0 * (a + chi * h) ** 3 / (E_prime * h ** 3)
        worst = max(worst, abs(delta / beam - 1))
        conjugate = float(row["conjugate_displacement"])
        work_ok = work_ok and abs(delta * P0 - conjugate) <= 1e-9 * abs(conjugate)
    check("dcb_growth: %d steps with a ligament >= 2 h" % n, n >= 20)
    check("dcb_growth: end forces +-lambda P per arm, no reaction at the clamp",
          forces_ok)
    check("dcb_growth: opening within 2 %% of beam theory (largest %.1f %%)"
          % (100 * worst), worst <= 0.02)
    check("dcb_growth: delta P0 = conjugate displacement (F_1, w)", work_ok)


def main():
    bilayer, files = sys.argv[1], sys.argv[2]
    scenes = sorted(glob.glob(os.path.join(files, "*.prm")))
    with tempfile.TemporaryDirectory() as work:
        outs = {os.path.basename(p)[:-4]: os.path.join(work, os.path.basename(p)[:-4])
                for p in scenes}
        with concurrent.futures.ThreadPoolExecutor(2) as pool:
            codes = dict(zip(outs, pool.map(
                lambda p: run(bilayer, p, outs[os.path.basename(p)[:-4]]),
                scenes)))
        for name in outs:
            check_scene(name, outs[name], codes[name])
        # Adaptive meshes with hanging nodes, on the clamped end too.
        adaptive = os.path.join(work, "els_adaptive")
        check_scene("els, 4 adaptive cycles", adaptive,
                    run(bilayer, os.path.join(files, "els.prm"), adaptive, 4))
        if codes.get("dcb_growth") == 0:
            check_dcb(outs["dcb_growth"])
        else:
            check("dcb_growth ran", False)
    print("%d scenes" % len(scenes))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()

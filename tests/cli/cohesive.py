#!/usr/bin/env python3
"""Cohesive interfaces from the command line (docs/cohesive.md), checked
against closed forms:

  - the bar of parameter_files/cohesive_bar.prm (bilinear law, all of Sigma
    a cohesive zone, the top moved by lambda U0, nu = 0): while the zone
    stays uniform, every step lies on the closed-form curve lambda U0 =
    delta + H T(delta) / E (1e-8 of U0), the first step ends at the peak
    (delta_0 = sigma_max / k0), the curve snaps back (lambda falls while
    the separation grows), the dissipated energy equals the law's integral
    at every step (1e-9) and G_Ic times the width at the end (1e-5), and the energy
    balance (the boundary forces' work less the stored energy) agrees with
    it within 1 % of G_Ic times the width at every step;
  - the same bar with the exponential law: the peak at delta_c = G_Ic /
    (e sigma_max) with the traction sigma_max, and G_Ic at the end;
  - the same bar under prescribed load factors past the peak: stops in one
    line naming the limit point, exit 2 (a failed run), its results in
    DIR.failed;
  - parameter_files/cohesive_shear.prm (pressed, sheared, broken in mode II,
    then sliding): the mixity is 1 (pure mode II: the normal part in
    contact), the normal traction is the pressure E U_y lambda / H at every
    step (1e-8), the shear traction is the law's k0 (1 - d) delta at every
    unbroken node (within k0 delta times the damage tolerance, the
    difference between the damage solved with and the one reported) and
    never above tau_max, the dissipated
    energy G_IIc times the width at full damage, and once broken the shear
    traction is Coulomb's F p at every node (1e-8); without friction a
    broken node's history is the prescribed slip (1e-9); pressed without shear,
    nothing is damaged whatever the pressure and nothing penetrates; with
    half of Sigma cohesive, the interface CSV carries the zone's damage at
    its nodes, -1 off it, and no node's damage falls from step to step;
  - parameter_files/cohesive_dcb.prm with 14 iterations allowed: steps
    that do not settle are retaken with half the increment, and each step
    dissipates the fraction it announces of Dissipation increment (1e-9);
  - the same DCB with l_cz = h / 4 on 12 cells per h: cohesive.csv's
    process_nodes counts the nodes with 0 < d < 1, and one line says that
    the process zone (about one node) is not resolved;
  - a bad entry (a penalty below strength^2 / (2 G_c)) refused in one line.
Usage: cohesive.py BILAYER PARAMETER_FILES
"""
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

failures = []


def check(label, passed):
    print("%s: %s" % (label, "yes" if passed else "NO"))
    if not passed:
        failures.append(label)


def run(bilayer, scene, out, settings):
    args = [bilayer, scene, "--set", "Output/Output directory=" + out,
            "--set", "Output/Terminal output=checks"]
    for key, value in settings.items():
        args += ["--set", "%s=%s" % (key, value)]
    result = subprocess.run(args, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, universal_newlines=True)
    return result.returncode, result.stdout, result.stderr


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f
                                   if not line.startswith("#")))


def zone(out, step):
    return rows(os.path.join(out, "cohesive-%04d.csv" % step))


def bilinear_traction(delta, sigma, k0, g):
    d0, df = sigma / k0, 2 * g / sigma
    if delta <= d0:
        return k0 * delta
    return max(0., sigma * (df - delta) / (df - d0))


def bar(bilayer, files, work):
    scene = os.path.join(files, "cohesive_bar.prm")
    sigma, g, k0, E, H, U0, width = 0.01, 1e-4, 100., 1., 10., 0.01, 1.
    # (Damage tolerance 1e-10: the state of each step as exact as the
    # closed form is checked to.)
    out = os.path.join(work, "bar")
    code, _, err = run(bilayer, scene, out,
                       {"Cohesive/Damage tolerance": "1e-10"})
    check("bar: the run ends with exit 0", code == 0)
    if code != 0:
        print(err)
        return
    steps = rows(os.path.join(out, "cohesive.csv"))
    # The steps whose zone is uniform (every node the same damage).
    uniform = []
    for r in steps:
        nodes = zone(out, int(r["step"]))
        damages = [float(n["damage"]) for n in nodes]
        if max(damages) - min(damages) <= 1e-9 and max(damages) < 1:
            uniform.append(r)
    check("bar: the zone stays uniform for at least 20 steps",
          len(uniform) >= 20)
    worst = 0
    for r in uniform:
        delta = float(r["largest_separation"])
        U = delta + H * bilinear_traction(delta, sigma, k0, g) / E
        worst = max(worst, abs(float(r["load_factor"]) * U0 - U) / U0)
    print("  largest deviation from the closed form: %.3g of U0" % worst)
    # (The state of a step is solved with damage within the Damage
    # tolerance, 1e-10, of the one reported; near full damage the
    # compliance 1 / (k0 (1 - d)) magnifies that by 1 / (1 - d) ~ 1e4.)
    check("bar: the uniform steps lie on the closed-form curve (1e-6 of U0)",
          worst <= 1e-6)
    first = steps[0]
    peak = (sigma / k0 + H * sigma / E) / U0
    check("bar: the first step ends at the peak (1e-8)",
          abs(float(first["load_factor"]) - peak) <= 1e-8 * peak and
          abs(float(first["largest_separation"]) - sigma / k0) <= 1e-12)
    lam = [float(r["load_factor"]) for r in uniform]
    sep = [float(r["largest_separation"]) for r in uniform]
    check("bar: snap-back (the load factor falls while the separation grows)",
          all(lam[i + 1] < lam[i] and sep[i + 1] > sep[i]
              for i in range(1, len(lam) - 1)))
    # The law's dissipation at the separation delta > delta_0: the area
    # under the law up to delta less the secant's triangle, sigma delta / 2
    # - T(delta) delta_0 / 2.
    law = 0
    for r in uniform:
        delta = float(r["largest_separation"])
        expected = (0.5 * sigma * delta -
                    0.5 * bilinear_traction(delta, sigma, k0, g) * sigma / k0
                    if delta > sigma / k0 else 0.)
        law = max(law, abs(float(r["dissipated"]) - width * expected))
    print("  largest deviation from the law's dissipation: %.3g of G_Ic w"
          % (law / (g * width)))
    check("bar: the dissipated energy is the law's (1e-6 of G_Ic w)",
          law <= 1e-6 * g * width)
    last = steps[-1]
    check("bar: at the end the dissipated energy is G_Ic times the width "
          "(1e-5)", abs(float(last["dissipated"]) - g * width) <= 1e-5 * g)
    balance = max(abs(float(r["dissipated_balance"]) - float(r["dissipated"]))
                  for r in steps)
    print("  largest gap of the energy balance: %.3g of G_Ic w"
          % (balance / (g * width)))
    check("bar: the energy balance agrees with the dissipated energy "
          "(1 % of G_Ic w)", balance <= 0.01 * g * width)

    # The exponential law: the peak at delta_c with the traction sigma_max.
    out = os.path.join(work, "bar_exponential")
    code, _, err = run(bilayer, scene, out,
                       {"Cohesive/Law": "exponential",
                        "Cohesive/Dissipation increment": "4e-6",
                        "Cohesive/Steps": "200"})
    check("exponential bar: the run ends with exit 0", code == 0)
    if code == 0:
        steps = rows(os.path.join(out, "cohesive.csv"))
        dc = g / (math.e * sigma)
        peak = (dc + H * sigma / E) / U0
        check("exponential bar: the first step ends at the peak (1e-8)",
              abs(float(steps[0]["load_factor"]) - peak) <= 1e-8 * peak and
              abs(float(steps[0]["largest_separation"]) - dc) <= 1e-12)
        check("exponential bar: at the end the dissipated energy is G_Ic "
              "times the width (1e-5)",
              abs(float(steps[-1]["dissipated"]) - g * width) <= 1e-5 * g)
    else:
        print(err)

    # Prescribed load factors past the peak: refused at the limit point.
    out = os.path.join(work, "bar_load")
    code, _, err = run(bilayer, scene, out,
                       {"Cohesive/Control": "load factor",
                        "Loads/Load factor": "2:2:12"})
    lines = [l for l in err.splitlines() if l.strip()]
    print("  " + (lines[-1] if lines else ""))
    check("bar under load factors past the peak: exit 2 (a failed run), one "
          "line naming the limit point, the results beside the directory "
          "(.failed)",
          code == 2 and len(lines) == 1 and "limit point" in err and
          not os.path.exists(out) and os.path.isdir(out + ".failed"))


def run_dcb(bilayer, files, work, label, settings):
    """cohesive_dcb.prm with SETTINGS (no VTU) into WORK/LABEL: (its
    folder, its stdout), or None after a failed exit check."""
    out = os.path.join(work, label)
    code, stdout, err = run(bilayer, os.path.join(files, "cohesive_dcb.prm"),
                            out, dict(settings, **{"Output/Write VTU": "false"}))
    check("%s: the run ends with exit 0" % label, code == 0)
    if code != 0:
        print(err)
        return None
    return out, stdout


def halving(bilayer, files, work):
    # A path-following step that does not settle is taken again with half
    # the increment: with few iterations allowed, the DCB's first steps
    # are halved, and each step then adds the fraction it announces of
    # Dissipation increment (the bisection on the load factor hits its
    # target to round-off).
    ran = run_dcb(bilayer, files, work, "halving",
                  {"Cohesive/Maximum iterations": "14", "Cohesive/Steps": "3",
                   "Cohesive/Method": "secant"})
    if ran is None:
        return
    out, stdout = ran
    fraction = {}
    for line in stdout.splitlines():
        m = re.match(r"step (\d+): the secant iteration did not settle; the "
                     r"increment halved to ([0-9.e-]+) of its value", line)
        if m:
            fraction[int(m.group(1))] = 0.5 ** round(
                -math.log2(float(m.group(2))))
    steps = rows(os.path.join(out, "cohesive.csv"))
    worst = 0
    for before, r in zip(steps, steps[1:]):
        added = float(r["dissipated"]) - float(before["dissipated"])
        expected = 4e-3 * fraction.get(int(r["step"]), 1.)
        worst = max(worst, abs(added - expected) / expected)
    check("halving: some step is halved", len(fraction) > 0)
    check("halving: each step dissipates the fraction of the increment it "
          "announces (1e-9)", len(steps) == 3 and worst <= 1e-9)


def newton(bilayer, files, work):
    # The Newton method on the interface and the secant iteration alone
    # solve the same discrete problem of each step (to the Damage
    # tolerance, 1e-6): the same curve. The Newton method's state is the
    # secant iteration's fixed point: the steps after the first two (the
    # first ends at the elastic limit, the second starts there, where the
    # law's kink lies under every node) settle in one secant iteration.
    curves = {}
    for method in ("newton", "secant"):
        ran = run_dcb(bilayer, files, work, "method-" + method,
                      {"Cohesive/Steps": "8", "Cohesive/Method": method})
        if ran is None:
            return
        curves[method] = rows(os.path.join(ran[0], "cohesive.csv"))
    a, b = curves["newton"], curves["secant"]
    worst = max(abs(float(x[c]) - float(y[c])) / abs(float(y[c]))
                for x, y in zip(a, b) for c in ("load_factor", "q")
                if float(y[c]) != 0)
    print("  Newton against secant: largest relative difference %.3g" % worst)
    check("newton: the curve of the secant iteration (8 steps, 1e-5)",
          len(a) == len(b) == 8 and worst <= 1e-5)
    check("newton: steps 2 on settle in one secant iteration from the "
          "Newton method's state (newton_iterations >= 0; -1 on every step "
          "of the secant iteration alone)",
          all(int(r["iterations"]) == 1 and int(r["newton_iterations"]) >= 0
              for r in a[2:]) and
          all(int(r["newton_iterations"]) == -1 for r in b))
    check("newton: each step dissipates the increment (1e-9)",
          all(abs(float(r["dissipated"]) - 4e-3 * int(r["step"])) <= 4e-12
              for r in a))


def coarse(bilayer, files, work):
    # The DCB with a cohesive length of h / 4 on 12 cells per h: a process
    # zone of about one node. cohesive.csv counts the nodes with
    # 0 < d < 1 of each step's zone file, and the run says in one line
    # that the zone is not resolved.
    ran = run_dcb(bilayer, files, work, "coarse zone",
                  {"Cohesive/Normal strength": "0.2",
                   "Cohesive/Shear strength": "0.2",
                   "Cohesive/Steps": "4",
                   "Output/Written steps": "every 1"})
    if ran is None:
        return
    out, stdout = ran
    counted = True
    for r in rows(os.path.join(out, "cohesive.csv")):
        inside = sum(1 for n in zone(out, int(r["step"]))
                     if 0 < float(n["damage"]) < 1)
        counted = counted and int(r["process_nodes"]) == inside
    check("coarse zone: process_nodes counts the nodes with 0 < d < 1",
          counted)
    check("coarse zone: one line says the process zone is not resolved",
          sum("the process zone held" in line and "fewer than 3" in line
              for line in stdout.splitlines()) == 1)


def shear(bilayer, files, work):
    scene = os.path.join(files, "cohesive_shear.prm")
    E, H, F, tau, g2, Uy, width = 100., 1., 0.5, 0.01, 2e-4, 2e-5, 1.
    out = os.path.join(work, "shear")
    code, _, err = run(bilayer, scene, out, {})
    check("shear: the run ends with exit 0", code == 0)
    if code != 0:
        print(err)
        return
    steps = rows(os.path.join(out, "cohesive.csv"))
    pressure = mixity = coulomb = law = 0
    peak_shear = 0
    broken = 0
    k0 = 100.
    for r in steps:
        lam = float(r["load_factor"])
        p = E * Uy * lam / H
        for n in zone(out, int(r["step"])):
            pressure = max(pressure, abs(float(n["traction_normal"]) - p))
            if float(n["damage"]) > 0:
                mixity = max(mixity, abs(float(n["mixity"]) - 1))
            peak_shear = max(peak_shear, abs(float(n["traction_tangential"])))
            if float(n["damage"]) < 1:
                # (Loading: the separation is the history. The state is
                # solved with a damage within the Damage tolerance, 1e-6,
                # of the one reported: the traction within k0 1e-6 delta.)
                law = max(law, abs(abs(float(n["traction_tangential"])) -
                                   k0 * (1 - float(n["damage"])) *
                                   float(n["history"])) /
                          (k0 * 1e-6 * float(n["history"]) + 1e-15))
            if float(n["damage"]) >= 1:
                broken += 1
                coulomb = max(coulomb,
                              abs(abs(float(n["traction_tangential"])) - F * p))
    check("shear: the normal traction is the pressure at every step (1e-8)",
          pressure <= 1e-8 * E * Uy * 6 / H)
    check("shear: pure mode II (mixity 1)", mixity <= 1e-12)
    check("shear: the shear traction never exceeds tau_max (1e-8)",
          peak_shear <= tau * (1 + 1e-8))
    check("shear: the shear traction of the unbroken nodes is the law's, "
          "k0 (1 - d) delta, within the damage tolerance", law <= 1.)
    check("shear: broken nodes slide with Coulomb's F p (1e-8)",
          broken > 0 and coulomb <= 1e-8 * tau)
    check("shear: the dissipated energy is G_IIc times the width (1e-9)",
          abs(float(steps[-1]["dissipated"]) - g2 * width) <= 1e-9 * g2)

    # Frictionless after damage: a broken node's faces slide freely, its
    # separation (and history) is the prescribed slip lambda U_x exactly.
    out = os.path.join(work, "frictionless")
    code, _, err = run(bilayer, scene, out, {"Contact/Friction": "none"})
    check("frictionless: the run ends with exit 0", code == 0)
    if code == 0:
        worst, broken = 0, 0
        for r in rows(os.path.join(out, "cohesive.csv")):
            slip = 0.01 * float(r["load_factor"])
            for n in zone(out, int(r["step"])):
                if float(n["damage"]) >= 1:
                    broken += 1
                    worst = max(worst, abs(float(n["history"]) - slip) / slip)
        check("frictionless: broken nodes' history is the slip lambda U_x "
              "(1e-9)", broken > 0 and worst <= 1e-9)
        # (Prescribed load factors: a softening zone has several equilibria
        # at one load factor; the secant iteration follows the path's, the
        # Newton method is not used.)
        check("frictionless: under prescribed load factors the secant "
              "iteration alone (newton_iterations -1)",
              all(int(r["newton_iterations"]) == -1
                  for r in rows(os.path.join(out, "cohesive.csv"))))
    else:
        print(err)

    # Half the interface cohesive: the interface files carry each zone
    # node's damage (the zone's own file's), -1 off the zone, and no
    # node's damage falls from one step to the next (irreversibility).
    out = os.path.join(work, "half")
    code, _, err = run(bilayer, scene, out,
                       {"Cohesive/Zone": "0, 0.5",
                        "Output/Write interface CSV": "true"})
    check("half zone: the run ends with exit 0", code == 0)
    if code == 0:
        steps = rows(os.path.join(out, "cohesive.csv"))
        agree, off, falls, damaged = True, True, False, 0
        before = {}
        for r in steps:
            step = int(r["step"])
            of_zone = {round(float(n["s"]), 9): float(n["damage"])
                       for n in zone(out, step)}
            for n in rows(os.path.join(out, "interface-%02d.csv" % step)):
                key, d = round(float(n["s"]), 9), float(n["damage"])
                if key in of_zone:
                    agree = agree and abs(d - of_zone[key]) <= 1e-12
                    damaged += d > 0
                    falls = falls or d < before.get(key, 0.) - 1e-12
                    before[key] = d
                else:
                    off = off and d == -1 and key >= 0.5
        check("half zone: the interface CSV's damage is the zone's at its "
              "nodes, damage grows somewhere", agree and damaged > 0)
        check("half zone: damage -1 off the zone", off)
        check("half zone: no node's damage falls between steps", not falls)
    else:
        print(err)

    # Pressed without shear, 1000 times harder: no damage, no penetration.
    out = os.path.join(work, "pressed")
    code, _, err = run(bilayer, scene, out,
                       {"Loads/Layer 1/Prescribed displacement":
                        "0; y > 0 ? -0.02 : 0"})
    check("pressed: the run ends with exit 0", code == 0)
    if code == 0:
        steps = rows(os.path.join(out, "cohesive.csv"))
        check("pressed: no damage under pressure alone",
              max(float(r["largest_damage"]) for r in steps) == 0)
        opening = max(float(n["history"]) for r in steps
                      for n in zone(out, int(r["step"])))
        check("pressed: no separation in the zone (1e-6 of delta_0, "
              "round-off)", opening <= 1e-6 * 1e-4)
    else:
        print(err)

    # A bad penalty: one line naming it.
    out = os.path.join(work, "bad")
    code, _, err = run(bilayer, scene, out,
                       {"Cohesive/Bilinear/Penalty stiffness": "0.1"})
    lines = [l for l in err.splitlines() if l.strip()]
    check("a penalty below strength^2 / (2 G_c): exit 1, one line naming it",
          code == 1 and len(lines) == 1 and
          "Cohesive/Bilinear/Penalty stiffness" in err)


def main():
    bilayer, files = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as work:
        bar(bilayer, files, work)
        shear(bilayer, files, work)
        halving(bilayer, files, work)
        newton(bilayer, files, work)
        coarse(bilayer, files, work)
    if failures:
        print("FAILED: " + "; ".join(failures))
        sys.exit(1)
    print("all cohesive checks pass")


main()

"""Fracture/Mode mix = stress intensity factors: the mode-dependent growth
laws read G_I = G cos^2 psi, G_II = G sin^2 psi, psi = atan2(K_II, K_I).
Griffith's crack (parameter_files/griffith.prm, a = 0.05, a/W = 1/20, two
global cycles) under tension s = 1e-3 and shear tau = 5e-4, quasi-static
growth with the Benzeggagh-Kenane law (G_IIc = 4 G_Ic, exponent 2) and a
toughness rising along Sigma (stable growth):
  - every step's G_II / G (summary.json growth.steps[].tips[]) is
    sin^2 psi of the same state's K (cycles[].crack_tips[]) to 1e-12;
  - at the first onset psi is atan(tau / s) = 26.565 degrees, the infinite
    plate's K_II / K_I, to 0.5 degrees, and G is the law's toughness
    G_Ic + (G_IIc - G_Ic) (sin^2 psi)^2 to 1e-6;
  - with the default (closure) the steps carry the closure split of the
    cycles' crack_tips;
  - Mode mix = stress intensity factors without Stress intensity factors
    is refused in one line naming both entries.
Usage: python3 growth_mode_mix.py BILAYER PARAMETER_FILE_DIRECTORY"""
import json
import math
import os
import subprocess
import sys
import tempfile

bilayer, scenes = sys.argv[1:3]
failures = 0
S, TAU, GIC = 1e-3, 5e-4, 1e-7


def check(what, ok):
    global failures
    print("%s: %s" % (what, "yes" if ok else "NO"))
    failures += 0 if ok else 1


def settings(mix):
    return {
        "Loads/Constants": "s = %r; p = 0; tau = %r; syy = s - p; exx = -nu1*(1+nu1)*syy/E1; "
                           "eyy = (1-nu1^2)*syy/E1; exy = tau*(1+nu1)/E1" % (S, TAU),
        "Mesh/Refinement": "global", "Mesh/Number of cycles": "2",
        "Fracture/Crack growth": "quasi-static",
        "Fracture/Toughness": "%r*(1+40*(abs(x)-0.05))" % GIC,
        "Fracture/Mode II toughness": "%r*(1+40*(abs(x)-0.05))" % (4 * GIC),
        "Fracture/Mixed-mode law": "Benzeggagh-Kenane", "Fracture/Mixed-mode exponent": "2",
        "Fracture/Mode mix": mix, "Loads/Load factor": "0.5:0.5:1",
        "Output/Terminal output": "checks", "Output/Write interface CSV": "false"}


def run(directory, values):
    args = [bilayer, os.path.join(scenes, "griffith.prm"),
            "--set", "Output/Output directory=" + directory]
    for key, value in values.items():
        args += ["--set", "%s=%s" % (key, value)]
    return subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)


with tempfile.TemporaryDirectory() as work:
    for mix in ("stress intensity factors", "closure"):
        directory = os.path.join(work, mix.split()[0])
        r = run(directory, settings(mix))
        check("%s: the run succeeds" % mix, r.returncode == 0)
        if r.returncode != 0:
            print(r.stderr.strip())
            continue
        summary = json.load(open(os.path.join(directory, "summary.json")))
        pairs = list(zip(summary["growth"]["steps"], summary["cycles"]))
        worst = 0.0
        for step, cycle in pairs:
            for tip, g in zip(step["tips"], cycle["crack_tips"]):
                if mix == "closure":
                    expected = g["G_II"] / g["G"]
                else:
                    expected = math.sin(math.radians(g["K_phase_angle"])) ** 2
                worst = max(worst, abs(tip["G_II"] / tip["G"] - expected))
        check("%s: %d steps, G_II / G of the steps = %s of the state, largest difference "
              "%.1e <= 1e-12" % (mix, len(pairs), "closure split" if mix == "closure"
                                 else "sin^2 psi of K", worst),
              len(pairs) > 3 and worst <= 1e-12)
        if mix == "closure":
            continue
        onset = next((k for k, (step, _) in enumerate(pairs) if step["kind"] == "onset"), None)
        check("stress intensity factors: an onset step", onset is not None)
        if onset is None:
            continue
        step, cycle = pairs[onset]
        psi = cycle["crack_tips"][0]["K_phase_angle"]
        exact = math.degrees(math.atan(TAU / S))
        check("first onset: psi = %.4f degrees, atan(tau / s) = %.4f (0.5)" % (psi, exact),
              abs(abs(psi) - exact) <= 0.5)
        mix_II = math.sin(math.radians(psi)) ** 2
        toughness = GIC + 3 * GIC * mix_II ** 2
        G = step["tips"][0]["G"]
        check("first onset: G = %.8e = G_Ic + (G_IIc - G_Ic) (sin^2 psi)^2 = %.8e (1e-6)"
              % (G, toughness), abs(G - toughness) <= 1e-6 * toughness)

    refused = run(os.path.join(work, "refused"),
                  dict(settings("stress intensity factors"),
                       **{"Fracture/Stress intensity factors": "false"}))
    lines = refused.stderr.strip().splitlines()
    check("Mode mix = stress intensity factors without K: exit 1, one line naming "
          "Fracture/Mode mix and Fracture/Stress intensity factors",
          refused.returncode == 1 and len(lines) == 1 and "Fracture/Mode mix" in lines[0]
          and "Fracture/Stress intensity factors" in lines[0]
          and not os.path.exists(os.path.join(work, "refused")))

print("failures: %d" % failures)
sys.exit(1 if failures else 0)

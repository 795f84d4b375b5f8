"""Checks what scripts/plot_sigma drew for one cycle (OUT/sigma-NN.gp and
OUT/sigma-NN.dat) against the rules of its docstring, recomputed here from
the result directory itself (interface-NN.csv, summary.json,
used_parameters.prm), independently of the script:
  - units: the y label of the opening and slip panels ends in [L] or
    [10^n L], those of the traction panels in [S] or [10^n S], the x label
    names [L]; L, S: summary.json's units.length and units.stress, or
    "length" and "stress" without them;
  - noise drawn as 0: each jump below rho * U and each traction below
    rho * T is 0 in the .dat, every other value is the CSV's (rho =
    max(Solver/Acceptance tolerance, 1e-12) of used_parameters.prm, else
    1e-9; U the cycle's displacement_scale; T the largest |traction|);
  - clipping: a traction panel clips exactly where a value near an open
    tip lies more than D/2 beyond the range [lo, hi] of the values away
    from the open tips (lo <= 0 <= hi, D = hi - lo), at hi + 0.15 D (or
    lo - 0.15 D); the key then says "clipped at C <S>; peak P <S>", and
    the .dat's clipped_ columns hold C exactly at the values beyond it.
Usage: python3 plot_sigma_rules.py RESULT_DIR CYCLE OUT [clipped|unclipped]
(the last word: what the case must show, on top of the rules). Prints one
line per check ("...: yes" / "...: NO ..."); exit status 1 if any failed.
"""
import csv
import json
import math
import os
import re
import sys

result, cycle, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
expect = sys.argv[4] if len(sys.argv) > 4 else None
failures = 0


def check(what, ok, why=""):
    global failures
    print("%s: %s" % (what, "yes" if ok else "NO " + why))
    failures += 0 if ok else 1


with open(os.path.join(result, "interface-%02d.csv" % cycle)) as f:
    lines = f.read().splitlines()
rows = [{k: float(v) for k, v in r.items()}
        for r in csv.DictReader(l for l in lines if not l.startswith("#"))]
rows.sort(key=lambda r: r["s"])
tips = [float(m.group(1)) for m in (re.match(r"# crack tip \d+ at x = ([^,:]+)", l) for l in lines) if m]
summary = {}
if os.path.exists(os.path.join(result, "summary.json")):
    summary = json.load(open(os.path.join(result, "summary.json")))
units = summary.get("units") or {}
L, S = (units["length"], units["stress"]) if "length" in units and "stress" in units else \
    ("length", "stress")
rho = 1e-9
prm = os.path.join(result, "used_parameters.prm")
if os.path.exists(prm):
    m = re.search(r"^\s*set Acceptance tolerance\s*=\s*(\S+)", open(prm).read(), re.M)
    if m:
        rho = max(float(m.group(1)), 1e-12)
U = [c for c in summary["cycles"] if c["cycle"] == cycle][0]["displacement_scale"]
TRACTIONS = ["contact_pressure", "normal_traction", "mu_g_x", "mu_g_y"]
T = max(abs(r[c]) for r in rows for c in TRACTIONS)
tolerance = {"jump_normal": rho * U, "jump_tangential": rho * U}
tolerance.update({c: rho * T for c in TRACTIONS})

# The .dat: its columns by the header's names.
with open(os.path.join(out, "sigma-%02d.dat" % cycle)) as f:
    dat_lines = f.read().splitlines()
names = [l for l in dat_lines if l.startswith("# s ")][0][2:].split()
dat = [dict(zip(names, map(float, l.split()))) for l in dat_lines if not l.startswith("#")]
check("the .dat has a row per node", len(dat) == len(rows), "%d rows, %d nodes" % (len(dat), len(rows)))

# Noise drawn as 0.
for c, tol in sorted(tolerance.items()):
    wrong, zeroed = [], 0
    for r, d in zip(rows, dat):
        want = 0.0 if abs(r[c]) < tol else r[c]
        zeroed += r[c] != 0 and want == 0
        if abs(d[c] - want) > 1e-9 * abs(want):
            wrong.append("s = %g: %g for %g" % (r["s"], d[c], r[c]))
    check("%s: below %.3g drawn as 0 (%d values), the others as they are" % (c, tol, zeroed),
          not wrong, "; ".join(wrong[:3]))

# Units in the labels.
with open(os.path.join(out, "sigma-%02d.gp" % cycle), encoding="utf-8") as f:
    gp = f.read()
ylabels = re.findall(r"^set ylabel '(.*)'$", gp, re.M)
check("four panels labelled", len(ylabels) == 4, str(ylabels))
for label, unit in zip(ylabels, [L, L, S, S]):
    check("the label %r ends in [%s]" % (label, unit),
          re.search(r"\[(10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+ )?%s\]$" % re.escape(unit), label) is not None)
check("the x axis says [%s]" % L, re.search(r"^set xlabel 's along .*\[%s\]" % re.escape(L), gp, re.M)
      is not None)
check("gnuplot draws the texts as written (noenhanced)",
      gp.count("noenhanced") == 2 and "set terminal" in gp)

# Clipping, panel by panel.
length = rows[-1]["s"] - rows[0]["s"]
crack = [r for r in rows if r["on_crack"]]
near = []
for t in tips:
    nearest = min(crack, key=lambda r: abs(r["s"] - t)) if crack else None
    opening = nearest["jump_normal"] if nearest and abs(nearest["jump_normal"]) >= rho * U else 0
    if opening > 0:
        i = min(range(len(rows)), key=lambda j: abs(rows[j]["s"] - t))
        h = max(abs(rows[j]["s"] - rows[i]["s"]) for j in (i - 1, i + 1) if 0 <= j < len(rows))
        near.append((t, max(1.5 * h, length / 50)))
plots = re.findall(r"^plot (.*)$", gp, re.M)
notes = []
for panel, cols in ((2, ["contact_pressure", "normal_traction"]), (3, ["mu_g_x", "mu_g_y"])):
    drawn = [(d[c], d["s"]) for d in dat for c in cols]
    inside = [v for v, s in drawn if any(abs(s - t) < r for t, r in near)]
    outside = [v for v, s in drawn if not any(abs(s - t) < r for t, r in near)]
    lo, hi = min(outside + [0.0]), max(outside + [0.0])
    D = hi - lo
    levels = {}
    if inside and outside and D > 0:
        if max(inside) > hi + D / 2:
            levels["high"] = (hi + 0.15 * D, max(inside))
        if min(inside) < lo - D / 2:
            levels["low"] = (lo - 0.15 * D, min(inside))
    text = plots[panel] if panel < len(plots) else ""
    for side, (level, peak) in sorted(levels.items()):
        note = "clipped at %.3g %s; peak %.3g %s" % (level, S, peak, S)
        notes.append(note)
        check("panel %d says %r" % (panel + 1, note), note in text, text[-200:])
    if levels:
        for c in cols:
            bad = []
            for d in dat:
                want = math.nan
                if "high" in levels and d[c] > levels["high"][0]:
                    want = levels["high"][0]
                if "low" in levels and d[c] < levels["low"][0]:
                    want = levels["low"][0]
                got = d.get("clipped_" + c, math.nan)
                if not (math.isnan(want) and math.isnan(got) or abs(got - want) <= 1e-9 * abs(want)):
                    bad.append(d["s"])
            check("panel %d: %s marked at the clip level exactly where beyond it" % (panel + 1, c),
                  not bad, "at s = %s" % bad[:4])
    if not levels:
        check("panel %d: not clipped" % (panel + 1), "clipped at" not in text, text[-200:])
if expect:
    check("the case is %s" % expect, bool(notes) == (expect == "clipped"), "; ".join(notes))
sys.exit(1 if failures else 0)

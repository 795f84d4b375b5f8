"""The driver mode of scripts/crack_growth (--driver): one bilayer run with
Fracture/Crack growth = sweep, read from its growth.csv (standard library
only; gnuplot for the figure).

    main(args, prm, scene)   runs the mode: ARGS of crack_growth's parser,
                             PRM the scene's path, SCENE its safe name
    read_growth(folder)      (rows, header) of FOLDER/growth.csv
    number(text)             a cell as a float (empty, null: NaN)
    tips_of(header)          the tip numbers of growth.csv's columns

The critical load of a crack length, for the mode-independent law,
lambda_c = lambda sqrt(G_c / G(l; lambda)) = sqrt(G_c / G(l; 1)) under
proportional loading (G is homogeneous of degree 2 in the load factor):
the script computes it from the driver's G and compares it with the
driver's own critical_load column.
"""
import csv
import math
import os
import platform
import shlex
import sys
import time

import bilayer_run
import study_lib

NAME = "crack_growth"
AGREEMENT = 1e-6   # largest relative difference of the two critical loads


def fail(message, status=1):
    print("%s: %s" % (NAME, message), file=sys.stderr)
    sys.exit(status)


def number(text):
    """A cell of growth.csv as a float: empty or null is NaN, inf stays."""
    if text is None or text.strip() in ("", "null", "nan"):
        return float("nan")
    try:
        return float(text)
    except ValueError:
        return float("nan")


def read_growth(folder):
    """The rows of FOLDER/growth.csv (dicts of strings) and its header."""
    path = os.path.join(folder, "growth.csv")
    if not os.path.lexists(path):
        fail("no growth.csv in %s" % folder)
    return study_lib.read_csv(path, NAME, ("step", "load_factor", "crack_length"),
                              "a growth.csv of bilayer")


def tips_of(header):
    return sorted({int(h[3:h.index("_")]) for h in header
                   if h.startswith("tip") and h.endswith("_G")})


def growing_tips(tip):
    """Fracture/Growing tips of --tip: start (1), end (2), both (all), or
    the tip numbers themselves ('1,3')."""
    named = {"start": "1", "end": "2", "both": "all", "all": "all"}
    if tip in named:
        return named[tip]
    try:
        numbers = [int(v) for v in tip.split(",")]
    except ValueError:
        numbers = []
    if not numbers or min(numbers) < 1 or max(numbers) > 10000:
        fail("error: argument --tip: %r: expected start, end, both, all or tip numbers in "
             "[1, 10000] such as '1,2' (scripts/crack_growth --help)" % tip[:60], 2)
    return ", ".join(str(n) for n in numbers)


def relative(a, b):
    """|a - b| / max(|a|, |b|); 0 where both are the same infinity."""
    if math.isinf(a) or math.isinf(b):
        return 0.0 if a == b else float("inf")
    scale = max(abs(a), abs(b))
    return abs(a - b) / scale if scale > 0 else 0.0


def figure_lines(path, data, tips, title, with_load):
    lines = ["set terminal pngcairo size 900,%d font ',11'" % (1000 if with_load else 550),
             "set output '%s'" % path]
    if with_load:
        lines.append("set multiplot layout 2,1 title %s noenhanced" % bilayer_run.gnuplot_string(title))
    else:
        lines.append("set title %s noenhanced" % bilayer_run.gnuplot_string(title))
    lines += ["set grid", "set key top left font ',10'", "set xlabel 'crack length l'",
              "set ylabel 'G(l) at the sweep''s load factor'"]
    colours = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd"]
    plots = ["'%s' using 1:%d with linespoints pt 7 ps 0.8 lw 2 lc rgb '%s' title 'G of tip %d'" % (
        data, 2 + 3 * i, colours[i % 4], t) for i, t in enumerate(tips)]
    lines.append("plot " + ", ".join(plots))
    if with_load:
        lines += ["set ylabel 'critical load factor lambda_c(l)'"]
        plots = []
        for i, t in enumerate(tips):
            plots.append("'%s' using 1:%d with linespoints pt 7 ps 0.8 lw 2 lc rgb '%s' "
                         "title 'tip %d, sqrt(G_c / G(l; 1))'" % (data, 3 + 3 * i, colours[i % 4], t))
            plots.append("'%s' using 1:%d with points pt 6 ps 2 lw 1.5 lc rgb '%s' "
                         "title 'tip %d, the driver''s critical_load'" % (
                             data, 4 + 3 * i, colours[i % 4], t))
        lines += ["plot " + ", ".join(plots), "unset multiplot"]
    return lines


def main(args, prm, scene):
    """crack_growth --driver."""
    if args.lengths or args.range:
        fail("--driver sweeps the crack lengths of the mesh (every vertex of Sigma, Fracture/"
             "Growth increment): --lengths and --range belong to the five-run mode", 2)
    settings = ["Fracture/Crack growth=sweep",
                "Fracture/Growing tips=%s" % growing_tips(args.tip),
                "Output/Written steps=none", "Output/Write VTU=false",
                "Output/Write interface CSV=false", "Output/Terminal output=checks"]
    if args.toughness is not None:
        if not (args.toughness > 0 and math.isfinite(args.toughness)):
            fail("--toughness must be a finite number > 0, got %g" % args.toughness)
        settings.append("Fracture/Toughness=%.17g" % args.toughness)
    settings += args.settings
    if bilayer_run.scene(prm, args.settings).get("Mesh/Refinement") == "adaptive":
        fail("the growth driver needs Mesh/Refinement = global (the tips move along Sigma on the "
             "meshes of the last cycle); the scene refines adaptively: add --set "
             "\"Mesh/Refinement=global\" (with Mesh/Number of cycles as wanted)")
    entries = bilayer_run.scene(prm, settings)
    law = entries.get("Fracture/Mixed-mode law", "mode independent")
    if args.toughness is not None and law != "mode independent":
        fail("--toughness G_c gives lambda_c = sqrt(G_c / G(l; 1)), the mode-independent law; "
             "the scene has Mixed-mode law = %s: pass the law's entries with --set and read the "
             "driver's critical_load alone (no --toughness)" % law)
    output = os.path.abspath(args.output or os.path.join(
        bilayer_run.ROOT, "results", "%s-%s" % (NAME, scene), "driver"))
    figure = bilayer_run.figure_path(NAME, args.figure, inside=(output,))
    bilayer_run.require("gnuplot")
    folder = bilayer_run.OutputFolder(NAME, output)
    names = {n: folder.claim(n) for n in ("command.txt", NAME + ".csv", NAME + ".dat",
                                           NAME + ".png")}
    run_dir = folder.claim("run", folder=True)
    header = ["command: %s" % " ".join(shlex.quote(a) for a in ["scripts/crack_growth"] + sys.argv[1:]),
              "date: %s" % time.strftime("%Y-%m-%d %H:%M:%S %Z"),
              "machine: %s, %d cores (%s)" % (platform.machine(), os.cpu_count(), platform.node())]
    print("\n".join(header))
    with open(names["command.txt"], "w") as f:
        f.write("\n".join(header) + "\n")
    print("scene: %s; one bilayer run, Fracture/Crack growth = sweep, Growing tips = %s, Growth "
          "increment = %s, toughness %s" % (scene, entries.get("Fracture/Growing tips"),
                                            entries.get("Fracture/Growth increment"),
                                            entries.get("Fracture/Toughness")), flush=True)
    start = time.time()
    r = bilayer_run.run(prm, settings, os.path.join(run_dir, "bilayer"))
    seconds = time.time() - start
    if r.returncode != 0:
        last = (r.stderr or r.stdout or "").strip().splitlines()
        fail("the sweep failed (exit %d): %s; output in %s" % (
            r.returncode, last[-1] if last else "no message", r.directory or run_dir))
    rows, columns = read_growth(r.directory)
    if not rows:
        fail("the sweep's growth.csv holds no step (%s)" % r.directory)
    tips = tips_of(columns)
    gc = args.toughness
    print("one row per crack length l (the crack's total length); per tip: s, G, G_I, G_II "
          "(empty: no mode split), status; lambda_c = lambda sqrt(G_c / G) (this script), "
          "critical_load (the driver's)")
    head = "%5s %9s %9s" % ("step", "lambda", "l")
    for t in tips:
        head += " | %9s %12s %12s %12s %12s %12s" % ("s_%d" % t, "G_%d" % t, "G_I_%d" % t,
                                                     "G_II_%d" % t, "lambda_c_%d" % t,
                                                     "driver_%d" % t)
    print(head)
    table, worst, compared, skipped, released_none = [], (0.0, None), 0, 0, 0
    for row in rows:
        lam, length = number(row["load_factor"]), number(row["crack_length"])
        line = "%5s %9.5g %9.5g" % (row["step"], lam, length)
        entry = {"step": row["step"], "lambda": lam, "l": length, "tips": {}}
        for t in tips:
            g = number(row.get("tip%d_G" % t))
            driver = number(row.get("tip%d_critical_load" % t))
            own = float("nan")
            if gc is not None and not math.isnan(g):
                own = lam * math.sqrt(gc / g) if g > 0 else float("inf")
            if gc is not None and not math.isnan(own):
                if math.isinf(own) and math.isnan(driver):
                    # Nothing released: an infinite critical load, which
                    # growth.csv writes as null (non-finite numbers are).
                    released_none += 1
                elif math.isnan(driver):
                    skipped += 1
                else:
                    compared += 1
                    d = relative(own, driver)
                    if d > worst[0] or worst[1] is None:
                        worst = (d, (row["step"], t))
            values = {k: number(row.get("tip%d_%s" % (t, k))) for k in ("s", "G_I", "G_II")}
            values.update(G=g, own=own, driver=driver, status=row.get("tip%d_status" % t) or "gone")
            entry["tips"][t] = values
            line += " | %9.5g %12.5e %12.5e %12.5e %12.6g %12.6g" % (
                values["s"], g, values["G_I"], values["G_II"], own, driver)
        print(line, flush=True)
        table.append(entry)

    with open(names[NAME + ".csv"], "w", newline="") as f:
        w = csv.writer(f)
        cols = ["step", "load_factor", "crack_length"]
        for t in tips:
            cols += ["tip%d_%s" % (t, k) for k in ("s", "G", "G_I", "G_II", "lambda_c",
                                                   "critical_load", "status")]
        w.writerow(cols)
        for e in table:
            cells = [e["step"], "%.10g" % e["lambda"], "%.10g" % e["l"]]
            for t in tips:
                v = e["tips"][t]
                cells += ["%.12e" % v[k] for k in ("s", "G", "G_I", "G_II", "own", "driver")]
                cells.append(v["status"])
            w.writerow(cells)
    with open(names[NAME + ".dat"], "w") as f:
        f.write("# l then per tip: G lambda_c (script) critical_load (driver)\n")
        for e in table:
            f.write("%.10g" % e["l"] + "".join(" %.12e %.12e %.12e" % (
                e["tips"][t]["G"], e["tips"][t]["own"], e["tips"][t]["driver"]) for t in tips)
                + "\n")
    lines = figure_lines(NAME + ".png", NAME + ".dat", tips, "%s: G along the sweep (driver)" % scene,
                         gc is not None)
    bilayer_run.gnuplot(NAME, lines, folder.path)
    print("figure: %s" % names[NAME + ".png"])
    if figure is not None:
        bilayer_run.copy_figure(NAME, names[NAME + ".png"], figure)
        print("figure: %s" % figure)
    print("table: %s" % names[NAME + ".csv"])
    print("one bilayer run, %d crack lengths, %.1f s; stop: %s" % (
        len(table), seconds, (r.summary or {}).get("growth", {}).get("stop", "?")))
    if gc is None:
        print("no --toughness: the driver's critical_load (with the scene's Fracture/Toughness "
              "%s) is printed, not checked" % entries.get("Fracture/Toughness"))
        return
    if released_none:
        print("%d tip rows release nothing (G <= 0): lambda_c is infinite, the driver's "
              "critical_load null (growth.csv writes non-finite numbers as null)" % released_none)
    if skipped:
        print("%d tip rows have G > 0 but no driver critical_load (a preload: the critical load is "
              "not sqrt(G_c / G)); not compared" % skipped)
    if compared == 0:
        fail("no tip row to compare the two critical loads")
    step, tip = worst[1]
    print("largest relative difference of lambda sqrt(G_c / G) and the driver's critical_load: "
          "%.2e (step %s, tip %d) over %d tip rows; required <= %g" % (
              worst[0], step, tip, compared, AGREEMENT))
    if not worst[0] <= AGREEMENT:
        fail("the critical loads differ by %.2e > %g (step %s, tip %d)" % (
            worst[0], AGREEMENT, step, tip))

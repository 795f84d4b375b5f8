"""The table and the plots of scripts/mesh_convergence (see its --help),
from a finished run of bilayer (standard library only, and gnuplot).

    python3 scripts/convergence_table.py RUN PLOTS NAME REFERENCE START END
        RUN: bilayer's output directory (its summary.json and
        used_parameters.prm); PLOTS: the folder of convergence.dat and the
        PNGs; NAME: the scene's name in the titles; REFERENCE: Pi_ref, or
        '' to extrapolate it; START, END: when the run began and ended
        (seconds, `date +%s.%N`), its wall time printed last
    python3 scripts/convergence_table.py --check-reference VALUE
        exit 0 where VALUE is a finite number, 1 (silently) where not
"""
import math
import os
import subprocess
import sys

import study_lib
from bilayer_run import gnuplot_string


def number(x):
    """x if it is a positive finite number, else None (absent, null, 0)."""
    return x if isinstance(x, (int, float)) and math.isfinite(x) and x > 0 else None


def highest_degree(run):
    """The highest polynomial degree p of the run (used_parameters.prm):
    e_h cannot fall faster than N^-p/2 in 2D, nor Pi_h - Pi faster than
    N^-p."""
    degree = 1
    try:
        for l in open(os.path.join(run, "used_parameters.prm")):
            if "Polynomial degree of layer" in l and "=" in l:
                degree = max(degree, int(l.split("=")[1]))
    except (OSError, ValueError):
        pass
    return degree


def reference(n, pi, given, degree):
    """(Pi_ref, how it was found, the number of cycles whose error against
    it is meaningful): GIVEN, else extrapolated from the last three cycles,
    else the finest cycle's energy (its own error omitted)."""
    cycles = len(pi)
    if given:
        return float(given), "given by --reference", cycles
    fit3 = study_lib.extrapolate(n[-3:], pi[-3:]) if cycles >= 3 else None
    if fit3 is not None:
        pi_ref, b = fit3
        how = ("extrapolated from cycles %d-%d (Pi_h - Pi_ref ~ N^-%.2f, i.e. h^%.2f)"
               % (cycles - 3, cycles - 1, b, 2 * b))
        if b > 1.1 * degree:
            how += ("; note: faster than the N^-%d that degree %d allows, so the last cycles "
                    "look pre-asymptotic and e_h may be underestimated (--reference VALUE "
                    "sets Pi_ref)" % (degree, degree))
        return pi_ref, how, cycles
    how = ("the finest cycle's energy (%s); its own error omitted" %
           ("fewer than 3 cycles" if cycles < 3 else
            "the last three energies do not converge monotonically"))
    return pi[-1], how, cycles - 1


def rates(n, values):
    """Rates in powers of h between consecutive cycles (None where either
    value is missing or the dofs did not grow)."""
    out = [None]
    for k in range(1, len(values)):
        a, b = values[k - 1], values[k]
        out.append(-2 * math.log(b / a) / math.log(n[k] / n[k - 1])
                   if a and b and n[k] > n[k - 1] else None)
    return out


def fit(n, values):
    """Least-squares slope s of log value against log N over the finer half
    of the cycles that have a value (value ~ N^s), its intercept and the
    first and last of those cycles; None with fewer than two."""
    pts = [(k, v) for k, v in enumerate(values) if v]
    pts = pts[len(pts) // 2:]
    if len(pts) < 2:
        return None
    s, c0 = study_lib.loglog_fit([n[k] for k, _ in pts], [v for _, v in pts])
    if math.isnan(s):
        return None
    return s, c0, pts[0][0], pts[-1][0]


def f(x, fmt):
    """x formatted, "-" for None, without the sign of a negative zero."""
    if x is None:
        return "-"
    text = fmt % x
    return text[1:] if text.startswith("-") and float(text) == 0 else text


def plot(plots, name, n, h, err, eta, fits, cycles):
    """error_vs_dofs.png (e_h and eta against N, log-log, with the fitted
    lines) and iterations_vs_h.png (or _vs_dofs.png where h does not
    change) in PLOTS, from its convergence.dat."""
    curves, points = [], 0
    for label, values, col, point, colour in (("e_h", err, 5, 7, 1), ("eta", eta, 7, 5, 2)):
        points = max(points, sum(1 for v in values if v))
        if not any(values):
            continue
        curves.append("'convergence.dat' using 2:%d with linespoints lw 2 pt %d lc %d title '%s'"
                      % (col, point, colour, label))
        if label in fits:
            s, c0, k0, k1 = fits[label]
            # The fitted line over all cycles (the early ones show how far
            # they are from the asymptotic rate).
            curves.append("(x >= %r && x <= %r) ? exp(%r) * x ** %r : 1/0 with lines dt 2 lw 1 "
                          "lc %d title '%s ~ N^%s (h^%s), fit of cycles %d-%d'"
                          % (0.9 * min(n), 1.1 * max(n), c0, s, colour, label, f(s, "%.2f"),
                             f(-2 * s, "%.2f"), k0, k1))
    script = ["set terminal pngcairo size 720,520", "set termoption noenhanced",
              "set datafile missing '-'", "set grid", "set logscale x"]
    pngs = []
    if points >= 2:
        pngs.append("error_vs_dofs.png")
        script += ["set output 'error_vs_dofs.png'", "set logscale y",
                   "set format y '%.0e'", "set samples 400",
                   "set xlabel 'dofs N'", "set ylabel 'energy norm'",
                   "set key bottom left",
                   "set title %s" % gnuplot_string(
                       "%s: error e_h = sqrt(2 |Pi_h - Pi_ref|) and estimate eta" % name),
                   "plot " + ", ".join(curves), "unset logscale y", "set format y '%g'"]
    # Against h; against N where h does not change (adaptive refinement that
    # keeps a coarse cell).
    x = ("h", 3, "h (longest cell edge)") if max(h) > min(h) else ("dofs", 2, "dofs N (h constant)")
    if cycles >= 2:
        pngs.append("iterations_vs_%s.png" % x[0])
        script += ["set output 'iterations_vs_%s.png'" % x[0], "set xlabel '%s'" % x[2],
                   "set ylabel 'iterations'", "set yrange [0:*]", "set key bottom right",
                   "set title %s" % gnuplot_string("%s: outer iterations vs %s" % (name, x[0])),
                   "plot 'convergence.dat' using %d:10 with linespoints pt 7 lw 2 title 'iterations'"
                   % x[1]]
    if pngs:
        subprocess.run(["gnuplot"], input="\n".join(script) + "\n", text=True, cwd=plots,
                       check=True)
        print("\n".join(os.path.join(plots, p) for p in pngs))
    else:
        print("(too few cycles to plot)")


def report(run, plots, name, given):
    """Prints the table and its notes, writes PLOTS/convergence.dat and the
    PNGs."""
    cycles = study_lib.cycles(run)
    n = [c["dofs"] for c in cycles]
    h = [max(c["h_max_minus"], c["h_max_plus"]) for c in cycles]
    pi = [c["energy"] for c in cycles]
    iterations = [c["iterations"] for c in cycles]
    eta = [number(c.get("eta")) for c in cycles]

    pi_ref, how, measured = reference(n, pi, given, highest_degree(run))
    err = [math.sqrt(2 * abs(p - pi_ref)) if k < measured else None for k, p in enumerate(pi)]
    err = [e if e is None or e > 0 else None for e in err]
    err_rate, eta_rate = rates(n, err), rates(n, eta)
    efficiency = [a / b if a and b else None for a, b in zip(eta, err)]

    columns = [("cycle", "%d"), ("dofs", "%d"), ("h", "%.4e"), ("energy", "%.10e"),
               ("e_h", "%.3e"), ("rate", "%.2f"), ("eta", "%.3e"), ("eta_rate", "%.2f"),
               ("efficiency", "%.2f"), ("iterations", "%d")]
    rows = [[f(v, fmt) for v, (_, fmt) in zip(r, columns)]
            for r in zip(range(len(cycles)), n, h, pi, err, err_rate, eta, eta_rate,
                         efficiency, iterations)]
    widths = [max(len(col), *(len(r[i]) for r in rows)) for i, (col, _) in enumerate(columns)]
    line = lambda cells: "  ".join(c.rjust(w) for c, w in zip(cells, widths))

    fits = {}
    notes = ["Pi_ref = %.10e: %s" % (pi_ref, how),
             "e_h = sqrt(2 |Pi_h - Pi_ref|); rates in powers of h ~ N^-1/2: "
             "-2 log(e_i/e_{i-1}) / log(N_i/N_{i-1}); efficiency = eta / e_h"]
    for label, values in (("e_h", err), ("eta", eta)):
        r = fit(n, values)
        if r is not None:
            fits[label] = r
            notes.append("least squares over cycles %d-%d: %s ~ N^%s (h^%s)" % (
                r[2], r[3], label, f(r[0], "%.2f"), f(-2 * r[0], "%.2f")))
    if not any(eta):
        notes.append("eta: not in summary.json (a bilayer without the global estimate)")

    table = [line([c for c, _ in columns])] + [line(r) for r in rows]
    print("%s: convergence" % name)
    print("\n".join(table))
    print("\n".join(notes))
    with open(os.path.join(plots, "convergence.dat"), "w") as out_file:
        out_file.write("".join("# %s\n" % s for s in notes))
        out_file.write("# " + " ".join(c for c, _ in columns) + "\n")
        for r in rows:
            out_file.write(" ".join(r) + "\n")
    plot(plots, name, n, h, err, eta, fits, len(cycles))


def main(argv):
    if len(argv) == 2 and argv[0] == "--check-reference":
        try:
            return 0 if math.isfinite(float(argv[1])) else 1
        except ValueError:
            return 1
    if len(argv) != 6:
        sys.exit("usage: convergence_table.py RUN PLOTS NAME REFERENCE START END | "
                 "--check-reference VALUE")
    run, plots, name, given, start, end = argv
    report(run, plots, name, given)
    print()
    print("wall time %s s; bilayer's table and summary.json in %s; convergence.dat and PNGs in %s"
          % (round(float(end) - float(start), 1), run, plots))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

"""Where the meshes of scripts/adaptive_study refine (see its --help): the
smallest cell width at the crack tips, at the end of the contact zone and
elsewhere in its four runs mesh-SCENE-interface-TERMS-WEIGHT, the cell
edges of three of them (edges-SCENE-WEIGHT.dat) and the picture of those
(gnuplot). Reads the VTU with VTK's Python module (Debian: python3-vtk9,
for /usr/bin/python3).

    /usr/bin/python3 scripts/adaptive_meshes.py OUT CYCLE PNG
        OUT: adaptive_study's output folder; CYCLE: the cycle read, two
        digits; PNG: the picture's name in OUT
"""
import subprocess
import sys

import vtk

import study_lib

out, last, png = sys.argv[1:4]


def cells(path):
    r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(path); r.Update()
    g = r.GetOutput()
    return [g.GetCell(c).GetBounds()[:4] for c in range(g.GetNumberOfCells())]


def contact_end(path):
    """The last open node and the first node in contact (mu_c > 0)."""
    rows = sorted((float(r["x"]), float(r["mu_c"])) for r in study_lib.interface_rows(path)
                  if r["on_crack"] == "1")
    for (x0, m0), (x1, m1) in zip(rows, rows[1:]):
        if m0 == 0 and m1 > 0:
            return x0, x1
    return None


runs = [("partial_closure", "true", "1"), ("partial_closure", "false", "1"),
        ("partial_closure", "true", "100"), ("full_opening", "true", "1")]
for scene, interface, weight in runs:
    d = "%s/mesh-%s-interface-%s-%s" % (out, scene, interface, weight)
    minus = cells("%s/solution-%s-u-minus.vtu" % (d, last))
    plus = cells("%s/solution-%s-u-plus.vtu" % (d, last))
    bracket = contact_end("%s/interface-%s.csv" % (d, last))
    pts = [("open crack tip", -0.5, 0.0), ("other crack tip", 0.5, 0.0)]
    if bracket is not None:
        xc = 0.5 * sum(bracket)
        pts += [("contact zone end in (%.4f, %.4f)" % bracket, xc, 0.0),
                ("open part of the crack", -0.15, 0.0),
                ("inside the contact zone", 0.5 * (xc + 0.5), 0.0)]
    pts += [("Sigma outside the crack", 0.75, 0.0), ("clamped corner", -1.0, -1.0),
            ("interior", 0.0, -0.5)]
    print("%s, interface terms %s, contact weight %s, cycle %s (%d + %d cells), smallest cell "
          "width (initial 0.125):" % (scene, interface, weight, last, len(minus), len(plus)))
    for name, x, y in pts:
        w = min([b[1] - b[0] for b in minus + plus
                 if b[0] - 1e-9 <= x <= b[1] + 1e-9 and b[2] - 1e-9 <= y <= b[3] + 1e-9])
        print("  %-34s %.4g" % (name, w))
    if interface == "true":
        with open("%s/edges-%s-%s.dat" % (out, scene, weight), "w") as f:
            for x0, x1, y0, y1 in minus + plus:
                f.write("%g %g\n%g %g\n%g %g\n%g %g\n%g %g\n\n" % (x0, y0, x1, y0, x1, y1, x0, y1, x0, y0))
script = """set terminal pngcairo size 1500,1000 font ',11'
set output 'adaptive_meshes.png'
set multiplot layout 2,3
set size ratio -1
unset key
set title 'Example 1 (partial closure): cycle %(last)s'
plot [-1:1][-1:1] 'edges-partial_closure-1.dat' with lines lw 0.5 lc 'black'
set title 'Example 1: open tip (-0.5, 0)'
plot [-0.6:-0.4][-0.1:0.1] 'edges-partial_closure-1.dat' with lines lw 0.5 lc 'black'
set title 'Example 1: contact zone (x > 0.17) and closed tip (0.5, 0)'
plot [0:0.6][-0.3:0.3] 'edges-partial_closure-1.dat' with lines lw 0.5 lc 'black'
set title 'Example 2 (full opening): cycle %(last)s'
plot [-1:1][-1:1] 'edges-full_opening-1.dat' with lines lw 0.5 lc 'black'
set title 'Example 2: tip (0.5, 0)'
plot [0.4:0.6][-0.1:0.1] 'edges-full_opening-1.dat' with lines lw 0.5 lc 'black'
set title 'Example 1, weight of the contact term 100: contact zone'
plot [0:0.6][-0.3:0.3] 'edges-partial_closure-100.dat' with lines lw 0.5 lc 'black'
unset multiplot
""" % {"png": png, "last": last, "out": out}
subprocess.run(["gnuplot"], input=script, text=True, check=True, cwd=out)
print("mesh picture: %s/%s" % (out, png))

"""Checks a picture of scripts/view against what it must show, from its
--describe JSON, its PNG and the solution files themselves (read here with
VTK's own reader, piece by piece, independently of scripts/view.py):
  - each layer has its own colour range: the 99th percentile of |value| over
    the layer's area (|cell average| of the point values, of the vector for
    a vector field, weighted by the
    cell areas, computed here from the pieces solution-NN-u-* for layer 1
    and solution-NN-v-* for layer 2) when the largest value exceeds it by
    more than 1.2 (then "saturated"), else the largest |value|; from 0 for
    a field >= 0;
  - the colour bar of each layer is titled with the layer ("layer 1 (u): ");
  - every colour bar, the title and the legend lie inside the picture
    ([0, 1]^2 as fractions), the bars do not overlap each other, and the
    outermost rows and columns of the PNG are background (nothing cut at
    the edge);
  - both layers are drawn alike: the same representation (edges on both or
    on neither, as EDGES says: on, off or auto), edge colour, line width and
    opacity;
  - in the PNG, each layer's region shows many colours (not one uniform
    colour);
  - units from RESULT_DIR/summary.json ("units": stress, length,
    energy_release_rate; without them "units of E", "length unit", "units
    of E × length"): the colour bars of a stress field and of the contact
    pressure end in "[stress]", the axes are titled "x [length]" and "y
    [length]";
  - length axes on each layer: at least two ticks along x and along y, at
    round values inside the layer's undeformed bounds (from the pieces),
    labelled with their values, every label inside the picture, apart from
    each other, from the layers' regions, the colour bars, the title and the
    legends;
  - the crack tips of the cycle (summary.json's crack_tips): a line "tip N
    at (x, y): G = g ± e" for each (", interface K" after the point where
    K >= 2), inside the picture and apart from the
    bars, and a number N drawn at the tip on each layer, inside the layer's
    region.
Usage: pvpython view_scene.py DESCRIBE.json PICTURE.png RESULT_DIR EDGES
Prints one line per check ("...: yes" / "...: NO ..."); exit status 1 if
any failed.
"""
import glob
import json
import math
import sys

from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

describe, picture, result, edges = sys.argv[1:5]
scene = json.load(open(describe))
failures = 0


def check(what, ok, why=""):
    global failures
    print("%s: %s" % (what, "yes" if ok else "NO " + why))
    failures += 0 if ok else 1


def own_scale(files, field):
    """(99th area percentile of |cell average|, largest |point value|, min)."""
    pairs, largest, smallest = [], 0.0, math.inf
    for name in files:
        reader = vtkXMLUnstructuredGridReader()
        reader.SetFileName(name)
        reader.Update()
        grid = reader.GetOutput()
        array = grid.GetPointData().GetArray(field)
        c = array.GetNumberOfComponents()

        vectors = [[array.GetComponent(i, j) for j in range(c)]
                   for i in range(grid.GetNumberOfPoints())]
        values = [v[0] if c == 1 else math.sqrt(sum(x * x for x in v)) for v in vectors]
        largest = max([largest] + [abs(v) for v in values])
        smallest = min([smallest] + values)
        for cell in range(grid.GetNumberOfCells()):
            ids = grid.GetCell(cell).GetPointIds()
            n = ids.GetNumberOfIds()
            p = [grid.GetPoint(ids.GetId(k)) for k in range(n)]
            if n == 4:  # VTK's quad order is counter-clockwise
                area = 0.5 * abs(sum(p[k][0] * p[(k + 1) % 4][1] - p[(k + 1) % 4][0] * p[k][1]
                                     for k in range(4)))
            else:
                area = 0.5 * abs(sum(p[k][0] * p[(k + 1) % n][1] - p[(k + 1) % n][0] * p[k][1]
                                     for k in range(n)))
            # |the cell average| (of the vector, for a vector field)
            mean = [sum(vectors[ids.GetId(k)][j] for k in range(n)) / n for j in range(c)]
            pairs.append((math.sqrt(sum(x * x for x in mean)), area))
    pairs.sort()
    total, running = sum(a for _, a in pairs), 0.0
    for v, a in pairs:
        running += a
        if running >= 0.99 * total:
            return v, largest, smallest
    return pairs[-1][0], largest, smallest


field = scene["field"]
layers = {entry["layer"]: entry for entry in scene["layers"]}
check("two layers drawn", sorted(layers) == [1, 2], str(sorted(layers)))
for layer, letter in ((1, "u"), (2, "v")):
    if layer not in layers:
        continue
    entry = layers[layer]
    files = sorted(glob.glob("%s/solution-%02d-%s-*.vtu" % (result, scene["cycle"], letter)))
    p99, largest, smallest = own_scale(files, field)
    saturated = 0 < p99 < largest / 1.2
    top = p99 if saturated else largest
    low, high = entry["range"]
    check("layer %d: the colours end at its own %s %.6g" % (
        layer, "99th percentile" if saturated else "largest value", top),
        abs(high - top) <= 1e-5 * top and entry["saturated"] == saturated,
        "(the range is %s, saturated %s)" % (entry["range"], entry["saturated"]))
    if smallest >= 0:
        check("layer %d: the colours start at 0" % layer, low == 0, str(low))
    bar = entry["bar"]
    check("layer %d: its colour bar is titled 'layer %d (%s): '" % (layer, layer, letter),
          bar["title"].startswith("layer %d (%s): " % (layer, letter)) and bar["visible"],
          repr(bar["title"]))
if 1 in layers and 2 in layers:
    check("the layers have different colour ranges",
          layers[1]["range"] != layers[2]["range"], str(layers[1]["range"]))
    same = all(layers[1][k] == layers[2][k]
               for k in ("representation", "edge_color", "line_width", "opacity"))
    check("both layers drawn alike (%s)" % layers[1]["representation"], same,
          str([(layers[l]["representation"], layers[l]["edge_color"], layers[l]["line_width"],
                layers[l]["opacity"]) for l in (1, 2)]))
want = {"on": "Surface With Edges", "off": "Surface"}.get(edges)
if want:
    check("edges %s on both layers" % edges,
          all(entry["representation"] == want for entry in layers.values()))

rects = [("layer %d bar" % l, layers[l]["bar"]["rect"]) for l in sorted(layers)]
if scene.get("contact_pressure_bar") and scene["contact_pressure_bar"]["visible"]:
    rects.append(("contact_pressure bar", scene["contact_pressure_bar"]["rect"]))
bars = list(rects)
rects += [("title", scene["title"]["rect"]), ("legend", scene["legend"]["rect"])]
for name, r in rects:
    check("%s inside the picture" % name,
          0 <= r[0] < r[2] <= 1 and 0 <= r[1] < r[3] <= 1, str(r))
for i in range(len(bars)):
    for j in range(i + 1, len(bars)):
        a, b = bars[i][1], bars[j][1]
        overlap = a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]
        check("%s and %s apart" % (bars[i][0], bars[j][0]), not overlap, "%s %s" % (a, b))

reader = vtkPNGReader()
reader.SetFileName(picture)
reader.Update()
image = reader.GetOutput()
nx, ny, _ = image.GetDimensions()
check("PNG of the described size", [nx, ny] == scene["size"], "%dx%d" % (nx, ny))
rgb = image.GetPointData().GetScalars()


def pixel(i, j):  # (i, j) from the lower left corner, as VTK reads it
    k = j * nx + i
    return tuple(int(rgb.GetComponent(k, c)) for c in range(3))


border = [(i, j) for i in range(nx) for j in (0, ny - 1)] + \
         [(i, j) for j in range(ny) for i in (0, nx - 1)]
dark = [p for p in border if min(pixel(*p)) < 200]
check("the border of the PNG is background (nothing cut at the edge)", not dark,
      "%d pixels drawn there, e.g. %s" % (len(dark), dark[:3]))
for layer in sorted(layers):
    r = layers[layer]["region"]
    x0, x1 = r[0] + 0.1 * (r[2] - r[0]), r[2] - 0.1 * (r[2] - r[0])
    y0, y1 = r[1] + 0.1 * (r[3] - r[1]), r[3] - 0.1 * (r[3] - r[1])
    colours = set()
    for j in range(int(y0 * ny), int(y1 * ny)):
        for i in range(int(x0 * nx), int(x1 * nx), 2):
            colours.add(tuple(c // 16 for c in pixel(i, j)))
    check("layer %d: many colours in its region of the PNG (%d)" % (layer, len(colours)),
          len(colours) >= 12)
# Units, axes and crack tips.
summary = {}
try:
    summary = json.load(open("%s/summary.json" % result))
except (OSError, ValueError):
    pass
units = summary.get("units") if isinstance(summary.get("units"), dict) else {}
stress = units.get("stress") or "units of E"
length = units.get("length") or "length unit"
g_unit = units.get("energy_release_rate") or "units of E \u00d7 length"
stress_field = field in ("von_mises", "stress_xx", "stress_yy", "stress_zz", "stress_xy")
for layer in sorted(layers):
    title = layers[layer]["bar"]["title"]
    if stress_field:
        check("layer %d: its bar says [%s]" % (layer, stress), ("[%s]" % stress) in title, repr(title))
if scene.get("contact_pressure_bar"):
    title = scene["contact_pressure_bar"]["title"]
    check("the contact pressure bar says [%s]" % stress, ("[%s]" % stress) in title, repr(title))


def undeformed_bounds(files):
    lo, hi = [math.inf] * 2, [-math.inf] * 2
    for name in files:
        reader = vtkXMLUnstructuredGridReader()
        reader.SetFileName(name)
        reader.Update()
        b = reader.GetOutput().GetBounds()
        lo = [min(lo[0], b[0]), min(lo[1], b[2])]
        hi = [max(hi[0], b[1]), max(hi[1], b[3])]
    return lo, hi


def apart(a, b):
    return not (a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3])


others = [(name, r) for name, r in rects] + \
    [("the region of layer %d" % l, layers[l]["region"]) for l in sorted(layers)]
if scene.get("crack_tips"):
    others.append(("crack tips", scene["crack_tips"]["rect"]))
labels = []
for layer, letter in ((1, "u"), (2, "v")):
    axes = scene.get("axes", {}).get(str(layer))
    if layer not in layers:
        continue
    if not axes:
        check("layer %d: length axes drawn" % layer, False, "none described")
        continue
    check("layer %d: axes titled x [%s], y [%s]" % (layer, length, length),
          axes["x_title"] == "x [%s]" % length and axes["y_title"] == "y [%s]" % length,
          "%r, %r" % (axes["x_title"], axes["y_title"]))
    lo, hi = undeformed_bounds(glob.glob("%s/solution-%02d-%s-*.vtu" % (result, scene["cycle"], letter)))
    for k, name in ((0, "x"), (1, "y")):
        ticks = axes[name + "_ticks"]
        step = ticks[1] - ticks[0] if len(ticks) > 1 else 0
        inside = all(lo[k] - 1e-9 * (hi[k] - lo[k]) <= v <= hi[k] + 1e-9 * (hi[k] - lo[k]) for v in ticks)
        round_ = step > 0 and all(abs(v / step - round(v / step)) < 1e-6 for v in ticks) and \
            ("%.0e" % step)[0] in "125"
        check("layer %d: %d round ticks along %s inside [%g, %g]" % (layer, len(ticks), name, lo[k], hi[k]),
              len(ticks) >= 2 and inside and round_, str(ticks))
        texts = sorted(float(e["text"]) for e in axes["labels"] if e["name"].startswith(name + " = "))
        check("layer %d: the %s ticks labelled with their values" % (layer, name),
              all(abs(a - b) <= 1e-9 * max(1.0, abs(b)) for a, b in zip(texts, ticks)) and
              len(texts) == len(ticks), "%s for %s" % (texts, ticks))
    labels += [("layer %d %s" % (layer, e["name"]), e["rect"]) for e in axes["labels"]]
for name, r in labels:
    if not (0 <= r[0] < r[2] <= 1 and 0 <= r[1] < r[3] <= 1):
        check("%s inside the picture" % name, False, str(r))
    clash = [o for o, q in others if not apart(r, q)]
    if clash:
        check("%s apart from %s" % (name, clash[0]), False, "%s" % r)
clash = [(a[0], b[0]) for i, a in enumerate(labels) for b in labels[i + 1:] if not apart(a[1], b[1])]
check("%d axis labels inside the picture, apart from each other, the layers and the legends" %
      len(labels),
      labels and not clash and all(0 <= r[0] < r[2] <= 1 and 0 <= r[1] < r[3] <= 1 for _, r in labels),
      str(clash[:3]))

record = [c for c in summary.get("cycles", []) if c.get("cycle") == scene["cycle"]]
tips = record[0].get("crack_tips") or [] if record else []
if tips:
    described = scene.get("crack_tips") or {}
    text = described.get("text", "")
    check("the crack tips listed with G [%s]" % g_unit, ("[%s]" % g_unit) in text, repr(text[:80]))
    for n, tip in enumerate(tips[:8], 1):
        where = ", interface %s" % tip["interface"] if tip.get("interface", 1) != 1 else ""
        line = "tip %d at (%.4g, %.4g)%s: " % (n, tip["x"], tip["y"], where)
        if tip.get("G") is None:
            line += "G not computed"
        else:
            line += "G = %.3g" % tip["G"]
            if tip.get("G_error") is not None:
                line += " \u00b1 %.2g" % tip["G_error"]
        check("the list says %r" % line, line in text.splitlines(), repr(text))
    r = described.get("rect", [0, 0, 0, 0])
    check("the list of tips inside the picture and apart from the bars",
          0 <= r[0] < r[2] <= 1 and 0 <= r[1] < r[3] <= 1 and all(apart(r, q) for _, q in bars), str(r))
    for layer in sorted(layers):
        region = layers[layer]["region"]
        for n in range(1, min(len(tips), 8) + 1):
            mark = [e for e in scene.get("tip_labels", []) if e["name"] == "tip %d, layer %d" % (n, layer)]
            ok = len(mark) == 1 and mark[0]["text"] == str(n)
            if ok:
                m = mark[0]["rect"]
                cx = (m[0] + m[2]) / 2
                ok = region[0] <= cx <= region[2] and region[1] <= m[1] <= region[3]
            check("layer %d: tip %d numbered at the tip" % (layer, n), ok, str(mark))
sys.exit(1 if failures else 0)

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
    colour).
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
sys.exit(1 if failures else 0)

"""The ParaView side of scripts/view (see its --help): one bilayer result
directory, one cycle, both layers side by side (or one above the other for
wide scenes), each warped by its displacement, coloured by a point field,
with the interface Sigma drawn on top: the crack faces of each layer warped
by their traces (u_minus/u_plus, v_minus/v_plus) and coloured by the contact
pressure (grey: 0, an open or untouched face), the glued part as a thin black
line. Writes a PNG and/or a ParaView state file.

Two modes:
  python3 view.py check RESULT_DIR CYCLE FIELD
      checks the directory, the cycle ('' for the last) and the field without
      ParaView (plain python3, fast); exit 0, or one line "view: ..." on stderr
      and exit 1.
  pvbatch view.py render JSON
      JSON: {"dir", "cycle", "field", "png" (or null), "state", "width",
      "height", "scale" (null: automatic)}. Prints "view-info: ..." lines for
      the wrapper, "view-error: ..." on a failure it understands and
      "view-done" when both files are written (pvbatch of Debian's ParaView
      5.11 sometimes crashes at exit; the wrapper retries on a missing
      "view-done").
The wrapper (scripts/view) owns the choice of the output files; this script
writes exactly the paths it is given.
"""

import json
import math
import os
import sys
import xml.etree.ElementTree as ET

MARKER = "bilayer scripts/view"
STRESS_FIELDS = ("von_mises", "stress_xx", "stress_yy", "stress_zz", "stress_xy")


class ViewError(Exception):
    """A problem with the input that the user can fix: one line."""


def collection(pvd):
    """[(timestep as float, absolute file)] of a ParaView .pvd collection."""
    try:
        root = ET.parse(pvd).getroot()
    except (ET.ParseError, OSError) as error:
        raise ViewError("%s: not a readable ParaView collection (%s)" % (pvd, error))
    entries = []
    for node in root.iter("DataSet"):
        try:
            entries.append((float(node.get("timestep", "0")),
                            os.path.join(os.path.dirname(pvd), node.get("file"))))
        except (TypeError, ValueError):
            raise ViewError("%s: a DataSet without a valid timestep or file" % pvd)
    if not entries:
        raise ViewError("%s: lists no data set" % pvd)
    return entries


def vtk_arrays(path):
    """({point array: components}, {cell array: components}, [piece files]) of
    a .vtu or .pvtu, from its XML header (only the header is read)."""
    header = []
    try:
        with open(path, "rb") as f:
            for raw in f:
                if raw.lstrip()[:1] != b"<":
                    continue  # data
                line = raw.decode("latin-1")
                header.append(line)
                if "</Piece>" in line or "</PUnstructuredGrid>" in line:
                    break
    except OSError as error:
        raise ViewError("%s: cannot be read (%s)" % (path, error.strerror))
    point, cell, pieces, section = {}, {}, [], None
    import re
    for line in header:
        if re.search(r"<P?PointData", line):
            section = point
        elif re.search(r"<P?CellData", line):
            section = cell
        elif re.search(r"</P?(PointData|CellData)>", line):
            section = None
        m = re.search(r'<P?DataArray[^>]*Name="([^"]+)"', line)
        if m and section is not None:
            c = re.search(r'NumberOfComponents="(\d+)"', line)
            section[m.group(1)] = int(c.group(1)) if c else 1
        m = re.search(r'<Piece Source="([^"]+)"', line)
        if m:
            pieces.append(os.path.join(os.path.dirname(path), m.group(1)))
    return point, cell, pieces


def discover(directory, cycle, field):
    """Everything the picture needs, checked; raises ViewError."""
    d = directory.rstrip("/") or "/"
    if not os.path.exists(d):
        raise ViewError("%s: no such directory" % directory)
    if not os.path.isdir(d):
        raise ViewError("%s: not a directory (give a bilayer output directory)" % directory)
    pvd = os.path.join(d, "solution.pvd")
    if not os.path.isfile(pvd):
        if os.path.isfile(os.path.join(d, "solution.xdmf")):
            raise ViewError("%s: the run wrote no VTU, only HDF5/XDMF (Output/Write VTU = false): "
                            "rerun with --set 'Output/Write VTU=true', or open solution.xdmf "
                            "in ParaView with the XDMF reader" % directory)
        if os.path.isfile(os.path.join(d, "summary.json")):
            raise ViewError("%s: no solution.pvd: the run wrote no VTU "
                            "(rerun with --set 'Output/Write VTU=true')" % directory)
        extra = ""
        if os.path.isdir(d + ".partial"):
            extra = " (a run is writing %s.partial)" % d
        elif os.path.isdir(d + ".failed"):
            extra = " (the results of a failed run are in %s.failed)" % d
        raise ViewError("%s: no solution.pvd: not a bilayer output directory%s" % (directory, extra))
    solutions = collection(pvd)
    cycles = [int(round(t)) for t, _ in solutions]
    if cycle is None or cycle == "":
        index = len(solutions) - 1
    else:
        try:
            wanted = int(cycle)
        except ValueError:
            raise ViewError("--cycle %s: not a whole number" % cycle)
        if wanted not in cycles:
            raise ViewError("--cycle %s: %s has cycle%s %s" % (
                cycle, directory, "s" if len(cycles) > 1 else "",
                "%d to %d" % (cycles[0], cycles[-1]) if len(cycles) > 1 else cycles[0]))
        index = cycles.index(wanted)
    time, solution = solutions[index]
    if not os.path.isfile(solution):
        raise ViewError("%s: missing (listed in solution.pvd)" % solution)
    point, cell, pieces = vtk_arrays(solution)
    for piece in pieces:
        if not os.path.isfile(piece):
            raise ViewError("%s: missing (a piece of %s)" % (piece, os.path.basename(solution)))
    if point.get("displacement") != 3:
        raise ViewError("%s: no point field 'displacement' with 3 components" % solution)
    if "layer" in cell:
        layer_association = "CELLS"
    elif "layer" in point:
        layer_association = "POINTS"
    else:
        raise ViewError("%s: no field 'layer'" % solution)
    if field not in point:
        raise ViewError("--field %s: %s has no point field '%s' (it has: %s)" % (
            field, os.path.basename(solution), field, ", ".join(sorted(point))))
    interface, note = None, None
    ipvd = os.path.join(d, "interface.pvd")
    if os.path.isfile(ipvd):
        for t, f in collection(ipvd):
            if abs(t - time) < 1e-9:
                interface = f
        if interface is None:
            note = "interface.pvd has no cycle %d: the layers are drawn without the interface" % cycles[index]
        elif not os.path.isfile(interface):
            note = "%s is missing: the layers are drawn without the interface" % interface
            interface = None
        else:
            ipoint = vtk_arrays(interface)[0]
            wanted = ("contact_pressure", "state", "u_minus", "u_plus", "v_minus", "v_plus")
            missing = [a for a in wanted if a not in ipoint]
            if missing:
                note = "%s lacks %s: the layers are drawn without the interface" % (
                    interface, ", ".join(missing))
                interface = None
    else:
        note = "no interface.pvd in %s: the layers are drawn without the interface line" % directory
    scene, record = os.path.basename(os.path.abspath(d)), {}
    try:
        with open(os.path.join(d, "summary.json")) as f:
            summary = json.load(f)
        scene = summary.get("scene") or scene
        for r in summary.get("cycles", []):
            if r.get("cycle") == cycles[index]:
                record = r
    except (OSError, ValueError):
        pass
    return {"dir": os.path.abspath(d), "solution": os.path.abspath(solution),
            "interface": interface and os.path.abspath(interface), "note": note,
            "cycle": cycles[index], "cycles": cycles, "time": time,
            "layer_association": layer_association, "field": field,
            "field_components": point[field], "scene": scene, "record": record}


def nice(x):
    """x rounded to two significant digits."""
    if x <= 0:
        return x
    e = math.floor(math.log10(x)) - 1
    return round(x / 10 ** e) * 10 ** e


def fmt(x):
    return "%.3g" % x if x is not None else "?"


def add_png_text(path, keyword, text):
    """Insert a tEXt chunk after IHDR (marks the file as ours)."""
    import struct
    import zlib
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ViewError("%s: ParaView did not write a PNG" % path)
    ihdr_end = 8 + 8 + struct.unpack(">I", data[8:12])[0] + 4
    body = keyword.encode("latin-1") + b"\0" + text.encode("latin-1")
    chunk = struct.pack(">I", len(body)) + b"tEXt" + body + \
        struct.pack(">I", zlib.crc32(b"tEXt" + body) & 0xFFFFFFFF)
    with open(path, "wb") as f:
        f.write(data[:ihdr_end] + chunk + data[ihdr_end:])


def mark_state(path, info):
    with open(path) as f:
        text = f.read()
    comment = "<!-- written by %s: %s, cycle %d; open with: paraview --state=<this file> -->\n" % (
        MARKER, info["dir"].replace("--", "- -"), info["cycle"])
    if text.startswith("<?xml"):
        first, rest = text.split("\n", 1)
        text = first + "\n" + comment + rest
    else:
        text = comment + text
    with open(path, "w") as f:
        f.write(text)


def render(args):
    from paraview.simple import (
        AssignViewToLayout, ColorBy, CreateLayout, Delete, CreateView, GetColorTransferFunction,
        GetOpacityTransferFunction, GetScalarBar, Render, SaveScreenshot, SaveState, Show,
        Text, Threshold, Transform, WarpByVector, XMLPartitionedUnstructuredGridReader,
        XMLUnstructuredGridReader, a3DText)

    info = discover(args["dir"], args["cycle"], args["field"])
    field = info["field"]
    width, height = int(args["width"]), int(args["height"])
    base = os.path.basename(info["solution"])
    solution = XMLPartitionedUnstructuredGridReader(registrationName=base, FileName=[info["solution"]])
    solution.UpdatePipeline()
    sinfo = solution.GetDataInformation()
    bounds = sinfo.GetBounds()
    size = max(bounds[1] - bounds[0], bounds[3] - bounds[2]) or 1.0
    umax = solution.PointData["displacement"].GetRange(-1)[1]

    if args.get("scale") is not None:
        scale = float(args["scale"])
        how = "--scale"
    elif umax > 0:
        scale = nice(0.1 * size / umax)
        how = "automatic: the largest displacement %s is warped to %.0f %% of the scene size %s" % (
            fmt(umax), 100 * scale * umax / size, fmt(size))
    else:
        scale = 1.0
        how = "the displacement is zero"
    print("view-info: cycle %d of %s, displacement x %s (%s)" % (
        info["cycle"], "%d to %d" % (info["cycles"][0], info["cycles"][-1]) if len(info["cycles"]) > 1
        else "%d" % info["cycles"][0], "%g" % scale, how))

    # The layers, warped, each with its own offset (decided below).
    layers = {}
    for layer in (1, 2):
        threshold = Threshold(registrationName="layer %d" % layer, Input=solution)
        threshold.Scalars = [info["layer_association"], "layer"]
        threshold.LowerThreshold = layer - 0.5
        threshold.UpperThreshold = layer + 0.5
        warp = WarpByVector(registrationName="layer %d warped" % layer, Input=threshold)
        warp.Vectors = ["POINTS", "displacement"]
        warp.ScaleFactor = scale
        warp.UpdatePipeline()
        if warp.GetDataInformation().GetNumberOfCells() > 0:
            layers[layer] = warp
        else:  # Materials/Number of layers = 1
            Delete(warp)
            Delete(threshold)
    if 1 not in layers:
        raise ViewError("%s: no cells of layer 1" % info["solution"])
    present = sorted(layers)

    interface = None
    if info["interface"]:
        interface = XMLUnstructuredGridReader(registrationName=os.path.basename(info["interface"]),
                                              FileName=[info["interface"]])
        interface.UpdatePipeline()
        crack = Threshold(registrationName="crack (open or closed)", Input=interface)
        crack.Scalars = ["POINTS", "state"]
        crack.LowerThreshold = -0.5
        crack.UpperThreshold = 1.5
        crack.AllScalars = 0  # the segments next to the tips too
        glued = Threshold(registrationName="glued", Input=interface)
        glued.Scalars = ["POINTS", "state"]
        glued.LowerThreshold = 1.5
        glued.UpperThreshold = 2.5
        crack.UpdatePipeline()
        glued.UpdatePipeline()
        pmax = interface.PointData["contact_pressure"].GetRange()[1]

    # Layout: one box for each layer (the union of the warped bounds of both),
    # side by side or one above the other, whichever shows them larger, in the
    # part of the picture left free by the title (top) and the colour bars
    # (right).
    b = [min(layers[l].GetDataInformation().GetBounds()[i] for l in present) if i % 2 == 0 else
         max(layers[l].GetDataInformation().GetBounds()[i] for l in present) for i in range(4)]
    w, h = max(b[1] - b[0], 1e-12 * size), max(b[3] - b[2], 1e-12 * size)
    px = max(0.5, max(width, height) / 1600.0)  # the size of the fonts and margins
    top, bottom, left, right = 96 * px, 24 * px, 24 * px, 250 * px
    label, gap = 34 * px, 50 * px
    box_w, box_h = width - left - right, height - top - bottom
    k_side = min((box_w - gap) / (2 * w), (box_h - label) / h)
    k_stack = min(box_w / w, (box_h - 2 * label - gap) / (2 * h))
    # (one above the other also when it is almost as large: Sigma's points
    # then lie at the same x in both layers)
    side = k_side > k_stack / 0.9
    k = max(k_side if side else k_stack, 1e-30)  # pixels per unit length
    if len(present) == 1:
        k = max(min(box_w / w, (box_h - label) / h), 1e-30)
        offsets = {1: (0.0, 0.0)}
        content = (b[0], b[1], b[2], b[3] + label / k)
    elif side:
        offsets = {1: (0.0, 0.0), 2: (w + gap / k, 0.0)}
        content = (b[0], b[0] + 2 * w + gap / k, b[2], b[3] + label / k)
    else:
        offsets = {1: (0.0, 0.0), 2: (0.0, -(h + (gap + label) / k))}
        content = (b[0], b[1], b[2] - h - (gap + label) / k, b[3] + label / k)
    eps = 1e-3 * size

    view = CreateView("RenderView")
    view.ViewSize = [width, height]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1, 1, 1]
    view.InteractionMode = "2D"
    view.CameraParallelProjection = 1
    layout = CreateLayout("bilayer view")
    AssignViewToLayout(view=view, layout=layout, hint=0)
    # The GUI shows the view with the picture's proportions (View > Preview):
    # the camera, the colour bars and the texts are placed for them.
    layout.PreviewMode = [width, height]

    # The field: sequential map for von Mises and magnitudes, diverging and
    # symmetric for signed components.
    lut = GetColorTransferFunction(field)
    GetOpacityTransferFunction(field)
    fmin, fmax = None, None
    for layer in present:
        placed = Transform(registrationName="layer %d placed" % layer, Input=layers[layer])
        placed.Transform = "Transform"
        placed.Transform.Translate = [offsets[layer][0], offsets[layer][1], 0.0]
        display = Show(placed, view)
        # the cell edges where the cells are at least 7 pixels wide on average
        lb = layers[layer].GetDataInformation().GetBounds()
        cells = layers[layer].GetDataInformation().GetNumberOfCells()
        cell_px = math.sqrt(max(lb[1] - lb[0], 1e-30) * max(lb[3] - lb[2], 1e-30) / cells) * k
        display.SetRepresentationType("Surface With Edges" if cell_px >= 7 * px else "Surface")
        display.EdgeColor = [0.45, 0.45, 0.45]
        ColorBy(display, ("POINTS", field, "Magnitude") if info["field_components"] > 1
                else ("POINTS", field))
        display.LookupTable = lut
        placed.UpdatePipeline()
        r = placed.PointData[field].GetRange(-1 if info["field_components"] > 1 else 0)
        fmin = r[0] if fmin is None else min(fmin, r[0])
        fmax = r[1] if fmax is None else max(fmax, r[1])
        text = a3DText(registrationName="label layer %d" % layer,
                       Text="layer %d (%s)" % (layer, "u" if layer == 1 else "v"))
        moved = Transform(registrationName="label layer %d placed" % layer, Input=text)
        moved.Transform = "Transform"
        th = 20 * px / k  # the height of the letters in lengths
        moved.Transform.Scale = [th, th, 1]
        moved.Transform.Translate = [b[0] + offsets[layer][0], b[3] + offsets[layer][1] + 10 * px / k, 0]
        tdisplay = Show(moved, view)
        tdisplay.AmbientColor = [0, 0, 0]
        tdisplay.DiffuseColor = [0, 0, 0]
    # The colours end at the 99th percentile of |value| over the area of both
    # layers: the corners where a clamped side meets a free one are singular
    # and would leave everything else in the lowest colour. The largest value
    # is named in the colour bar's title.
    signed = field.startswith("stress_") and fmin < 0 < fmax
    top = percentile_abs(solution, field, 99.0)
    largest = max(abs(fmin), abs(fmax))
    saturated = top is not None and 0 < top < largest / 1.2
    if not saturated:
        top = largest
    if signed:
        lut.ApplyPreset("Cool to Warm", True)
        lut.RescaleTransferFunction(-top, top)
    else:
        lut.ApplyPreset("Viridis (matplotlib)", True)
        low = min(0.0, fmin)
        lut.RescaleTransferFunction(low, top if top > low else low + 1.0)
    lut.AutomaticRescaleRangeMode = "Never"
    if field in STRESS_FIELDS:
        unit = "units of E"
    elif field == "displacement":
        unit = "length unit"
    else:
        unit = None
    bar = GetScalarBar(lut, view)
    name = "%s magnitude" % field if info["field_components"] > 1 else field
    bar.Title = name + ("" if not unit else " [%s]" % unit if len(name + unit) < 22 else "\n[%s]" % unit)
    if saturated:
        bar.Title += ("\ndata %s to %s (saturated)" % (fmt(fmin), fmt(fmax)) if signed
                      else "\nlargest %s (saturated)" % fmt(largest))
    bar.ComponentTitle = ""
    style_bar(bar, px, width, height, 0.56, right)

    if interface is not None:
        cp = GetColorTransferFunction("contact_pressure")
        GetOpacityTransferFunction("contact_pressure")
        top_value = pmax if pmax > 0 else 1.0
        # grey at 0 (open, or a closed face without pressure), then orange,
        # red, dark red
        cp.RGBPoints = [0.0, 0.62, 0.62, 0.62,
                        0.02 * top_value, 1.0, 0.75, 0.25,
                        0.5 * top_value, 0.9, 0.1, 0.05,
                        top_value, 0.35, 0.0, 0.0]
        cp.ColorSpace = "RGB"
        cp.AutomaticRescaleRangeMode = "Never"
        for layer, letter in ((1, "u"), (2, "v")):
            if layer not in layers:
                continue
            pieces = [("glued", glued, letter + "_minus", 1.0),
                      ("minus face", crack, letter + "_minus", 2.0),
                      ("plus face", crack, letter + "_plus", 2.0)]
            for what, source, vector, z in pieces:
                warp = WarpByVector(registrationName="Sigma %s, layer %d" % (what, layer), Input=source)
                warp.Vectors = ["POINTS", vector]
                warp.ScaleFactor = scale
                moved = Transform(registrationName="Sigma %s, layer %d placed" % (what, layer), Input=warp)
                moved.Transform = "Transform"
                moved.Transform.Translate = [offsets[layer][0], offsets[layer][1], z * eps]
                d = Show(moved, view)
                d.SetRepresentationType("Surface")
                if what == "glued":
                    d.ColorArrayName = ["POINTS", ""]
                    d.AmbientColor = [0, 0, 0]
                    d.DiffuseColor = [0, 0, 0]
                    d.LineWidth = 2.0 * px
                else:
                    ColorBy(d, ("POINTS", "contact_pressure"))
                    d.LookupTable = cp
                    d.LineWidth = 3.5 * px
        cbar = GetScalarBar(cp, view)
        cbar.Title = "contact_pressure\n[units of E]"
        cbar.ComponentTitle = ""
        style_bar(cbar, px, width, height, 0.19, right)
        cp.RescaleTransferFunction(0.0, top_value)
        legend = ("Sigma, thick: the crack faces\n"
                  "(traces %s),\n"
                  "coloured by contact_pressure,\n"
                  "grey: 0 (open); thin black: %s") % (
                      "u-, u+ and v-, v+" if 2 in layers else "u-, u+",
                      "glued" if 2 in layers else "no crack")
        if pmax <= 0:  # no colour bar for a pressure that is 0 everywhere
            cbar.Visibility = 0
            legend += "\n\ncontact_pressure = 0 everywhere:\nno contact on the crack"
    else:
        legend = "Sigma not drawn:\nno interface file"

    # The title
    r = info["record"]
    line1 = "%s, cycle %d%s" % (info["scene"], info["cycle"],
                                " (the last)" if info["cycle"] == info["cycles"][-1] and len(info["cycles"]) > 1
                                else "")
    if r:
        line1 += ": %s dofs, energy %s" % (r.get("dofs", "?"), "%.6g" % r["energy"] if "energy" in r else "?")
        if r.get("converged") is False:
            line1 += " (NOT converged)"
    if len(present) == 1:
        line2 = "layer 1 (u) only (one layer), warped by the displacement x %g" % scale
    else:
        line2 = "layer 1 (u) %s, layer 2 (v) %s; both warped by the displacement x %g" % (
            "left" if side else "above", "right" if side else "below", scale)
    title = Text(registrationName="title", Text=line1 + "\n" + line2)
    tdisplay = Show(title, view)
    tdisplay.WindowLocation = "Upper Center"
    tdisplay.FontSize = int(round(19 * px))
    tdisplay.Color = [0, 0, 0]
    tdisplay.Justification = "Center"
    note = Text(registrationName="legend", Text=legend)
    ndisplay = Show(note, view)
    ndisplay.WindowLocation = "Lower Right Corner"
    ndisplay.FontSize = int(round(14 * px))
    ndisplay.Color = [0.2, 0.2, 0.2]

    # The camera: the content's box centred in the free part of the picture.
    Render(view)
    cx_px, cy_px = left + box_w / 2, bottom + box_h / 2
    ccx, ccy = (content[0] + content[1]) / 2, (content[2] + content[3]) / 2
    fx = ccx - (cx_px - width / 2) / k
    fy = ccy - (cy_px - height / 2) / k
    view.CameraFocalPoint = [fx, fy, 0]
    view.CameraPosition = [fx, fy, 10 * size]
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelScale = height / (2 * k)
    Render(view)

    if args.get("png"):
        SaveScreenshot(args["png"], view, ImageResolution=[width, height])
        add_png_text(args["png"], "Software", MARKER)
    SaveState(args["state"])
    mark_state(args["state"], info)
    print("view-done")


def percentile_abs(source, field, q):
    """The q-th percentile of |value| (of the magnitude for vectors) over the
    area of source (cell averages weighted by the cell areas: the points that
    adaptive refinement crowds into a singular corner count for their area);
    None if the data cannot be fetched."""
    try:
        from paraview import servermanager
        from paraview.simple import CellSize, Delete, MergeBlocks, PointDatatoCellData
        merged = MergeBlocks(Input=source)
        cells = PointDatatoCellData(Input=merged)
        sizes = CellSize(Input=cells)
        sizes.ComputeArea = 1
        data = servermanager.Fetch(sizes)
        for proxy in (sizes, cells, merged):
            Delete(proxy)
        array = data.GetCellData().GetArray(field)
        area = data.GetCellData().GetArray("Area")
        n, c = array.GetNumberOfTuples(), array.GetNumberOfComponents()
        if n == 0:
            return None
        pairs = sorted((math.sqrt(sum(array.GetComponent(i, j) ** 2 for j in range(c))),
                        abs(area.GetComponent(i, 0))) for i in range(n))
    except Exception:
        return None
    total = sum(a for _, a in pairs)
    if total <= 0:
        return pairs[min(n - 1, max(0, int(math.ceil(q / 100.0 * n)) - 1))][0]
    running = 0.0
    for value, a in pairs:
        running += a
        if running >= q / 100.0 * total:
            return value
    return pairs[-1][0]


def style_bar(bar, px, width, height, y, right):
    bar.Orientation = "Vertical"
    bar.WindowLocation = "Any Location"
    bar.Position = [(width - right + 30 * px) / width, y]
    bar.ScalarBarLength = 0.28
    bar.ScalarBarThickness = int(round(18 * px))
    bar.TitleFontSize = int(round(17 * px))
    bar.LabelFontSize = int(round(15 * px))
    bar.TitleColor = [0, 0, 0]
    bar.LabelColor = [0, 0, 0]
    bar.HorizontalTitle = 1
    bar.TitleJustification = "Left"
    bar.AutomaticLabelFormat = 1
    bar.RangeLabelFormat = "%-#6.3g"
    bar.Visibility = 1


def main(argv):
    if len(argv) >= 2 and argv[1] == "check" and len(argv) == 5:
        try:
            info = discover(argv[2], argv[3], argv[4])
        except ViewError as error:
            print("view: %s" % error, file=sys.stderr)
            return 1
        except Exception as error:  # one line, never a backtrace
            print("view: %s: cannot be read (%s: %s)" % (argv[2], type(error).__name__, error),
                  file=sys.stderr)
            return 1
        if info["note"]:
            print("note: %s" % info["note"])
        return 0
    if len(argv) == 3 and argv[1] == "render":
        try:
            render(json.loads(argv[2]))
        except ViewError as error:
            print("view-error: %s" % error)
            return 1
        except Exception as error:  # one line for the wrapper, never a backtrace
            if os.environ.get("VIEW_DEBUG"):
                import traceback
                traceback.print_exc()
            print("view-error: ParaView failed: %s: %s" % (type(error).__name__, str(error).splitlines()[0]
                                                            if str(error) else ""))
            return 1
        return 0
    print("usage: see scripts/view --help", file=sys.stderr)
    return 1


if __name__ == "__main__":
    code = main(sys.argv)
    sys.stdout.flush()
    sys.exit(code)

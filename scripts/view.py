"""The ParaView side of scripts/view (see its --help): one bilayer result
directory, one cycle, both layers side by side (or one above the other for
wide scenes), each warped by its displacement, coloured by a point field on
its own colour scale (its own colour bar), the cell edges alike on both,
with the interface Sigma drawn on top: the crack faces of each layer warped
by their traces (u_minus/u_plus, v_minus/v_plus) and coloured by the contact
pressure (grey: 0, an open or untouched face), the glued part as a thin black
line; length axes below and left of each layer (round ticks of the undeformed
coordinates in the length unit); the crack tips' energy release rates G
(summary.json's crack_tips of the cycle) listed beside the picture, each
tip's number drawn at the tip. Units: summary.json's "units" (stress,
length, energy_release_rate), else "units of E", "length unit", "units of E
× length". The title, the colour bars, the legend and the list of tips are
measured as drawn and fitted into the picture. Writes a PNG and/or a ParaView state file, and with
"describe" a JSON account of what was drawn (tests/cli/view_scene.py).

Three modes:
  python3 view.py check RESULT_DIR CYCLE FIELD
      checks the directory, the cycle ('' for the last) and the field without
      ParaView (plain python3, fast); exit 0, or one line "view: ..." on stderr
      and exit 1.
  python3 view.py request DIR CYCLE FIELD PNG STATE WIDTH HEIGHT SCALE EDGES DESCRIBE
      prints the JSON of render from the wrapper's values ('' for PNG,
      SCALE, DESCRIBE: null; EDGES true, false or '': null).
  pvbatch view.py render JSON
      JSON: {"dir", "cycle", "field", "png" (or null), "state", "width",
      "height", "scale" (null: automatic), "edges" (null: automatic, true,
      false), "describe" (a JSON file to write, or null)}. Prints "view-info: ..." lines for
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
TIPS_LISTED = 8  # the crack tips listed with their G and numbered in the picture


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
        if not isinstance(summary, dict):   # not bilayer's: no title data
            summary = {}
        if isinstance(summary.get("scene"), str) and summary["scene"]:
            scene = summary["scene"]
        for r in summary.get("cycles") if isinstance(summary.get("cycles"), list) else []:
            if isinstance(r, dict) and r.get("cycle") == cycles[index]:
                record = r
    except (OSError, ValueError, RecursionError):
        summary = {}
    units = summary.get("units") if isinstance(summary.get("units"), dict) else {}
    tips = [t for t in record.get("crack_tips") or [] if isinstance(t, dict) and
            all(isinstance(t.get(k), (int, float)) and not isinstance(t.get(k), bool)
                for k in ("x", "y"))] if isinstance(record.get("crack_tips"), list) else []
    return {"dir": os.path.abspath(d), "solution": os.path.abspath(solution),
            "interface": interface and os.path.abspath(interface), "note": note,
            "pieces": [os.path.abspath(p) for p in pieces] or [os.path.abspath(solution)],
            "cycle": cycles[index], "cycles": cycles, "time": time,
            "layer_association": layer_association, "field": field,
            "field_components": point[field], "scene": scene, "record": record,
            "units": {k: unit_text(units.get(k)) for k in ("length", "stress", "energy_release_rate")},
            "tips": tips}


def unit_text(value):
    """A unit of summary.json as drawn (ParaView's fonts hold Latin-1: the
    Greek mu becomes the micro sign), or None where it is not a short line
    of text."""
    if not isinstance(value, str):
        return None
    text = " ".join(value.replace("\u03bc", "\u00b5").split())
    if not text or len(text) > 40 or not text.isprintable():
        return None
    return text


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
        AppendDatasets, AssignViewToLayout, ColorBy, CreateLayout, Delete, CreateView, GetColorTransferFunction,
        GetOpacityTransferFunction, GetScalarBar, Render, SaveScreenshot, SaveState, Show,
        Text, Threshold, Transform, WarpByVector,
        XMLUnstructuredGridReader, a3DText)

    info = discover(args["dir"], args["cycle"], args["field"])
    field = info["field"]
    width, height = int(args["width"]), int(args["height"])
    # The pieces of the .pvtu (one per subproblem: a layer on a region), each
    # read on its own and grouped by its value of 'layer'. (No Threshold on
    # the partitioned data set: Debian's ParaView 5.11 crashes in
    # vtkExtractCells there now and then.)
    by_layer, other = {}, set()
    for path in info["pieces"]:
        piece = XMLUnstructuredGridReader(registrationName=os.path.basename(path), FileName=[path])
        piece.UpdatePipeline()
        data = piece.CellData if info["layer_association"] == "CELLS" else piece.PointData
        if piece.GetDataInformation().GetNumberOfCells() == 0 or "layer" not in data.keys():
            Delete(piece)
            continue
        low, high = data["layer"].GetRange()
        if round(low) != round(high):
            raise ViewError("%s: cells of layers %d to %d in one piece (bilayer writes one layer "
                            "per piece)" % (path, round(low), round(high)))
        layer = int(round(low))
        if layer in (1, 2):
            by_layer.setdefault(layer, []).append(piece)
        else:
            other.add(layer)
            Delete(piece)
    if 1 not in by_layer:
        raise ViewError("%s: no cells of layer 1" % info["solution"])
    if other:
        print("view-info: layer%s %s not drawn (the view shows layers 1 and 2)" % (
            "s" if len(other) > 1 else "", ", ".join("%d" % l for l in sorted(other))))
    sources = {}
    for layer, pieces in by_layer.items():
        sources[layer] = pieces[0] if len(pieces) == 1 else AppendDatasets(
            registrationName="layer %d" % layer, Input=pieces)
        sources[layer].UpdatePipeline()
    infos = [sources[l].GetDataInformation() for l in sources]
    bounds = [min(i.GetBounds()[j] for i in infos) if j % 2 == 0 else max(i.GetBounds()[j] for i in infos)
              for j in range(6)]
    size = max(bounds[1] - bounds[0], bounds[3] - bounds[2]) or 1.0
    umax = max(sources[l].PointData["displacement"].GetRange(-1)[1] for l in sources)

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
    for layer in sorted(sources):
        warp = WarpByVector(registrationName="layer %d warped" % layer, Input=sources[layer])
        warp.Vectors = ["POINTS", "displacement"]
        warp.ScaleFactor = scale
        warp.UpdatePipeline()
        layers[layer] = warp
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

    # The picture: px scales the fonts and margins with the picture (1 at
    # the default 1600x800; the smaller of the two ratios, so that a narrow
    # or a flat picture keeps room for the legends).
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
    px = max(0.5, min(width / 1600.0, height / 800.0))
    pad = max(4.0, 10 * px)  # the free border of the picture [pixels]

    # Each layer its own colour scale: a compliant layer carries smaller
    # stresses and would be one dark colour on the scale of a stiff one.
    # The colours of a layer end at the 99th percentile of |value| over its
    # area: the corners where a clamped side meets a free one are singular
    # and would leave everything else in the lowest colour. The largest
    # value is named in the colour bar's title.
    components = -1 if info["field_components"] > 1 else 0
    stress_unit = info["units"]["stress"] or "units of E"
    length_unit = info["units"]["length"] or "length unit"
    if field in STRESS_FIELDS:
        unit = stress_unit
    elif field == "displacement":
        unit = length_unit
    else:
        unit = None
    field_name = {"von_mises": "von Mises"}.get(field, field)
    if info["field_components"] > 1:
        field_name += " magnitude"
    placed, displays, scales, bars = {}, {}, {}, {}
    for layer in present:
        placed[layer] = Transform(registrationName="layer %d placed" % layer, Input=layers[layer])
        placed[layer].Transform = "Transform"
        display = Show(placed[layer], view)
        display.UseSeparateColorMap = 1
        ColorBy(display, ("POINTS", field, "Magnitude") if components < 0 else ("POINTS", field))
        lut = GetColorTransferFunction(field, display, separate=True)
        GetOpacityTransferFunction(field, display, separate=True)
        display.LookupTable = lut
        displays[layer] = display
        fmin, fmax = layers[layer].PointData[field].GetRange(components)
        signed = field.startswith("stress_") and fmin < 0 < fmax
        p99 = percentile_abs(sources[layer], field, 99.0)
        largest = max(abs(fmin), abs(fmax))
        saturated = p99 is not None and 0 < p99 < largest / 1.2
        top = p99 if saturated else largest
        if signed:
            lut.ApplyPreset("Cool to Warm", True)
            low, high = -top, top
        else:
            lut.ApplyPreset("Viridis (matplotlib)", True)
            low = min(0.0, fmin)
            high = top if top > low else low + 1.0
        lut.RescaleTransferFunction(low, high)
        lut.AutomaticRescaleRangeMode = "Never"
        bar = GetScalarBar(lut, view)
        letter = "u" if layer == 1 else "v"
        bar.Title = "layer %d (%s): %s%s" % (layer, letter, field_name, "\n[%s]" % unit if unit else "")
        if saturated:
            bar.Title += ("\ndata %s to %s (saturated)" % (fmt(fmin), fmt(fmax)) if signed
                          else "\nlargest %s (saturated)" % fmt(largest))
        bar.ComponentTitle = ""
        bars[layer] = bar
        scales[layer] = {"layer": layer, "name": letter, "range": [low, high], "data_range": [fmin, fmax],
                         "percentile_99": p99, "saturated": saturated, "signed": signed}

    cbar = None
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
        cbar = GetScalarBar(cp, view)
        cbar.Title = "Sigma: contact pressure\n[%s]" % stress_unit
        cbar.ComponentTitle = ""
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
    column = [bars[layer] for layer in present] + ([cbar] if cbar is not None and pmax > 0 else [])

    # The title
    r = info["record"]
    line1 = "%s, cycle %d%s" % (info["scene"], info["cycle"],
                                " (the last)" if info["cycle"] == info["cycles"][-1] and len(info["cycles"]) > 1
                                else "")
    if r:
        line1 += ": %s dofs, energy %s" % (r.get("dofs", "?"), "%.6g" % r["energy"] if "energy" in r else "?")
        if r.get("converged") is False:
            line1 += " (NOT converged)"
    def title_lines(side, wrapped):
        if len(present) == 1:
            line2 = "layer 1 (u) only (one layer), warped by the displacement x %g" % scale
        else:
            line2 = "layer 1 (u) %s, layer 2 (v) %s; both warped by the displacement x %g" % (
                "left" if side else "above", "right" if side else "below", scale)
        if wrapped:  # a narrow picture: more, shorter lines
            return line1.replace(": ", ":\n") + "\n" + line2.replace("; ", ";\n")
        return line1 + "\n" + line2

    wrapped = False
    title = Text(registrationName="title", Text=title_lines(False, wrapped))
    tdisplay = Show(title, view)
    tdisplay.WindowLocation = "Upper Center"
    tdisplay.Color = [0, 0, 0]
    tdisplay.Justification = "Center"
    note = Text(registrationName="legend", Text=legend)
    ndisplay = Show(note, view)
    ndisplay.WindowLocation = "Any Location"
    ndisplay.Color = [0.2, 0.2, 0.2]
    notes = [ndisplay]
    if info["tips"]:
        g_unit = info["units"]["energy_release_rate"] or "units of E × length"
        gtext = Text(registrationName="crack tips", Text=tips_text(info["tips"], g_unit))
        gdisplay = Show(gtext, view)
        gdisplay.WindowLocation = "Any Location"
        gdisplay.Justification = "Left"
        gdisplay.Color = [0, 0, 0]
        notes.append(gdisplay)

    # The legends, measured as ParaView draws them and fitted into the
    # picture: the title across the top, the colour bars and the legend text
    # one below the other in a column at the right; the fonts shrink (and
    # the bars get shorter) until all of it lies inside the picture.
    Render(view)
    f, length = 1.0, min(0.22 * height, 230 * px)
    for attempt in range(12):
        tdisplay.FontSize = max(6, int(round(19 * px * f)))
        for d in notes:
            d.FontSize = max(6, int(round(14 * px * f)))
        for bar in column:
            style_bar(bar, px * f, length / height)
        Render(view)
        t_rect = text_rect(tdisplay, view)
        relative = [bar_rect(bar, width, height, relative=True) for bar in column]
        n_rects = [text_rect(d, view) for d in notes]
        gap = 16 * px * f
        top_margin = (height - t_rect[1]) + pad  # (the title sits below the top edge)
        col_w = max([r_[2] - r_[0] for r_ in relative + n_rects]) + 2 * pad
        texts_h = sum(r_[3] - r_[1] for r_ in n_rects) + gap * (len(notes) - 1)
        need = sum(r_[3] - r_[1] for r_ in relative) + texts_h + gap * len(column)
        avail = height - top_margin - pad
        fits_w = (t_rect[2] - t_rect[0] <= width - 2 * pad) and col_w <= 0.45 * width
        if t_rect[2] - t_rect[0] > width - 2 * pad and not wrapped and attempt >= 2:
            wrapped = True
            title.Text = title_lines(False, wrapped)
            continue
        if need > avail:
            titles = sum(r_[3] - r_[1] for r_ in relative) - len(column) * length
            shorter = (avail - texts_h - gap * len(column) - titles) / max(1, len(column))
            if fits_w and shorter >= max(30.0, 50 * px * f):
                length = shorter - 1
                continue
        elif fits_w:
            break
        f *= 0.85
        length *= 0.85
    right = col_w
    x0 = width - col_w + pad
    cursor = height - top_margin
    for bar, r_ in zip(column, relative):
        bar.Position = [(x0 - r_[0]) / width, (cursor - r_[3]) / height]
        cursor -= (r_[3] - r_[1]) + gap
    # (each text's offset from its position, measured at the origin)
    for d in notes:
        d.Position = [0.0, 0.0]
    Render(view)
    for d, n_rect in zip(notes, n_rects):
        n0 = text_rect(d, view)
        d.Position = [(x0 - n0[0]) / width, (cursor - (n_rect[3] - n_rect[1]) - n0[1]) / height]
        cursor -= (n_rect[3] - n_rect[1]) + gap

    # Layout: one box for each layer (the union of the warped bounds of both),
    # side by side or one above the other, whichever shows them larger, in the
    # part of the picture left free by the title (top) and the colour bars
    # (right); each box with room for its length axes below and left of it.
    b = [min(layers[l].GetDataInformation().GetBounds()[i] for l in present) if i % 2 == 0 else
         max(layers[l].GetDataInformation().GetBounds()[i] for l in present) for i in range(4)]
    w, h = max(b[1] - b[0], 1e-12 * size), max(b[3] - b[2], 1e-12 * size)
    top, bottom, left = top_margin, 2 * pad, 2 * pad
    # (label: the 10-pixel gap and the letters of "layer N (x)", 1.44 times
    # their 20-pixel size with the descenders)
    label, lgap = 40 * px * f, 50 * px * f
    axes = Axes(view, px * f, length_unit, 3e-3 * size)
    ax_left, ax_bottom = axes.room([sources[l].GetDataInformation().GetBounds() for l in present])
    box_w, box_h = max(width - left - right, 10.0), max(height - top - bottom, 10.0)
    k_side = min((box_w - lgap - 2 * ax_left) / (2 * w), (box_h - label - ax_bottom) / h)
    k_stack = min((box_w - ax_left) / w, (box_h - 2 * (label + ax_bottom) - lgap) / (2 * h))
    # (one above the other also when it is almost as large: Sigma's points
    # then lie at the same x in both layers)
    side = k_side > k_stack / 0.9
    k = max(k_side if side else k_stack, 1e-30)  # pixels per unit length
    if len(present) == 1:
        k = max(min((box_w - ax_left) / w, (box_h - label - ax_bottom) / h), 1e-30)
        offsets = {1: (0.0, 0.0)}
        content = (b[0] - ax_left / k, b[1], b[2] - ax_bottom / k, b[3] + label / k)
    elif side:
        offsets = {1: (0.0, 0.0), 2: (w + (lgap + ax_left) / k, 0.0)}
        content = (b[0] - ax_left / k, b[0] + 2 * w + (lgap + ax_left) / k, b[2] - ax_bottom / k,
                   b[3] + label / k)
    else:
        offsets = {1: (0.0, 0.0), 2: (0.0, -(h + (lgap + label + ax_bottom) / k))}
        content = (b[0] - ax_left / k, b[1], b[2] - h - (lgap + label + 2 * ax_bottom) / k,
                   b[3] + label / k)
    eps = 1e-3 * size
    title.Text = title_lines(side, wrapped)

    # The cell edges: the same on both layers (colour, width, opacity),
    # shown where the cells of the coarser-drawn layer are at least 7 pixels
    # wide on average (or as --edges/--no-edges say).
    cell_px = {}
    for layer in present:
        lb = layers[layer].GetDataInformation().GetBounds()
        cells = max(1, layers[layer].GetDataInformation().GetNumberOfCells())
        cell_px[layer] = math.sqrt(max(lb[1] - lb[0], 1e-30) * max(lb[3] - lb[2], 1e-30) / cells) * k
    edges = args.get("edges")
    if edges is None:
        edges = min(cell_px.values()) >= 7 * px
    for layer in present:
        placed[layer].Transform.Translate = [offsets[layer][0], offsets[layer][1], 0.0]
        display = displays[layer]
        display.SetRepresentationType("Surface With Edges" if edges else "Surface")
        display.EdgeColor = [0.45, 0.45, 0.45]
        display.LineWidth = 1.0
        display.Opacity = 1.0
        text = a3DText(registrationName="label layer %d" % layer,
                       Text="layer %d (%s)" % (layer, "u" if layer == 1 else "v"))
        moved = Transform(registrationName="label layer %d placed" % layer, Input=text)
        moved.Transform = "Transform"
        th = 20 * px * f / k  # the height of the letters in lengths
        moved.Transform.Scale = [th, th, 1]
        moved.Transform.Translate = [b[0] + offsets[layer][0] + 4 * px * f / k, b[3] + offsets[layer][1] + 10 * px * f / k, 0]
        ldisplay = Show(moved, view)
        ldisplay.AmbientColor = [0, 0, 0]
        ldisplay.DiffuseColor = [0, 0, 0]

    if interface is not None:
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

    # The length axes of each layer, and the number of each crack tip at
    # the tip, warped with the layer (the numbers of the list of G).
    axis_info = {layer: axes.add(layer, sources[layer].GetDataInformation().GetBounds(), b,
                                 offsets[layer], k) for layer in present}
    places = tip_places(info["tips"][:TIPS_LISTED], interface, scale)
    for n, place in enumerate(places, 1):
        for layer in present:
            x, y = place[layer]
            axes.labels.add("tip %d, layer %d" % (n, layer), "%d" % n,
                            (x + offsets[layer][0], y + offsets[layer][1]), (0.5, 0.0),
                            (0.0, 8 * px * f), colour=(0.55, 0.0, 0.0), bold=True)
    labels_drawn = axes.labels.draw()

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

    # What was drawn, as measured: for scripts/view --describe and its test.
    def normalised(rect):
        return [rect[0] / width, rect[1] / height, rect[2] / width, rect[3] / height]

    scene = {"written_by": MARKER, "size": [width, height], "field": field, "cycle": info["cycle"],
             "displacement_scale": scale, "edges": bool(edges), "layers": [],
             "title": {"rect": normalised(text_rect(tdisplay, view)), "font_size": int(tdisplay.FontSize)},
             "legend": {"rect": normalised(text_rect(ndisplay, view)), "font_size": int(ndisplay.FontSize)},
             "contact_pressure_bar": None}
    for layer in present:
        d = displays[layer]
        lb = placed[layer].GetDataInformation().GetBounds()
        region = [width / 2 + (lb[0] - fx) * k, height / 2 + (lb[2] - fy) * k,
                  width / 2 + (lb[1] - fx) * k, height / 2 + (lb[3] - fy) * k]
        entry = dict(scales[layer])
        entry.update({"colour_map": str(d.LookupTable.GetXMLLabel()) if d.LookupTable else None,
                      "representation": d.SMProxy.GetProperty("Representation").GetElement(0),
                      "edge_color": [float(c) for c in d.GetPropertyValue("EdgeColor")],
                      "line_width": float(d.GetPropertyValue("LineWidth")),
                      "opacity": float(d.GetPropertyValue("Opacity")),
                      "region": normalised(region),
                      "bar": {"title": str(bars[layer].Title), "visible": bool(bars[layer].Visibility),
                              "rect": normalised(bar_rect(bars[layer], width, height))}})
        scene["layers"].append(entry)
    if cbar is not None:
        scene["contact_pressure_bar"] = {"title": str(cbar.Title), "visible": bool(cbar.Visibility),
                                         "rect": normalised(bar_rect(cbar, width, height))}
    scene["crack_tips"] = None if len(notes) < 2 else {
        "text": str(notes[1].Input.Text), "rect": normalised(text_rect(notes[1], view)),
        "font_size": int(notes[1].FontSize)}
    scene["axes"] = {str(layer): dict(axis_info[layer], labels=[]) for layer in present}
    scene["tip_labels"] = []
    for name, text, point, (dx, dy, w_, h_) in labels_drawn:
        x_ = width / 2 + (point[0] - fx) * k + dx
        y_ = height / 2 + (point[1] - fy) * k + dy
        entry = {"name": name, "text": text, "rect": normalised([x_, y_, x_ + w_, y_ + h_])}
        layer = name.rsplit(" ", 1)[-1]
        if name.startswith("tip "):
            scene["tip_labels"].append(entry)
        else:
            scene["axes"][layer]["labels"].append(entry)

    if args.get("png"):
        SaveScreenshot(args["png"], view, ImageResolution=[width, height])
        add_png_text(args["png"], "Software", MARKER)
    SaveState(args["state"])
    mark_state(args["state"], info)
    if args.get("describe"):
        with open(args["describe"], "w") as out:
            json.dump(scene, out, indent=1)
            out.write("\n")
    print("view-done")


def nice_ticks(lo, hi, most):
    """Round values in [lo, hi], 1, 2 or 5 times a power of ten apart, at
    most MOST of them (one, lo, where hi <= lo)."""
    if not hi > lo:
        return [lo]
    e = 10.0 ** math.floor(math.log10((hi - lo) / max(1, most - 1)))
    for m in (1, 2, 5, 10, 20):
        step = m * e
        first, last = math.ceil(lo / step - 1e-9), math.floor(hi / step + 1e-9)
        if last - first + 1 <= most:
            break
    return [float("%.12g" % (i * step)) for i in range(int(first), int(last) + 1)]


def tick_label(value):
    text = "%.6g" % value
    return "0" if text == "-0" else text


class Labels:
    """Texts drawn at points of the scene (ParaView's billboard text: the
    font of the colour bars, kept beside its point when the view is zoomed
    in the GUI), each aligned to its point: ALIGN (a, b) puts the point at
    the fraction a of the text's width and b of its height, SHIFT (dx, dy)
    moves it by pixels. The sizes are measured as drawn."""

    def __init__(self, view, font, z):
        self.view, self.font, self.z = view, font, z
        self.items = []   # [text, point, align, shift, colour, bold, name]

    def measure(self, strings):
        """{text: (width, height)} in pixels of texts in this font."""
        from paraview.simple import Delete, Hide, Render, Show, Text
        probes = {}
        for s in set(strings):
            source = Text(Text=s)
            display = Show(source, self.view)
            display.FontSize = self.font
            display.WindowLocation = "Any Location"
            probes[s] = (source, display)
        Render(self.view)
        sizes = {}
        for s, (source, display) in probes.items():
            r = text_rect(display, self.view)
            sizes[s] = (r[2] - r[0], r[3] - r[1])
            Hide(source, self.view)
            Delete(source)
        return sizes

    def add(self, name, text, point, align, shift=(0.0, 0.0), colour=(0, 0, 0), bold=False):
        self.items.append([text, point, align, shift, colour, bold, name])

    def draw(self):
        """Shows every text at its point; returns [(name, text, point,
        [dx, dy, width, height])], the offset of each text's lower left
        corner from its point and its size in pixels."""
        from paraview.simple import Show, Text
        sizes = self.measure([i[0] for i in self.items])
        drawn = []
        for text, point, align, shift, colour, bold, name in self.items:
            w_, h_ = sizes[text]
            dx = -align[0] * w_ + shift[0]
            dy = -align[1] * h_ + shift[1]
            display = Show(Text(registrationName=name, Text=text), self.view)
            display.TextPropMode = "Billboard 3D Text"
            display.BillboardPosition = [point[0], point[1], self.z]
            display.DisplayOffset = [int(round(dx)), int(round(dy))]
            display.FontSize = self.font
            display.Color = list(colour)
            display.Bold = int(bold)
            drawn.append((name, text, point, [round(dx), round(dy), w_, h_]))
        return drawn


class Axes:
    """The length axes of the layers: an x axis below and a y axis left of
    each layer's box, ticks at round values of the undeformed coordinates
    (the reference bounds of the layer), the tick labels and the titles
    "x [unit]", "y [unit]"."""

    def __init__(self, view, scale, unit, z):
        self.view, self.z, self.scale = view, z, scale
        self.labels = Labels(view, max(7, int(round(15 * scale))), z)
        self.tick, self.gap = 6 * scale, 4 * scale
        self.titles = ("x [%s]" % unit, "y [%s]" % unit)

    def room(self, bounds):
        """(left, bottom): the pixels the axes take left of and below a
        layer's box, for layers of the given reference bounds."""
        ylabels = [tick_label(v) for b in bounds for v in nice_ticks(b[2], b[3], 5)]
        self.sizes = self.labels.measure(list(self.titles) + ylabels + ["0"])
        self.label_w = max(self.sizes[s][0] for s in ylabels)
        self.label_h = self.sizes["0"][1]
        g = self.gap
        left = g + self.tick + g + self.label_w + 2 * g + self.sizes[self.titles[1]][0] + g
        bottom = g + self.tick + g + self.label_h + g + self.sizes[self.titles[0]][1] + g
        return left, bottom

    def ticks(self, lo, hi, k, horizontal):
        """The ticks in [lo, hi], as many (at most 6 along x, 5 along y) as
        leave room between their labels at k pixels per length."""
        for most in range(6 if horizontal else 5, 1, -1):
            values = nice_ticks(lo, hi, most)
            if len(values) < 2:
                return values
            need = (max(len(tick_label(v)) for v in values) * self.sizes["0"][0] + 2 * self.label_h
                    if horizontal else 2 * self.label_h)
            if (values[1] - values[0]) * k >= need:
                return values
        return nice_ticks(lo, hi, 2)

    def add(self, layer, ref, box, offset, k):
        """The axes of LAYER: REF its reference bounds, BOX the drawn box
        (both layers' warped bounds), OFFSET its place in the picture; returns
        {"x_ticks", "y_ticks", "x_title", "y_title"}."""
        from paraview.simple import PolyLineSource, Show
        ox, oy = offset
        ay = box[2] + oy - self.gap / k  # the x axis, below the layer
        ax = box[0] + ox - self.gap / k  # the y axis, left of it
        xt = self.ticks(ref[0], ref[1], k, True)
        yt = self.ticks(ref[2], ref[3], k, False)
        t = self.tick / k
        paths = {"x": [(ref[0] + ox, ay)] + [p for v in xt for p in ((v + ox, ay), (v + ox, ay - t), (v + ox, ay))] +
                      [(ref[1] + ox, ay)],
                 "y": [(ax, ref[2] + oy)] + [p for v in yt for p in ((ax, v + oy), (ax - t, v + oy), (ax, v + oy))] +
                      [(ax, ref[3] + oy)]}
        for name, points in sorted(paths.items()):
            line = PolyLineSource(registrationName="%s axis, layer %d" % (name, layer))
            line.Points = [c for p in points for c in (p[0], p[1], self.z)]
            display = Show(line, self.view)
            display.ColorArrayName = ["POINTS", ""]
            display.AmbientColor = [0, 0, 0]
            display.DiffuseColor = [0, 0, 0]
            display.LineWidth = max(1.0, 1.5 * self.scale)
        g = self.gap
        for v in xt:
            self.labels.add("x = %s, layer %d" % (tick_label(v), layer), tick_label(v),
                            (v + ox, ay - t), (0.5, 1.0), (0.0, -g))
        for v in yt:
            self.labels.add("y = %s, layer %d" % (tick_label(v), layer), tick_label(v),
                            (ax - t, v + oy), (1.0, 0.5), (-g, 0.0))
        self.labels.add("x title, layer %d" % layer, self.titles[0], ((ref[0] + ref[1]) / 2 + ox, ay - t),
                        (0.5, 1.0), (0.0, -(g + self.label_h + g)))
        self.labels.add("y title, layer %d" % layer, self.titles[1], (ax - t, (ref[2] + ref[3]) / 2 + oy),
                        (1.0, 0.5), (-(g + self.label_w + 2 * g), 0.0))
        return {"x_ticks": xt, "y_ticks": yt, "x_title": self.titles[0], "y_title": self.titles[1]}


def tip_places(tips, interface, scale):
    """[{layer: (x, y)}]: where each tip is drawn on layers 1 and 2, its
    point warped by the trace of the layer at the nearest point of Sigma's
    polyline (u_minus, v_minus; glued there) times SCALE; the tip's own
    point where there is no interface file or the tip lies on another
    interface (crack_tips[].interface >= 2)."""
    points, traces = [], {1: None, 2: None}
    if interface is not None:
        try:
            from paraview import servermanager
            data = servermanager.Fetch(interface)
            points = [data.GetPoint(i) for i in range(data.GetNumberOfPoints())]
            for layer, name in ((1, "u_minus"), (2, "v_minus")):
                array = data.GetPointData().GetArray(name)
                if array is not None:
                    traces[layer] = [array.GetTuple(i) for i in range(len(points))]
        except Exception:
            points = []
    places = []
    for tip in tips:
        x, y = float(tip["x"]), float(tip["y"])
        place = {1: (x, y), 2: (x, y)}
        if points and tip.get("interface", 1) == 1:
            i = min(range(len(points)), key=lambda j: (points[j][0] - x) ** 2 + (points[j][1] - y) ** 2)
            for layer in (1, 2):
                if traces[layer] is not None:
                    place[layer] = (points[i][0] + scale * traces[layer][i][0],
                                    points[i][1] + scale * traces[layer][i][1])
        places.append(place)
    return places


def tips_text(tips, unit, most=None):
    """The energy release rate of each crack tip (summary.json's crack_tips
    of the cycle), as listed beside the picture (the first MOST,
    TIPS_LISTED by default)."""
    most = most or TIPS_LISTED
    def number(x):
        return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)
    lines = ["crack tips: energy release rate", "G \u00b1 its error bar [%s]" % unit]
    for n, tip in enumerate(tips[:most], 1):
        g, e = tip.get("G"), tip.get("G_error")
        value = "G = %.3g" % g if number(g) else "G not computed"
        if number(g) and number(e):
            value += " \u00b1 %.2g" % e
        where = ", interface %s" % tip["interface"] if tip.get("interface", 1) != 1 else ""
        lines.append("tip %d at (%.4g, %.4g)%s: %s" % (n, tip["x"], tip["y"], where, value))
    if len(tips) > most:
        lines.append("(%d more in summary.json)" % (len(tips) - most))
    return "\n".join(lines)


def bar_rect(bar, width, height, relative=False):
    """[x0, y0, x1, y1] in pixels (from the lower left corner) of a colour bar
    as drawn (bar, labels and title), after a Render; relative: from the
    bar's Position."""
    rep = bar.GetClientSideObject().GetRepresentation()
    r = rep.GetScalarBarActor().GetBoundingRect()
    ox, oy = (0.0, 0.0) if relative else (rep.GetPosition()[0] * width, rep.GetPosition()[1] * height)
    return [ox + r.GetX(), oy + r.GetY(), ox + r.GetX() + r.GetWidth(), oy + r.GetY() + r.GetHeight()]


def text_rect(display, view):
    """[x0, y0, x1, y1] in pixels of a Text source's text as drawn."""
    rep = display.GetClientSideObject().GetTextWidgetRepresentation().GetRepresentation()
    actor = rep.GetTextActor()
    renderer = view.GetRenderer()
    bb = [0.0] * 4
    actor.GetBoundingBox(renderer, bb)
    o = actor.GetPositionCoordinate().GetComputedDisplayValue(renderer)
    return [o[0] + bb[0], o[1] + bb[2], o[0] + bb[1], o[1] + bb[3]]


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


def style_bar(bar, px, length):
    """A vertical colour bar of the given length (a fraction of the
    picture's height), fonts and thickness scaled by px; placed later."""
    bar.Orientation = "Vertical"
    bar.WindowLocation = "Any Location"
    bar.ScalarBarLength = length
    bar.ScalarBarThickness = max(4, int(round(18 * px)))
    bar.TitleFontSize = max(6, int(round(17 * px)))
    bar.LabelFontSize = max(6, int(round(15 * px)))
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
    if len(argv) == 12 and argv[1] == "request":
        a = argv[2:]
        print(json.dumps({"dir": a[0], "cycle": a[1], "field": a[2], "png": a[3] or None,
                          "state": a[4], "width": int(a[5]), "height": int(a[6]),
                          "scale": float(a[7]) if a[7] else None,
                          "edges": {"true": True, "false": False}.get(a[8]),
                          "describe": a[9] or None}))
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

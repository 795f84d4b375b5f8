"""The cell terms of the goal-oriented estimates in the solution files
(docs/fracture.md §11): with Fracture/Goal-oriented estimate, every piece
solution-NN-*.vtu carries the cell data dwr_energy and, on the cycles with
G, dwr_G; summed over the cells of all pieces,
  - dwr_G equals the sum over the tips of G_dwr_absolute (summary.json),
  - dwr_energy is at least |energy_dwr| (the signed sum of the same terms),
both to the precision of the Float32 arrays; without the estimate the
fields are absent. Griffith's crack (two tips), three adaptive Q2 cycles.
Usage: python3 goal_fields.py BILAYER PARAMETER_FILE_DIRECTORY"""
import base64
import glob
import json
import os
import re
import struct
import subprocess
import sys
import tempfile
import zlib

bilayer, scenes = sys.argv[1:3]
failures = 0


def check(what, ok):
    global failures
    print("%s: %s" % (what, "yes" if ok else "NO"))
    failures += 0 if ok else 1


def cell_array(path, name):
    """The Float32 cell array NAME of a VTU file written by deal.II (base64,
    zlib-compressed blocks with a UInt32 header), or None."""
    text = open(path).read()
    m = re.search(r'<DataArray type="Float32" Name="%s" format="binary">\s*(\S+)\s*</DataArray>'
                  % name, text)
    if m is None:
        return None
    data = m.group(1)
    head = base64.b64decode(data[:8])
    blocks = struct.unpack("<I", head[:4])[0]
    header_length = 4 * (3 + blocks)
    encoded = (header_length + 2) // 3 * 4
    header = struct.unpack("<%dI" % (3 + blocks), base64.b64decode(data[:encoded]))
    raw = base64.b64decode(data[encoded:])
    values, offset = b"", 0
    for size in header[3:]:
        values += zlib.decompress(raw[offset:offset + size])
        offset += size
    return struct.unpack("<%df" % (len(values) // 4), values)


def run(directory, *settings):
    args = [bilayer, os.path.join(scenes, "griffith.prm"),
            "--set", "Output/Output directory=" + directory,
            "--set", "Output/Terminal output=checks", "--set", "Output/Write VTU=true",
            "--set", "Output/Write interface CSV=false", "--set", "Mesh/Number of cycles=3"]
    for s in settings:
        args += ["--set", s]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    return json.load(open(os.path.join(directory, "summary.json")))["cycles"]


with tempfile.TemporaryDirectory() as work:
    directory = os.path.join(work, "goal")
    cycles = run(directory, "Fracture/Goal-oriented estimate=true")
    for c in cycles:
        pieces = sorted(glob.glob(os.path.join(directory, "solution-%02d-*.vtu" % c["cycle"])))
        cells = c["cells_minus"] + c["cells_plus"]
        energy, G, n = 0.0, 0.0, 0
        has_G = True
        for piece in pieces:
            e = cell_array(piece, "dwr_energy")
            g = cell_array(piece, "dwr_G")
            check("cycle %d: %s has dwr_energy" % (c["cycle"], os.path.basename(piece)),
                  e is not None)
            if e is None:
                continue
            n += len(e)
            energy += sum(e)
            has_G = has_G and g is not None
            G += sum(g) if g is not None else 0
        # Each cell is written as (degree)^2 patches' subcells, each with
        # the cell's value.
        per_cell = n / cells if cells else 0
        tips = [t for t in c["crack_tips"] if t.get("G_dwr_absolute") is not None]
        check("cycle %d: %d subcells, %g per cell (a square of a whole number)"
              % (c["cycle"], n, per_cell),
              per_cell > 0 and abs(round(per_cell ** 0.5) ** 2 - per_cell) < 1e-12)
        if not tips:
            check("cycle %d: no tip with an estimate, no dwr_G" % c["cycle"], not has_G)
            continue
        expected = sum(t["G_dwr_absolute"] for t in tips)
        check("cycle %d: sum of dwr_G %.6e = sum of G_dwr_absolute %.6e (1e-5)"
              % (c["cycle"], G / per_cell, expected),
              has_G and abs(G / per_cell - expected) <= 1e-5 * expected)
        check("cycle %d: sum of dwr_energy %.6e >= |energy_dwr| %.6e"
              % (c["cycle"], energy / per_cell, abs(c["energy_dwr"])),
              energy / per_cell >= (1 - 1e-5) * abs(c["energy_dwr"]))

    directory = os.path.join(work, "plain")
    run(directory, "Mesh/Number of cycles=1")
    piece = sorted(glob.glob(os.path.join(directory, "solution-00-*.vtu")))[0]
    check("without the estimate: no dwr_energy, no dwr_G",
          cell_array(piece, "dwr_energy") is None and cell_array(piece, "dwr_G") is None
          and cell_array(piece, "layer") is not None)

print("failures: %d" % failures)
sys.exit(1 if failures else 0)

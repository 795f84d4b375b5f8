#!/usr/bin/env python3
"""The tables of the outputs in docs/outputs.md ("## Outputs (a contract
for scripts)", "### Every file, field and column"; the README's until it
became an entry door) against what the program writes.

Runs BILAYER on parameter_files/partial_closure.prm with VTU and HDF5 output
and two cycles into a temporary directory, then checks that every name the
run writes appears in the doc's table for its file (program names are a
subset of the doc's: the tables may name more, e.g. columns that another
version or another parameter writes):
  - every file of the output directory (the marker included) matches a
    pattern of the table whose header starts with "file" (NN: the cycle,
    {a,b}: one of a, b; ".K" before ".vtu": the piece of a process);
  - the point and cell arrays of every solution piece (.vtu), of the .pvtu,
    and the attributes of solution.xdmf (those of the .h5 pieces) appear in
    the table after the paragraph naming `solution-NN-{u,v}-{minus,plus}.vtu`;
  - the point arrays of interface-NN.vtu, the header of interface-NN.csv,
    every key of summary.json (nested objects as "object.key", crack tips as
    "crack_tips[].key", the top level's keys but "cycles" too), the header
    of table.csv, the column headers of table.txt and table.tex, the line
    kinds of .bilayer-output: each in its file's table;
  - table.tex has the compact columns alone: cycle, dofs, energy, eta, and
    G tip k, dG tip k per tip.
A table belongs to the file named by the first `code` of the paragraph
before it. Tip numbers are the doc's <k>: G_tip2 is `G_tip<k>`, "G tip 2"
is `G tip <k>`; boundary parts the doc's <part>, regions <K>: Fy_left_r2 is
`Fy_<part>_r<K>`.
Usage: readme_outputs.py BILAYER SOURCE_DIR   (exit status 0: every name is
in the doc; 1: the missing names are listed)
"""

import json
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

DOC = os.path.join("docs", "outputs.md")  # the doc with the tables, from SOURCE_DIR


def readme_tables(path):
    """{file key: set of names in the first column}, from the Outputs
    section of the doc PATH; the table headed "file" is returned under the
    key "files"."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    start = text.find("\n## Outputs")
    if start < 0:
        raise SystemExit("%s has no section '## Outputs'" % DOC)
    end = text.find("\n## ", start + 1)
    lines = text[start:end if end > 0 else len(text)].split("\n")
    tables, paragraph, blank, i = {}, [], False, 0
    while i < len(lines):
        line = lines[i]
        if line.startswith("|"):
            rows = []
            while i < len(lines) and lines[i].startswith("|"):
                rows.append(lines[i])
                i += 1
            cells = [r.strip("|").split("|")[0].strip() for r in rows]
            header = cells[0]
            names = set()
            for c in cells[2:]:  # after the header and the |---| line
                names.update(c.split("`")[1::2])
            if header == "file":
                key = "files"
            else:
                codes = " ".join(paragraph).split("`")[1::2]
                if not codes:
                    raise SystemExit("%s: a table of the outputs without a `file` "
                                     "in the paragraph before it: %s" % (DOC, rows[0]))
                key = codes[0]
            tables.setdefault(key, set()).update(names)
            paragraph, blank = [], True
            continue
        if not line.strip():
            blank = True
        elif blank:
            paragraph, blank = [line], False
        else:
            paragraph.append(line)
        i += 1
    return tables


def tips(name):
    """The doc's spelling of a tip's column: G_tip2 -> G_tip<k>."""
    return re.sub(r"tip( ?)\d+", r"tip\1<k>", name)


def parts(name):
    """The doc's spelling of a boundary part's column of table.csv:
    Fy_left -> Fy_<part>, uy_left_r2 -> uy_<part>_r<K>."""
    name = re.sub(r"^(F[xy]|u[xy])_.+_r\d+$", r"\1_<part>_r<K>", name)
    return re.sub(r"^(F[xy]|u[xy])_[^<]+$", r"\1_<part>", name)


def file_pattern(pattern):
    """A file pattern of the doc as a regular expression."""
    out, i = "", 0
    while i < len(pattern):
        if pattern.startswith("NN", i):
            out += "[0-9]{2,}"
            i += 2
        elif pattern[i] == "{":
            j = pattern.index("}", i)
            out += "(" + "|".join(re.escape(a) for a in pattern[i + 1:j].split(",")) + ")"
            i = j + 1
        else:
            out += re.escape(pattern[i])
            i += 1
    # a subproblem shared by several processes: one piece per process
    return out.replace(r"\.vtu", r"(\.[0-9]+)?\.vtu")


def json_keys(value, prefix=""):
    keys = []
    if isinstance(value, dict):
        for k, v in value.items():
            name = prefix + k
            if isinstance(v, dict):
                keys += json_keys(v, name + ".")
            elif isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
                for x in v:
                    keys += json_keys(x, name + "[].")
            else:
                keys.append(name)
    return keys


def vtk_arrays(path, tags):
    root = ET.parse(path).getroot()
    return {a.get("Name") for tag in tags for section in root.iter(tag)
            for a in section if a.get("Name")}


def main(argv):
    if len(argv) != 3:
        print(__doc__.split("\n")[-4], file=sys.stderr)
        return 2
    bilayer, source = argv[1], argv[2]
    tables = readme_tables(os.path.join(source, DOC))
    with open(os.path.join(source, DOC), encoding="utf-8") as f:
        readme = f.read()
    work = tempfile.mkdtemp()
    out = os.path.join(work, "result")
    run = subprocess.run(
        [bilayer, os.path.join(source, "parameter_files", "partial_closure.prm"),
         "--set", "Output/Output directory=" + out, "--set", "Output/Write VTU=true",
         "--set", "Output/Write HDF5=true", "--set", "Output/Progress interval=0",
         "--set", "Mesh/Number of cycles=2"],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    if run.returncode != 0:
        print("bilayer failed (%d):\n%s" % (run.returncode, run.stdout[-2000:]))
        return 1

    written = {}  # file key in the doc -> names the program wrote
    def add(key, names):
        written.setdefault(key, set()).update(names)

    files = sorted(os.listdir(out))
    for f in files:
        p = os.path.join(out, f)
        if re.fullmatch(r"solution-[0-9]+-[uv]-(minus|plus)(\.[0-9]+)?\.vtu", f):
            add("solution-NN-{u,v}-{minus,plus}.vtu", vtk_arrays(p, ("PointData", "CellData")))
        elif re.fullmatch(r"solution-[0-9]+\.pvtu", f):
            add("solution-NN-{u,v}-{minus,plus}.vtu", vtk_arrays(p, ("PPointData", "PCellData")))
        elif f == "solution.xdmf":
            add("solution-NN-{u,v}-{minus,plus}.vtu",
                {a.get("Name") for a in ET.parse(p).getroot().iter("Attribute")})
        elif re.fullmatch(r"interface-[0-9]+\.vtu", f):
            add("interface-NN.vtu", vtk_arrays(p, ("PointData",)))
        elif re.fullmatch(r"interface-[0-9]+\.csv", f):
            with open(p) as h:
                header = next(l for l in h if not l.startswith("#"))
            add("interface-NN.csv", header.strip().split(","))
        elif f == "summary.json":
            with open(p) as h:
                summary = json.load(h)
            add("summary.json", json_keys({k: v for k, v in summary.items() if k != "cycles"}))
            for cycle in summary["cycles"]:
                add("summary.json", json_keys(cycle))
        elif f in ("table.csv", "table.txt"):
            with open(p) as h:
                lines = h.read().split("\n")
            # The note lines "# tip k: <where>, grows towards ..." first: the
            # doc must show their form.
            notes = [l for l in lines if l.startswith("#")]
            for l in notes:
                if not re.match(r"# tip [0-9]+: .*grows", l):
                    add(f, ["an unexplained note line '%s'" % l])
                elif "`# tip k:" not in readme:
                    add(f, ["the note line '%s'" % l])
            header = next(l for l in lines if not l.startswith("#"))
            if f == "table.csv":
                add("table.csv", {parts(tips(k)) for k in header.strip().split(",")})
            else:
                # "| cycle | P | ... | time [s] | G tip 1 |": cells between bars
                add("table.txt", [tips(c.strip()) for c in header.strip().strip("|").split("|")])
        elif f == "table.tex":
            with open(p) as h:
                tex = h.read()
            # the header row: the first row of cells ("a & b & ... \\")
            row = next(l for l in tex.split("\n") if "&" in l)
            row = row.replace("\\hline", "").replace("\\\\", "")
            columns = [tips(c.strip().strip("$")) for c in row.split("&")]
            add("table.txt", columns)
            # The compact table for a paper: these columns alone.
            if columns != ["cycle", "dofs", "energy", "eta"] + ["G tip <k>", "dG tip <k>"] * (
                    (len(columns) - 4) // 2):
                add("table.tex", ["the compact columns (cycle, dofs, energy, eta, G and dG "
                                  "per tip), not %s" % columns])
        elif f == ".bilayer-output":
            kinds = tables.get(".bilayer-output", set())
            with open(p) as h:
                for line in h:
                    line = line.rstrip("\n")
                    match = [k for k in kinds if line.startswith(k.rstrip("."))]
                    add(".bilayer-output", match[:1] or [line[:40]])

    missing = []
    patterns = [file_pattern(p) for p in tables.get("files", ())]
    for f in files:
        if not any(re.fullmatch(p, f) for p in patterns):
            missing.append("file %s: not in the table of files" % f)
    for key, names in sorted(written.items()):
        known = tables.get(key)
        if known is None:
            missing.append("%s: no table for it after a paragraph naming `%s`" % (key, key))
            continue
        for name in sorted(names - known):
            missing.append("%s: `%s` is written but not in the table of %s" % (key, name, DOC))
    for key in ("summary.json", "table.csv", "table.txt", "interface-NN.csv", "interface-NN.vtu",
                "solution-NN-{u,v}-{minus,plus}.vtu", ".bilayer-output"):
        if not written.get(key):
            missing.append("%s: the run wrote nothing of it (the check is broken)" % key)
    n = sum(len(v) for v in written.values())
    if missing:
        print("%s, ## Outputs: %d of %d names the run writes are missing:" % (DOC, len(missing), n))
        for m in missing:
            print("  " + m)
        return 1
    print("%s, ## Outputs: all %d files and %d names the run writes are in its tables"
          % (DOC, len(files), n))
    subprocess.run(["rm", "-rf", work])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

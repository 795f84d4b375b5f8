"""Read bilayer's results into Python (standard library and numpy): a run's
output directory or a folder of scripts/sweep.

    import sys; sys.path.insert(0, "scripts")     # from the repository
    import bilayer_results

    run = bilayer_results.load("results/partial_closure")
    run.summary["scene"]              # summary.json parsed (a dict)
    run.cycles[-1]["energy"]          # its cycles (a list of dicts)
    run.table["energy"]               # table.csv: a numpy array a column
    run.interface[0]["jump_normal"]   # interface-00.csv, read when first used
    run.growth                        # growth.csv as columns (None: none)
    run.parameters                    # used_parameters.prm (text)

    sweep = bilayer_results.load("results/sweep-partial_closure")
    sweep.table["G_tip1"]             # sweep.csv: a numpy array a column
    sweep.entries                     # the varied entries ("Section/Entry")
    sweep.runs[0].cycles[-1]["dofs"]  # point 1's run (None: it failed)

load(path) -> Run or Sweep      the folder PATH (a Sweep where it holds
                                sweep.json and sweep.csv, else a Run)
read_columns(path) -> Columns   a CSV file of bilayer as numpy columns:
                                '#' lines skipped; a column of whole
                                numbers int64, of numbers float64 (an empty
                                cell, null or nan: NaN), else str
Run and Sweep are also read as dicts (run["summary"], sweep["table"]).

Run as a program, `python3 scripts/bilayer_results.py DIR` prints a
one-screen overview of DIR; a folder it cannot read is one line on stderr
and exit status 1.
"""
import collections.abc
import csv
import json
import os
import re
import sys

try:
    import numpy as np
except ImportError:
    if __name__ == "__main__":
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        import bilayer_run
        bilayer_run.require("import:numpy")
    raise ImportError("bilayer_results needs numpy: install the Debian package "
                      "python3-numpy") from None

_INTERFACE = re.compile(r"^interface-([0-9]+)\.csv$")


class ResultsError(ValueError):
    """A folder or file that is not bilayer's (the message says why)."""


class Columns(dict):
    """{column: numpy array} of a CSV file, in the order of its header
    (names); len(columns) is the number of columns, columns.rows the
    number of rows."""

    def __init__(self, names, arrays, rows):
        super().__init__(zip(names, arrays))
        self.names, self.rows = list(names), rows

    def __repr__(self):
        return "Columns(%d rows: %s)" % (self.rows, ", ".join(self.names))


def _array(cells):
    """The cells of a column as int64, float64 (empty, null, nan: NaN) or
    str."""
    if cells and all(re.fullmatch(r"[+-]?[0-9]+", c.strip()) for c in cells):
        return np.array([int(c) for c in cells], dtype=np.int64)
    values = []
    for c in cells:
        c = c.strip()
        if c in ("", "null", "nan"):
            values.append(np.nan)
            continue
        try:
            values.append(float(c))
        except ValueError:
            return np.array(cells, dtype=str)
    return np.array(values, dtype=float)


def read_columns(path):
    """Columns of the CSV file PATH ('#' lines skipped)."""
    with open(path, encoding="utf-8", newline="") as f:
        table = list(csv.reader(l for l in f if not l.startswith("#") and l.strip()))
    if not table:
        raise ResultsError("%s has no header line: not a CSV file of bilayer" % path)
    header, body = [h.strip() for h in table[0]], table[1:]
    for number, row in enumerate(body, 2):
        if len(row) != len(header):
            raise ResultsError("%s: row %d has %d cells where the header has %d" % (
                path, number, len(row), len(header)))
    return Columns(header, [_array([r[i] for r in body]) for i in range(len(header))],
                   len(body))


def _json(path):
    try:
        with open(path, encoding="utf-8") as f:
            value = json.load(f)
    except ValueError as e:
        raise ResultsError("%s is not JSON (%s)" % (path, " ".join(str(e).split())[:100]))
    if not isinstance(value, dict):
        raise ResultsError("%s holds no JSON object" % path)
    return value


class Interface(collections.abc.Mapping):
    """{cycle: Columns of interface-NN.csv}, each file read when first
    used; the keys are the cycles whose file is in the folder."""

    def __init__(self, folder):
        self.folder, self.read = folder, {}
        self.files = {}
        for name in os.listdir(folder):
            match = _INTERFACE.match(name)
            if match:
                self.files[int(match.group(1))] = os.path.join(folder, name)

    def __getitem__(self, cycle):
        if cycle not in self.read:
            self.read[cycle] = read_columns(self.files[cycle])
        return self.read[cycle]

    def __iter__(self):
        return iter(sorted(self.files))

    def __len__(self):
        return len(self.files)

    def __repr__(self):
        return "Interface(cycles %s)" % sorted(self.files)


class _Record:
    """Attributes also read as keys (record["summary"])."""

    def __getitem__(self, key):
        try:
            return getattr(self, key)
        except AttributeError:
            raise KeyError(key)

    def keys(self):
        return [k for k in vars(self) if not k.startswith("_")]


class Run(_Record):
    """One run of bilayer: path, summary, cycles, table, growth (None
    where the run wrote no growth.csv), interface (an Interface) and
    parameters (the text of used_parameters.prm, None where missing)."""

    def __init__(self, path):
        self.path = os.path.abspath(path)
        self.summary = _json(os.path.join(path, "summary.json"))
        self.cycles = self.summary.get("cycles")
        if not isinstance(self.cycles, list):
            raise ResultsError("%s has no list of cycles: not a summary.json of bilayer" %
                               os.path.join(path, "summary.json"))
        self.table = self._optional("table.csv", read_columns)
        self.growth = self._optional("growth.csv", read_columns)
        self.interface = Interface(path)
        self.parameters = self._optional("used_parameters.prm", _text)

    def _optional(self, name, reader):
        path = os.path.join(self.path, name)
        return reader(path) if os.path.isfile(path) else None

    @property
    def last(self):
        """The last cycle (a dict; {} where there is none)."""
        return self.cycles[-1] if self.cycles else {}

    def __repr__(self):
        return "Run(%s: %s, %d cycles)" % (self.path, self.summary.get("scene"), len(self.cycles))


def _text(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


class Sweep(_Record):
    """A folder of scripts/sweep: path, meta (sweep.json), entries (the
    varied entries), table (Columns of sweep.csv, one row a point) and
    runs (point k's Run at runs[k - 1]; None where its folder holds no
    summary.json: a failed point)."""

    def __init__(self, path):
        self.path = os.path.abspath(path)
        self.meta = _json(os.path.join(path, "sweep.json"))
        self.entries = [v["entry"] for v in self.meta.get("vary", [])]
        self.table = read_columns(os.path.join(path, "sweep.csv"))
        self.runs = []
        for point in self.meta.get("points", []):
            folder = os.path.join(self.path, point["folder"])
            ok = os.path.isfile(os.path.join(folder, "summary.json"))
            self.runs.append(Run(folder) if ok else None)

    def __repr__(self):
        return "Sweep(%s: %d points over %s)" % (self.path, len(self.runs),
                                                 ", ".join(self.entries))


def load(path):
    """The results in the folder PATH: a Sweep (sweep.json and sweep.csv
    there) or a Run (summary.json there); ResultsError otherwise."""
    failed = path.rstrip(os.sep) + ".failed"
    hint = "; a failed run's results are in " + failed if os.path.isdir(failed) else ""
    if not os.path.isdir(path):
        raise ResultsError("%s is not a folder%s" % (path, hint))
    if all(os.path.isfile(os.path.join(path, n)) for n in ("sweep.json", "sweep.csv")):
        return Sweep(path)
    if os.path.isfile(os.path.join(path, "summary.json")):
        return Run(path)
    raise ResultsError("%s holds neither summary.json (a run of bilayer) nor sweep.json and "
                       "sweep.csv (a sweep)%s" % (path, hint))


def _g(x):
    return "-" if x is None else "%.4g" % x if isinstance(x, (int, float)) else str(x)


def _run_lines(run):
    last = run.last
    yield "run: %s (scene %s), %d cycles; files: %s" % (
        run.path, run.summary.get("scene"), len(run.cycles), ", ".join(
            n for n, v in (("table.csv", run.table), ("growth.csv", run.growth),
                           ("used_parameters.prm", run.parameters)) if v is not None) +
        (", interface CSV of cycles %s" % list(run.interface) if len(run.interface) else ""))
    yield "last cycle %s: dofs %s, energy %s, converged %s, accepted %s" % (
        last.get("cycle"), last.get("dofs"), _g(last.get("energy")), last.get("converged"),
        last.get("accepted"))
    for t, tip in enumerate(last.get("crack_tips") or [], 1):
        yield "  tip %d at (%s, %s): G = %s +- %s, G_I %s, G_II %s, phase angle %s deg" % (
            t, _g(tip.get("x")), _g(tip.get("y")), _g(tip.get("G")), _g(tip.get("G_error")),
            _g(tip.get("G_I")), _g(tip.get("G_II")), _g(tip.get("phase_angle")))
    for part in last.get("boundary_parts") or []:
        f, u = part.get("force") or [None, None], part.get("mean_displacement") or [None, None]
        yield "  part %s%s: force (%s, %s), mean displacement (%s, %s)" % (
            part.get("name"), " (clamped)" if part.get("clamped") else "",
            _g(f[0]), _g(f[1]), _g(u[0]), _g(u[1]))
    for name, columns in (("table.csv", run.table), ("growth.csv", run.growth)):
        if columns is not None:
            yield "%s: %d rows; columns %s" % (name, columns.rows, ", ".join(columns.names)[:160])


def _sweep_lines(sweep):
    failed = [i for i, r in enumerate(sweep.runs) if r is None]
    yield "sweep: %s (scene %s), %d points%s; %d failed" % (
        sweep.path, os.path.basename(sweep.meta.get("scene", "?")), sweep.table.rows,
        " (zipped)" if sweep.meta.get("zip") else "", len(failed))
    for v in sweep.meta.get("vary", []):
        yield "  %s: %s" % (v["entry"], ", ".join(v["values"])[:100])
    shown = ["point"] + sweep.entries + ["exit", "energy"] + \
        [c for c in sweep.table.names if re.fullmatch(r"G_tip[0-9]+", c)][:4]
    cells = [[_cell(sweep.table[c][i]) for c in shown] for i in range(sweep.table.rows)]
    widths = [max([len(c)] + [len(r[j]) for r in cells]) for j, c in enumerate(shown)]
    yield "  ".join(c.ljust(w) for c, w in zip(shown, widths))
    for row in cells[:40]:
        yield "  ".join(c.ljust(w) for c, w in zip(row, widths))
    if len(cells) > 40:
        yield "... %d more points (sweep.csv)" % (len(cells) - 40)


def _cell(x):
    if isinstance(x, (float, np.floating)):
        return "-" if np.isnan(x) else "%.5g" % x
    return str(x)


def main(argv):
    if len(argv) != 1 or argv[0].startswith("-"):
        print("bilayer_results.py: usage: python3 scripts/bilayer_results.py DIR (a run's output "
              "directory or a folder of scripts/sweep)", file=sys.stderr)
        return 2
    try:
        results = load(argv[0])
    except (ResultsError, OSError, UnicodeDecodeError) as e:
        print("bilayer_results.py: %s" % " ".join(str(e).split())[:300], file=sys.stderr)
        return 1
    lines = _sweep_lines(results) if isinstance(results, Sweep) else _run_lines(results)
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import bilayer_run
    bilayer_run.guard(lambda: main(sys.argv[1:]), "bilayer_results.py")

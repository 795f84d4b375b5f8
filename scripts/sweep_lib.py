"""Parameter sweeps over bilayer runs: the machinery of scripts/sweep and
scripts/friction_study (standard library only; gnuplot for the figures).

    parse_vary(text) -> Vary(entry, values, log)
                           one --vary "Section/Entry=VALUES": a list
                           "v1,v2,..." (split on ','), a JSON list
                           '["a, b", "c"]', or a range "start:stop:count"
                           (count values evenly spaced) or
                           "start:stop:count:log" (geometrically spaced);
                           raises Refusal naming what is allowed
    parse_setting(text, option) -> (entry, value)
                           one "Section/Entry=value" of --set or --vary
    combinations(varies, zipped) -> [[(entry, value), ...], ...]
                           the grid (the cartesian product, the last
                           --vary fastest) or, zipped, the i-th values
                           of each --vary together
    make_points(values, runs) -> [Point]
                           point k's folder RUNS/NNN-SLUG (SLUG from its
                           values)
    check_entries(prm, settings, varies, binary)
                           raises Refusal where bilayer refuses PRM with
                           SETTINGS or has no entry a --vary names
    commands(prm, settings, points, binary) -> [argv]
                           bilayer's command line of each point
    plan(points, commands, changed) -> {number: "kept" | "run"}
                           which points finished before; raises Refusal
                           (exit 1) for a point folder the sweep may not use
    run_points(prm, settings, points, binary, jobs, changed, say)
                           -> [Result]: runs each point (JOBS at a time),
                           keeps a point finished before with the same
                           command, reports progress through SAY
    table(results, entries) -> (header, rows)
                           one row a point: the varied values, exit, wall
                           time, and from the last cycle of summary.json
                           dofs, energy, converged, accepted, G, dG, G_I,
                           G_II and psi of each crack tip, the force and
                           the mean displacement of each boundary part
    write_csv(path, header, rows), markdown(header, rows)
    number(text)           TEXT as a finite float, or None
    plot(folder, stem, header, rows, column, against, entries, log_x, title)
                           a gnuplot figure (PNG and PDF) of COLUMN against
                           the varied entry AGAINST, one curve per value
                           of the other varied entries, error bars on G

A point's folder is bilayer's output directory (Output/Output directory),
to which the sweep adds stdout.txt, stderr.txt and the marker .sweep-point
(JSON: the command, the exit status, the wall time, the files the sweep
wrote) once the run has ended. A point is finished when its folder holds
summary.json and a marker of exit 0 whose command is the point's. The
sweep removes only files its marker lists (never bilayer's, never the
user's): before it reruns a point that failed, or whose command changed
where CHANGED is "rerun" (CHANGED "refuse": such a point stops the whole
sweep before any run, with one line).
"""
import collections
import concurrent.futures
import csv
import datetime
import difflib
import itertools
import json
import math
import os
import re
import tempfile
import threading
import time

import bilayer_run

MARKER = ".sweep-point"
OWN_FILES = ("stdout.txt", "stderr.txt")
WRITER = "scripts/sweep"
MOST_POINTS = 10000
# The columns of each crack tip t (NAME_tip<t>) and the keys of summary.json's
# crack_tips[t - 1] they hold; phase_angle is in degrees.
TIP_COLUMNS = (("G", "G"), ("dG", "G_error"), ("G_I", "G_I"), ("G_II", "G_II"),
               ("psi", "phase_angle"))
# The columns of each boundary part (NAME_<part>): the key of summary.json's
# boundary_parts[] and the component.
PART_COLUMNS = (("Fx", "force", 0), ("Fy", "force", 1), ("ux", "mean_displacement", 0),
                ("uy", "mean_displacement", 1))
FIXED_COLUMNS = ("exit", "wall_s", "dofs", "energy", "converged", "accepted")
COLUMN_PATTERN = re.compile(r"^(%s)$|^(%s)_tip[1-9][0-9]*$|^(%s)_.+$" % (
    "|".join(FIXED_COLUMNS), "|".join(c for c, _ in TIP_COLUMNS),
    "|".join(c for c, _, _ in PART_COLUMNS)))

Vary = collections.namedtuple("Vary", "entry values log")
Point = collections.namedtuple("Point", "number values folder")
Point.__doc__ = """One point of a sweep: its number (1, 2, ...), its values
[(entry, value), ...] and its folder (bilayer's output directory)."""
Result = collections.namedtuple("Result", "point command returncode seconds kept error summary")
Result.__doc__ = """One point after the sweep: its command (bilayer's argv),
exit status, wall time [s], kept (finished before, not rerun), error (the
first error line of a failed run, else ''), summary (summary.json parsed
after exit 0, else None)."""


class Refusal(Exception):
    """Input the sweep refuses: one line (the message) and an exit status."""

    def __init__(self, message, status=2):
        super().__init__(message)
        self.status = status


def _shown(text, most=60):
    text = repr(text)
    return text if len(text) <= most else text[:most - 3] + "..."


def parse_setting(text, option):
    """(entry, value) of "Section/Entry=value" given to OPTION."""
    entry, sep, value = text.partition("=")
    entry = entry.strip()
    if not sep or not entry or "/" not in entry:
        raise Refusal("%s %s: expected Section/Entry=value (an entry of the scene, its "
                      "sections separated by '/')" % (option, _shown(text)))
    if any(ord(c) < 32 for c in text):
        raise Refusal("%s %s holds control characters" % (option, _shown(text)))
    if entry == "Output/Output directory":
        raise Refusal("%s %s: the sweep sets Output/Output directory of each point "
                      "(DIR/runs/NNN-...); name DIR with --output" % (option, _shown(text)))
    return entry, value.strip()


def number(text):
    """TEXT as a finite float, or None."""
    try:
        x = float(text)
    except ValueError:
        return None
    return x if math.isfinite(x) else None


def _range_values(text, parts):
    """The values of the range "start:stop:count[:log]" (PARTS split)."""
    where = "--vary range %s" % _shown(text)
    start, stop = number(parts[0]), number(parts[1])
    if start is None or stop is None:
        raise Refusal("%s: start and stop must be finite numbers (start:stop:count or "
                      "start:stop:count:log)" % where)
    try:
        count = int(parts[2])
    except ValueError:
        count = 0
    if not 1 <= count <= MOST_POINTS:
        raise Refusal("%s: count must be a whole number in [1, %d]" % (where, MOST_POINTS))
    log = len(parts) == 4
    if log and parts[3].strip() != "log":
        raise Refusal("%s: the fourth part may only be 'log' (geometric spacing)" % where)
    if log and (start <= 0 or stop <= 0):
        raise Refusal("%s: a log range needs start > 0 and stop > 0" % where)
    values = []
    for k in range(count):
        t = k / (count - 1) if count > 1 else 0.0
        x = start * (stop / start) ** t if log else start + t * (stop - start)
        values.append("%.12g" % x)
    return values, log


def _json_values(text):
    """The values of a JSON list: strings as they are, numbers as JSON
    writes them, booleans as true and false."""
    where = "--vary list %s" % _shown(text)
    try:
        items = json.loads(text)
    except ValueError as e:
        raise Refusal("%s is not a JSON list (%s): write [\"v1\", \"v2\", ...]" % (
            where, " ".join(str(e).split())[:80]))
    if not isinstance(items, list) or not items:
        raise Refusal("%s: expected a non-empty JSON list of strings and numbers" % where)
    values = []
    for item in items:
        if isinstance(item, bool):
            values.append("true" if item else "false")
        elif isinstance(item, str):
            values.append(item)
        elif isinstance(item, (int, float)) and math.isfinite(item):
            values.append(json.dumps(item))
        else:
            raise Refusal("%s: %s is neither a string nor a finite number" % (
                where, _shown(item)))
    return values


def parse_vary(text):
    """Vary(entry, values, log) of --vary TEXT (see the module's
    docstring); raises Refusal with one line naming what is allowed."""
    entry, spec = parse_setting(text, "--vary")
    parts = spec.split(":")
    if spec.startswith("["):
        values, log = _json_values(spec), False
    elif "," not in spec and len(parts) in (3, 4) and number(parts[0]) is not None:
        values, log = _range_values(spec, parts)
    else:
        values, log = [v.strip() for v in spec.split(",")], False
        if any(not v for v in values):
            raise Refusal("--vary %s: an empty value in the list (values separated by ','; a "
                          "JSON list such as '%s=[\"a, b\", \"\"]' keeps commas and empty "
                          "values)" % (_shown(text), entry))
    if any(ord(c) < 32 for v in values for c in v):
        raise Refusal("--vary %s: a value holds control characters" % _shown(text))
    return Vary(entry, values, log)


def _first_repeat(items):
    """The first item of ITEMS that an earlier one equals (None: none)."""
    return next((x for i, x in enumerate(items) if x in items[:i]), None)


def combinations(varies, zipped=False):
    """The values of each point: [[(entry, value), ...], ...]."""
    entries = [v.entry for v in varies]
    twice = [e for i, e in enumerate(entries) if e in entries[:i]]
    if twice:
        raise Refusal("--vary names %s twice: one --vary per entry" % _shown(twice[0]))
    if zipped:
        lengths = sorted({len(v.values) for v in varies})
        if len(lengths) > 1:
            raise Refusal("--zip needs --vary lists of one length, got %s" % ", ".join(
                "%d (%s)" % (len(v.values), v.entry) for v in varies))
        rows = list(zip(*[v.values for v in varies]))
        if _first_repeat(rows) is not None:
            raise Refusal("--zip: the values %s come twice" % _shown(
                ", ".join(_first_repeat(rows)), 100))
    else:
        for v in varies:
            if _first_repeat(v.values) is not None:
                raise Refusal("--vary %s repeats the value %s" % (
                    _shown(v.entry), _shown(_first_repeat(v.values))))
        count = 1
        for v in varies:
            count *= len(v.values)
        if count > MOST_POINTS:
            raise Refusal("--vary: the grid has %d points, more than %d" % (count, MOST_POINTS))
        rows = itertools.product(*[v.values for v in varies])
    return [list(zip(entries, row)) for row in rows]


def _safe(text):
    return re.sub(r"_+", "_", re.sub(r"[^A-Za-z0-9.+-]", "_", text)).strip("_")


def slug(values, most=60):
    """A folder name's part from the values of a point: each entry's last
    name and its value, odd characters replaced by '_'."""
    text = "-".join("%s_%s" % (_safe(e.rsplit("/", 1)[-1]), _safe(v)) for e, v in values)
    return text[:most].rstrip("_-.") or "point"


def make_points(values, runs):
    """The points of VALUES (of combinations()), point k in RUNS/NNN-SLUG."""
    width = max(3, len(str(len(values))))
    return [Point(k, v, os.path.join(runs, "%0*d-%s" % (width, k, slug(v))))
            for k, v in enumerate(values, 1)]


def check_entries(prm, settings, varies, binary):
    """Raise Refusal where bilayer refuses PRM with SETTINGS (the --set
    entries) or where a --vary names no entry of the scene."""
    entries, refusal = bilayer_run.read_entries(prm, settings, binary)
    if entries is None:
        raise Refusal("bilayer refuses %s%s: %s" % (
            prm, " with the --set entries" if settings else "", refusal))
    for v in varies:
        if v.entry not in entries:
            near = difflib.get_close_matches(v.entry, list(entries), 1, 0.6)
            raise Refusal("--vary %s: %s has no entry %s%s" % (
                _shown(v.entry), prm, _shown(v.entry),
                " (did you mean %s?)" % near[0] if near else ""))


def point_command(prm, settings, point, binary):
    """bilayer's argv for POINT: the scene, SETTINGS, its values, its
    folder as Output/Output directory."""
    return bilayer_run.command(prm, list(settings) + ["%s=%s" % ev for ev in point.values] +
                               ["Output/Output directory=" + point.folder], binary=binary)


def commands(prm, settings, points, binary):
    """bilayer's argv of each of POINTS (absolute paths)."""
    prm, binary = os.path.abspath(prm), os.path.abspath(binary)
    return [point_command(prm, settings, p, binary) for p in points]


def read_marker(folder):
    """(marker, foreign): the sweep's marker of FOLDER as a dict (None
    where there is none), and whether a .sweep-point there is not one."""
    path = os.path.join(folder, MARKER)
    if not os.path.lexists(path):
        return None, False
    try:
        if os.path.islink(path) or not os.path.isfile(path):
            raise ValueError
        with open(path, encoding="utf-8") as f:
            marker = json.load(f)
        if not isinstance(marker, dict) or marker.get("written_by") != WRITER or \
                not isinstance(marker.get("command"), list):
            raise ValueError
    except (OSError, ValueError, UnicodeDecodeError):
        return None, True
    return marker, False


def _difference(old, new):
    """The first arguments where the commands OLD and NEW differ."""
    for a, b in itertools.zip_longest(old, new, fillvalue="(nothing)"):
        if a != b:
            return "its %s records %s where this sweep has %s" % (
                MARKER, _shown(a, 80), _shown(b, 80))
    return "none"


def plan(points, commands, changed):
    """{number: "kept" | "run"}; raises Refusal (exit 1) naming the first
    point folder that the sweep may not use."""
    state = {}
    for point, cmd in zip(points, commands):
        marker, foreign = read_marker(point.folder)
        if foreign:
            raise Refusal("%s holds a %s that the sweep did not write: it is left as it is; "
                          "choose another --output" % (point.folder, MARKER), 1)
        if marker is not None and marker["command"] != cmd and changed != "rerun":
            raise Refusal("%s was run with another command (%s): it is left as it "
                          "is; choose another --output or move that folder" % (
                              point.folder, _difference(marker["command"], cmd)), 1)
        finished = marker is not None and marker["command"] == cmd and \
            marker.get("exit") == 0 and os.path.isfile(os.path.join(point.folder,
                                                                     "summary.json"))
        state[point.number] = "kept" if finished else "run"
    return state


def clear_own(folder):
    """Remove the files the sweep's marker in FOLDER lists, the marker,
    and FOLDER itself where the sweep created it and it is now empty."""
    marker, _ = read_marker(folder)
    if marker is None:
        return
    for name in marker.get("files", []):
        path = os.path.join(folder, name)
        if name in OWN_FILES and os.path.isfile(path) and not os.path.islink(path):
            os.remove(path)
    os.remove(os.path.join(folder, MARKER))
    if marker.get("created_folder") and not os.listdir(folder):
        os.rmdir(folder)


def _write_new(path, text):
    """Write TEXT to the new file PATH; False where PATH exists."""
    try:
        with open(path, "x", encoding="utf-8") as f:
            f.write(text)
    except FileExistsError:
        return False
    return True


def record(folder, cmd, returncode, seconds, stdout, stderr):
    """Write stdout.txt, stderr.txt and the marker into FOLDER after a run
    (the folder created where bilayer left none); files that exist are
    left as they are and not listed."""
    created = not os.path.isdir(folder)
    if created:
        os.makedirs(folder)
    files = [name for name, text in zip(OWN_FILES, (stdout, stderr))
             if _write_new(os.path.join(folder, name), text or "")]
    marker = {"written_by": WRITER, "command": cmd, "exit": returncode,
              "wall_seconds": seconds, "files": files, "created_folder": created,
              "finished": datetime.datetime.now().isoformat(timespec="seconds")}
    fd, tmp = tempfile.mkstemp(dir=folder, prefix=MARKER + ".")
    os.fchmod(fd, 0o644)
    with os.fdopen(fd, "w") as f:
        json.dump(marker, f, indent=1)
        f.write("\n")
    os.replace(tmp, os.path.join(folder, MARKER))


def first_error(stderr, stdout=""):
    """The first line of STDERR that names an error or a failure, else its
    first line, else the last line of STDOUT."""
    lines = [l.strip() for l in (stderr or "").splitlines() if l.strip()]
    for line in lines:
        if re.search(r"error|FAILED|fail", line):
            return line
    if lines:
        return lines[0]
    rest = [l.strip() for l in (stdout or "").splitlines() if l.strip()]
    return rest[-1] if rest else "no message"


def _load_summary(folder):
    try:
        with open(os.path.join(folder, "summary.json"), encoding="utf-8") as f:
            summary = json.load(f)
    except (OSError, ValueError):
        return None
    return summary if isinstance(summary, dict) else None


def describe(point):
    return ", ".join("%s=%s" % ev for ev in point.values)


def _run_one(prm, settings, point, cmd, binary, say, total):
    """Run POINT (its own files cleared first) and record it."""
    clear_own(point.folder)
    say("[%d/%d] start   %s" % (point.number, total, describe(point)))
    t0 = time.monotonic()
    run = bilayer_run.run(prm, list(settings) + ["%s=%s" % ev for ev in point.values],
                          point.folder, binary=binary)
    seconds = time.monotonic() - t0
    error = "" if run.returncode == 0 else first_error(run.stderr, run.stdout)
    try:
        record(point.folder, cmd, run.returncode, seconds, run.stdout, run.stderr)
    except OSError as e:
        error = error or "cannot record the run in %s: %s" % (point.folder, e.strerror or e)
    summary = _load_summary(point.folder) if run.returncode == 0 else None
    if run.returncode == 0 and summary is None:
        error = "exit 0 but no summary.json in %s" % point.folder
    say("[%d/%d] %s exit %d, %.1f s  %s%s" % (
        point.number, total, "done   " if not error else "FAILED ", run.returncode, seconds,
        describe(point), ": " + error if error else ""))
    return Result(point, cmd, run.returncode, seconds, False, error, summary)


def run_points(prm, settings, points, binary, jobs=1, changed="refuse", say=print):
    """Run POINTS of the scene PRM with SETTINGS (a list of
    "Section/Entry=value", before each point's values), JOBS at a time;
    a point finished before with the same command is kept. CHANGED: what
    a point whose recorded command differs gets ("refuse": Refusal before
    any run; "rerun"). SAY(line) reports each start and end. Returns the
    Results in the order of POINTS."""
    prm, binary = os.path.abspath(prm), os.path.abspath(binary)
    argvs = commands(prm, settings, points, binary)
    state = plan(points, argvs, changed)
    lock = threading.Lock()

    def said(line):
        with lock:
            say(line)

    results = {}
    for point, cmd in zip(points, argvs):
        if state[point.number] == "kept":
            marker, _ = read_marker(point.folder)
            said("[%d/%d] kept    %s (finished before)" % (point.number, len(points),
                                                         describe(point)))
            results[point.number] = Result(point, cmd, 0, marker.get("wall_seconds", 0.0),
                                           True, "", _load_summary(point.folder))
    todo = [(p, c) for p, c in zip(points, argvs) if state[p.number] == "run"]
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        futures = [pool.submit(_run_one, prm, settings, p, c, binary, said, len(points))
                   for p, c in todo]
        try:
            for future in concurrent.futures.as_completed(futures):
                r = future.result()
                results[r.point.number] = r
        except BaseException:
            for future in futures:
                future.cancel()
            raise
    return [results[p.number] for p in points]


def _cell(value):
    """A value of summary.json as a CSV cell: numbers in full precision,
    booleans 1 and 0, null empty."""
    if value is None or isinstance(value, (list, dict)):
        return ""
    if isinstance(value, bool):
        return "1" if value else "0"
    if isinstance(value, float):
        return repr(value) if math.isfinite(value) else ""
    return str(value)


def _component(vector, i):
    return vector[i] if isinstance(vector, list) and len(vector) > i else None


def last_cycle(summary):
    """The last cycle object of SUMMARY ({} where there is none)."""
    cycles = (summary or {}).get("cycles")
    return cycles[-1] if isinstance(cycles, list) and cycles and \
        isinstance(cycles[-1], dict) else {}


def table(results, entries, runs_parent=None):
    """(header, rows) of the sweep's table: one dict of CSV cells a point;
    the folder column relative to RUNS_PARENT."""
    tips, parts = 0, []
    for r in results:
        last = last_cycle(r.summary)
        tips = max(tips, len(last.get("crack_tips") or []))
        for part in last.get("boundary_parts") or []:
            if part.get("name") not in parts:
                parts.append(part.get("name"))
    header = ["point"] + list(entries) + list(FIXED_COLUMNS)
    header += ["%s_tip%d" % (c, t) for t in range(1, tips + 1) for c, _ in TIP_COLUMNS]
    header += ["%s_%s" % (c, name) for name in parts for c, _, _ in PART_COLUMNS]
    header += ["error", "folder"]
    rows = []
    for r in results:
        row = {"point": str(r.point.number), "exit": str(r.returncode),
               "wall_s": "%.3f" % r.seconds, "error": r.error,
               "folder": os.path.relpath(r.point.folder, runs_parent or os.getcwd())}
        row.update(dict(r.point.values))
        last = last_cycle(r.summary)
        for key in FIXED_COLUMNS[2:]:
            row[key] = _cell(last.get(key))
        for t, tip in enumerate(last.get("crack_tips") or [], 1):
            for column, key in TIP_COLUMNS:
                row["%s_tip%d" % (column, t)] = _cell(tip.get(key))
        for part in last.get("boundary_parts") or []:
            for column, key, i in PART_COLUMNS:
                row["%s_%s" % (column, part.get("name"))] = _cell(_component(part.get(key), i))
        rows.append(row)
    return header, rows


def write_csv(path, header, rows):
    with open(path, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(header)
        for row in rows:
            w.writerow([row.get(h, "") for h in header])


def _short(text):
    """A CSV cell for the Markdown table: numbers to 6 digits."""
    x = number(text) if text and not text.isdigit() else None
    return ("%.6g" % x if x is not None else text).replace("|", "\\|")


def markdown(header, rows, folder=False):
    """The table as Markdown (without the folder column unless FOLDER;
    without the error column where no point failed)."""
    shown = [h for h in header if (folder or h != "folder") and
             (h != "error" or any(r.get("error") for r in rows))]
    titles = {"wall_s": "wall [s]"}
    lines = ["| " + " | ".join(titles.get(h, h) for h in shown) + " |",
             "|" + "---|" * len(shown)]
    for row in rows:
        lines.append("| " + " | ".join(
            ("%.2f" % float(row[h]) if h == "wall_s" else _short(row.get(h, "")))
            for h in shown) + " |")
    return "\n".join(lines) + "\n"


def _curves(header, rows, column, against, entries):
    """[(title, [(x, y, dy or None), ...]), ...]: the points of COLUMN
    against AGAINST, one curve per value of the other ENTRIES."""
    others = [e for e in entries if e != against]
    match = re.match(r"^G_tip([0-9]+)$", column)
    error = "dG_tip" + match.group(1) if match and "dG_tip" + match.group(1) in header else None
    curves = collections.OrderedDict()
    for row in rows:
        y = number(row.get(column) or "")
        x = number(row.get(against) or "")
        if x is None or y is None:
            continue
        title = ", ".join("%s = %s" % (e.rsplit("/", 1)[-1], row[e]) for e in others)
        dy = number(row.get(error) or "") if error else None
        curves.setdefault(title, []).append((x, y, dy))
    return [(t, sorted(p)) for t, p in curves.items()], error


def plot(folder, stem, header, rows, column, against, entries, log_x=False, title=""):
    """Write STEM.dat and draw STEM.png and STEM.pdf in FOLDER: COLUMN
    against AGAINST; False where no point has both values."""
    curves, error = _curves(header, rows, column, against, entries)
    if not curves:
        return False
    with open(os.path.join(folder, stem + ".dat"), "w") as f:
        for i, (name, points) in enumerate(curves):
            f.write("%s# %s\n# %s %s%s\n" % ("\n\n" if i else "", name or "all points",
                                            against, column, " " + error if error else ""))
            for x, y, dy in points:
                f.write("%.12g %.12g%s\n" % (x, y, " %.12g" % (dy if dy is not None else 0)
                                              if error else ""))
    style = "using 1:2:3 with yerrorlines" if error else "using 1:2 with linespoints"
    plots = ", ".join("%s index %d %s pt 7 title %s" % (
        bilayer_run.gnuplot_string(stem + ".dat") if i == 0 else "''", i, style,
        bilayer_run.gnuplot_string(name or column)) for i, (name, _) in enumerate(curves))
    body = ["set grid", "set key outside right top" if len(curves) > 1 else "set key top left",
            "set title %s" % bilayer_run.gnuplot_string(title),
            "set xlabel %s" % bilayer_run.gnuplot_string(against),
            "set ylabel %s" % bilayer_run.gnuplot_string(
                column + (" (error bars: %s)" % error if error else "")),
            "set logscale x" if log_x else "unset logscale x", "set format y '%g'",
            "set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05",
            "plot " + plots]
    lines = ["set terminal pngcairo size 900,600 noenhanced font ',10'",
             "set output %s" % bilayer_run.gnuplot_string(stem + ".png")] + body + [
        "set terminal pdfcairo size 6.5in,4.3in noenhanced font ',9'",
        "set output %s" % bilayer_run.gnuplot_string(stem + ".pdf"), "replot", "set output"]
    bilayer_run.gnuplot("sweep", lines, folder)
    return True

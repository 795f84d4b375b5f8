"""Run bilayer from the Python scripts of scripts/ (standard library only).

The scripts import it from their own directory (`import bilayer_run`):

    ROOT, BILAYER          the repository and build/bilayer in it
    argument_parser(doc)   an ArgumentParser whose --help is the script's
                           docstring (first paragraph, then the rest) and
                           whose errors are one line "SCRIPT: error: ...
                           (scripts/SCRIPT --help)", exit 2
    integer(lo, hi), number(lo, hi, ...), numbers(lo, hi, ...), text(what)
                           argparse types: a whole number, a finite number,
                           a list "A,B,..." of finite numbers in a range, a
                           non-empty string; a bad value is refused by the
                           parser naming the option and the allowed range
    guard(main)            runs MAIN() as a script's body: its status;
                           Ctrl-C exits 130 with one line, a closed stdout
                           1, an OSError one line "SCRIPT: PATH: why" (1),
                           anything else "SCRIPT: internal error: ..." (1);
                           never a traceback
    MPI_ENV                the environment for mpirun as root, oversubscribed
    setup()                scripts/setup --no-install (configure and build
                           if needed, never install), quietly; exits with its
                           status (after its one-line message) if it fails;
                           exits 1 with one line when BILAYER is then not an
                           executable
    require(*tools)        exits 1 with one line naming the Debian package
                           of the first of TOOLS (gnuplot, mpirun, ...) not
                           on PATH: the scripts never install anything
                           (the packages: scripts/tool_packages.txt; the
                           bash scripts: require of common.sh)
    command(prm, settings, processes=None, binary=BILAYER, mpirun=("mpirun",))
                           the command line: BINARY PRM --set S/E=v ...,
                           behind MPIRUN -np PROCESSES when processes is given
    run(prm, settings, directory=None, ...) -> Run
                           runs it with Output/Output directory=DIRECTORY
                           (default: a temporary directory, removed after the
                           run) and reads the run's summary.json
    read_summary(directory, returncode) -> (summary, where)
    scene(prm, settings) -> {"Section/Entry": value}
                           every entry of PRM as bilayer reads it (its
                           includes, then SETTINGS), from bilayer PRM
                           --print-parameters; exits 1 with bilayer's line
                           when it refuses the file
    read_entries(prm, settings, binary) -> (entries, refusal)
                           the same without exiting: (None, bilayer's
                           line) where bilayer refuses the file
    figure_path(script, value, inside)
                           a --figure PNG: new, or a committed file under
                           docs/; one line and exit 1 otherwise
    copy_figure(script, source, figure)
                           the copy to it (one line and exit 1 on failure)
    OutputFolder(script, path, default)
                           the folder a script writes its results into
                           (see its docstring: never a folder the script
                           did not make, never a file it did not write)
    safe_name(prm)         the scene's name for a default folder: its stem,
                           odd characters replaced ('..prm' is not '..')
    gnuplot(script, lines, cwd)
                           gnuplot on LINES in CWD; one line, exit 1 if it fails
    gnuplot_string(text)   TEXT as a gnuplot string literal

BILAYER is build/bilayer, or the program the environment variable BILAYER
names (then scripts/setup is not run).

Run as a program (for the bash scripts of scripts/):
    python3 scripts/bilayer_run.py output SCRIPT DIR [NAME ...]
        opens DIR as SCRIPT's output folder, claims the files NAME (a
        trailing / for a folder) and prints DIR's absolute path; one line
        on stderr and exit 1 when it may not
    python3 scripts/bilayer_run.py entry PRM SECTION/ENTRY [--set S/E=v ...]
        prints the value of one entry as bilayer reads PRM
    python3 scripts/bilayer_run.py name PRM
        prints safe_name(PRM)

settings: a dict {"Section/Entry": value} or a list of "Section/Entry=value"
strings. A run whose checks fail (exit 2) leaves its results in DIR.failed and
DIR as it was; a refused run writes nothing. bilayer writes only into
directories it created itself (or empty ones), so DIRECTORY should not exist
or be empty.
"""
import argparse
import collections
import importlib.util
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BILAYER = os.path.abspath(os.environ.get("BILAYER") or os.path.join(ROOT, "build", "bilayer"))
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
           "OMPI_MCA_rmaps_base_oversubscribe": "1"}

Run = collections.namedtuple("Run", "returncode stdout stderr summary directory")
Run.__doc__ = """One finished run of bilayer.

returncode: its exit status; stdout, stderr: its terminal output (None where
not captured); summary: summary.json parsed (None where the run left none);
directory: where summary.json was read (DIR or DIR.failed; None for a
temporary directory, which is gone)."""


class ArgumentParser(argparse.ArgumentParser):
    """argparse.ArgumentParser whose errors (an unknown option, a missing
    or bad value) are one line on stderr, "SCRIPT: error: MESSAGE
    (scripts/SCRIPT --help)", and exit status 2: no usage block."""

    def error(self, message):
        message = " ".join(str(message).split())
        self.exit(2, "%s: error: %s (scripts/%s --help)\n" % (self.prog, message, self.prog))


def argument_parser(doc):
    """An ArgumentParser describing a script by its docstring DOC: the
    first paragraph above the options, the rest below, as written; its
    errors are one line, exit 2."""
    first, _, rest = doc.partition("\n\n")
    return ArgumentParser(description=first, epilog=rest or None,
                          formatter_class=argparse.RawDescriptionHelpFormatter)


def _shown(value):
    """VALUE for a message: quoted, cut at 60 characters, one line."""
    value = repr(value)
    return value if len(value) <= 60 else value[:57] + "..."


def integer(lo, hi):
    """An argparse type: a whole number in [LO, HI]."""
    def parse(value):
        try:
            n = int(value.strip())
        except ValueError:
            raise argparse.ArgumentTypeError(
                "expected a whole number in [%d, %d], got %s" % (lo, hi, _shown(value)))
        if not lo <= n <= hi:
            raise argparse.ArgumentTypeError(
                "%s is outside the allowed range [%d, %d]" % (_shown(value), lo, hi))
        return n
    parse.__name__ = "whole number"
    return parse


def _finite(value):
    """VALUE as a finite float, or None."""
    try:
        x = float(value.strip())
    except ValueError:
        return None
    return x if math.isfinite(x) else None


def _range_text(lo, hi, lo_open, hi_open):
    return "%s%s, %s%s" % ("(" if lo_open or lo is None else "[",
                           "-inf" if lo is None else "%g" % lo,
                           "inf" if hi is None else "%g" % hi,
                           ")" if hi_open or hi is None else "]")


def _inside(x, lo, hi, lo_open, hi_open):
    return ((lo is None or (x > lo if lo_open else x >= lo)) and
            (hi is None or (x < hi if hi_open else x <= hi)))


def number(lo=None, hi=None, lo_open=False, hi_open=False):
    """An argparse type: a finite number in the range from LO to HI (None:
    unbounded; *_open: the bound itself excluded)."""
    allowed = _range_text(lo, hi, lo_open, hi_open)

    def parse(value):
        x = _finite(value)
        if x is None:
            raise argparse.ArgumentTypeError(
                "expected a finite number in %s, got %s" % (allowed, _shown(value)))
        if not _inside(x, lo, hi, lo_open, hi_open):
            raise argparse.ArgumentTypeError(
                "%s is outside the allowed range %s" % (_shown(value), allowed))
        return x
    parse.__name__ = "number"
    return parse


def numbers(lo=None, hi=None, lo_open=False, hi_open=False, most=100):
    """An argparse type: "A,B,..." with 1 to MOST finite numbers in the
    range from LO to HI (as number())."""
    allowed = _range_text(lo, hi, lo_open, hi_open)

    def parse(value):
        parts = value.split(",")
        if not value.strip() or len(parts) > most:
            raise argparse.ArgumentTypeError(
                "expected 1 to %d numbers in %s separated by ',', got %s" % (
                    most, allowed, _shown(value)))
        out = []
        for part in parts:
            x = _finite(part)
            where = _shown(part.strip()) + (" in " + _shown(value) if len(parts) > 1 else "")
            if x is None:
                raise argparse.ArgumentTypeError(
                    "%s is not a finite number (expected numbers in %s separated by ',')" % (
                        where, allowed))
            if not _inside(x, lo, hi, lo_open, hi_open):
                raise argparse.ArgumentTypeError(
                    "%s is outside the allowed range %s" % (where, allowed))
            out.append(x)
        return out
    parse.__name__ = "list of numbers"
    return parse


def text(what):
    """An argparse type: a non-empty string (a path, a name) without
    control characters; WHAT names it in the message."""
    def parse(value):
        if not value.strip():
            raise argparse.ArgumentTypeError("expected %s, got an empty string" % what)
        if any(ord(c) < 32 for c in value):
            raise argparse.ArgumentTypeError("%s %s holds control characters" % (
                what, _shown(value)))
        return value
    parse.__name__ = what
    return parse


def guard(main, name=None):
    """Run MAIN() as a script's body and exit with its status (None: 0),
    never with a traceback: KeyboardInterrupt (Ctrl-C) exits 130 with one
    line; a closed standard output (BrokenPipeError) exits 1 quietly; an
    OSError not handled before (a disk full, a file that vanished) is one
    line "SCRIPT: PATH: why", exit 1; anything else, a bug, is one line
    "SCRIPT: internal error: TYPE: message", exit 1 (a last safety net:
    foreseeable bad input has its own message)."""
    name = name or os.path.basename(sys.argv[0])
    try:
        status = main()
    except KeyboardInterrupt:
        _quiet_stdout()
        print("%s: interrupted" % name, file=sys.stderr)
        sys.exit(130)
    except BrokenPipeError:
        _quiet_stdout()
        sys.exit(1)
    except OSError as e:
        _quiet_stdout()
        where = e.filename if e.filename is not None else ""
        print("%s: %s%s" % (name, "%s: " % where if where else "",
                            e.strerror or " ".join(str(e).split())), file=sys.stderr)
        sys.exit(1)
    except Exception as e:  # noqa: BLE001 (the last safety net: one line)
        _quiet_stdout()
        message = " ".join(str(e).split())[:300]
        print("%s: internal error: %s%s" % (name, type(e).__name__,
                                            ": " + message if message else ""), file=sys.stderr)
        sys.exit(1)
    sys.exit(status or 0)


def _quiet_stdout():
    """Flush stdout, or where it is closed send the rest to /dev/null (no
    "Exception ignored" at exit)."""
    try:
        sys.stdout.flush()
    except (OSError, ValueError):
        try:
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        except (OSError, ValueError):
            pass


def tool_packages():
    """{tool: "package ..."} of scripts/tool_packages.txt: the Debian
    packages of each tool the scripts run."""
    packages = {}
    with open(os.path.join(ROOT, "scripts", "tool_packages.txt")) as f:
        for line in f:
            words = line.split()
            if words and not words[0].startswith("#"):
                packages[words[0]] = " ".join(words[1:])
    return packages


def setup():
    """scripts/setup --no-install with its output discarded: configures and
    builds if needed, never installs. If it fails (its one line on stderr
    names what is missing), exits with its status."""
    if not os.environ.get("BILAYER"):
        p = subprocess.run([os.path.join(ROOT, "scripts", "setup"), "--no-install"],
                           stdout=subprocess.DEVNULL)
        if p.returncode != 0:
            sys.exit(p.returncode)
    if not (os.path.isfile(BILAYER) and os.access(BILAYER, os.X_OK)):
        sys.exit("%s: no executable %s (build it: scripts/setup; or name the program in the "
                 "environment variable BILAYER)" % (os.path.basename(sys.argv[0]), BILAYER))


def require(*tools):
    """Exit 1 with the one line "SCRIPT: TOOL is missing: install the
    Debian package PACKAGE" (scripts/tool_packages.txt) for the first of
    TOOLS that is not on PATH (import:NAME: a module this Python cannot
    import); the scripts never install."""
    for tool in tools:
        if tool.startswith("import:"):
            if importlib.util.find_spec(tool[len("import:"):]) is not None:
                continue
        elif shutil.which(tool) is not None:
            continue
        sys.exit(missing_tool(os.path.basename(sys.argv[0]), tool))


def missing_tool(script, tool):
    """The line of require() for TOOL in SCRIPT."""
    module = tool.startswith("import:")
    package = tool_packages().get(tool, tool[len("import:"):] if module else tool)
    name = "python3's " + tool[len("import:"):] if module else tool
    return "%s: %s is missing: install the Debian package%s %s" % (
        script, name, "s" if " " in package else "", package)


def set_list(settings):
    """The "Section/Entry=value" strings of a dict or a list of them."""
    if isinstance(settings, dict):
        return ["%s=%s" % (k, v) for k, v in settings.items()]
    return list(settings)


def command(prm, settings=(), processes=None, binary=BILAYER, mpirun=("mpirun",)):
    """The command line running BINARY on PRM with one --set per setting;
    with processes, behind MPIRUN... -np PROCESSES."""
    # A file whose name starts with '-' is not an option.
    cmd = [binary, os.path.join(".", prm) if str(prm).startswith("-") else prm]
    for s in set_list(settings):
        cmd += ["--set", s]
    if processes is not None:
        cmd = list(mpirun) + ["-np", str(processes)] + cmd
    return cmd


def read_summary(directory, returncode):
    """(summary.json parsed, the directory it was read from) of a run into
    DIRECTORY that exited with RETURNCODE: DIRECTORY after a success;
    DIRECTORY.failed, else DIRECTORY, after a failure; (None, None) where
    neither holds one that is a JSON object."""
    places = [directory] if returncode == 0 else [directory + ".failed", directory]
    for where in places:
        path = os.path.join(where, "summary.json")
        if os.path.isfile(path):
            try:
                with open(path, encoding="utf-8") as f:
                    summary = json.load(f)
            except (OSError, ValueError):
                continue
            if isinstance(summary, dict):
                return summary, where
    return None, None


def run(prm, settings=(), directory=None, processes=None, binary=BILAYER,
        mpirun=("mpirun",), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
        env=None, cwd=None, check=False):
    """Run bilayer on PRM with SETTINGS and Output/Output directory=DIRECTORY
    (appended last, so it wins) and return a Run.

    directory None: a fresh temporary directory, removed with whatever the
    run left beside it (DIR.failed). processes, binary, mpirun: as in
    command(). stdout, stderr, env, cwd, check: as in subprocess.run (text
    mode; default: both captured; check raises CalledProcessError on a
    non-zero exit)."""
    if directory is None:
        with tempfile.TemporaryDirectory(prefix="bilayer-run-") as tmp:
            r = run(prm, settings, os.path.join(tmp, "out"), processes, binary, mpirun,
                    stdout, stderr, env, cwd, check)
            return r._replace(directory=None)
    cmd = command(prm, set_list(settings) + ["Output/Output directory=" + directory],
                  processes, binary, mpirun)
    p = subprocess.run(cmd, stdout=stdout, stderr=stderr, env=env, cwd=cwd,
                       text=True, check=check)
    summary, where = read_summary(directory, p.returncode)
    return Run(p.returncode, p.stdout, p.stderr, summary, where)


def scene(prm, settings=(), binary=None):
    """{"Section/Subsection/Entry": value} of every entry of PRM as bilayer
    reads it: the file with its includes, then SETTINGS (a dict or a list
    of "Section/Entry=value"), from `bilayer PRM --print-parameters`. Exits
    1 with bilayer's one line where it refuses the file or a setting."""
    entries, refusal = read_entries(prm, settings, binary)
    if entries is None:
        sys.exit(refusal)
    return entries


def read_entries(prm, settings=(), binary=None):
    """(entries, None) with entries as scene() returns them, or (None, the
    line bilayer refused PRM or SETTINGS with) where it refuses them."""
    p = subprocess.run(command(prm, settings, binary=binary or BILAYER) + ["--print-parameters"],
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if p.returncode != 0:
        lines = p.stderr.strip().splitlines()
        return None, lines[-1] if lines else "%s: bilayer could not read %s (exit %d)" % (
            os.path.basename(sys.argv[0]), prm, p.returncode)
    entries, sections = {}, []
    for line in p.stdout.splitlines():
        line = line.strip()
        if line.startswith("subsection "):
            sections.append(line[len("subsection "):].strip())
        elif line == "end" and sections:
            sections.pop()
        elif line.startswith("set ") and " = " in line:
            key, value = line[4:].split(" = ", 1)
            entries["/".join(sections + [key.strip()])] = value.strip()
        elif line.startswith("set ") and line.endswith(" ="):
            entries["/".join(sections + [line[4:-2].strip()])] = ""
    return entries, None


def safe_name(prm):
    """The stem of PRM as a name for a folder: characters other than
    letters, digits, '.', '_', '-' become '_', and a name that is empty,
    starts with '.' or '-' gets 'scene' in front ('...prm' is 'scene..',
    never '..')."""
    stem = os.path.basename(str(prm))
    if stem.endswith(".prm"):
        stem = stem[:-4]
    stem = "".join(c if c.isalnum() and c.isascii() or c in "._-" else "_" for c in stem)
    if not stem or stem[0] in ".-":
        stem = "scene" + stem
    return stem


def gnuplot(script, lines, cwd):
    """Run gnuplot on LINES (a list of commands) in the folder CWD; exit 1
    with one line (gnuplot's last) where it fails."""
    p = subprocess.run(["gnuplot"], input="\n".join(lines) + "\n", text=True, cwd=cwd,
                       stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    if p.returncode != 0:
        sys.exit("%s: gnuplot failed (exit %d): %s" % (
            script, p.returncode, (p.stderr.strip().splitlines() or ["no message"])[-1]))


def gnuplot_string(text):
    """TEXT as a gnuplot single-quoted string ('' inside is one ')."""
    return "'" + str(text).replace("'", "''").replace("\n", " ") + "'"


def figure_path(script, value, inside=()):
    """The absolute path of a script's --figure PNG (None for None): a
    new file in an existing, writable folder, or a file under docs/ that
    git tracks (the committed figure it replaces). Exits 1 with one line
    where VALUE is empty, names a folder or a path inside one of the
    folders INSIDE (the results read, the output folder), its folder is
    missing or not writable, or it exists otherwise."""
    if value is None:
        return None
    if not value.strip():
        sys.exit("%s: --figure is an empty string: name a new PNG file" % script)
    figure = os.path.abspath(value)
    for folder in inside:
        real = os.path.realpath(folder)
        if os.path.realpath(figure) == real or \
                os.path.realpath(figure).startswith(real + os.sep):
            sys.exit("%s: --figure %s is inside %s: name a file outside it" % (
                script, value, folder))
    if os.path.isdir(figure) or value.endswith(os.sep):
        sys.exit("%s: --figure %s is a folder: name a new PNG file" % (script, value))
    parent = os.path.dirname(figure)
    if not os.path.isdir(parent):
        sys.exit("%s: --figure %s: the folder %s does not exist" % (script, value, parent))
    if not os.access(parent, os.W_OK | os.X_OK):
        sys.exit("%s: --figure %s: the folder %s is not writable" % (script, value, parent))
    if os.path.lexists(figure):
        docs = os.path.realpath(os.path.join(ROOT, "docs"))
        tracked = not os.path.islink(figure) and os.path.isfile(figure) and \
            os.path.realpath(figure).startswith(docs + os.sep) and subprocess.run(
                ["git", "-C", ROOT, "ls-files", "--error-unmatch", figure],
                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode == 0
        if not tracked:
            sys.exit("%s: --figure %s exists and is not a committed file under docs/: it is "
                     "left as it is; name a new file" % (script, figure))
    return figure


def copy_figure(script, source, figure):
    """Copy the figure SOURCE to FIGURE (of figure_path()); exit 1 with one
    line where it cannot be written."""
    try:
        shutil.copyfile(source, figure)
    except OSError as e:
        sys.exit("%s: cannot write --figure %s: %s" % (script, figure, e.strerror or e))


class OutputFolder:
    """The folder a script writes its results into.

    OutputFolder(SCRIPT, PATH, DEFAULT) opens PATH (the user's --output;
    DEFAULT, a path, when PATH is None or empty) for scripts/SCRIPT:
      - a folder that does not exist is created (with its parents), and a
        marker file .script-output in it records the script, the folder's
        identity (device and inode: a copy, cp -r, has its own, so the copy
        of an output folder is not the script's) and, one line each, the
        files and folders the script writes there;
      - an empty folder is taken (and marked);
      - a folder whose marker is the same script's and names the folder
        itself is taken again;
      - anything else (a non-empty folder without such a marker, a file, a
        folder under docs/) is refused: one line on stderr, exit 1.
    claim(NAME) returns the path of NAME in the folder for the script to
    write, refusing (exit 1) when NAME exists and the marker does not list
    it (a file the user put there is never overwritten); claim(NAME,
    folder=True) also creates it as a folder. Files of the user in the
    folder stay; the script deletes nothing in it."""

    MARKER = ".script-output"

    def __init__(self, script, path=None, default=None):
        self.script = script
        given = path or default
        if not given:
            self.fail("no output folder given")
        self.path = os.path.abspath(given)
        docs = os.path.join(ROOT, "docs")
        real = os.path.realpath(self.path)
        if real == os.path.realpath(docs) or real.startswith(os.path.realpath(docs) + os.sep):
            self.fail("the output folder %s is under docs/ (committed files): choose another "
                      "--output" % self.path)
        self.listed = []
        if not os.path.lexists(self.path):
            try:
                os.makedirs(self.path)
            except OSError as e:
                self.fail("cannot create the output folder %s: %s" % (self.path, e.strerror))
        elif os.path.islink(self.path) or not os.path.isdir(self.path):
            self.fail("%s exists and is not a folder: choose another --output" % self.path)
        else:
            try:
                names = sorted(os.listdir(self.path))
            except OSError as e:
                self.fail("cannot read the output folder %s: %s; choose another --output" % (
                    self.path, e.strerror or e))
            listed = self.read_marker()
            if listed is not None:
                self.listed = listed
            elif names:
                why = ("its %s is another folder's (a copy) or another script's" % self.MARKER
                       if self.MARKER in names else "and no %s of scripts/%s" % (
                           self.MARKER, script))
                shown = [n for n in names if n != self.MARKER] or names
                self.fail("%s holds '%s', %s: it is not an output folder of scripts/%s; "
                          "choose another --output (an empty or new folder)" % (
                              self.path, shown[0], why, script))
        self.write_marker()

    def __fspath__(self):
        return self.path

    def __str__(self):
        return self.path

    def fail(self, message):
        print("%s: %s" % (self.script, message), file=sys.stderr)
        sys.exit(1)

    def identity(self):
        st = os.stat(self.path)
        return "%d:%d" % (st.st_dev, st.st_ino)

    def first_line(self):
        return ("This folder was written by scripts/%s. A later run of scripts/%s into it "
                "writes the files listed here and nothing else.") % (self.script, self.script)

    def read_marker(self):
        """The names the marker lists, or None where it is not this
        script's marker of this folder."""
        marker = os.path.join(self.path, self.MARKER)
        if os.path.islink(marker) or not os.path.isfile(marker):
            return None
        try:
            with open(marker) as f:
                lines = f.read().splitlines()
        except (OSError, UnicodeDecodeError):
            return None
        if not lines or lines[0] != self.first_line() or \
                lines[1:2] != ["identity: " + self.identity()]:
            return None
        return [l[len("file: "):] for l in lines if l.startswith("file: ")]

    def write_marker(self):
        text = "\n".join([self.first_line(), "identity: " + self.identity(),
                          "folder: " + self.path] +
                         ["file: " + n for n in self.listed]) + "\n"
        tmp = None
        try:
            fd, tmp = tempfile.mkstemp(dir=self.path, prefix=self.MARKER + ".")
            os.fchmod(fd, 0o644)
            with os.fdopen(fd, "w") as f:
                f.write(text)
            os.replace(tmp, os.path.join(self.path, self.MARKER))
        except OSError as e:
            if tmp is not None and os.path.lexists(tmp):
                os.remove(tmp)   # the script's own temporary file
            self.fail("cannot write into the output folder %s: %s; choose another --output" % (
                self.path, e.strerror or e))

    def claim(self, name, folder=False):
        """The path of NAME (a plain name, no '/') in the folder, for the
        script to write; exit 1 where NAME exists and is not the script's."""
        if not name or "/" in name or name in (".", "..", self.MARKER):
            self.fail("'%s' is not a name of a file in the output folder" % name)
        path = os.path.join(self.path, name)
        if os.path.lexists(path) and name not in self.listed:
            self.fail("%s exists and scripts/%s did not write it: it is left as it is; move it "
                      "or choose another --output" % (path, self.script))
        if os.path.islink(path):
            self.fail("%s is a symbolic link: it is left as it is; remove it or choose another "
                      "--output" % path)
        if name not in self.listed:
            self.listed.append(name)
            self.write_marker()
        if folder and not os.path.isdir(path):
            try:
                os.mkdir(path)
            except OSError as e:
                self.fail("cannot create %s: %s" % (path, e.strerror or e))
        return path


def main(argv):
    """The command-line interface for the bash scripts (see the module's
    docstring)."""
    if len(argv) >= 3 and argv[0] == "output":
        sys.argv[0] = argv[1]
        folder = OutputFolder(argv[1], argv[2])
        for name in argv[3:]:
            folder.claim(name.rstrip("/"), folder=name.endswith("/"))
        print(folder.path)
        return 0
    if len(argv) >= 3 and argv[0] == "entry":
        settings, rest = [], argv[3:]
        while rest:
            if rest[0] != "--set" or len(rest) < 2:
                sys.exit("bilayer_run.py entry: expected --set Section/Entry=value, got '%s'"
                         % rest[0])
            settings.append(rest[1])
            rest = rest[2:]
        entries = scene(argv[1], settings)
        if argv[2] not in entries:
            sys.exit("bilayer_run.py entry: no entry %s" % argv[2])
        print(entries[argv[2]])
        return 0
    if len(argv) == 2 and argv[0] == "name":
        print(safe_name(argv[1]))
        return 0
    print("bilayer_run.py: usage: bilayer_run.py output SCRIPT DIR [NAME ...] | entry PRM "
          "SECTION/ENTRY [--set S/E=v ...] | name PRM", file=sys.stderr)
    return 2


if __name__ == "__main__":
    guard(lambda: main(sys.argv[1:]), "bilayer_run.py")

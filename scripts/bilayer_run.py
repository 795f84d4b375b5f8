"""Run bilayer from the Python scripts of scripts/ (standard library only).

The scripts import it from their own directory (`import bilayer_run`):

    ROOT, BILAYER          the repository and build/bilayer in it
    argument_parser(doc)   an ArgumentParser whose --help is the script's
                           docstring (first paragraph, then the rest)
    MPI_ENV                the environment for mpirun as root, oversubscribed
    setup()                scripts/setup --no-install (configure and build
                           if needed, never install), quietly; exits with its
                           status (after its one-line message) if it fails
    require(*tools)        exits 1 with one line naming the Debian package
                           of the first of TOOLS (gnuplot, mpirun, ...) not
                           on PATH: the scripts never install anything
    command(prm, settings, processes=None, binary=BILAYER, mpirun=("mpirun",))
                           the command line: BINARY PRM --set S/E=v ...,
                           behind MPIRUN -np PROCESSES when processes is given
    run(prm, settings, directory=None, ...) -> Run
                           runs it with Output/Output directory=DIRECTORY
                           (default: a temporary directory, removed after the
                           run) and reads the run's summary.json
    read_summary(directory, returncode) -> (summary, where)

settings: a dict {"Section/Entry": value} or a list of "Section/Entry=value"
strings. A run whose checks fail (exit 2) leaves its results in DIR.failed and
DIR as it was; a refused run writes nothing. bilayer writes only into
directories it created itself (or empty ones), so DIRECTORY should not exist
or be empty.
"""
import argparse
import collections
import json
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BILAYER = os.path.join(ROOT, "build", "bilayer")
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
           "OMPI_MCA_rmaps_base_oversubscribe": "1"}

Run = collections.namedtuple("Run", "returncode stdout stderr summary directory")
Run.__doc__ = """One finished run of bilayer.

returncode: its exit status; stdout, stderr: its terminal output (None where
not captured); summary: summary.json parsed (None where the run left none);
directory: where summary.json was read (DIR or DIR.failed; None for a
temporary directory, which is gone)."""


def argument_parser(doc):
    """An argparse.ArgumentParser describing a script by its docstring DOC:
    the first paragraph above the options, the rest below, as written."""
    first, _, rest = doc.partition("\n\n")
    return argparse.ArgumentParser(description=first, epilog=rest or None,
                                   formatter_class=argparse.RawDescriptionHelpFormatter)


# The Debian package that provides each tool the scripts run.
PACKAGES = {"gnuplot": "gnuplot-nox", "pvbatch": "paraview python3-paraview",
            "Xvfb": "xvfb", "gmsh": "gmsh",
            "mpirun": "openmpi-bin", "numdiff": "numdiff", "h5dump": "hdf5-tools"}


def setup():
    """scripts/setup --no-install with its output discarded: configures and
    builds if needed, never installs. If it fails (its one line on stderr
    names what is missing), exits with its status."""
    p = subprocess.run([os.path.join(ROOT, "scripts", "setup"), "--no-install"],
                       stdout=subprocess.DEVNULL)
    if p.returncode != 0:
        sys.exit(p.returncode)


def require(*tools):
    """Exit 1 with one line naming the Debian package to install for the
    first of TOOLS that is not on PATH (the scripts never install)."""
    for tool in tools:
        if shutil.which(tool) is None:
            package = PACKAGES.get(tool, tool)
            sys.exit("%s: %s is missing: install the Debian package%s %s" % (
                os.path.basename(sys.argv[0]), tool, "s" if " " in package else "", package))


def set_list(settings):
    """The "Section/Entry=value" strings of a dict or a list of them."""
    if isinstance(settings, dict):
        return ["%s=%s" % (k, v) for k, v in settings.items()]
    return list(settings)


def command(prm, settings=(), processes=None, binary=BILAYER, mpirun=("mpirun",)):
    """The command line running BINARY on PRM with one --set per setting;
    with processes, behind MPIRUN... -np PROCESSES."""
    cmd = [binary, prm]
    for s in set_list(settings):
        cmd += ["--set", s]
    if processes is not None:
        cmd = list(mpirun) + ["-np", str(processes)] + cmd
    return cmd


def read_summary(directory, returncode):
    """(summary.json parsed, the directory it was read from) of a run into
    DIRECTORY that exited with RETURNCODE: DIRECTORY after a success;
    DIRECTORY.failed, else DIRECTORY, after a failure; (None, None) where
    neither holds one."""
    places = [directory] if returncode == 0 else [directory + ".failed", directory]
    for where in places:
        path = os.path.join(where, "summary.json")
        if os.path.isfile(path):
            with open(path) as f:
                return json.load(f), where
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

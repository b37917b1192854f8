#!/usr/bin/python3
"""The hostile-input matrix of issue 15: every bad input of the issue and every rule of SPEC §4.

    /usr/bin/python3 tests/test_hostile_inputs.py PATH/TO/thinlayer

Each case runs thinlayer (or the report) in a folder that already holds a user's files -- an
earlier result, notes, a sub-folder -- and asserts the exit status, a single clear line on
stderr, and the folder afterwards: byte for byte as before for every refused input, or with
exactly the expected change. The signal cases kill a run while its temporary file exists and
check that none is left and the earlier result is intact. Cheap scenes only (the bar on an
8 x 8 mesh), so the whole matrix takes seconds.
"""

import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np

from input_matrix import snapshot
from process_session import run_in_session

HERE = os.path.dirname(os.path.abspath(__file__))
MAKE_REPORT = os.path.join(HERE, "..", "report", "make_report.py")
CHEAP = "--case bar --row 1 --nx 8 --ny 8"  # a limit-mode bar that solves in milliseconds

THINLAYER = None
failures = []
passed = 0
folders = []  # every folder this script made, removed at the end


earlier = []  # the earlier result every user folder holds: one solve, copied into each folder


def earlier_result():
    """A results file thinlayer wrote (the cheap bar), made once for the whole matrix."""
    if not earlier:
        folder = tempfile.mkdtemp(prefix="thinlayer-hostile-earlier-")
        folders.append(folder)
        path = os.path.join(folder, "previous.h5")
        r = subprocess.run([THINLAYER, "solve", *CHEAP.split(), "--out", path], capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        earlier.append(path)
    return earlier[0]


def user_folder():
    """A folder as a user has it before a run: an earlier result, notes, a sub-folder, a FIFO."""
    folder = tempfile.mkdtemp(prefix="thinlayer-hostile-")
    folders.append(folder)
    shutil.copyfile(earlier_result(), os.path.join(folder, "previous.h5"))
    with open(os.path.join(folder, "notes.txt"), "w") as notes:
        notes.write("the user's notes\n")
    os.makedirs(os.path.join(folder, "sub"))
    with open(os.path.join(folder, "sub", "data.csv"), "w") as data:
        data.write("1,2,3\n")
    os.mkfifo(os.path.join(folder, "fifo.h5"))
    os.symlink("previous.h5", os.path.join(folder, "link.h5"))
    os.symlink("not-yet.h5", os.path.join(folder, "dangling.h5"))
    os.makedirs(os.path.join(folder, "study"))
    return folder


survivors = []  # processes a run left behind, per case (checked by refused())


def run(argv, folder, timeout=120):
    """The run in its own session, so that whatever it started can be found after it."""
    r, survivors[:] = run_in_session(argv, folder, timeout)
    return r


def check(name, condition, detail=""):
    global passed
    if condition:
        passed += 1
    else:
        failures.append(f"{name}: {detail}")
        print(f"FAIL {name}: {detail}")


def refused(name, args, message, prefix=None, status=2, report=False):
    """A bad input: exit `status`, one line on stderr naming the problem, the folder unchanged."""
    folder = user_folder()
    before = snapshot(folder)
    argv = [sys.executable, MAKE_REPORT, *args] if report else [THINLAYER, *args]
    r = run(argv, folder)
    lines = r.stderr.strip().splitlines()
    prefix = prefix or ("make_report: " if report else f"thinlayer {args[0]}: ")
    check(name, r.returncode == status, f"exit {r.returncode}, expected {status}; stderr {r.stderr!r}")
    check(name, len(lines) == 1, f"{len(lines)} lines on stderr: {r.stderr!r}")
    check(name, bool(lines) and lines[0].startswith(prefix) and message in lines[0],
          f"expected {prefix!r} and {message!r} in {r.stderr!r}")
    check(name, snapshot(folder) == before, "the folder changed")
    check(name, not survivors, f"processes {survivors} outlived the run")
    print(f"case {name}: {' '.join(args)!r} -> exit {status}, '{message}', files unchanged")
    return folder


def solve(extra):
    return ["solve", *CHEAP.split(), *extra]


def layer(extra, case="bar"):
    base = ["solve", "--case", "bar", "--mode", "layer", "--row", "1", "--nx", "8", "--ny", "8"] if case == "bar" \
        else ["solve", "--case", "dovetail", "--mode", "layer", "--law-case", "d"]
    return base + extra


def refused_inputs():
    # Numbers are decimal: no hex, no blanks, overflow and underflow named (SPEC §4).
    refused("hex", layer(["--eps", "0x10"]), "not a decimal number: '0x10'")
    refused("leading blank", layer(["--eps", " 3"]), "not a decimal number")
    refused("trailing blank in an integer", ["solve", "--case", "bar", "--row", "1 "], "not an integer: '1 '")
    refused("underflow", layer(["--eps", "1e-400"]), "underflows")
    refused("overflow", layer(["--eps", "1e999"]), "overflows")
    refused("NaN", ["solve", "--case", "bar", "--lambda-bar", "nan", "--mu-bar", "5"], "NaN")
    refused("hex integer", solve(["--max-iterations", "0x8"]), "not an integer")
    refused("integer out of range", ["solve", "--case", "bar", "--row", "1", "--nx", "99999999999"], "out of range")
    refused("decimal for an integer", ["solve", "--case", "bar", "--row", "1", "--nx", "8.5"], "not an integer")
    # An option's value is never another option.
    refused("--out --quiet", ["study", "table3", "--out", "--quiet"], "--out needs a value, got the option '--quiet'")
    refused("--out --json", solve(["--out", "--json"]), "--out needs a value")
    refused("--eps --out o.h5", layer(["--eps", "--out", "o.h5"]), "--eps needs a value")
    refused("missing value at the end", solve(["--out"]), "--out")
    # Repeated, conflicting options and stray arguments.
    refused("repeated --case", ["solve", "--case", "bar", "--case", "dovetail", "--row", "1"], "--case is given 2 times")
    refused("repeated flag", solve(["--json", "--json"]), "--json is given 2 times")
    refused("repeated --out", solve(["--out", "a.h5", "--out", "b.h5"]), "--out is given 2 times")
    refused("conflicting --row and --lambda-bar", solve(["--lambda-bar", "4", "--mu-bar", "5"]), "either --row")
    refused("stray argument to solve", solve(["extra"]), "unexpected argument 'extra'")
    refused("stray argument to study", ["study", "table3", "extra"], "unexpected argument 'extra'")
    refused("unknown option", solve(["--bogus", "3"]), "unknown option --bogus")
    refused("option the study does not read", ["study", "table3", "--cases", "d"], "--cases does not apply to study table3")
    refused("--quick for thresholds", ["study", "thresholds", "--quick"], "--quick does not apply")
    refused("verify --relaxation-cap", ["verify", "--out", "v", "--relaxation-cap", "3"], "does not apply to verify")
    refused("duplicate dovetail case", ["study", "dovetail", "--cases", "dd"], "case 'd' is given twice")
    refused("unknown study", ["study", "table4"], "unknown study 'table4'")
    refused("bar option on the dovetail", ["solve", "--case", "dovetail", "--law-case", "d", "--nx", "8"], "does not apply")
    # Values that would be silently wrong.
    refused("--max-iterations 0", solve(["--max-iterations", "0"]), "--max-iterations must be >= 1")
    refused("--diagonal with Q1", solve(["--diagonal", "left"]), "--diagonal applies to P1")
    refused("--scale overflowing lambda_bar", solve(["--scale", "1e308"]), "overflows")
    # Geometric sanity: a layer thicker than the case allows.
    refused("--eps 50 on the 40 mm bar", layer(["--eps", "50"]), "no thin layer for the bar")
    # The bar's own limit (issue 26, item 7): its rows' layers are nearly incompressible above 1 mm.
    refused("--eps 1.5 on the bar, above its 1 mm", layer(["--eps", "1.5"]), "at most 1 mm")
    refused("--eps 1e300 on the dovetail", layer(["--eps", "1e300"], "dovetail"), "no thin layer for the dovetail")
    refused("--eps 0.5 in a dovetail study", ["study", "dovetail", "--eps", "0.5"], "no thin layer")
    refused("--rate-eps that grows", ["study", "convergence", "--rate-eps", "1e-5,1e-4,1e-6"], "the grid must decrease")
    refused("--rate-eps of one thickness", ["study", "convergence", "--rate-eps", "1e-5"], "at least two")
    refused("--rate-eps for a study without rates", ["study", "dovetail", "--rate-eps", "1e-4,1e-5"],
            "--rate-eps does not apply")
    refused("--eps 0", layer(["--eps", "0"]), "--eps must be finite and > 0")
    # Unwritable outputs: exit 2 from every command, nothing created, nothing replaced.
    refused("--out onto a FIFO", solve(["--out", "fifo.h5"]), "FIFO")
    refused("--vtu onto a FIFO", solve(["--vtu", "fifo.h5"]), "FIFO")
    refused("--out onto a device", solve(["--out", "/dev/null"]), "device")
    refused("--out onto a directory", solve(["--out", "sub"]), "Is a directory")
    refused("--out in a missing directory", solve(["--out", "missing/x.h5"]), "No such file or directory")
    refused("--out where nothing can be created", solve(["--out", "/proc/thinlayer.h5"]), "/proc/thinlayer.h5")
    refused("--out and --vtu the same file", solve(["--out", "x.h5", "--vtu", "x.h5"]), "same file")
    refused("study --out onto a file", ["study", "thresholds", "--out", "notes.txt"], "notes.txt")


def refused_with_setup(name, setup, args, message, report=False):
    """As refused(), in a folder prepared by `setup(folder)` first."""
    folder = user_folder()
    setup(folder)
    before = snapshot(folder)
    argv = [sys.executable, MAKE_REPORT, *args] if report else [THINLAYER, *args]
    r = run(argv, folder)
    lines = r.stderr.strip().splitlines()
    check(name, r.returncode == 2, f"exit {r.returncode}; stderr {r.stderr!r}")
    check(name, len(lines) == 1 and message in lines[0], f"expected one line with {message!r}: {r.stderr!r}")
    check(name, snapshot(folder) == before, "the folder changed")
    check(name, not survivors, f"processes {survivors} outlived the run")
    print(f"case {name}: {' '.join(args)!r} -> exit 2, '{message}', files unchanged")


def prepared_refusals():
    def fifo_results(folder):
        os.mkfifo(os.path.join(folder, "study", "results.h5"))
    refused_with_setup("study results.h5 a FIFO", fifo_results, ["study", "thresholds", "--out", "study"], "FIFO")

    def foreign(folder):
        with h5py.File(os.path.join(folder, "foreign.h5"), "w") as f:
            f["data"] = [1, 2, 3]
    refused_with_setup("report on a foreign HDF5 file", foreign, ["foreign.h5", "out"], "foreign", report=True)

    def older(folder):
        with h5py.File(os.path.join(folder, "older.h5"), "w") as f:
            f.attrs["layout"], f.attrs["layout_version"] = "thinlayer-results", 0
            f.create_group("scenes")
    refused_with_setup("report on an older layout", older, ["older.h5", "out"], "older", report=True)

    def own_page(folder):
        with open(os.path.join(folder, "index.html"), "w") as page:
            page.write("<html>the user's page</html>")
    refused_with_setup("report over a page it did not write", own_page, ["previous.h5", "."],
                       "not a report this script wrote", report=True)
    refused_with_setup("report on a missing file", lambda folder: None, ["missing.h5", "out"], "no such file",
                       report=True)


def issue26_refusals():
    """Issue 26: the command line declared in CLI11 keeps every rule; outputs never replace a file
    thinlayer did not write; loads that would overflow are refused before the solve."""
    refused("--opt=value: an option as the value", solve(["--out=--quiet"]), "--out needs a value, got the option '--quiet'")
    refused("--opt=value: hex", layer(["--eps=0x10"]), "not a decimal number: '0x10'")
    refused("--opt=value given twice", solve(["--out=a.h5", "--out", "b.h5"]), "--out is given 2 times")
    refused("a flag given a value", solve(["--json=1"]), "--json takes no value")
    refused("an empty value", solve(["--out="]), "--out: empty value")
    refused("an octal-looking integer is decimal, and checked", ["solve", "--case", "bar", "--row", "07"], "unknown Table 3 row 7")
    refused("an empty item in a list", ["study", "dovetail", "--eps", "1e-3,,1e-4"], "not a decimal number: ''")
    refused("--load-scale 1e308 (overflow up front)", solve(["--load-scale", "1e308"]), "overflow the solve")
    refused("--load-scale -1e200", solve(["--load-scale", "-1e200"]), "overflow the solve")
    refused("--max-nodes 0", ["solve", "--scene", "x.json", "--max-nodes", "0"], "--max-nodes must be >= 1")
    refused("--max-nodes on the bar", solve(["--max-nodes", "10"]), "--max-nodes applies to a scene file (--scene) only")
    refused("--out onto the user's notes", solve(["--out", "notes.txt"]), "notes.txt': it exists and is not a thinlayer results")
    refused("--vtu onto the user's notes", solve(["--vtu", "notes.txt"]), "is not a VTU file thinlayer wrote")
    refused("--vtu onto a results file", solve(["--vtu", "previous.h5"]), "is not a VTU file thinlayer wrote")
    refused("--out onto a CSV of the user's", solve(["--out", "sub/data.csv"]), "is not a thinlayer results file")

    def foreign_h5(folder):
        with h5py.File(os.path.join(folder, "foreign.h5"), "w") as f:
            f["data"] = [1, 2, 3]
    refused_with_setup("--out onto another tool's HDF5", foreign_h5, solve(["--out", "foreign.h5"]), "not a thinlayer results file")

    def text_results(folder):
        with open(os.path.join(folder, "study", "results.h5"), "w") as f:
            f.write("not HDF5\n")
    refused_with_setup("study --out DIR holding a text results.h5", text_results, ["study", "thresholds", "--out", "study"],
                       "study/results.h5': it exists and is not a thinlayer results file")

    def user_summary(folder):
        with open(os.path.join(folder, "study", "summary.json"), "w") as f:
            f.write('{"my": "summary"}\n')
    refused_with_setup("verify --out DIR holding the user's summary.json", user_summary, ["verify", "--out", "study"],
                       "summary.json': it exists and is not a summary.json thinlayer wrote")


def forced_and_own_outputs():
    """--force replaces a file thinlayer did not write; without it, thinlayer's own files are replaced."""
    folder = user_folder()
    r = run([THINLAYER, *solve(["--out", "notes.txt", "--force"])], folder)
    check("--force replaces the user's file", r.returncode == 0 and h5py.is_hdf5(os.path.join(folder, "notes.txt")), r.stderr)
    r = run([THINLAYER, *solve(["--vtu", "scene.vtu"])], folder)
    r2 = run([THINLAYER, *solve(["--vtu", "scene.vtu", "--friction", "0.5"])], folder)
    check("a VTU thinlayer wrote is replaced without --force", r.returncode == 0 and r2.returncode == 0, r.stderr + r2.stderr)
    print("case --force and thinlayer's own outputs: replaced; a foreign file only with --force")


def tiny_filesystem():
    """A 64 KB tmpfs holding an earlier result (root only: mount)."""
    folder = tempfile.mkdtemp(prefix="thinlayer-tmpfs-")
    folders.append(folder)
    if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", folder], capture_output=True).returncode != 0:
        return None
    return folder


def disk_full_cases():
    """SPEC §4: a full disk is exit 2 with one line, never a crash (it was exit 139 and HDF5's text), and
    the earlier result survives."""
    if os.geteuid() != 0:
        print("SKIP disk-full cases: mounting a small tmpfs needs root")
        return
    lap = os.path.join(HERE, "..", "cases", "lap_joint", "lap_joint.json")
    cases = [("solve --out", solve(["--out", "{d}/previous.h5"]), "{d}/previous.h5"),
             ("solve --vtu", solve(["--vtu", "{d}/previous.vtu"]), "{d}/previous.vtu"),
             ("solve --scene --out", ["solve", "--scene", lap, "--out", "{d}/previous.h5"], "{d}/previous.h5"),
             ("study table3 --out", ["study", "table3", "--quick", "--quiet", "--out", "{d}"], "{d}/results.h5"),
             ("study validity --scene --out", ["study", "validity", "--scene", lap, "--quiet", "--out", "{d}"], "{d}/results.h5"),
             ("study validity --scene --out NEW (no empty folder left)",
              ["study", "validity", "--scene", lap, "--quiet", "--out", "{d}/NEW"], "{d}/NEW/results.h5")]
    for name, args, target in cases:
        d = tiny_filesystem()
        if d is None:
            print("SKIP disk-full cases: cannot mount a tmpfs here")
            return
        try:
            seed = run([THINLAYER, *solve(["--out", f"{d}/previous.h5", "--vtu", f"{d}/previous.vtu"])], d)
            check(f"disk full, {name}: an earlier result", seed.returncode == 0, seed.stderr)
            before = snapshot(d)
            r = run([THINLAYER, *[a.format(d=d) for a in args]], d)
            lines = r.stderr.strip().splitlines()
            check(f"disk full, {name}", r.returncode == 2, f"exit {r.returncode}: {r.stderr!r}")
            check(f"disk full, {name}", len(lines) == 1 and "No space left on device" in lines[0], repr(r.stderr))
            check(f"disk full, {name}", snapshot(d) == before, "the earlier result or the folder changed")
            check(f"disk full, {name}", not survivors, str(survivors))
            print(f"case disk full, {name}: exit 2, {lines[0] if lines else ''!r}, earlier result intact")
        finally:
            subprocess.run(["umount", d], capture_output=True)
    mpirun = shutil.which("mpirun")
    d = tiny_filesystem()
    if mpirun and d:
        try:
            run([THINLAYER, "study", "table3", "--quick", "--quiet", "--out", d], d)  # an earlier result, if it fits
            before = snapshot(d)
            r = run([mpirun, "--oversubscribe", "--allow-run-as-root", "-n", "2", THINLAYER, "study", "table3", "--quick",
                     "--quiet", "--out", d], d)
            ours = [line for line in r.stderr.splitlines() if line.startswith("thinlayer")]
            check("disk full under mpirun -n 2", r.returncode == 2, f"exit {r.returncode}: {r.stderr!r}")
            check("disk full under mpirun -n 2", len(ours) == 1 and "No space left on device" in ours[0], repr(r.stderr))
            check("disk full under mpirun -n 2", snapshot(d) == before, "the folder changed")
            print(f"case disk full under mpirun -n 2 study table3: exit 2, {ours[0] if ours else ''!r}")
        finally:
            subprocess.run(["umount", d], capture_output=True)


def written_cases():
    # --out through a symbolic link: the link stays, its target is replaced by a results file.
    folder = user_folder()
    before = snapshot(folder)
    r = run([THINLAYER, *solve(["--out", "link.h5"])], folder)
    after = snapshot(folder)
    check("--out through a link", r.returncode == 0, r.stderr)
    check("--out through a link", after["link.h5"] == ("link", "previous.h5"), "the link was replaced")
    check("--out through a link", after["previous.h5"] != before["previous.h5"], "the target was not rewritten")
    check("--out through a link", {k for k in after if k not in ("previous.h5",)} ==
          {k for k in before if k not in ("previous.h5",)}, "other files changed")
    with h5py.File(os.path.join(folder, "previous.h5"), "r") as f:
        check("--out through a link", f.attrs["layout"] == "thinlayer-results" and f.attrs["layout_version"] == 2,
              dict(f.attrs))
    print("case --out through a link: exit 0, link kept, its target rewritten, nothing else touched")

    # A dangling link: its target is created.
    r = run([THINLAYER, *solve(["--out", "dangling.h5"])], folder)
    check("--out through a dangling link", r.returncode == 0 and os.path.islink(os.path.join(folder, "dangling.h5"))
          and os.path.isfile(os.path.join(folder, "not-yet.h5")), r.stderr)
    print("case --out through a dangling link: exit 0, the link kept, its target created")

    # A solve file is a results file, self-describing, and the report reads it.
    r = run([THINLAYER, *solve(["--out", "scene.h5", "--json"])], folder)
    check("solve --json", r.returncode == 0, r.stderr)
    out_lines = r.stdout.strip().splitlines()
    check("solve --json", len(out_lines) == 1, r.stdout)
    summary = json.loads(out_lines[0]) if out_lines else {}
    for key in ("counts", "residual", "stop_cause", "iterations", "times_s", "converged"):
        check("solve --json", key in summary, f"no {key} in {summary}")
    counts = summary.get("counts", {}).get("S", {})
    check("solve --json", sum(counts.values()) == 8, f"8 contact nodes on an 8 x 8 mesh, got {counts}")
    print("case solve --json: exit 0, one JSON line with counts, residual, stop cause, iterations, times")
    with h5py.File(os.path.join(folder, "scene.h5"), "r") as f:
        check("solve file", "environment" in f and "checks" in f, list(f))
        g = f["scenes"][list(f["scenes"])[0]]
        check("solve file", g["interface/S/status"].attrs["legend"] == "0 gap, 1 slide, 2 stick", "no legend")
        check("solve file", g["interface/S/sigma_N"].attrs["units"] == "daN/mm^2", "no units")
        check("solve file", g.attrs["eps_units"] == "mm", "no unit on eps")
        check("solve file", "force_convention" in g["interface/S"].attrs, "no force convention")
        check("solve file", list(g["mesh/body_names"].asstr()[()]) == ["bar"], "body names")
        check("solve file", (g["interface/S/node_minus"][()] == -1).all(), "the foundation is -1")
        nodes, plus, x = g["mesh/nodes"][()], g["interface/S/node_plus"][()], g["interface/S/x"][()]
        check("solve file", abs(nodes[plus] - x).max() == 0, "node_plus does not name the interface nodes")
        # The cell stresses balance the applied tractions: the mean sigma_22 of the top row of
        # cells is F2 = -5 and the mean sigma_11 of the left column is -F1 = -10 (daN/mm^2),
        # since the rows and columns of a structured mesh carry the whole load.
        centres = nodes[g["mesh/cells"][()]].mean(axis=1)
        stress = g["mesh/cell_stress"][()]
        top, left = centres[:, 1] > centres[:, 1].max() - 1e-9, centres[:, 0] < centres[:, 0].min() + 1e-9
        check("solve file", abs(stress[top, 1].mean() + 5) < 1e-9 and abs(stress[left, 0].mean() + 10) < 1e-9,
              f"cell stresses {stress[top, 1].mean()}, {stress[left, 0].mean()}")
        # The force convention as written: interface forces + reactions + loads balance.
        i = g["interface/S"]
        normal = i["normal"][()]
        tangent = np.stack([normal[:, 1], -normal[:, 0]], axis=1)
        force = ((-i["sigma_N"][()])[:, None] * normal + i["sigma_T"][()][:, None] * tangent) * i["length"][()][:, None]
        total = force.sum(axis=0) + g["reactions/D"][()] + g["reactions/DE"][()] + np.array([10 * 40, -5 * 40])
        check("solve file", abs(total).max() < 1e-9 * 400, f"the force convention does not balance: {total}")
    print("case solve file: layout 2, /environment, /checks, units, legend, node_plus/minus, body names, "
          "cell stresses and the force convention balancing the loads")
    before = snapshot(folder)
    r = run([sys.executable, MAKE_REPORT, "scene.h5", "."], folder)
    after = snapshot(folder)
    check("report on a solve file, in its folder", r.returncode == 0, r.stderr)
    check("report on a solve file, in its folder", all(after.get(k) == v for k, v in before.items()),
          "a file the report did not write changed")
    check("report on a solve file, in its folder",
          all(k == "index.html" or k == "figures" or k.startswith("figures/") for k in set(after) - set(before)),
          sorted(set(after) - set(before)))
    print("case report DIR/file.h5 DIR: exit 0, only index.html and figures/ added, every other file as before")

    # --version and the help list every study.
    r = run([THINLAYER, "--version"], folder)
    check("--version", r.returncode == 0 and r.stdout.startswith("thinlayer ") and "layout" in r.stdout, r.stdout)
    for args in (["--help"], ["study", "--help"]):
        r = run([THINLAYER, *args], folder)
        for study in ("table3", "dovetail", "convergence", "validity", "thresholds", "asymptotics", "timing", "stress"):
            check(f"help {args}", study in r.stdout, f"{study} not in the help")
    print("case --version, --help, study --help: exit 0, every study named")


def killed(name, args, signum, wait_for_tmp, report=False):
    """Kill a run while it writes: no temporary file left, the earlier result intact."""
    folder = user_folder()
    out = os.path.join(folder, "study")
    if report:
        subprocess.run([sys.executable, MAKE_REPORT, os.path.join(folder, "previous.h5"), out], check=True,
                       capture_output=True)
    else:
        os.replace(os.path.join(folder, "previous.h5"), os.path.join(out, "results.h5"))
    before = snapshot(folder)
    argv = [sys.executable, MAKE_REPORT, *args] if report else [THINLAYER, *args]
    process = subprocess.Popen(argv, cwd=folder, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 60
    marker = ".report-building-" if report else ".tmp."
    seen = False
    while time.monotonic() < deadline and process.poll() is None:
        if not wait_for_tmp or any(marker in n for n in os.listdir(out)):
            seen = True
            break
        time.sleep(0.01)
    process.send_signal(signum)
    status = process.wait(timeout=60)
    after = snapshot(folder)
    check(name, seen, "the run ended before its temporary file appeared")
    check(name, status in (-signum, 128 + signum), f"exit status {status}")
    check(name, not any(marker in k for k in after), sorted(k for k in after if marker in k))
    check(name, after == before, "the earlier result or another file changed")
    print(f"case {name}: {signal.Signals(signum).name} mid-write -> no temporary file, earlier result intact")


def signal_cases():
    killed("SIGINT during study table3", ["study", "table3", "--quick", "--quiet", "--out", "study"], signal.SIGINT, True)
    killed("SIGTERM during study table3", ["study", "table3", "--quick", "--quiet", "--out", "study"], signal.SIGTERM,
           True)
    # A hang-up (the terminal closed; under mpirun a Ctrl-C often reaches a rank as SIGHUP first).
    killed("SIGHUP during study table3", ["study", "table3", "--quick", "--quiet", "--out", "study"], signal.SIGHUP, True)
    killed("SIGTERM during solve", layer(["--eps", "1e-3", "--out", "study/results.h5"], "dovetail"), signal.SIGTERM,
           False)
    killed("SIGTERM during the report", ["previous.h5", "study"], signal.SIGTERM, True, report=True)


def main(argv):
    global THINLAYER
    if len(argv) != 2:
        print("usage: test_hostile_inputs.py PATH/TO/thinlayer", file=sys.stderr)
        return 2
    THINLAYER = os.path.abspath(argv[1])
    start = time.monotonic()
    try:
        refused_inputs()
        prepared_refusals()
        issue26_refusals()
        forced_and_own_outputs()
        disk_full_cases()
        written_cases()
        signal_cases()
    finally:
        for folder in folders:
            shutil.rmtree(folder, ignore_errors=True)
    print(f"\n{passed} assertions passed, {len(failures)} failed, in {time.monotonic() - start:.1f} s")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

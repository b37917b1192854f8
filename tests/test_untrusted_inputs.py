#!/usr/bin/python3
"""Issue 34's hostile matrix: gmsh reads only what thinlayer read, in a box with a clock; no
untrusted file is parsed in the main process; outputs are distinct; bounds and messages.

    /usr/bin/python3 tests/test_untrusted_inputs.py PATH/TO/thinlayer PATH/TO/cases/lap_joint [GROUP ...]

(GROUP: a function below, to run only those; every group by default.) Issue 43's groups follow
issue 34's: side_files, machine, report_one_file, write_time, report_folder, one_line,
tmpdir_clock_names.

Every case runs thinlayer (or the report) in its own session in a folder holding the user's files
and asserts: the exit status, exactly one line on stderr holding the expected words, the wall
time under a stated bound, the folder byte for byte as before (or exactly the expected change),
nothing written in a folder outside it (where a statement would aim), no staging folder left in
$TMPDIR, and no process of the run left. It prints a table of the cases (name, exit, the line,
seconds) at the end.
"""

import json
import os
import random
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import h5py

from input_matrix import snapshot, two_quads_msh as msh
from process_session import run_in_session, session_processes

THINLAYER = os.path.abspath(sys.argv[1])
LAP = os.path.abspath(sys.argv[2])
HERE = os.path.dirname(os.path.abspath(__file__))
MAKE_REPORT = os.path.join(HERE, "..", "report", "make_report.py")
CHEAP = ["--case", "bar", "--row", "1", "--nx", "8", "--ny", "8"]  # a bar that solves in milliseconds

failures = []
passed = 0
table = []  # (case, exit, stderr line, seconds)
OUTSIDE = tempfile.mkdtemp(prefix="thinlayer-outside-")  # where a hostile script aims its writes
TMP = tempfile.mkdtemp(prefix="thinlayer-tmpdir-")      # the runs' $TMPDIR: the staging folders go there
ENV = dict(os.environ, TMPDIR=TMP)
# Under an address-space limit (the memory cases), one BLAS and one OpenMP thread: OpenBLAS spins
# for ever on an allocation that fails (docs/security.md, "The box"); it is no part of what is tested here.
LIMITED_ENV = dict(ENV, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")


def check(name, ok, detail=""):
    global passed
    if ok:
        passed += 1
    else:
        failures.append(f"{name}: {detail}")
        print(f"FAIL {name}: {detail}")


def run(argv, folder, timeout=300, limit_memory=None):
    """argv in its own session, $TMPDIR private; with `limit_memory`, under that address-space limit.
    A run past `timeout` is killed (its whole session) and reported as exit None."""
    import resource
    preexec = None
    if limit_memory is not None:
        preexec = lambda: resource.setrlimit(resource.RLIMIT_AS, (limit_memory, limit_memory))  # noqa: E731
    try:
        return run_in_session(argv, folder, timeout, env=ENV if limit_memory is None else LIMITED_ENV, preexec=preexec)
    except subprocess.TimeoutExpired:
        for pid in session_processes_of(argv):
            os.kill(pid, signal.SIGKILL)
        return subprocess.CompletedProcess(argv, None, "", f"(killed after {timeout} s)"), []


def session_processes_of(argv):
    """The processes running `argv` (a run that outlived its timeout)."""
    found = []
    for pid in os.listdir("/proc"):
        if pid.isdigit():
            try:
                with open(f"/proc/{pid}/cmdline", "rb") as c:
                    if c.read().split(b"\0")[:len(argv)] == [a.encode() for a in argv]:
                        found.append(int(pid))
            except OSError:
                pass
    return found


def run_during(argv, folder, timeout, env, during, ready=None):
    """argv in its own session; `during()` is called once `ready()` holds (by default: the run has
    begun meshing, its staging folder is in $TMPDIR), or at once if it never does within 30 s."""
    ready = ready or (lambda: os.listdir(TMP))
    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        p = subprocess.Popen(argv, cwd=folder, stdout=out, stderr=err, text=True, start_new_session=True, env=env)
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline and p.poll() is None and not ready():
            time.sleep(0.01)
        during()
        try:
            p.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()
        time.sleep(0.05)
        out.seek(0), err.seek(0)
        return subprocess.CompletedProcess(argv, p.returncode, out.read(), err.read()), session_processes(p.pid)


def one_line_text(text):
    """No control character but the newlines that end its lines (SPEC §4: messages are escaped)."""
    return all(c == "\n" or (" " <= c and c != "\x7f" and not "\x80" <= c <= "\x9f") for c in text)


def case(name, args, status, words, folder, seconds, changes=(), report=False, limit_memory=None, lines=1, env=None,
         during=None, ready=None, absent=None):
    """One case: exit `status`, `lines` line(s) on stderr (the first holding `words`), no control
    character in them, within `seconds`, the folder as before but for the entries named in `changes`,
    nothing outside, nothing left; with `during`, that is done once the run meshes; `absent`: a
    string found nowhere in what the run printed."""
    before, outside = snapshot(folder), snapshot(OUTSIDE)
    argv = [sys.executable, MAKE_REPORT, *args] if report else [THINLAYER, *args]
    start = time.monotonic()
    if during:
        r, survivors = run_during(argv, folder, max(2 * seconds, 30), env or ENV, during, ready)
    elif env:
        try:
            r, survivors = run_in_session(argv, folder, max(2 * seconds, 30), env=env)
        except subprocess.TimeoutExpired:
            r, survivors = subprocess.CompletedProcess(argv, None, "", "(killed)"), []
    else:
        r, survivors = run(argv, folder, timeout=max(2 * seconds, 30), limit_memory=limit_memory)
    took = time.monotonic() - start
    got = r.stderr.strip().splitlines()
    line = got[0] if got else ""
    check(name, one_line_text(r.stderr), f"a control character on stderr: {r.stderr[-500:]!r}")
    if absent:
        check(name, absent not in r.stderr and absent not in r.stdout, f"{absent!r} was printed")
    check(name, r.returncode == status, f"exit {r.returncode}, expected {status}; stderr {r.stderr[-2000:]!r}")
    check(name, len(got) == lines, f"{len(got)} lines on stderr, expected {lines}: {r.stderr[-2000:]!r}")
    check(name, words in line, f"{words!r} not in {line!r}")
    check(name, took < seconds, f"{took:.1f} s, the bound is {seconds} s")
    after = snapshot(folder)
    changed = {k for k in set(before) | set(after) if before.get(k) != after.get(k)}
    check(name, changed <= set(changes), f"the folder changed: {sorted(changed - set(changes))}")
    check(name, snapshot(OUTSIDE) == outside, "a file appeared outside the folder")
    check(name, not os.listdir(TMP), f"left in $TMPDIR: {os.listdir(TMP)}")
    check(name, not survivors, f"processes {survivors} outlived the run")
    table.append((name, r.returncode, line, took))
    print(f"case {name}: exit {r.returncode}, {took:.2f} s, {line!r}")
    for leftover in os.listdir(TMP):
        shutil.rmtree(os.path.join(TMP, leftover), ignore_errors=True)
    return r


TWO_QUADS = {"name": "q", "bodies": {"a": {"group": "a", "lambda": 4500, "mu": 5400},
                                      "b": {"group": "b", "lambda": 4500, "mu": 5400}},
             "interface": {"group": "bond", "plus": "b", "minus": "a", "friction": 0.5,
                           "layer": {"gamma": 1, "delta": 1, "lambda_g": 4500, "mu_g": 5400}},
             "supports": [{"group": "bottom", "u": [0, 0]}, {"group": "top", "u": [0.001, -0.001]}]}


class Scene:
    """A scene folder: the lap joint, the user's notes and an earlier result."""

    def __init__(self):
        self.folder = tempfile.mkdtemp(prefix="thinlayer-untrusted-")
        self.lap = json.load(open(os.path.join(LAP, "lap_joint.json")))
        self.geo = open(os.path.join(LAP, "lap_joint.geo")).read()
        self.write("lap_joint.geo", self.geo)
        self.write("lap_joint.json", self.lap)
        self.write("notes.txt", "the user's notes\n")
        r = subprocess.run([THINLAYER, "solve", *CHEAP, "--out", "previous.h5"], cwd=self.folder, capture_output=True)
        assert r.returncode == 0, r.stderr

    def path(self, name):
        return os.path.join(self.folder, name)

    def write(self, name, content, binary=False):
        os.makedirs(os.path.dirname(self.path(name)), exist_ok=True)
        if isinstance(content, (dict, list)):
            content = json.dumps(content, indent=1)
        with open(self.path(name), "wb" if binary else "w") as f:
            f.write(content)
        return name

    def with_geo(self, name, first=None, last=None, **changes):
        """name.geo: the lap joint's .geo with a first and a last line; name.json naming it."""
        self.write(name + ".geo", (first + "\n" if first else "") + self.geo + ("\n" + last + "\n" if last else ""))
        scene = json.loads(json.dumps(self.lap))
        scene["geometry"] = name + ".geo"
        scene.update(changes)
        return self.write(name + ".json", scene)

    def with_json(self, name, change):
        scene = json.loads(json.dumps(self.lap))
        change(scene)
        return self.write(name + ".json", scene)


def outside(name):
    return os.path.join(OUTSIDE, name)


def unscanned_routes(s):
    """Statements that reached gmsh unscanned: each route is now read, checked and refused."""
    f = s.folder
    script = f'Sleep 1e7;\nSystem "touch {outside("pwned")}";\n'
    s.write("script.msh", script)
    scene = dict(TWO_QUADS, mesh="script.msh")
    case("mesh: a .msh holding script text", ["solve", "--scene", s.write("script_msh.json", scene), "--out", "r.h5"], 2,
         "script.msh:1: a mesh file that does not begin with $MeshFormat", f, 10)
    case("mesh: a .msh holding script text, study --out", ["study", "validity", "--scene", "script_msh.json", "--out", "D"], 2,
         "script.msh:1: a mesh file that does not begin with $MeshFormat", f, 10)
    case("Merge of a .msh holding script text",
         ["solve", "--scene", s.with_geo("merge_msh", last='Merge "script.msh";'), "--out", "r.h5"], 2,
         "script.msh:1: a mesh file that does not begin with $MeshFormat", f, 10)
    for ext in (".Msh", ".xao", ".inp", ".Step", ".msh.gz", ".pos"):
        s.write("data" + ext, "$MeshFormat\n" + script)
        case(f"Merge of a '{ext}' file", ["solve", "--scene", s.with_geo("merge" + ext.replace(".", "_"),
             last=f'Merge "data{ext}";'), "--out", "r.h5"], 2, f"the extension '{ext[ext.rfind('.'):]}'", f, 10)
    # gmsh merges NAME.geo.opt unasked; thinlayer stages the .geo alone, so it is never read.
    s.with_geo("with_opt")
    s.write("with_opt.geo.opt", f'Sleep 1e7;\nSystem "touch {outside("pwned_opt")}";\n')
    case("a .geo.opt beside the .geo: not read", ["solve", "--scene", "with_opt.json", "--mesh-timeout", "60"], 0, "", f,
         30, lines=0)
    case("a NUL byte in a // comment", ["solve", "--scene", s.with_geo("nul", first="// a comment\0 Sleep 1e7;")], 2,
         "nul.geo:1: a NUL byte", f, 10)
    s.write("sub/inc.geo", "x = 1;\n")
    s.write("sub\\inc.geo", f'System "touch {outside("pwned_backslash")}";\n')
    case("a backslash in an Include", ["solve", "--scene", s.with_geo("backslash", last='Include "sub\\inc.geo";')], 2,
         "holding a backslash", f, 10)
    s.write("loop_b.geo", 'Include "loop_a.geo";\n')
    s.with_geo("loop_a", last='Include "loop_b.geo";')
    case("an include loop", ["solve", "--scene", "loop_a.json"], 2, "an include loop", f, 10)
    case("a .geo that includes itself", ["solve", "--scene", s.with_geo("self", last='Include "self.geo";')], 2,
         "an include loop", f, 10)
    case("a string gmsh would cut at 1023 bytes",
         ["solve", "--scene", s.with_geo("long_string", first='s = "' + "a" * 1100 + 'Sleep 1e7;";')], 2,
         "long_string.geo:1: a string of 1110 bytes: gmsh reads at most 1023", f, 10)
    case("a keyword right after a number (1e5Sleep)", ["solve", "--scene", s.with_geo("number_keyword", first="x = 1e5Sleep 1e7;")],
         2, "number_keyword.geo:1: 'Sleep' stalls the run", f, 10)
    case("an Include of an absolute name", ["solve", "--scene", s.with_geo("absolute", last='Include "/etc/hostname";')], 2,
         "an absolute file name", f, 10)
    with open(outside("elsewhere.geo"), "w") as e:
        e.write("x = 1;\n")
    os.symlink(outside("elsewhere.geo"), s.path("elsewhere_link.geo"))
    case("an Include of a link leading out of the folder",
         ["solve", "--scene", s.with_geo("link_out", last='Include "elsewhere_link.geo";')], 2,
         "a link to a file outside the scene's folder", f, 10)
    case("a ListFromFile outside the folder",
         ["solve", "--scene", s.with_geo("list_out", last='v() = ListFromFile("../x.txt");')], 2,
         "a file outside the scene's folder", f, 10)
    case("a geometry outside the scene's folder",
         ["solve", "--scene", s.with_json("geometry_out", lambda j: j.update(geometry="../lap_joint.geo"))], 2,
         "a file outside the scene's folder", f, 10)


def hangs(s):
    """What hung: a FIFO read by the scan or by gmsh, a Sleep or a loop that uses no CPU limit."""
    f = s.folder
    os.mkfifo(s.path("fifo.geo"))
    os.mkfifo(s.path("fifo.msh"))
    case("a FIFO in an Include", ["solve", "--scene", s.with_geo("fifo_include", last='Include "fifo.geo";')], 2,
         "fifo.geo is a FIFO", f, 10)
    case("a FIFO merged", ["solve", "--scene", s.with_geo("fifo_merge", last='Merge "fifo.msh";')], 2, "fifo.msh is a FIFO",
         f, 10)
    case("a FIFO as the scene's mesh", ["solve", "--scene", s.write("fifo_mesh.json", dict(TWO_QUADS, mesh="fifo.msh"))], 2,
         "fifo.msh is a FIFO", f, 10)
    os.mkfifo(s.path("fifo.json"))
    case("a FIFO as the scene file", ["solve", "--scene", "fifo.json"], 2, "is not a regular file", f, 10)
    loop = s.with_geo("loop", first="For i In {1:2000000000}\nEndFor")
    case("a loop the scan lets through: the clock", ["solve", "--scene", loop, "--mesh-timeout", "2", "--out", "r.h5"], 2,
         "loop.geo: gmsh did not finish within the wall-clock limit of 2 s (--mesh-timeout) while reading the geometry", f, 20)
    case("the clock, study --out NEW", ["study", "validity", "--scene", loop, "--mesh-timeout", "2", "--out", "NEW"], 2,
         "wall-clock limit of 2 s", f, 20)
    case("--mesh-timeout 0", ["solve", "--scene", "lap_joint.json", "--mesh-timeout", "0"], 2,
         "--mesh-timeout must be in (0, 1e6] seconds", f, 10)
    case("--mesh-timeout on the bar", ["solve", *CHEAP, "--mesh-timeout", "5"], 2,
         "--mesh-timeout applies to a scene file (--scene) only", f, 10)


def damaged(source, seed, count=8):
    """`source`'s bytes with `count` bytes changed at random (seeded) places."""
    data = bytearray(open(source, "rb").read())
    rng = random.Random(seed)
    for _ in range(count):
        data[rng.randrange(len(data))] = rng.randrange(256)
    return bytes(data)


def untrusted_files(s):
    """Existing outputs and results files are never parsed where a crash would be a signal."""
    f = s.folder
    good = s.path("previous.h5")
    marker_broken = bytearray(open(good, "rb").read())
    marker_broken[3] ^= 0xFF
    s.write("marker_broken.h5", bytes(marker_broken), binary=True)
    case("--out onto a results file whose marker is damaged", ["solve", *CHEAP, "--out", "marker_broken.h5"], 2,
         "it exists and is not a thinlayer results file", f, 10)
    os.makedirs(s.path("DAMAGED"), exist_ok=True)
    s.write("DAMAGED/results.h5", bytes(marker_broken), binary=True)
    case("study --out DIR holding a damaged results.h5", ["study", "thresholds", "--out", "DAMAGED"], 2,
         "is not a thinlayer results file", f, 10)
    for seed in range(4):
        name = f"damaged_{seed}.h5"
        data = damaged(good, seed)
        s.write(name, data, binary=True)
        ours = data.startswith(b"thinlayer-results\n")
        case(f"--out onto a damaged results file (seed {seed})", ["solve", *CHEAP, "--out", name], 0 if ours else 2,
             "" if ours else "not a thinlayer results file", f, 10, changes={name} if ours else (), lines=0 if ours else 1)
    for seed in range(2):
        name = f"report_damaged_{seed}.h5"
        s.write(name, damaged(good, 100 + seed, 64), binary=True)
        before = snapshot(f)
        start = time.monotonic()
        r, survivors = run([sys.executable, MAKE_REPORT, name, f"out_{seed}", "--time-limit", "60"], f)
        took = time.monotonic() - start
        lines = r.stderr.strip().splitlines()
        label = f"report on a damaged results file (seed {100 + seed})"
        check(label, r.returncode in (0, 2), f"exit {r.returncode}: {r.stderr[-1000:]!r}")
        check(label, r.returncode == 0 or (len(lines) == 1 and lines[0].startswith("make_report: ")), repr(r.stderr[-1000:]))
        check(label, not survivors, str(survivors))
        if r.returncode != 0:
            check(label, snapshot(f) == before, "the folder changed")
        table.append((label, r.returncode, lines[0] if lines else "", took))
        print(f"case {label}: exit {r.returncode}, {took:.2f} s")
        shutil.rmtree(s.path(f"out_{seed}"), ignore_errors=True)
    # The report's clock: a report cannot finish in 0.5 s (matplotlib alone takes longer); what it
    # built is removed, the folder it would have made too.
    case("report past its --time-limit", ["previous.h5", "slow_report", "--time-limit", "0.5"], 2,
         "the report did not finish within 0.5 s (--time-limit)", f, 30, report=True)
    crash = os.path.join(HERE, "data", "h5_crashes_hdf5.h5")
    if os.path.exists(crash):
        shutil.copy(crash, s.path("crashes.h5"))
        case("report on a results file that crashes HDF5", ["crashes.h5", "crash_report"], 2,
             "reading it crashed the report (SIG", f, 60, report=True)


def outputs(s):
    """Outputs distinct after every link, dangling ones too, --force or not; no empty folder left."""
    f = s.folder
    os.makedirs(s.path("O"))
    os.symlink("same.x", s.path("O/ln"))  # dangling
    case("--out O/same.x --vtu O/ln (ln -> same.x, dangling)", ["solve", *CHEAP, "--out", "O/same.x", "--vtu", "O/ln"], 2,
         "--out and --vtu name the same file", f, 10)
    case("the same, --force", ["solve", *CHEAP, "--out", "O/same.x", "--vtu", "O/ln", "--force"], 2,
         "--out and --vtu name the same file", f, 10)
    case("the same, a scene", ["solve", "--scene", "lap_joint.json", "--out", "O/same.x", "--vtu", "O/ln"], 2,
         "--out and --vtu name the same file", f, 10)
    s.write("leaf.geo", "y = 2;\n")
    case("--out --force onto a file the geometry includes",
         ["solve", "--scene", s.with_geo("include_leaf", last='Include "leaf.geo";'), "--out", "leaf.geo", "--force"], 2,
         "it is a file its geometry reads (leaf.geo), an input of this run", f, 10)
    os.symlink("previous.h5", s.path("to_previous.vtu"))
    case("--vtu a link to the --out file", ["solve", *CHEAP, "--out", "previous.h5", "--vtu", "to_previous.vtu"], 2,
         "name the same file", f, 10)
    os.makedirs(s.path("S"))
    os.symlink("results.h5", s.path("S/bondline_fields.csv"))  # dangling
    case("study --out DIR whose bondline_fields.csv is a link to results.h5",
         ["study", "validity", "--scene", "lap_joint.json", "--out", "S"], 2,
         "results.h5 and bondline_fields.csv name the same file", f, 10)
    os.makedirs(s.path("V"))
    os.symlink("results.h5", s.path("V/summary.json"))  # dangling
    case("verify --out DIR whose summary.json is a link to results.h5", ["verify", "--out", "V"], 2,
         "results.h5 and summary.json name the same file", f, 10)
    for signum in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP):
        new = s.path("NEW")
        p = subprocess.Popen([THINLAYER, "study", "table3", "--quick", "--quiet", "--out", "NEW"], cwd=f, env=ENV,
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline and not os.path.isdir(new):
            time.sleep(0.005)
        check(f"{signum.name} as study creates its folder", os.path.isdir(new), "the folder never appeared")
        p.send_signal(signum)
        status = p.wait(timeout=60)
        label = f"{signum.name} in the first moments of study --out NEW"
        check(label, status == -signum, f"status {status}")
        check(label, not os.path.lexists(new), "the empty output folder was left")
        table.append((label, status, "(killed)", 0.0))
        print(f"case {label}: status {status}, NEW {'left' if os.path.lexists(new) else 'removed'}")
        shutil.rmtree(new, ignore_errors=True)
    slow = s.with_geo("slow", first="For i In {1:2000000000}\nEndFor")
    p = subprocess.Popen([THINLAYER, "study", "validity", "--scene", slow, "--out", "NEW"], cwd=f, env=ENV,
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline and (len(session_processes(p.pid)) < 2 or not os.listdir(TMP)):
        time.sleep(0.02)  # the meshing child and its staging folder (not the report folder's check)
    check("SIGTERM while meshing", len(session_processes(p.pid)) >= 2 and os.listdir(TMP), "no meshing child, no staging")
    p.send_signal(signal.SIGTERM)
    status = p.wait(timeout=30)
    time.sleep(0.1)
    check("SIGTERM while meshing", status == -signal.SIGTERM, f"status {status}")
    check("SIGTERM while meshing: nothing left", not os.path.lexists(s.path("NEW")) and not os.listdir(TMP) and
          not session_processes(p.pid), f"{os.listdir(TMP)} {session_processes(p.pid)}")
    table.append(("SIGTERM while gmsh meshes a study's scene", status, "(killed)", 0.0))
    print("case SIGTERM while meshing: the folder, the staging folder and the child gone")


def csv_cell(s):
    """A group named like a spreadsheet formula, with a comma: quoted and neutralised (RFC 4180)."""
    import csv
    group = "=HYPERLINK(1),x"
    geo = s.geo.replace('Physical Curve("bondline")', f'Physical Curve("{group}")')
    s.write("formula.geo", geo)
    scene = json.loads(json.dumps(s.lap))
    scene.update(geometry="formula.geo", mesh_size={"interface": 2, "far": 4}, eps=[0.01, 0.005, 0.0025])
    scene["interface"]["group"] = group
    s.write("formula.json", scene)
    start = time.monotonic()
    r, survivors = run([THINLAYER, "study", "convergence", "--scene", "formula.json", "--out", "CSV", "--quiet"], s.folder)
    took = time.monotonic() - start
    check("a formula as a group name", r.returncode in (0, 1) and not survivors, r.stderr[-2000:])
    path = s.path("CSV/bondline_fields.csv")
    if os.path.exists(path):
        with open(path, newline="") as c:
            rows = [row for row in csv.reader(line for line in c if not line.startswith("#"))]
        header, data = rows[0], rows[1:]
        check("a formula as a group name: 14 fields per row", data and all(len(row) == len(header) == 14 for row in data),
              f"{len(header)} headers, rows of {sorted({len(row) for row in data})} fields")
        check("a formula as a group name: neutralised", data and all(row[4] == "'" + group for row in data),
              f"bondline cells {sorted({row[4] for row in data})}")
    else:
        check("a formula as a group name: the CSV", False, "no CSV written")
    table.append(("a group named '=HYPERLINK(1),x' in bondline_fields.csv", r.returncode, "(14 fields, \"'=HYPERLINK(1),x\")",
                  took))
    print(f"case a formula as a group name: exit {r.returncode}, {took:.1f} s")
    shutil.rmtree(s.path("CSV"), ignore_errors=True)


def bounds(s):
    f = s.folder
    case("a 15 MB JSON key", ["solve", "--scene", s.write("key.json", '{"' + "k" * 15_000_000 + '": [1, 2, 3]}')], 2,
         "key.json:1:2: a key of 15000000 bytes", f, 20)
    case("a 15 M-letter scene name", ["solve", "--scene", s.with_json("long_name", lambda j: j.update(name="n" * 15_000_000))],
         2, "'name' in the scene is 15000000 bytes long; a name is at most 64", f, 20)
    s.write("semicolons.geo", ";" * (8 << 20))
    case("an 8 MB .geo of ';'", ["solve", "--scene", s.with_json("semicolons", lambda j: j.update(geometry="semicolons.geo"))],
         2, "larger than 4 MiB", f, 20)
    for big in ("key.json", "long_name.json", "semicolons.geo"):  # the later cases' snapshots need not read them
        os.remove(s.path(big))
    # A square in no body, meshed all the same: counted by the estimate.
    s.with_geo("extra_surface", last="Point(101) = {0, 10, 0}; Point(102) = {20, 10, 0}; Point(103) = {20, 30, 0};\n"
               "Point(104) = {0, 30, 0}; Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104};\n"
               "Line(104) = {104, 101}; Curve Loop(101) = {101, 102, 103, 104}; Plane Surface(101) = {101};",
               mesh_size={"interface": 0.5, "far": 0.5})
    case("a surface in no body, --max-nodes 3000", ["solve", "--scene", "extra_surface.json", "--max-nodes", "3000"], 2,
         "above the limit of 3000 (--max-nodes)", f, 20)
    no_size = {k: v for k, v in s.lap.items() if k != "mesh_size"}
    s.write("transfinite.geo", s.geo + "\nTransfinite Curve{1} = 1e8;\n")
    s.write("transfinite.json", dict(no_size, geometry="transfinite.geo"))
    case("Transfinite Curve{1} = 1e8 without mesh_size", ["solve", "--scene", "transfinite.json"], 2,
         "transfinite.geo: estimating the mesh's size took more than 512 MiB", f, 90)
    s.write("factor.geo", s.geo + "\nMesh.MeshSizeFactor = 1e-7;\n")
    s.write("factor.json", dict(no_size, geometry="factor.geo"))
    case("Mesh.MeshSizeFactor = 1e-7 without mesh_size", ["solve", "--scene", "factor.json"], 2,
         "(--max-nodes)", f, 60)


def memory(s):
    """Out of memory anywhere: exit 2, one line naming the phase (under an address-space limit set
    as `ulimit -v` would). One BLAS thread: OpenBLAS retries a failed allocation for ever (README)."""
    f = s.folder
    fine = s.with_json("fine", lambda j: j.update(mesh_size={"interface": 0.01, "far": 0.01}))
    case("out of memory while meshing (an inherited limit)", ["solve", "--scene", fine, "--max-nodes", "50000000"], 2,
         "gmsh ran out of its memory limit (0.39 GiB, the limit this process inherited (ulimit -v)) while meshing", f, 60,
         limit_memory=400 << 20)
    band = s.with_json("band", lambda j: j.update(mesh_size={"interface": 0.004, "far": 2}))
    case("out of memory while solving", ["solve", "--scene", band, "--out", "r.h5"], 2,
         "out of memory while solving the limit mode of band.json (std::bad_alloc)", f, 60, limit_memory=700 << 20)


def messages(s):
    """Every message names its file (and line): a mesh's nodes, a material near its bounds."""
    f = s.folder
    for label, first, words in (("a NaN node", ("nan", "0"), "has a coordinate that is not a finite number"),
                                ("a node at infinity", ("inf", "0"), "has a coordinate that is not a finite number"),
                                ("a node at 1e300", ("1e300", "0"), "lies beyond 1e9 mm of the origin")):
        name = label.replace(" ", "_")
        s.write(name + ".msh", msh(first_node=first))
        case(f".msh: {label}", ["solve", "--scene", s.write(name + ".json", dict(TWO_QUADS, mesh=name + ".msh"))], 2,
             f"{name}.msh: node 1 at (", f, 10)
        check(f".msh: {label}: said", words in table[-1][2], table[-1][2])
    # A damaged .msh is read by gmsh in the child: what it does there is a message.
    s.write("huge_count.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 999999999999 1 999999999999\n"
            "1 1 0 999999999999\n1\n")
    case("a .msh announcing 1e12 nodes", ["solve", "--scene", s.write("huge_count.json", dict(TWO_QUADS, mesh="huge_count.msh"))],
         2, "huge_count.msh: gmsh ran out of its memory limit (8 GiB) while reading the mesh", f, 30)
    s.write("tilted.msh", msh(z=0.5))
    case("a .msh with z != 0", ["solve", "--scene", s.write("tilted.json", dict(TWO_QUADS, mesh="tilted.msh"))], 2,
         "tilted.msh: node 1 at (0, 0, 0.5) is off the plane z = 0", f, 10)
    s.write("off_plane.geo", s.geo.replace("Point(1) = {0, 0, 0, h};", "Point(1) = {0, 0, 0.5, h};"))
    case("a .geo with a point off z = 0", ["solve", "--scene", s.with_json("off_plane", lambda j: j.update(
         geometry="off_plane.geo"))], 2, "is off the plane z = 0", f, 60)
    nu = "-0.9999999999999999"
    s.write("nu_body.json", json.dumps(s.lap).replace('"lambda": 5108, "mu": 2632}', '"E": 70000, "nu": ' + nu + "}", 1))
    case("a body with nu = -0.9999999999999999", ["solve", "--scene", "nu_body.json"], 2,
         "nu_body.json:1:", f, 10)
    check("nu: said", "(nu too close to -1 or 0.5)" in table[-1][2], table[-1][2])
    glue = json.loads(json.dumps(s.lap))
    glue["interface"].pop("layer")
    glue["interface"]["glue"] = {"E": 3000, "nu": float(nu), "thickness": 0.2}
    s.write("nu_glue.json", json.dumps(glue).replace(repr(float(nu)), nu))
    case("a glue with nu = -0.9999999999999999", ["solve", "--scene", "nu_glue.json"], 2,
         "the glue: E and nu give", f, 10)


# ---- Issue 43: what gmsh reads is what was scanned; no environment; the report reads one file ----

SLOW = "For i In {1:300000}\nEndFor"  # a geometry whose reading takes a fraction of a second, once per mesh
SLOWER = "For i In {1:600000}\nEndFor"  # about 0.5 s to read on this machine idle, 1.6 s loaded


def side_files(s):
    """Staged means scanned: gmsh merges F.opt after every file F it merges (Common/OpenFile.cpp); no
    file of a scene may end in .opt, whatever names it, and a list is scanned like a script."""
    f = s.folder
    s.write("side.geo.opt", f'Sleep 6;\nSystem "touch {outside("pwned_side")}";\n')
    case("ListFromFile of the .geo's own .opt, in If (0)",
         ["solve", "--scene", s.with_geo("side", first='If (0) v() = ListFromFile("side.geo.opt"); EndIf')], 2,
         "side.geo:1: 'ListFromFile' of \"side.geo.opt\": a file named '*.opt'", f, 10)
    s.write("part.geo.opt", "x = 1;\n")
    case("Include of a .opt", ["solve", "--scene", s.with_geo("inc_opt", last='Include "part.geo.opt";')], 2,
         "no file of a scene may end in .opt", f, 10)
    s.write("mesh.msh.opt", "Sleep 6;\n")
    case("Merge of a .msh's .opt", ["solve", "--scene", s.with_geo("merge_opt", last='Merge "mesh.msh.opt";')], 2,
         "no file of a scene may end in .opt", f, 10)
    s.write("shape.step.opt", "ISO-10303-21;\n")
    case("ShapeFromFile of a .opt", ["solve", "--scene", s.with_geo("shape_opt", first='SetFactory("OpenCASCADE");',
         last='v() = ShapeFromFile("shape.step.opt");')], 2, "no file of a scene may end in .opt", f, 10)
    s.write("chain.geo.opt.opt", "Sleep 6;\n")
    case("ListFromFile of a .opt's .opt", ["solve", "--scene", s.with_geo("chain", last='v() = ListFromFile("chain.geo.opt.opt");')],
         2, "no file of a scene may end in .opt", f, 10)
    s.write("own.geo.opt", s.geo)
    case("a geometry named *.opt", ["solve", "--scene", s.with_json("own_opt", lambda j: j.update(geometry="own.geo.opt"))], 2,
         "'geometry' must name a gmsh .geo file, got ./own.geo.opt", f, 10)  # before scene_sources' own refusal
    s.write("sleepy.txt", "1 2 3\nSleep 6;\n")
    case("a ListFromFile list holding Sleep", ["solve", "--scene", s.with_geo("sleepy_list", last='v() = ListFromFile("sleepy.txt");')],
         2, "sleepy.txt:2: 'Sleep' stalls the run", f, 10)
    s.write("numbers.txt", "1 2 3.5\n4e-1\n")
    case("a ListFromFile list of numbers (the control)",
         ["solve", "--scene", s.with_geo("number_list", last='v() = ListFromFile("numbers.txt");')], 0, "", f, 60, lines=0)


def machine(s):
    """The scene sees no environment and probes nothing: refused by the scan, before gmsh runs."""
    f = s.folder
    env = dict(ENV, TOKEN="s3cret-token-43")
    case("GetEnv(TOKEN) in an Error, TOKEN set", ["solve", "--scene", s.with_geo("getenv", first='Error(StrCat("x=", GetEnv("TOKEN")));')],
         2, "getenv.geo:1: 'GetEnv' reads the user's environment", f, 10, env=env, absent="s3cret-token-43")
    case("GetEnv in a coordinate", ["solve", "--scene", s.with_geo("getenv_x", last='Point(200) = {StrLen(GetEnv("TOKEN")), 0, 0};'),
         "--out", "r.h5"], 2, "'GetEnv' reads the user's environment", f, 10, env=env, absent="s3cret-token-43")
    for word, statement, why in (
            ("FileExists", 'If (FileExists("/etc/hostname")) Error("seen"); EndIf', "probes the file system"),
            ("AbsolutePath", 's = AbsolutePath("lap_joint.geo");', "works on where files lie"),
            ("CurrentDir", 'Printf(StrCat("in ", CurrentDir));', "works on where files lie"),
            ("DirName", 's = DirName("/etc/passwd");', "works on where files lie"),
            ("TotalMemory", "x = TotalMemory;", "reads the machine's clock or memory"),
            ("Today", "s = Today;", "reads the machine's clock or memory"),
            ("GetValue", 'x = GetValue("x?", 1);', "asks the terminal")):
        case(f"{word} in a .geo", ["solve", "--scene", s.with_geo("machine_" + word, first=statement)], 2,
             f"machine_{word}.geo:1: '{word}' {why}", f, 10)


def report_one_file(s):
    """The report opens the one file it is given: external links, external storage and virtual
    datasets refused before anything is read (crafted with h5py)."""
    f = s.folder
    good = s.path("previous.h5")

    def crafted(name, change):
        shutil.copy(good, s.path(name))
        with h5py.File(s.path(name), "a") as h:
            change(h)
        return name

    with h5py.File(outside("other.h5"), "w") as o:
        o["got"] = [b"a secret of another file"]
        o["nums"] = [1.0, 2.0, 3.0, 4.0]
    kinds = (
        ("external storage (/environment/x in /etc/passwd)", "ext_storage.h5",
         lambda h: h.create_dataset("environment/x", shape=(64,), dtype="u1", external=[("/etc/passwd", 0, 64)]),
         "/environment/x keeps its values in another file ('/etc/passwd', external storage)"),
        ("an external link", "ext_link.h5",
         lambda h: h.__setitem__("environment/other", h5py.ExternalLink(outside("other.h5"), "/got")),
         "/environment/other is an external link to"),
        ("an external link five groups down", "ext_deep.h5",
         lambda h: h.__setitem__("environment/a/b/c/d/e", h5py.ExternalLink(outside("other.h5"), "/got")),
         "/environment/a/b/c/d/e is an external link"),
        ("a virtual dataset", "virtual.h5", lambda h: h.create_virtual_dataset(
            "environment/v", vds_layout(outside("other.h5"))), "/environment/v is a virtual dataset"),
        ("a virtual dataset of this very file", "virtual_self.h5", lambda h: h.create_virtual_dataset(
            "environment/v", vds_layout(".")), "/environment/v is a virtual dataset"),
        ("a hard link back to the root, then an external link", "cycle.h5",
         lambda h: (h.__setitem__("environment/root", h["/"]),
                    h.__setitem__("environment/zz", h5py.ExternalLink(outside("other.h5"), "/got"))),
         "/environment/zz is an external link"),
    )
    for label, name, change, words in kinds:
        crafted(name, change)
        case(f"report: {label}", [name, "rep_" + name, "--time-limit", "60"], 2, f"make_report: {name}: ", f, 30,
             report=True, absent="secret of another file")
        check(f"report: {label}: said", words in table[-1][2], table[-1][2])
    crafted("soft_link.h5", lambda h: h.__setitem__("environment/alias", h5py.SoftLink("/checks")))
    elsewhere = tempfile.mkdtemp(prefix="thinlayer-report-")
    case("report: a soft link inside the file (the control)", ["soft_link.h5", os.path.join(elsewhere, "r"), "--time-limit",
         "120"], 0, "", f, 120, report=True, lines=0)
    check("report: a soft link: written", os.path.exists(os.path.join(elsewhere, "r", "index.html")), "no index.html")
    shutil.rmtree(elsewhere, ignore_errors=True)


def vds_layout(source):
    layout = h5py.VirtualLayout(shape=(4,), dtype="f8")
    layout[:] = h5py.VirtualSource(source, "nums" if source != "." else "/checks/pass", shape=(4,))
    return layout


def write_time(s):
    """Outputs judged again when they are written: a file the user saves at an output's path while
    the run works is kept, the run exits 2 saying so (studies, validity-map and solve --vtu alike)."""
    f = s.folder
    slow = s.with_geo("slow_w", first=SLOW)
    users = b"the user's own file, saved during the run\n"

    def save(*names):
        def write():
            for name in names:
                os.makedirs(os.path.dirname(s.path(name)) or f, exist_ok=True)
                with open(s.path(name), "wb") as u:
                    u.write(users)
        return write

    def kept(label, *names):
        for name in names:
            with open(s.path(name), "rb") as u:
                check(f"{label}: {name} kept", u.read() == users, "replaced")

    label = "solve --vtu: the .vtu saved during the run"
    case(label, ["solve", "--scene", slow, "--vtu", "w.vtu"], 2, "cannot write 'w.vtu': it exists and is not", f, 60,
         changes={"w.vtu"}, during=save("w.vtu"))
    kept(label, "w.vtu")
    label = "study --scene: DIR/results.h5 saved during the run"
    # Saved once the study has opened its results file (W1 made), so judged at the commit.
    case(label, ["study", "validity", "--scene", slow, "--out", "W1", "--quiet", "--eps", "0.1,0.05,0.02"], 2,
         "cannot write 'W1/results.h5'", f, 120, changes={"W1", "W1/results.h5"},
         during=save("W1/results.h5"), ready=lambda: os.path.isdir(s.path("W1")) and time.sleep(0.3) is None)
    kept(label, "W1/results.h5")
    label = "study --scene: DIR/bondline_fields.csv saved during the run"
    case(label, ["study", "convergence", "--scene", slow, "--out", "W2", "--quiet", "--eps", "0.1,0.05,0.02"], 2,
         "cannot write 'W2/bondline_fields.csv': it exists and is not a CSV file thinlayer wrote", f, 120,
         changes={"W2", "W2/bondline_fields.csv"}, during=save("W2/bondline_fields.csv"))
    kept(label, "W2/bondline_fields.csv")
    label = "validity-map: its CSV saved during the run"
    case(label, ["study", "validity-map", "--scene", slow, "--out", "W3", "--quiet", "--thickness-ratios", "1e-2",
                 "--modulus-ratios", "1e-1", "--poisson", "0.45"], 2,
         "cannot write 'W3/validity_map_lap-joint.csv'", f, 180, changes={"W3", "W3/validity_map_lap-joint.csv"},
         during=save("W3/validity_map_lap-joint.csv"))
    kept(label, "W3/validity_map_lap-joint.csv")
    for name in ("W1", "W2", "W3", "w.vtu"):
        shutil.rmtree(s.path(name), ignore_errors=True) if os.path.isdir(s.path(name)) else os.remove(s.path(name))


def report_folder(s):
    """The report's folder is checked before the work: a folder it would refuse costs seconds, not
    the study; a report refused after all the same is exit 2 naming the files kept."""
    f = s.folder
    s.write("R1/report/index.html", "<html>the user's page</html>\n")
    case("study --scene: DIR/report/index.html the user's", ["study", "validity", "--scene", "lap_joint.json", "--out", "R1"],
         2, "the report's folder: ", f, 10)
    check("study --scene: DIR/report/index.html: said", "index.html: exists and is not a report this script wrote" in table[-1][2],
          table[-1][2])
    s.write("R2/report", "a file where the report's folder goes\n")
    case("study --scene: DIR/report a file", ["study", "convergence", "--scene", "lap_joint.json", "--out", "R2"], 2,
         "/R2/report: exists and is not a directory", f, 10)
    s.write("R3/report/figures", "a file where the figures go\n")
    case("study --scene: DIR/report/figures a file", ["study", "validity", "--scene", "lap_joint.json", "--out", "R3"], 2,
         "/R3/report/figures: exists and is not a directory", f, 10)
    case("validity-map: DIR/report/index.html the user's",
         ["study", "validity-map", "--scene", "lap_joint.json", "--out", "R1", "--thickness-ratios", "1e-2"], 2,
         "the report's folder: ", f, 10)
    case("verify: DIR/report/index.html the user's", ["verify", "--out", "R1"], 2, "the report's folder: ", f, 10)
    # Refused at the end all the same: a figure of the joint's report saved by the user.
    s.write("R4/report/figures/scene_lap-joint.png", "the user's picture\n")
    kept = {"R4", "R4/results.h5", "R4/bondline_fields.csv"}
    case("study --scene: a figure in the way, found by the report", ["study", "validity", "--scene", "lap_joint.json",
         "--out", "R4", "--quiet", "--eps", "0.1,0.05,0.02"], 2, "the report was not written (", f, 120, changes=kept)
    check("a figure in the way: what is kept", table[-1][2].endswith("kept R4/results.h5 and R4/bondline_fields.csv"),
          table[-1][2])
    for name in ("R1", "R2", "R3", "R4"):
        shutil.rmtree(s.path(name), ignore_errors=True)


def one_line(s):
    """Every value echoed from a file or from gmsh escaped: one line, no control character."""
    f = s.folder
    evil = "x\x1b[31mRED\nY"
    fields = (
        ("units", lambda j: j.update(units=evil)),
        ("plane", lambda j: j.update(plane=evil)),
        ("element", lambda j: j.update(element=evil)),
        ("geometry", lambda j: j.update(geometry=evil + ".geo")),
        ("faces", lambda j: j["interface"].update(faces={"plus": evil, "minus": "contact"})),
        ("plus", lambda j: j["interface"].update(plus=evil)),
        ("minus", lambda j: j["interface"].update(minus=evil)),
        ("an unknown key", lambda j: j.update({evil: 1})),
        ("a support group", lambda j: j["supports"][0].update(group=evil)),
    )
    for label, change in fields:
        case(f"one line: {label} holding ESC and a newline", ["solve", "--scene", s.with_json("evil_" + label.split()[-1], change)],
             2, "x\\u001b[31mRED\\u000aY", f, 10)
    s.write("gmsh_error.geo", s.geo + '\nError("first\x1b[2J\nsecond");\n')
    case("one line: gmsh's error text holding ESC and a newline",
         ["solve", "--scene", s.with_json("gmsh_error", lambda j: j.update(geometry="gmsh_error.geo"))], 2,
         "first\\u001b[2J\\u000asecond", f, 30)


def tmpdir_clock_names(s):
    """A relative TMPDIR works; --mesh-timeout bounds all the meshing of a command; the longest name
    a file system takes works as --out."""
    f = s.folder
    os.makedirs(s.path("rel_tmp"), exist_ok=True)
    for tmpdir in ("rel_tmp", "./rel_tmp/../rel_tmp/"):
        case(f"TMPDIR={tmpdir}", ["solve", "--scene", "lap_joint.json"], 0, "", f, 60, lines=0,
             env=dict(ENV, TMPDIR=tmpdir))
        check(f"TMPDIR={tmpdir}: nothing left in it", not os.listdir(s.path("rel_tmp")), str(os.listdir(s.path("rel_tmp"))))
    # The limit: a multiple of one mesh of this geometry, as measured now: the four meshes of the
    # study (2.5 meshes) and the two of the map (h and h/2: 1.5 meshes) together do not fit in it.
    # One mesh is the fastest of three: the machine's load moves it (a mesh measured loaded and two
    # run idle once fitted in 1.5 of it); the fastest is the nearest to an idle machine's.
    # (The clock's arithmetic itself: tests/test_meshing_child.cpp.)
    slow = s.with_geo("slow_clock", first=SLOWER)
    one_mesh = min(json.loads(subprocess.run([THINLAYER, "solve", "--scene", slow, "--json"], cwd=f, capture_output=True,
                                             text=True, env=ENV).stdout)['times_s']['meshing'] for _ in range(3))
    limit = f"{2.5 * one_mesh:.2f}"
    case(f"study --scene --mesh-timeout {limit} (2.5 meshes): one clock for all its meshes",
         ["study", "validity", "--scene", slow, "--mesh-timeout", limit, "--quiet"], 2, "slow_clock.geo: ", f, 30)
    check("one clock: said", f"the wall-clock limit of {float(limit):g} s (--mesh-timeout" in table[-1][2], table[-1][2])
    limit = f"{1.5 * one_mesh:.2f}"
    case(f"validity-map --mesh-timeout {limit} (1.5 meshes)", ["study", "validity-map", "--scene", slow, "--mesh-timeout",
         limit, "--quiet", "--thickness-ratios", "1e-2,1e-1", "--modulus-ratios", "1e-1", "--poisson", "0.45"], 2,
         f"the wall-clock limit of {float(limit):g} s (--mesh-timeout", f, 30)
    for command in ("solve", "study"):
        r = subprocess.run([THINLAYER, command, "--help"], capture_output=True, text=True)
        check(f"{command} --help: the clock is the command's", "all the meshing of the command" in " ".join(r.stdout.split()),
              r.stdout[-300:])
    for length in (253, 255):
        name = "n" * (length - 3) + ".h5"
        case(f"--out a {length}-byte name", ["solve", *CHEAP, "--out", name], 0, "", f, 10, lines=0, changes={name})
        os.remove(s.path(name))


GROUPS = ("unscanned_routes", "hangs", "untrusted_files", "outputs", "bounds", "messages", "memory", "csv_cell",
          "side_files", "machine", "report_one_file", "write_time", "report_folder", "one_line", "tmpdir_clock_names")


def main():
    start = time.monotonic()
    s = Scene()
    only = sys.argv[3:]  # optional: the groups to run (GROUPS' names); all by default
    try:
        for group in GROUPS:
            if not only or group in only:
                globals()[group](s)
    finally:
        shutil.rmtree(s.folder, ignore_errors=True)
        shutil.rmtree(OUTSIDE, ignore_errors=True)
        shutil.rmtree(TMP, ignore_errors=True)
    print("\n| case | exit | stderr | s |\n|---|---|---|---|")
    for name, status, line, took in table:
        print(f"| {name} | {status} | {line[:160]} | {took:.2f} |")
    print(f"\n{len(table)} cases; {passed} checks passed, {len(failures)} failed, in {time.monotonic() - start:.1f} s")
    for failure in failures:
        print("FAIL", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Issue 34's hostile matrix: gmsh reads only what thinlayer read, in a box with a clock; no
untrusted file is parsed in the main process; outputs are distinct; bounds and messages.

    /usr/bin/python3 tests/test_untrusted_inputs.py PATH/TO/thinlayer PATH/TO/cases/lap_joint

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
import stat
import subprocess
import sys
import tempfile
import time

import h5py

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


def snapshot(folder):
    """Every entry under folder: its kind and, for a regular file, its bytes; a link, its target."""
    result = {}
    for root, dirs, files in os.walk(folder):
        for name in dirs + files:
            path = os.path.join(root, name)
            info = os.lstat(path)
            key = os.path.relpath(path, folder)
            if stat.S_ISREG(info.st_mode):
                with open(path, "rb") as f:
                    result[key] = f.read()
            elif stat.S_ISLNK(info.st_mode):
                result[key] = ("link", os.readlink(path))
            else:
                result[key] = stat.S_IFMT(info.st_mode)
    return result


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


def case(name, args, status, words, folder, seconds, changes=(), report=False, limit_memory=None, lines=1):
    """One case: exit `status`, `lines` line(s) on stderr (the first holding `words`), within `seconds`,
    the folder as before but for the entries named in `changes`, nothing outside, nothing left."""
    before, outside = snapshot(folder), snapshot(OUTSIDE)
    argv = [sys.executable, MAKE_REPORT, *args] if report else [THINLAYER, *args]
    start = time.monotonic()
    r, survivors = run(argv, folder, timeout=max(2 * seconds, 30), limit_memory=limit_memory)
    took = time.monotonic() - start
    got = r.stderr.strip().splitlines()
    line = got[0] if got else ""
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


def msh(z=0.0, first_node=None):
    """Two bodies of two quads each as a gmsh 4.1 mesh (tests/test_scene_inputs.py's), z for every
    node, and optionally node 1 at `first_node` (x, y) given as text."""
    nodes = [(x, y) for y in (0, 1, 2) for x in (0, 1, 2)]
    text = [f"{x} {y} {z}" for x, y in nodes]
    if first_node:
        text[0] = f"{first_node[0]} {first_node[1]} {z}"
    return "\n".join([
        "$MeshFormat", "4.1 0 8", "$EndMeshFormat",
        "$PhysicalNames", "5", '1 1 "bottom"', '1 2 "bond"', '1 3 "top"', '2 4 "a"', '2 5 "b"', "$EndPhysicalNames",
        "$Entities", "0 3 2 0",
        "1 0 0 0 2 0 0 1 1 0", "2 0 1 0 2 1 0 1 2 0", "3 0 2 0 2 2 0 1 3 0",
        "1 0 0 0 2 1 0 1 4 0", "2 0 1 0 2 2 0 1 5 0", "$EndEntities",
        "$Nodes", "3 9 1 9",
        *[line for curve in range(3) for line in (f"1 {curve + 1} 0 3", *[str(3 * curve + k + 1) for k in range(3)],
                                                  *text[3 * curve:3 * curve + 3])],
        "$EndNodes",
        "$Elements", "5 10 1 10",
        "1 1 1 2", "1 1 2", "2 2 3",
        "1 2 1 2", "3 4 5", "4 5 6",
        "1 3 1 2", "5 7 8", "6 8 9",
        "2 1 3 2", "7 1 2 5 4", "8 2 3 6 5",
        "2 2 3 2", "9 4 5 8 7", "10 5 6 9 8",
        "$EndElements", ""])


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


def main():
    start = time.monotonic()
    s = Scene()
    try:
        unscanned_routes(s)
        hangs(s)
        untrusted_files(s)
        outputs(s)
        bounds(s)
        messages(s)
        memory(s)
        csv_cell(s)
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

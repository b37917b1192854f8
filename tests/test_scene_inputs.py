#!/usr/bin/python3
"""Scene files on the command line (SPEC §5): every bad scene input is refused with exit status 2,
exactly one line on stderr naming the problem (and, for the JSON, its line and column), and
nothing written; the shipped lap joint solves in both modes.

    /usr/bin/python3 tests/test_scene_inputs.py PATH/TO/thinlayer PATH/TO/cases/lap_joint
"""

import json
import os
import shutil
import stat
import subprocess
import sys
import tempfile

import h5py

THINLAYER = os.path.abspath(sys.argv[1])
LAP = os.path.abspath(sys.argv[2])
failures = []
passed = 0

# Two strips side by side sharing the curve "bond"; a third square "loose" touching nothing.
GEO = """
Point(1) = {0, 0, 0, 1}; Point(2) = {4, 0, 0, 1}; Point(3) = {4, 2, 0, 1}; Point(4) = {0, 2, 0, 1};
Point(5) = {4, 4, 0, 1}; Point(6) = {0, 4, 0, 1};
Point(7) = {10, 0, 0, 1}; Point(8) = {12, 0, 0, 1}; Point(9) = {12, 2, 0, 1}; Point(10) = {10, 2, 0, 1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {4, 3}; Line(4) = {4, 1};
Line(5) = {3, 5}; Line(6) = {5, 6}; Line(7) = {6, 4};
Line(8) = {7, 8}; Line(9) = {8, 9}; Line(10) = {9, 10}; Line(11) = {10, 7};
Curve Loop(1) = {1, 2, -3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {3, 5, 6, 7}; Plane Surface(2) = {2};
Curve Loop(3) = {8, 9, 10, 11}; Plane Surface(3) = {3};
Physical Surface("a") = {1}; Physical Surface("b") = {2}; Physical Surface("loose") = {3};
Physical Curve("bond") = {3}; Physical Curve("bottom") = {1}; Physical Curve("top") = {6};
Physical Curve("a_only") = {2};
Physical Point("corner") = {1};
"""


def scene(**changes):
    s = {"name": "t", "geometry": "t.geo", "mesh_size": {"interface": 0.5, "far": 1},
         "bodies": {"a": {"group": "a", "lambda": 4500, "mu": 5400},
                    "b": {"group": "b", "lambda": 4500, "mu": 5400}},
         "interface": {"group": "bond", "plus": "b", "minus": "a", "friction": 0.5,
                       "layer": {"gamma": 1, "delta": 1, "lambda_g": 4500, "mu_g": 5400}},
         "supports": [{"group": "bottom", "u": [0, 0]}, {"group": "top", "u": [0.001, 0.001]}]}
    s.update(changes)
    return s


def snapshot(folder):
    result = {}
    for root, dirs, files in os.walk(folder):
        for name in dirs + files:
            path = os.path.join(root, name)
            info = os.lstat(path)
            if stat.S_ISREG(info.st_mode):
                with open(path, "rb") as f:
                    result[os.path.relpath(path, folder)] = f.read()
            else:
                result[os.path.relpath(path, folder)] = stat.S_IFMT(info.st_mode)
    return result


def check(name, ok, detail=""):
    global passed
    if ok:
        passed += 1
    else:
        failures.append(f"{name}: {detail}")


def refused(name, args, expect_in_message, folder):
    """Runs thinlayer with args in folder; asserts exit 2, one stderr line containing the text, and
    the folder unchanged byte for byte."""
    before = snapshot(folder)
    r = subprocess.run([THINLAYER, *args], cwd=folder, capture_output=True, text=True)
    lines = r.stderr.strip().splitlines()
    check(name + " exit 2", r.returncode == 2, f"exit {r.returncode}, stderr {r.stderr!r}")
    check(name + " one line", len(lines) == 1, repr(r.stderr))
    check(name + " message", any(expect_in_message in l for l in lines), f"{expect_in_message!r} not in {r.stderr!r}")
    check(name + " nothing written", snapshot(folder) == before, "the folder changed")


def done_when(folder):
    """Issue 27's "Done when", as a new user runs it: the shipped double lap (0.2 mm of epoxy,
    E = 3000 MPa, nu = 0.35, between aluminium strips, in N and MPa, bonded) in one
    `study validity --scene`: both modes, the verdict, a report showing the bondline shear and peel
    stresses, and the bondline fields as CSV."""
    lap = os.path.join(os.path.dirname(LAP), "double_lap")
    for name in ("double_lap.json", "double_lap.geo"):
        shutil.copy(os.path.join(lap, name), os.path.join(folder, name))
    r = subprocess.run([THINLAYER, "study", "validity", "--scene", "double_lap.json", "--out", "dl", "--quiet"], cwd=folder,
                       capture_output=True, text=True)
    check("double lap: study exit 0", r.returncode == 0, r.stdout[-2000:] + r.stderr)
    check("double lap: the verdict printed", "Thickness validity" in r.stdout and "0.01" in r.stdout, r.stdout[-2000:])
    results = os.path.join(folder, "dl", "results.h5")
    if not os.path.exists(results):
        check("double lap: results.h5", False, "missing")
        return
    with h5py.File(results) as h:
        g = h["studies"]["scene"]["double-lap"]
        check("double lap: an engineer's glue", g.attrs["family"] == "engineer", str(dict(g.attrs)))
        check("double lap: both modes", {h["scenes"][s].attrs["mode"] for s in h["scenes"]} == {"limit", "layer"}, "")
        check("double lap: validity", set(g["validity"]["status"].asstr()[()]) <= {"found", "at_least", "below_range"}, "")
        described = all("description" in g[d].attrs for d in ("eps", "e_u", "validity/eps_max", "peaks/shear"))
        check("double lap: study datasets described", described and g["eps"].attrs["units"] == "mm" and
              g["peaks"]["shear"].attrs["units"] == "MPa", "")
        limit = h["scenes"][g["limit_scene"].asstr()[0]]
        check("double lap: loads and supports stored", "supports" in limit and set(limit["supports"]) == {"clamp", "grip"}, "")
        check("double lap: in MPa", limit["interface"]["bond_top"]["S"]["sigma_T"].attrs["units"] == "MPa", "")
    with open(os.path.join(folder, "dl", "report", "index.html"), encoding="utf-8") as f:
        page = f.read()
    check("double lap: the joint's report", "<title>thinlayer joint report: double-lap</title>" in page and
          "shear stresses" in page and "peel" in page and "not in this results file" not in page, page[:300])
    for name in ("joint_double-lap_bondline_bond_top.png", "joint_double-lap_peaks.png", "joint_double-lap_shape.png"):
        check("double lap: figure " + name, os.path.exists(os.path.join(folder, "dl", "report", "figures", name)), name)
    # The joint's report is the report's own: a second run replaces it.
    report_py = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "report", "make_report.py")
    r = subprocess.run([sys.executable, report_py, results, os.path.join(folder, "dl", "report")], capture_output=True,
                       text=True)
    check("double lap: the report re-run over its own", r.returncode == 0, r.stderr)
    with open(os.path.join(folder, "dl", "bondline_fields.csv"), encoding="utf-8") as f:
        rows = [line for line in f if not line.startswith("#")]
    check("double lap: bondline fields as CSV", rows[0].startswith("scene,mode,eps,h,bondline,node,s,") and len(rows) > 100,
          rows[0] if rows else "empty")


def main():
    folder = tempfile.mkdtemp(prefix="thinlayer-scene-")
    try:
        with open(os.path.join(folder, "t.geo"), "w") as f:
            f.write(GEO)
        with open(os.path.join(folder, "notes.txt"), "w") as f:
            f.write("the user's notes\n")

        def write(name, content):
            with open(os.path.join(folder, name), "w") as f:
                f.write(content if isinstance(content, str) else json.dumps(content, indent=1))
            return name

        outs = ["--out", "r.h5", "--vtu", "r.vtu"]
        refused("missing file", ["solve", "--scene", "nothere.json", *outs], "nothere.json does not exist", folder)
        write("syntax.json", '{\n "name": "t",\n "bodies": {"a": 1,}\n}\n')
        refused("syntax error", ["solve", "--scene", "syntax.json", *outs], "syntax.json:3:20: syntax error", folder)
        s = scene()
        s["interface"]["frction"] = 0.5
        write("unknown.json", s)
        r = subprocess.run(["grep", "-n", "frction", "unknown.json"], cwd=folder, capture_output=True, text=True)
        line = r.stdout.split(":")[0]
        refused("unknown key", ["solve", "--scene", "unknown.json", *outs], f"unknown.json:{line}:", folder)
        refused("unknown key named", ["solve", "--scene", "unknown.json", *outs], "unknown key 'frction' in interface", folder)
        s = scene()
        s["bodies"]["b"]["group"] = "bee"
        write("group.json", s)
        refused("missing group", ["solve", "--scene", "group.json", *outs], "group 'bee' is no physical surface", folder)
        s = scene()
        s["interface"]["group"] = "a_only"
        write("shared.json", s)
        refused("interface not shared", ["solve", "--scene", "shared.json", *outs], "is not shared by its bodies", folder)
        s = scene()
        s["bodies"]["loose"] = {"group": "loose", "lambda": 4500, "mu": 5400}
        write("loose.json", s)
        refused("body held by nothing", ["solve", "--scene", "loose.json", *outs], "body 'loose' has no support and no contact", folder)
        s = scene()
        s["supports"] = [{"group": "bottom", "u": [0, 0]}]
        s["interface"]["layer"] = None
        del s["interface"]["layer"]
        s["interface"]["law"] = {"lambda_bar": "inf", "mu_bar": 5}
        write("lawonly.json", s)
        refused("layer mode of a law-only scene", ["solve", "--scene", "lawonly.json", "--mode", "layer", "--eps", "0.01", *outs],
                "has no layer mode", folder)
        s = scene()
        s["supports"] = []
        write("nosupport.json", s)
        refused("no support at all", ["solve", "--scene", "nosupport.json", *outs], "nothing holds the assembly", folder)
        s = scene()
        s["bodies"]["a"]["mu"] = "5400"
        write("type.json", s)
        refused("wrong type", ["solve", "--scene", "type.json", *outs], "'mu' in body 'a' must be a number, not a string", folder)
        write("good.json", scene())
        # The plus body moves with its bondline (cases/scene/scene_morph.h): the 4 mm bondline holds a
        # layer up to a tenth of its length.
        refused("eps too thick", ["solve", "--scene", "good.json", "--mode", "layer", "--eps", "0.5", *outs],
                "too thick for this joint: at most 0.4 mm, a tenth of the length of the interface", folder)
        refused("bad number", ["solve", "--scene", "good.json", "--mode", "layer", "--eps", "0x10", *outs], "--eps", folder)
        refused("case and scene", ["solve", "--scene", "good.json", "--case", "bar", *outs], "--case", folder)
        refused("study: bad scene", ["study", "convergence", "--scene", "unknown.json", "--out", "study"], "unknown key 'frction'",
                folder)
        refused("study: scene on a study without", ["study", "table3", "--scene", "good.json", "--out", "study"],
                "--scene applies to study convergence and study validity only", folder)

        # The engineer's joint keys (issue 27): each bad value refused at its line.
        s = scene()
        s["interface"]["faces"] = {"plus": "glued"}
        write("faces.json", s)
        refused("bad face", ["solve", "--scene", "faces.json", *outs], "'plus' in faces must be \"bonded\" or \"contact\"", folder)
        s = scene()
        s["interface"]["glue"] = {"E": 3000, "nu": 0.35, "thickness": 0.2}
        write("twoglues.json", s)
        refused("layer and glue", ["solve", "--scene", "twoglues.json", *outs], "needs exactly one of 'layer', 'glue' and 'law'",
                folder)
        s = scene()
        del s["interface"]["layer"]
        s["interface"]["glue"] = {"E": 3000, "nu": 0.35}
        write("nothick.json", s)
        refused("glue without thickness", ["solve", "--scene", "nothick.json", *outs], "glue has no 'thickness'", folder)
        s = scene()
        s["loads"] = [{"group": "top", "traction": [0, 1], "pressure": 2}]
        write("twoloads.json", s)
        refused("two kinds of load", ["solve", "--scene", "twoloads.json", *outs], "needs exactly one of 'traction'", folder)
        write("kN.json", scene(units="mm-kN"))
        refused("unknown units", ["solve", "--scene", "kN.json", *outs], "'units' must be \"mm-daN\" (the default) or \"mm-N\"",
                folder)
        s = scene()
        s["interfaces"] = [dict(s["interface"]), dict(s["interface"])]
        del s["interface"]
        write("twice.json", s)
        refused("bondline listed twice", ["solve", "--scene", "twice.json", *outs], "bondline group 'bond' is listed twice", folder)
        s = scene()
        s["interfaces"] = [s["interface"]]
        write("both.json", s)
        refused("interface and interfaces", ["solve", "--scene", "both.json", *outs],
                "exactly one of 'interface' (one bondline) and 'interfaces'", folder)
        s = scene()
        s["bodies"]["a"]["E"] = 7000
        write("lame_and_young.json", s)
        refused("lambda and E", ["solve", "--scene", "lame_and_young.json", *outs], "needs either 'lambda' and 'mu' or 'E' and 'nu'",
                folder)
        refused("layer mode without a thickness", ["solve", "--scene", "good.json", "--mode", "layer", *outs],
                "layer mode needs --eps", folder)
        refused("eps in limit mode of the paper's family", ["solve", "--scene", "good.json", "--eps", "0.01", *outs],
                "--eps applies to the layer mode only", folder)

        # The same joint pulled apart with its faces in contact (the paper's): nothing holds it
        # across the bondline, and the solve says so.
        s = scene()
        s["supports"] = [{"group": "bottom", "u": [0, 0]}, {"group": "top", "u": [0, 0.001]}]
        write("apart.json", s)
        r = subprocess.run([THINLAYER, "solve", "--scene", "apart.json", "--json"], cwd=folder, capture_output=True, text=True)
        check("no load: said", r.returncode == 0 and "carries no load" in r.stderr and
              json.loads(r.stdout)["carries_load"] is False, r.stdout + r.stderr)
        s["interface"]["faces"] = {"plus": "bonded", "minus": "bonded"}
        write("bonded.json", s)
        r = subprocess.run([THINLAYER, "solve", "--scene", "bonded.json", "--json"], cwd=folder, capture_output=True, text=True)
        if r.returncode == 0:
            j = json.loads(r.stdout)
            check("bonded: carries the tension", j["carries_load"] and j["reactions"]["top"][1] > 0, r.stdout)
            check("bonded: reactions in --json balance", abs(j["reactions"]["top"][1] + j["reactions"]["bottom"][1]) < 1e-9, r.stdout)
        else:
            check("bonded solve", False, r.stderr)

        # A support on a physical point: the bottom on rollers, the corner pinned.
        s = scene()
        s["supports"] = [{"group": "bottom", "u": [None, 0]}, {"group": "corner", "u": [0, 0]},
                         {"group": "top", "u": [0.001, -0.001]}]
        write("point.json", s)
        r = subprocess.run([THINLAYER, "solve", "--scene", "point.json", "--json", "--out", "point.h5"], cwd=folder,
                           capture_output=True, text=True)
        check("support on a point", r.returncode == 0 and json.loads(r.stdout)["converged"], r.stdout + r.stderr)
        if r.returncode == 0:
            with h5py.File(os.path.join(folder, "point.h5")) as h:
                reactions = h["scenes"][json.loads(r.stdout)["scene"]]["reactions"]
                check("a point's reaction", set(reactions) == {"bottom", "corner", "top"}, str(list(reactions)))
        write("underflow.json", json.dumps(scene()).replace('"friction": 0.5', '"friction": 1e-400'))
        refused("underflow", ["solve", "--scene", "underflow.json", *outs], "underflows a double", folder)

        # The shipped lap joint, both modes: written results files that describe themselves.
        lap = os.path.join(LAP, "lap_joint.json")
        r = subprocess.run([THINLAYER, "solve", "--scene", lap, "--json", "--out", "limit.h5"], cwd=folder,
                           capture_output=True, text=True)
        check("lap joint limit exit 0", r.returncode == 0, r.stderr)
        if r.returncode == 0:
            j = json.loads(r.stdout)
            check("lap joint limit converged", j["converged"] and j["residual"]["value"] <= 1e-10, r.stdout)
            with h5py.File(os.path.join(folder, "limit.h5")) as h:
                g = h["scenes"][j["scene"]]
                check("lap joint limit file", g.attrs["case"] == "lap-joint" and "S" in g["interface"] and
                      set(g["reactions"]) == {"clamp", "anvil", "grip"}, str(list(g)))
        r = subprocess.run([THINLAYER, "solve", "--scene", lap, "--mode", "layer", "--eps", "0.01", "--json", "--out", "layer.h5"],
                           cwd=folder, capture_output=True, text=True)
        check("lap joint layer exit 0", r.returncode == 0, r.stderr)
        if r.returncode == 0:
            j = json.loads(r.stdout)
            check("lap joint layer converged", j["converged"], r.stdout)
            check("lap joint layer faces", set(j["counts"]) == {"S+", "S-", "combined"}, r.stdout)
        done_when(folder)
    finally:
        shutil.rmtree(folder)
    print(f"{passed} checks passed, {len(failures)} failed")
    for f in failures:
        print("FAIL", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

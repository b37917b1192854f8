#!/usr/bin/python3
"""Seeded friction-held joints: the limit mode's sparse Newton judged off the scenes it was built on.

    /usr/bin/python3 scripts/random_friction_joints.py --thinlayer build/thinlayer --seeds 1-40 \
        [--peer build/thinlayer_export_problem] [--refine 1,2,4]

Each seed draws a double lap whose inner strip has no support and is held by its two bondlines in
contact with friction (the shape of cases/friction_lap, SPEC §5): strip thicknesses, overlap,
friction coefficient, the two clamping pressures (independently: the inner strip is then pressed
harder from one side), the glue (E, ν, thickness), the element size along the bondlines, and the
pull as a fraction 0.05 … 1.2 of the capacity 2 f p̄ × overlap (p̄ the smaller pressure, so that a
fraction above 1 may or may not be refused: thinlayer's own capacity check decides). None of these
draws were looked at while the solver was written (it was built on cases/friction_lap alone).

For each seed it runs `thinlayer solve --scene … --json` (limit mode) and prints the method, the
factorisations, the residual and the wall time; a refused overload is counted as such (exit 1 with
its line). With --peer, GetFEM (scripts/getfem_peer.py, from the bonded start) solves the same
discrete problem and the answers are compared (reactions, u, r, every status). With --refine, the
seed is solved again with the element size divided by each factor (the steps must not grow).
"""
import argparse
import json
import math
import os
import random
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
GEO = os.path.join(HERE, "..", "cases", "friction_lap", "friction_lap.geo")


def seeds(text):
    out = []
    for part in text.split(","):
        if "-" in part:
            a, b = part.split("-")
            out.extend(range(int(a), int(b) + 1))
        else:
            out.append(int(part))
    return out


def draw(seed):
    """One scene's parameters (lengths mm, stresses MPa, forces N/mm)."""
    g = random.Random(seed)
    p = {
        "ti": round(g.uniform(1.0, 5.0), 3),          # inner strip thickness
        "to": round(g.uniform(0.5, 3.0), 3),          # outer strips' thickness
        "a": 10.0,
        "overlap": round(g.uniform(8.0, 40.0), 2),
        "f": round(g.uniform(0.05, 1.0), 3),
        "p_top": round(10 ** g.uniform(math.log10(5), math.log10(150)), 2),
        "p_bottom": None,
        "E_g": round(10 ** g.uniform(2, 4), 1),
        "nu_g": round(g.uniform(0.2, 0.45), 3),
        "t_g": round(10 ** g.uniform(-2, -0.5), 4),
        "h": round(g.uniform(0.15, 0.5), 3),
        "fraction": round(g.uniform(0.05, 1.2), 3),
        "sign": g.choice((-1, 1)),
    }
    p["p_bottom"] = p["p_top"] if g.random() < 0.5 else round(10 ** g.uniform(math.log10(5), math.log10(150)), 2)
    capacity = 2 * p["f"] * min(p["p_top"], p["p_bottom"]) * p["overlap"]
    p["pull"] = round(p["sign"] * p["fraction"] * capacity, 2)
    return p


def write_scene(folder, seed, p, h):
    geo = open(GEO, encoding="utf-8").read()
    b = p["a"] + p["overlap"]
    for name, value in (("ti", p["ti"]), ("to", p["to"]), ("a", p["a"]), ("b", b), ("c", b + 10.0)):
        geo, n = re.subn(r"^%s = [^;]*;" % name, "%s = %r;" % (name, value), geo, count=1, flags=re.M)
        if n != 1:
            raise SystemExit("friction_lap.geo has no line '%s = ...;'" % name)
    with open(os.path.join(folder, "joint_%d.geo" % seed), "w", encoding="utf-8") as out:
        out.write(geo)
    glue = {"E": p["E_g"], "nu": p["nu_g"], "thickness": p["t_g"]}
    scene = {
        "name": "random-friction-joint-%d" % seed,
        "geometry": "joint_%d.geo" % seed,
        "mesh_size": {"interface": h, "far": max(4 * h, 1.0)},
        "units": "mm-N",
        "bodies": {name: {"group": name, "E": 70000, "nu": 0.33} for name in ("inner", "outer_top", "outer_bottom")},
        "interfaces": [
            {"group": "bond_top", "plus": "outer_top", "minus": "inner", "friction": p["f"], "glue": glue},
            {"group": "bond_bottom", "plus": "outer_bottom", "minus": "inner", "friction": p["f"], "glue": glue},
        ],
        "supports": [{"group": "clamp", "u": [0, 0]}],
        "loads": [{"group": "grip", "force": [p["pull"], 0]},
                  {"group": "press_top", "pressure": p["p_top"]},
                  {"group": "press_bottom", "pressure": p["p_bottom"]}],
    }
    path = os.path.join(folder, "joint_%d_h%g.json" % (seed, h))
    with open(path, "w", encoding="utf-8") as out:
        json.dump(scene, out, indent=1)
    return path


def solve(thinlayer, scene):
    start = time.monotonic()
    r = subprocess.run([thinlayer, "solve", "--scene", scene, "--json"], capture_output=True, text=True, timeout=1800)
    wall = time.monotonic() - start
    lines = [l for l in r.stderr.splitlines() if l.strip()]
    try:
        j = json.loads(r.stdout) if r.stdout.strip() else None
    except json.JSONDecodeError:
        j = None
    return r.returncode, j, lines, wall


def peer(exporter, scene, h, folder):
    out = os.path.join(folder, "peer_%s.json" % os.path.basename(scene))
    r = subprocess.run([sys.executable, os.path.join(HERE, "getfem_peer.py"), "--exporter", exporter, "--scene", scene,
                        "--sizes", "%r" % h, "--starts", "bonded", "--repeat", "1", "--json", out,
                        "--workdir", os.path.join(folder, "export_" + os.path.basename(scene))],
                       capture_output=True, text=True, timeout=1800)
    if r.returncode != 0 or not os.path.exists(out):
        return None, (r.stdout + r.stderr).strip().splitlines()[-1:]
    res = json.load(open(out, encoding="utf-8"))
    res = res[0] if isinstance(res, list) else res.get("results", [res])[0]
    return res, []


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--thinlayer", required=True)
    parser.add_argument("--seeds", default="1-20")
    parser.add_argument("--peer", help="thinlayer_export_problem: compare with GetFEM from the bonded start")
    parser.add_argument("--refine", default="1", help="element size divisors, e.g. 1,2,4")
    args = parser.parse_args()
    factors = [float(x) for x in args.refine.split(",")]
    folder = tempfile.mkdtemp(prefix="thinlayer-random-friction-")
    print("scenes in %s" % folder)
    print("| seed | f | p top/bottom (MPa) | pull (N/mm, of capacity) | glue E, nu, t | h (mm) | nodes on S | method | steps (the Newton's: factorisations) | residual | wall (s) | GetFEM (steps; reactions, u, r; statuses differing) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    tally = {"converged": 0, "round-off floor": 0, "refused": 0, "failed": 0, "peer_agrees": 0, "peer_run": 0,
             "newton": 0, "fallback": 0}
    steps_by_factor = {f: [] for f in factors}
    for seed in seeds(args.seeds):
        p = draw(seed)
        for factor in factors:
            h = round(p["h"] / factor, 5)
            scene = write_scene(folder, seed, p, h)
            code, j, lines, wall = solve(args.thinlayer, scene)
            cells = ["%d" % seed, "%g" % p["f"], "%g / %g" % (p["p_top"], p["p_bottom"]),
                     "%g (%.2f)" % (p["pull"], p["fraction"]), "%g, %g, %g" % (p["E_g"], p["nu_g"], p["t_g"]), "%g" % h]
            if j is None:
                kind = "refused" if code == 1 and any("friction cannot hold" in l for l in lines) else "failed"
                tally[kind] += 1 if factor == factors[0] else 0
                cells += ["-", kind, "-", "-", "%.2f" % wall, (lines[-1] if lines else "exit %d" % code)[:160]]
                print("| " + " | ".join(cells) + " |", flush=True)
                break
            # counts: {"<bondline>/S": {"gap": .., "slide": .., "stick": ..}, ...}
            n_s = sum(sum(c.get(k, 0) for k in ("gap", "slide", "stick")) for c in j.get("counts", {}).values())
            if factor == factors[0]:
                stop = j.get("stop_cause", "")
                tally["converged" if j["converged"] else "round-off floor" if stop == "round-off floor" else "failed"] += 1
                tally["newton" if j["solver_method"] == "sparse Newton" else "fallback"] += 1
            steps_by_factor[factor].append(j["iterations"])
            cells += ["%d" % n_s, j["solver_method"], "%d" % j["iterations"], "%.1e" % j["residual"]["value"], "%.2f" % wall]
            if args.peer:
                res, why = peer(args.peer, scene, h, folder)
                if res is None:
                    cells.append("peer failed: %s" % (why[0] if why else "?"))
                else:
                    b = res.get("bonded") or {}
                    tally["peer_run"] += 1
                    agree = b.get("converged") and max(b.get("reactions", 1), b.get("u", 1), b.get("r", 1)) <= 1e-8 \
                        and b.get("status_differ", 1) == 0
                    tally["peer_agrees"] += 1 if agree else 0
                    cells.append("%s%d; %.0e, %.0e, %.0e; %d" % ("" if b.get("converged") else "NOT converged ",
                                                                  b.get("steps", -1), b.get("reactions", math.nan),
                                                                  b.get("u", math.nan), b.get("r", math.nan),
                                                                  b.get("status_differ", -1)))
            else:
                cells.append("-")
            print("| " + " | ".join(cells) + " |", flush=True)
    print("\n%d converged, %d stopped at their round-off floor, %d refused (over friction's capacity), %d failed" %
          (tally["converged"], tally["round-off floor"], tally["refused"], tally["failed"]))
    print("the sparse Newton alone: %d; the condensed path after it: %d" % (tally["newton"], tally["fallback"]))
    for factor in factors:
        s = sorted(steps_by_factor[factor])
        if s:
            print("h / %g: steps median %g, max %d over %d scenes (a fall-back's: the Newton's and the condensed path's)" %
                  (factor, s[len(s) // 2], s[-1], len(s)))
    if args.peer:
        print("GetFEM agrees (reactions, u, r to 1e-8; every status) on %d of %d" % (tally["peer_agrees"], tally["peer_run"]))
    return 0 if tally["failed"] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())

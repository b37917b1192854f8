#!/usr/bin/python3
"""The convergence study (S2) of the bonded laws (SPEC §1.6, docs/joints.md "Bonded faces"): the dovetail
of cases/bonded_laws as a scene file, for each Table 2 case (γ, δ) and each combination of faces
(both bonded: the bilateral spring law; one bonded, one in contact: Table 1's law; both in contact:
the paper's), run through `thinlayer study convergence --scene`; prints one Markdown table of the
rates from the layer model's Cauchy differences (the mesh floor cancels) — through the whole grid
and where it ends (the last three differences, the rate the check reads, with the last two local
slopes) —, the floor at h = 0.05 and its rate in h, beside the predicted rate.

    /usr/bin/python3 scripts/bonded_law_rates.py build/thinlayer OUT_DIR [--cases bcdefghi] [--faces bb,bc,cb,cc]
                                                 [--geometry dovetail|ring]

--geometry ring: the control without corners (cases/bonded_laws/ring.geo: the same laws, faces,
friction, element size and thicknesses on a smooth glued arc; studies/convergence_rates.md).

OUT_DIR/<scene name>/ receives each scene file and its study (results.h5, report/).
"""

import argparse
import json
import os
import subprocess
import sys
import time

import h5py

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
TEMPLATES = {"dovetail": os.path.join(ROOT, "cases", "bonded_laws", "dovetail_d_bonded_bonded.json"),
             "ring": os.path.join(ROOT, "cases", "bonded_laws", "ring_c_bonded_contact.json")}
EXPONENTS = {"a": (1.5, 1.5), "b": (1.5, 1), "c": (1, 1.5), "d": (1, 1), "e": (0.5, 1.5), "f": (0.5, 1),
             "g": (1.5, 0.5), "h": (1, 0.5), "i": (0.5, 0.5)}
# Case (c) with one face bonded is pre-asymptotic down to 1e-8 on the dovetail: its slot corner,
# where the right flank's contact zone ends, adds a term whose local slopes fall to 0.25 at 1e-6
# and rise back to 0.49 at 1e-10 (studies/convergence_rates.md, "The bonded laws' three misses").
# SPEC 3 S2 item 1: "further where a case is still pre-asymptotic": its grid is 1e-4 ... 1e-10
# (the scene's own, 1e-3 ... 1e-6, everywhere else). The ring (no corner) needs none.
EXTENDED_GRID = [10 ** (-k / 2) for k in range(8, 21)]


def extended(case, faces, geometry):
    return geometry == "dovetail" and case == "c" and faces in ("bc", "cb")


FACES = {"bb": ("bonded", "bonded"), "bc": ("bonded", "contact"), "cb": ("contact", "bonded"),
         "cc": ("contact", "contact")}
QUANTITIES = ("u", "jump_N", "jump_T", "sigma_N", "sigma_T")


def scene(case, faces, geometry):
    with open(TEMPLATES[geometry]) as f:
        s = json.load(f)
    gamma, delta = EXPONENTS[case]
    plus, minus = FACES[faces]
    s["name"] = f"{geometry}-{case}-{plus}-{minus}"
    s["geometry"] = os.path.join(ROOT, "cases", "bonded_laws", geometry + ".geo")
    s["interface"]["faces"] = {"plus": plus, "minus": minus}
    s["interface"]["layer"]["gamma"] = gamma
    s["interface"]["layer"]["delta"] = delta
    if extended(case, faces, geometry):
        s["eps"] = EXTENDED_GRID
    return s


def rate(g, q, prefix="p_"):
    if not g.attrs.get("fitted_" + q, 0):
        return "n/a"
    return f"{g.attrs[prefix + q]:.2f}"


def tail(c, q):
    """The rate where the grid ends and the last two local slopes: "0.49 (0.48, 0.49)"."""
    if not c.attrs.get("fitted_tail_" + q, 0):
        return "n/a"
    slopes = c["local_slope_" + q][()]
    return f"{c.attrs['p_tail_' + q]:.2f} ({slopes[-2]:.2f}, {slopes[-1]:.2f})"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("thinlayer")
    parser.add_argument("out")
    parser.add_argument("--cases", default="bcdefghi")
    parser.add_argument("--faces", default="bb,bc,cb,cc")
    parser.add_argument("--geometry", default="dovetail", choices=sorted(TEMPLATES))
    args = parser.parse_args()
    rows = []
    for case in args.cases:
        for faces in args.faces.split(","):
            s = scene(case, faces, args.geometry)
            folder = os.path.join(args.out, s["name"])
            os.makedirs(folder, exist_ok=True)
            path = os.path.join(folder, "scene.json")
            with open(path, "w") as f:
                json.dump(s, f, indent=1)
            start = time.monotonic()
            r = subprocess.run([args.thinlayer, "study", "convergence", "--scene", path, "--out", folder, "--quiet"],
                               capture_output=True, text=True)
            seconds = time.monotonic() - start
            if r.returncode not in (0, 1):
                print(f"{s['name']}: exit {r.returncode}: {r.stderr.strip()}", file=sys.stderr)
                continue
            with h5py.File(os.path.join(folder, "results.h5")) as h:
                g = h["studies"]["scene"][s["name"]]
                c, fl = g["cauchy"], g["floor"]
                checks = dict(zip([x.decode() for x in h["checks"]["id"][()]], h["checks"]["pass"][()]))
                rate_check = checks.get(f"scene.{s['name']}.rate")
                converged = all(checks.get(f"scene.{s['name']}.{k}", 0) for k in ("limit_converged", "layer_converged"))
                floor = {q: fl["floor_" + q][0] for q in QUANTITIES}
                rows.append([case, "/".join(FACES[faces]), g.attrs["table1_case"], f"{g.attrs['p_predicted']:g}"] +
                            [rate(c, q) for q in QUANTITIES] + [tail(c, "u"), tail(c, "sigma_N"), tail(c, "sigma_T")] +
                            [f"{floor['u']:.1e}", f"{floor['sigma_N']:.1e}", f"{floor['sigma_T']:.1e}", rate(fl, "u", "rate_"),
                             rate(fl, "sigma_N", "rate_"), "yes" if converged else "NO",
                             "—" if rate_check is None else ("pass" if rate_check else "FAIL"), f"{seconds:.1f}"])
            print(" | ".join(rows[-1]), file=sys.stderr)
    header = ["case", "faces plus/minus", "law case", "p predicted"] + [f"p {q}" for q in QUANTITIES] + \
             ["tail u (slopes)", "tail σ_N", "tail σ_T"] + \
             ["floor u", "floor σ_N", "floor σ_T", "floor rate in h (u)", "(σ_N)", "converged", "rate check", "s"]
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for row in rows:
        print("| " + " | ".join(row) + " |")


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Control experiment for study S2's rates (SPEC §3 S2): does a status change cap a rate?

A node of S whose combined status changes between two neighbouring thicknesses of the rate
grid contributes an O(1) jump to the interface stresses near it, which no power law of ε
describes. This script recomputes the Cauchy differences of σ_N or σ_T away from the slot
corners, once as the study does and once without the nodes whose status changes anywhere on
the grid (and their two neighbours), and fits the slope on the study's tail (both scenes
converged, ε_k ≤ 1e-4). If the second slope meets the prediction where the first does not,
the status change is the cause.

    /usr/bin/python3 scripts/status_change_control.py results.h5 CASE [sigma_T|sigma_N]

Reads /studies/convergence/CASE/cauchy (the grid, convergence flags) and the layer scenes of
that grid under /scenes. Norms are unweighted L² over nodes and unscaled, so the differences
differ from the study's by a constant factor; slopes do not. Prints; writes nothing.
"""
import sys

import h5py
import numpy as np

CORNERS = np.array([[-0.4, 0.0], [0.4, 0.0], [-0.6, -0.5], [0.6, -0.5]])  # the slot's (L units)
CORNER_RADIUS = 0.1  # as the study's default (studies/tools/mode_distance.h)
TAIL_EPS_MAX = 1e-4  # the study's tail rule (studies/tools/cauchy_rate.h)


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def grid_scenes(f, case, grid):
    """The layer scene of each grid thickness, matched by attributes (at the study's tolerance)."""
    found = {}
    for name, g in f["scenes"].items():
        a = g.attrs
        if text(a["mode"]) != "layer" or text(a["law_case"]) != case or "-tol" in name:
            continue
        for k, eps in enumerate(grid):
            if abs(a["eps"] - eps) <= 1e-6 * eps:
                found[k] = g
    missing = [grid[k] for k in range(len(grid)) if k not in found]
    if missing:
        sys.exit(f"no layer scene of case {case} at eps {missing} in the file")
    return [found[k] for k in range(len(grid))]


def slope(eps, diff, in_tail):
    x = [np.log(e) for e, t in zip(eps, in_tail) if t]
    y = [np.log(d) for d, t in zip(diff, in_tail) if t]
    return (np.polyfit(x, y, 1)[0], len(x)) if len(x) >= 3 else (float("nan"), len(x))


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    path, case = sys.argv[1], sys.argv[2]
    quantity = sys.argv[3] if len(sys.argv) == 4 else "sigma_T"
    if quantity not in ("sigma_T", "sigma_N"):
        sys.exit("quantity must be sigma_T or sigma_N")
    with h5py.File(path, "r") as f:
        cauchy = f.get(f"studies/convergence/{case}/cauchy")
        if cauchy is None:
            sys.exit(f"{path} has no /studies/convergence/{case}/cauchy (run study convergence first)")
        grid, converged = cauchy["eps"][()], cauchy["converged"][()].astype(bool)
        scenes = grid_scenes(f, case, grid)
        x = scenes[0]["interface/S+/x"][()]
        field = [g[f"interface/S+/{quantity}"][()] for g in scenes]
        status = [g["combined_status"][()] for g in scenes]
    away = np.array([np.min(np.linalg.norm(CORNERS - p, axis=1)) > CORNER_RADIUS for p in x])
    changed = set()
    for k in range(len(grid) - 1):
        nodes = np.nonzero(status[k] != status[k + 1])[0]
        if len(nodes):
            print(f"eps {grid[k]:.3g} -> {grid[k + 1]:.3g}: status of S node(s) {nodes.tolist()} changes "
                  f"(at {', '.join(f'({x[i][0]:.3f}, {x[i][1]:.3f})' for i in nodes)})")
        changed |= set(nodes.tolist())
    settled = away.copy()
    for i in changed:
        settled[max(i - 1, 0):i + 2] = False
    in_tail = [grid[k] <= TAIL_EPS_MAX * (1 + 1e-9) and converged[k] and converged[k + 1] for k in range(len(grid) - 1)]
    print(f"case {case}, {quantity} away from the corners: Cauchy differences (unweighted L2; '*' tail)")
    print(f"  {'eps_k':>10} {'all away nodes':>16} {'without changes':>16}")
    diffs = {"all": [], "settled": []}
    for k in range(len(grid) - 1):
        for key, mask in (("all", away), ("settled", settled)):
            diffs[key].append(np.linalg.norm((field[k] - field[k + 1])[mask]))
        print(f"  {grid[k]:>10.3g} {diffs['all'][-1]:>16.3e} {diffs['settled'][-1]:>16.3e}{' *' if in_tail[k] else ''}")
    for key, label in (("all", f"all {int(away.sum())} away nodes"),
                       ("settled", f"without the {int(away.sum() - settled.sum())} changing nodes and neighbours")):
        p, n = slope(grid[:-1], diffs[key], in_tail)
        print(f"  slope on the tail, {label}: {p:.2f} ({n} differences)")


if __name__ == "__main__":
    main()

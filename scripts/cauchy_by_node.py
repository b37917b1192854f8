#!/usr/bin/python3
"""Where along the bondline a scene study's Cauchy differences live (issue 36's control of the bonded
laws' rates, studies/convergence_rates.md): from the results file of `thinlayer study convergence
--scene` (one bondline), node by node along S, the difference of σ_N and σ_T (plus face) between
neighbouring thicknesses and its local slope ln(d_k/d_k+1)/ln(ε_k/ε_k+1) (a geometric grid), each node's
combined status at every thickness (G gap, S slide, K stick) against the limit's; then the rate of u,
σ_N and σ_T over the nodes farther than R from given corners, and over all.

    /usr/bin/python3 scripts/cauchy_by_node.py RESULTS.h5 [--corners x,y;x,y;...] [--radius R] [--every K]
"""

import argparse
import sys

import h5py
import numpy as np


def layer_scenes(scenes):
    """The study's own layer scenes (not the floor's, whose ids end in -h<h>), by decreasing ε."""
    own = [k for k in scenes if "-layer-eps" in k and k.endswith("-fast")]
    return sorted(own, key=lambda k: -scenes[k].attrs["eps"])


def fit(eps, d):
    """The Cauchy rate p of d_k ≈ C ε_k^p (1 − ρ_k^p), least squares on ln d (as cauchy_fit.h)."""
    best = None
    for p in np.arange(0.02, 2.0, 0.001):
        r = np.log(d) - p * np.log(eps[:-1]) - np.log(1 - (eps[1:] / eps[:-1]) ** p)
        misfit = ((r - r.mean()) ** 2).sum()
        if best is None or misfit < best[0]:
            best = (misfit, p)
    return best[1]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results")
    parser.add_argument("--corners", default="-0.4,0;0.4,0;-0.6,-0.5;0.6,-0.5", help="the dovetail slot's by default")
    parser.add_argument("--radius", type=float, default=0.1)
    parser.add_argument("--every", type=int, default=2, help="print every K-th node")
    a = parser.parse_args()
    f = h5py.File(a.results, "r")
    scenes = f["scenes"]
    layers = layer_scenes(scenes)
    limit = scenes[[k for k in scenes if k.endswith("-limit-fast")][0]]
    eps = np.array([scenes[k].attrs["eps"] for k in layers])
    status = lambda v: "".join("GSK"[int(x)] for x in v)
    print("combined status per eps (limit last):")
    for e, k in zip(eps, layers):
        print(f"  {e:9.2e} {status(scenes[k]['combined_status'][()])}")
    print(f"  limit     {status(limit['interface/S/status'][()])}")
    for q in ("sigma_N", "sigma_T"):
        fields = [scenes[k]["interface/S+/" + q][()] for k in layers]
        d = [np.abs(fields[i] - fields[i + 1]) for i in range(len(fields) - 1)]
        print(f"\n{q}: difference to the next eps per node (x 1e3), then local slopes")
        for e, row in zip(eps, d):
            print(f"  {e:9.2e} " + " ".join(f"{v * 1e3:6.2f}" for v in row[::a.every]))
        for i in range(len(d) - 1):
            slope = np.log(np.maximum(d[i], 1e-300) / np.maximum(d[i + 1], 1e-300)) / np.log(eps[i] / eps[i + 1])
            print(f"  {eps[i]:9.2e} " + " ".join(f"{v:6.2f}" for v in slope[::a.every]))
    corners = np.array([[float(c) for c in p.split(",")] for p in a.corners.split(";")])
    X = limit["mesh/nodes"][()]
    far = np.min(np.linalg.norm(X[:, None, :] - corners[None], axis=2), axis=1) > a.radius
    x_S = limit["interface/S/x"][()]
    far_S = np.min(np.linalg.norm(x_S[:, None, :] - corners[None], axis=2), axis=1) > a.radius
    w = limit["interface/S/length"][()]
    n = X.shape[0]
    print(f"\nCauchy rates (local slopes), over all nodes and farther than {a.radius} from the corners:")
    for name, values, weights in [
            ("u", [scenes[k]["u"][:n] for k in layers], None),
            ("u_away", [scenes[k]["u"][:n][far] for k in layers], None),
            ("sigma_N_away", [scenes[k]["interface/S+/sigma_N"][()][far_S] for k in layers], w[far_S]),
            ("sigma_T_away", [scenes[k]["interface/S+/sigma_T"][()][far_S] for k in layers], w[far_S])]:
        d = np.array([np.sqrt(((values[i] - values[i + 1]) ** 2 * (1 if weights is None else weights)).sum())
                      for i in range(len(values) - 1)])
        slopes = np.log(d[:-1] / d[1:]) / np.log(eps[:-2] / eps[1:-1])
        print(f"  {name:13s} p = {fit(eps, d):.2f}  (" + " ".join(f"{s:.2f}" for s in slopes) + ")")
    return 0


if __name__ == "__main__":
    sys.exit(main())

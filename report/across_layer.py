"""The displacement jump across a whole layer, adherent to adherent, from a layer scene.

A layer scene stores the jumps of its two contact faces (S+: upper adherent / layer, S-:
layer / lower adherent), not the jump across the layer, which is what the limit law's [u]
stands for. That jump is the difference of the two adherents' displacements at matched
points of S+ and S-; we read it from `u` at the adherents' nodes.

At each face point two mesh nodes coincide (one per body on either side). Which is which is
decided by the stored face jump: with the SPEC §4 conventions (normal n from the minus side
into the plus side, tangent t = n turned clockwise) jump_N = (u⁻ − u⁺)·n and
jump_T = (u⁺ − u⁻)·t, and only one assignment reproduces it. Where both do, the two nodes
move together and the choice does not matter. A point with a single node faces a rigid body
(the bar's foundation), whose displacement is zero.
"""

import numpy as np

from results_file import array
from scenes import arc_length


def tangent(normal):
    return np.stack([normal[:, 1], -normal[:, 0]], axis=1)


def face_displacements(nodes, u, face):
    """Displacements of the plus-side and minus-side bodies at each point of a face."""
    x, n = face["x"], face["normal"]
    t = tangent(n)
    tol = 1e-9 * max(1.0, float(np.abs(nodes).max()))
    close = np.linalg.norm(nodes[None, :, :] - x[:, None, :], axis=2) <= tol
    plus = np.zeros_like(x)
    minus = np.zeros_like(x)
    zero = np.zeros(2)
    for k in range(len(x)):
        found = np.flatnonzero(close[k])
        if len(found) >= 2:
            options = [(u[found[0]], u[found[1]]), (u[found[1]], u[found[0]])]
        elif len(found) == 1:
            options = [(u[found[0]], zero), (zero, u[found[0]])]
        else:
            raise ValueError(f"no mesh node at interface point {x[k]}")

        def misfit(pair):
            up, um = pair
            return abs((um - up) @ n[k] - face["jump_N"][k]) + abs((up - um) @ t[k] - face["jump_T"][k])
        plus[k], minus[k] = min(options, key=misfit)
    return plus, minus


def across_layer(f, scene_id):
    """Per point of S+: arc length s, the across-layer jumps J_N, J_T (same conventions as
    the limit law's [u]_N, [u]_T), the stresses on S+, the combined status, the length."""
    node = f["scenes"][scene_id]
    nodes, u = array(node["mesh"], "nodes"), array(node, "u")
    faces = {}
    for name in ("S+", "S-"):
        g = node["interface"][name]
        faces[name] = {k: array(g, k) for k in ("x", "normal", "jump_N", "jump_T", "sigma_N", "sigma_T", "length")}
    upper, _ = face_displacements(nodes, u, faces["S+"])       # the adherent above the layer
    _, lower_all = face_displacements(nodes, u, faces["S-"])   # the adherent below it
    # The faces are matched point to point; where S- has more points (the bar's node under D)
    # take, for each S+ point, the nearest S- point.
    xp, xm = faces["S+"]["x"], faces["S-"]["x"]
    nearest = np.argmin(np.linalg.norm(xp[:, None, :] - xm[None, :, :], axis=2), axis=1)
    lower = lower_all[nearest]
    n = faces["S+"]["normal"]
    d = lower - upper
    status = array(node, "combined_status") if "combined_status" in node else np.full(len(xp), -1)
    return {
        "s": arc_length(xp),
        "J_N": np.einsum("ij,ij->i", d, n),
        "J_T": -np.einsum("ij,ij->i", d, tangent(n)),
        "sigma_N": faces["S+"]["sigma_N"],
        "sigma_T": faces["S+"]["sigma_T"],
        "status": status[: len(xp)],
        "length": faces["S+"]["length"],
    }


def stiffness_ratios(fields):
    """Node-wise −σ_N/J_N over nodes in contact (not gap, compressed, interpenetrating) and
    −σ_T/J_T over stick nodes: the layer's apparent normal and tangential stiffness."""
    status, jn, jt = fields["status"], fields["J_N"], fields["J_T"]
    sn, st = fields["sigma_N"], fields["sigma_T"]
    scale_n = max(np.abs(jn).max(initial=0.0), 1e-300)
    scale_t = max(np.abs(jt).max(initial=0.0), 1e-300)
    contact = (status != 0) & (sn < 0) & (jn > 1e-9 * scale_n)
    stick = (status == 2) & (np.abs(jt) > 1e-9 * scale_t) & (st != 0)
    return -sn[contact] / jn[contact], -st[stick] / jt[stick]

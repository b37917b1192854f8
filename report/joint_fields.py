"""The fields along each bondline of a scene-file scene, read from the results file alone (SPEC §5,
"the answer drawn"): arc length, the stresses on the plus adherent's face (peel σ_N, shear σ_T;
σ_N > 0 is tension) and the jumps across the whole bondline — in layer mode across the layer, from
the two adherents' nodes of each point (node_plus of S+ and node_minus of S-), so that both modes
show the quantity the limit law's [u] stands for — and the status of each node (a layer scene's
combined status).

Names of the interfaces (cases/scene/scene_model.h): "S", "S+", "S-" in the one-bondline form,
"<group>/S", ... in the list form; the bondline's own attributes are on `interface` or
`interface/<group>`. The arc length is measured along the minus side (S in limit mode, S- in
layer mode: positions the layer mode does not move), from the bondline's first node.
"""

from dataclasses import dataclass

import numpy as np

from results_file import array, attr, strings
from scenes import arc_length


@dataclass
class Bondline:
    name: str          # its group ("" in the one-bondline form)
    s: np.ndarray      # mm
    sigma_N: np.ndarray
    sigma_T: np.ndarray
    jump_N: np.ndarray  # mm
    jump_T: np.ndarray
    status: np.ndarray
    # On the minus adherent's face: the layer's other face (S-) in layer mode, the same as the plus
    # face's in limit mode. A layer's two faces differ near its ends; the worse one breaks.
    sigma_N_minus: np.ndarray = None
    sigma_T_minus: np.ndarray = None
    x: np.ndarray = None       # positions along the bondline (the minus side's), mm
    normal: np.ndarray = None  # unit normals, minus into plus


def bondline_groups(scene):
    """The bondlines of a scene group: [(name, group of its interfaces)] in file order."""
    interface = scene["interface"]
    if "S" in interface or "S+" in interface:
        return [("", interface)]
    return [(name, interface[name]) for name in interface]


def bondline_fields(scene):
    """One Bondline per bondline of the scene group `scene` (an h5py group under /scenes)."""
    u = array(scene, "u")
    out = []
    combined_all = array(scene, "combined_status") if "combined_status" in scene else None
    offset = 0
    for name, g in bondline_groups(scene):
        if "S" in g:  # limit mode (or a law only in layer mode): S has it all
            S = g["S"]
            x, status = array(S, "x"), array(S, "status")
            fields = Bondline(name, arc_length(x), array(S, "sigma_N"), array(S, "sigma_T"), array(S, "jump_N"),
                              array(S, "jump_T"), status, array(S, "sigma_N"), array(S, "sigma_T"), x,
                              array(S, "normal"))
        else:
            plus, minus = g["S+"], g["S-"]
            n = array(minus, "normal")
            up = u[array(plus, "node_plus")]
            um = u[array(minus, "node_minus")]
            d = um - up  # u⁻ − u⁺
            t = np.column_stack([n[:, 1], -n[:, 0]])
            if "combined_status" in g:
                status = array(g, "combined_status")
            elif combined_all is not None:
                status = combined_all[offset:offset + len(n)]
            else:
                status = array(plus, "status")
            fields = Bondline(name, arc_length(array(minus, "x")), array(plus, "sigma_N"), array(plus, "sigma_T"),
                              np.sum(n * d, axis=1), -np.sum(t * d, axis=1), status, array(minus, "sigma_N"),
                              array(minus, "sigma_T"), array(minus, "x"), n)
        offset += len(fields.s)
        out.append(fields)
    return out


def scene_units(scene):
    """(stress unit, force unit) a scene's numbers are in (mm-daN unless it says mm-N)."""
    units = attr(scene, "units", "mm-daN")
    return ("MPa", "N") if units == "mm-N" else ("daN/mm²", "daN")


def peaks(fields):
    """(largest tension σ_N⁺ and its arc length, largest |σ_T| and its arc length)."""
    k_peel = int(np.argmax(fields.sigma_N))
    k_shear = int(np.argmax(np.abs(fields.sigma_T)))
    return max(fields.sigma_N[k_peel], 0.0), fields.s[k_peel], abs(fields.sigma_T[k_shear]), fields.s[k_shear]


def study_scene_ids(study, name):
    """A study's dataset of scene ids (layer_scene, limit_scene) as a list."""
    return strings(study[name]) if name in study else []

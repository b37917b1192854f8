"""The scenes under /scenes: an index of their attributes (cheap: no dataset is read) and
readers for the interface fields a figure needs."""

from dataclasses import dataclass, field

import numpy as np

from results_file import array, attr, group


@dataclass
class Scene:
    id: str
    case: str
    mode: str
    law_case: str
    solver: str
    eps: float
    gamma: float
    delta: float
    lambda_bar: float
    mu_bar: float
    converged: int
    residual: float
    wall_time_s: float
    attrs: dict = field(repr=False, default_factory=dict)


def index_scenes(f):
    """Every scene's attributes, in the file's (alphabetical) order."""
    g = group(f, "scenes")
    if g is None:
        return []
    scenes = []
    for sid, node in g.items():
        a = {name: attr(node, name) for name in node.attrs}
        scenes.append(Scene(
            id=sid, case=a.get("case", ""), mode=a.get("mode", ""), law_case=a.get("law_case", ""),
            solver=a.get("solver", ""), eps=float(a.get("eps", np.nan)), gamma=float(a.get("gamma", np.nan)),
            delta=float(a.get("delta", np.nan)), lambda_bar=float(a.get("lambda_bar", np.nan)),
            mu_bar=float(a.get("mu_bar", np.nan)), converged=int(a.get("converged", 0)),
            residual=float(a.get("residual", np.nan)), wall_time_s=float(a.get("wall_time_s", np.nan)),
            attrs=a))
    return scenes


def find(scenes, **match):
    """The scenes whose fields equal every keyword given."""
    return [s for s in scenes if all(getattr(s, k) == v for k, v in match.items())]


def read_interface(f, scene_id, name):
    """The datasets of /scenes/<id>/interface/<name> as a dict of arrays."""
    g = f["scenes"][scene_id]["interface"][name]
    return {k: array(g, k) for k in g.keys()}


def scene_status(f, scene_id):
    """The status per node of S: the limit scene's `S`, or a layer scene's combined status
    (gap if either face is open, else slide if either slides), with the positions of the
    face it is reported on (S for the limit, S+ for the layer)."""
    node = f["scenes"][scene_id]
    if "combined_status" in node:
        status = array(node, "combined_status")
        x = array(node["interface"]["S+"], "x")[: len(status)]
        return x, status
    return array(node["interface"]["S"], "x"), array(node["interface"]["S"], "status")


def arc_length(x):
    """Distance along the polyline through the points x (M×2), starting at 0."""
    x = np.asarray(x, dtype=float)
    if len(x) == 0:
        return np.zeros(0)
    steps = np.linalg.norm(np.diff(x, axis=0), axis=1)
    return np.concatenate([[0.0], np.cumsum(steps)])

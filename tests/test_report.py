#!/usr/bin/python3
"""Tests of report/make_report.py on small synthetic results files written with h5py.

Run with Debian's interpreter (it sees python3-h5py and python3-matplotlib):
    /usr/bin/python3 tests/test_report.py
CTest runs it as `report_py` when that interpreter imports both.
"""

import os
import re
import subprocess
import sys
import tempfile
import unittest

import h5py
import numpy as np

MAKE_REPORT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "report", "make_report.py")
STR = h5py.string_dtype()


# --- Synthetic results files ---------------------------------------------------------------

def strings(values):
    return np.array(values, dtype=object)


def scene_attrs(g, **a):
    defaults = dict(case="bar", mode="limit", law_case="table3-row-1", eps=0.0, gamma=1.0, delta=1.0,
                    lambda_bar=4.5e8, mu_bar=5.4e8, friction=1.0, plane="strain", element="Q1", solver="fast",
                    iterations=3, residual=1e-13, converged=1, wall_time_s=1e-3, status_tolerance=1e-6,
                    tolerance=1e-10, nx=32, ny=32)
    defaults.update(a)
    for k, v in defaults.items():
        g.attrs[k] = v


def write_interface(g, x, normal, jump_n, jump_t, sigma_n, sigma_t, status):
    m = len(x)
    g["x"], g["normal"] = np.asarray(x, float), np.asarray(normal, float)
    g["length"] = np.full(m, 1.0 / m)
    g["jump_N"], g["jump_T"] = np.asarray(jump_n, float), np.asarray(jump_t, float)
    g["sigma_N"], g["sigma_T"] = np.asarray(sigma_n, float), np.asarray(sigma_t, float)
    g["status"] = np.asarray(status, np.int32)


def write_bar_scene(f, row, solver="fast"):
    """A bar limit scene: 32 nodes along AD with a gap / slide / stick pattern."""
    sid = f"bar-table3-row-{row}-Q1-32x32-plane_strain-{solver}"
    g = f.create_group(f"scenes/{sid}")
    scene_attrs(g, law_case=f"table3-row-{row}", solver=solver)
    x = np.stack([np.arange(32) * 1.25, np.zeros(32)], axis=1)
    status = np.array([0] * 3 + [1] * 14 + [2] * 15)
    write_interface(g.create_group("interface/S"), x, np.tile([0.0, 1.0], (32, 1)),
                    np.where(status == 0, -1e-4, 0.0), np.linspace(1e-2, 0, 32) * row,
                    np.where(status == 0, 0.0, -5.0), np.where(status == 0, 0.0, 2.0), status)
    g["mesh/nodes"], g["mesh/cells"] = np.zeros((4, 2)), np.zeros((1, 4), np.int32)
    g["u"] = np.zeros((4, 2))
    g["reactions/D"] = np.zeros(2)
    return sid


def write_bar_layer_scene(f, row, eps):
    """A bar layer scene: S+ (32 nodes) and S- (33 nodes), with the combined status."""
    sid = f"bar-table3-row-{row}-Q1-32x32-plane_strain-fast-layer-eps{eps:g}"
    g = f.create_group(f"scenes/{sid}")
    # Film admissibility (SPEC 1.5): the thinnest of these layers slid 56 elements (the bar's row 5
    # film at 1e-4 slides 70 mm), the others stayed put.
    scene_attrs(g, mode="layer", law_case=f"table3-row-{row}", eps=eps, lambda_eps=eps * 4.5e8,
                mu_eps=eps * 5.4e8, layer_elements=2, film_slip_over_h=55.8 if eps < 1e-3 else 0.01,
                film_strain_max=200.0 if eps < 1e-3 else 1e-5)
    status = np.array([0] * 3 + [1] * 14 + [2] * 15)
    for face, m, y in (("S+", 32, 0.0), ("S-", 33, -eps)):
        x = np.stack([np.arange(m) * 1.25, np.full(m, y)], axis=1)
        st = np.concatenate([status, [2]])[:m]
        write_interface(g.create_group(f"interface/{face}"), x, np.tile([0.0, 1.0], (m, 1)), np.zeros(m),
                        np.zeros(m), np.full(m, -5.0), np.full(m, 2.0), st)
    g["combined_status"] = status.astype(np.int32)
    g["mesh/nodes"], g["mesh/cells"], g["u"] = np.zeros((4, 2)), np.zeros((1, 4), np.int32), np.zeros((4, 2))


def write_dovetail_scenes(f, case, gamma, delta, lambda_bar, mu_bar, eps_values):
    """A limit scene and layer scenes along a straight S (y = 0, 5 nodes) whose layer is
    compressed by c and sheared by d, with stresses that make its apparent stiffness
    tend to K_N = λ̄ + 2μ̄, K_T = μ̄ as ε → 0."""
    m = 5
    xs = np.linspace(0.0, 1.0, m)
    normal = np.tile([0.0, 1.0], (m, 1))
    status = np.array([0, 1, 2, 2, 2])
    k_n, k_t = lambda_bar + 2 * mu_bar, mu_bar
    c, d = 1e-4, 2e-4
    limit_id = f"dovetail-limit-{case}-h0.25-fast"
    g = f.create_group(f"scenes/{limit_id}")
    scene_attrs(g, case="dovetail", law_case=case, gamma=gamma, delta=delta, lambda_bar=lambda_bar,
                mu_bar=mu_bar, friction=0.5)
    write_interface(g.create_group("interface/S"), np.stack([xs, np.zeros(m)], 1), normal,
                    np.full(m, c), np.full(m, d), np.full(m, -k_n * c), np.full(m, -k_t * d), status)
    g["mesh/nodes"], g["mesh/cells"], g["u"] = np.zeros((m, 2)), np.zeros((1, 4), np.int32), np.zeros((m, 2))
    layer_ids = []
    for eps in eps_values:
        sid = f"dovetail-layer-{case}-eps{eps:g}-h0.25-fast"
        layer_ids.append(sid)
        g = f.create_group(f"scenes/{sid}")
        scene_attrs(g, case="dovetail", mode="layer", law_case=case, eps=eps, gamma=gamma, delta=delta,
                    lambda_bar=lambda_bar, mu_bar=mu_bar, friction=0.5, lambda_eps=eps * lambda_bar,
                    mu_eps=eps * mu_bar, layer_elements=1, film_slip_over_h=0.0, film_strain_max=0.0)
        # Nodes: base and layer bottom at y = 0, layer top and tenon at y = eps (coincident pairs).
        bottom, top = np.stack([xs, np.zeros(m)], 1), np.stack([xs, np.full(m, eps)], 1)
        nodes = np.concatenate([bottom, bottom, top, top])
        u_tenon = np.tile([d, -c], (m, 1))
        u = np.concatenate([np.zeros((m, 2)), np.zeros((m, 2)), u_tenon, u_tenon])
        g["mesh/nodes"], g["u"] = nodes, u
        g["mesh/cells"] = np.array([[m + k, m + k + 1, 2 * m + k + 1, 2 * m + k] for k in range(m - 1)], np.int32)
        scale = 1.0 - 10 * eps  # the layer is softer than its limit by O(eps)
        for face, x in (("S+", top), ("S-", bottom)):
            write_interface(g.create_group(f"interface/{face}"), x, normal, np.zeros(m), np.zeros(m),
                            np.full(m, -k_n * c * scale), np.full(m, -k_t * d * scale), status)
        g["combined_status"] = status.astype(np.int32)
    return limit_id, layer_ids


def write_table3_study(f, with_sensitivity=True):
    g = f.create_group("studies/table3")
    g.attrs["missing_transition_mm"] = -1.0
    rows = g.create_group("rows")
    rows["row"] = np.arange(1, 7, dtype=np.int32)
    paper = np.array([[3, 16, 13], [3, 14, 15], [3, 13, 16], [0, 0, 32], [0, 0, 32], [0, 0, 32]], np.int32)
    base = np.array([[3, 14, 15], [2, 6, 24], [0, 7, 25], [0, 0, 32], [0, 0, 32], [0, 0, 32]], np.int32)
    for prefix, counts in (("paper", paper), ("baseline", base), ("fast", base), ("relaxation", base)):
        for j, name in enumerate(("gap", "slide", "stick")):
            rows[f"{prefix}_{name}"] = counts[:, j]
    for solver in ("fast", "relaxation"):
        rows[f"{solver}_iterations"] = np.full(6, 5, np.int32)
        rows[f"{solver}_time_s"] = np.full(6, 1e-3)
        rows[f"{solver}_residual"] = np.full(6, 1e-12)
    rows["interface_jump_distance"] = np.full(6, 1e-10)
    ref = g.create_group("refinement")
    ref["n"] = np.array([32, 64], np.int32)
    for r in range(1, 7):
        ref[f"row{r}/gap_contact_mm"] = np.array([3.75, 3.12]) if r < 3 else np.array([-1.0, -1.0])
        ref[f"row{r}/stick_slip_mm"] = np.array([21.25, 21.3]) if r < 4 else np.array([-1.0, -1.0])
    if with_sensitivity:
        s = g.create_group("sensitivity")
        n = 12
        s.create_dataset("plane", data=strings(["strain", "stress"] * 6), dtype=STR)
        s.create_dataset("element", data=strings(["Q1", "P1-left", "P1-right"] * 4), dtype=STR)
        s["nx"], s["ny"] = np.full(n, 32, np.int32), np.array([8, 16] * 6, np.int32)
        s["row"] = np.repeat(np.arange(1, 7), 2).astype(np.int32)
        s["gap"], s["slide"], s["stick"] = (np.full(n, 3, np.int32), np.full(n, 16, np.int32),
                                            np.full(n, 13, np.int32))
        s["converged"], s["matches_paper"] = np.ones(n, np.int32), np.array([1, 0] * 6, np.int32)
        s["scale"], s["residual"] = np.ones(n), np.full(n, 1e-12)
        s["gap_contact_mm"], s["stick_slip_mm"] = np.full(n, 3.0), np.full(n, 22.0)


def write_convergence_study(f, case, limit_id, layer_ids, eps, p_fit, passed):
    g = f.require_group("studies/convergence")
    g.attrs.update(dict(tolerance=1e-8, corner_radius=0.1, primary_quantity="u_away", rate_tolerance=0.15))
    c = g.create_group(case)
    c.attrs.update({"gamma": 1.0, "delta": 1.0, "p_predicted": 1.0, "p_fit": p_fit, "p_stderr": 0.05,
                    "C_fit": 0.1, "pass": int(passed)})
    c.attrs["limit_scene"] = limit_id
    c["eps"] = np.asarray(eps)
    for q in ("u", "u_away", "jump_N", "jump_T", "sigma_N", "sigma_T", "jump_N_away", "jump_T_away",
              "sigma_N_away", "sigma_T_away"):
        c[f"e_{q}"] = 0.1 * np.asarray(eps) ** p_fit
        c.attrs[f"p_{q}"], c.attrs[f"p_{q}_stderr"] = p_fit, 0.05
    c["status_diff"] = np.zeros(len(eps), np.int32)
    c.create_dataset("layer_scene", data=strings(layer_ids), dtype=STR)


def write_cauchy_rates(f, case, p, passed, measurable=True):
    """The rate grid of one case: differences C ε_k^p, all converged (or none, not measurable)."""
    eps = 10.0 ** (-np.arange(8, 13) / 2)
    c = f["studies/convergence"][case].create_group("cauchy")
    c["eps"] = eps
    c["converged"] = np.full(len(eps), int(measurable), np.int32)
    c["iterations"] = np.full(len(eps), 30, np.int32)
    c["residual"] = np.full(len(eps), 1e-12 if measurable else 1e-6)
    c["status_changes"] = np.zeros(len(eps) - 1, np.int32)
    checked = ("R_top", "u", "u_away", "sigma_N_away", "sigma_T_away")
    for q in checked:
        c["d_" + q] = 0.02 * eps[:-1] ** p
        c["in_tail_" + q] = np.full(len(eps) - 1, int(measurable), np.int32)
        c.attrs.update({"p_" + q: p if measurable else 0.0, f"p_{q}_stderr": 0.01, "C_" + q: 0.02,
                        "points_" + q: 4 if measurable else 0, "fitted_" + q: int(measurable),
                        "pass_" + q: int(passed)})
    c.attrs.update(dict(checked=",".join(checked), p_predicted=0.5, grid_ratio=10 ** -0.5))


def write_controls(f):
    """S2's controls: the quadrature of case (e) (a reach falling like ε^(−1/4)) and the two selections."""
    q = f.create_group("studies/convergence/controls/quadrature")
    eps = 10.0 ** -np.arange(4, 9)
    q["eps"], q["reach"] = eps, 0.05 * eps ** -0.25
    for side, p in (("selective", -0.3), ("rule", 0.45)):
        s = q.create_group(side)
        s["converged"] = np.ones(len(eps), np.int32)
        s.create_dataset("layer_scene", data=strings([f"dovetail-layer-e-eps{e:g}-{side}" for e in eps]), dtype=STR)
        s["zigzag_rms"] = np.full(len(eps), 0.2 if side == "selective" else 0.01)
        s["d_sigma_N_away"] = 1e-3 * eps[:-1] ** p / eps[0] ** p
        s.attrs.update(dict(slope_sigma_N_away=p, slope_sigma_N_away_stderr=0.01, fitted=1))
    q.attrs.update(dict(law_case="e", reach_exponent=-0.25, reach_exponent_stderr=0.01, reach_fitted=1,
                        predicted_reach_exponent=-0.25))
    s = f.create_group("studies/convergence/controls/selection")
    s.create_dataset("case", data=strings(["e", "e"]), dtype=STR)
    s.create_dataset("quadrature", data=strings(["rule", "selective"]), dtype=STR)
    s["eps"], s["converged"] = np.array([5e-4, 5e-4]), np.ones(2, np.int32)
    s["spread_R_top"], s["cauchy_R_top"] = np.array([1e-12, 2.5e-5]), np.array([3e-4, 3e-4])
    s.attrs["agreement"] = 1e-8


def write_floor(f):
    g = f["studies/convergence"].create_group("floor")
    h = np.array([0.1, 0.05, 0.025])
    g["h"], g["S_nodes"], g["converged"] = h, np.array([25, 45, 93], np.int32), np.ones(3, np.int32)
    for q in ("R_top", "u", "sigma_N"):
        g["floor_" + q], g["eps_part_" + q] = 0.03 * h, np.full(3, 1e-6)
        g.attrs.update({"rate_" + q: 1.0, f"rate_{q}_stderr": 0.01, "fitted_" + q: 1})
    g.attrs.update(dict(law_case="d", eps=10 ** -5.5, eps_previous=1e-5))


def write_validity_and_thresholds(f):
    v = f.create_group("studies/validity")
    v.create_dataset("case", data=strings(["b", "b", "d", "d"]), dtype=STR)
    v["tau"] = np.array([0.01, 0.05, 0.01, 0.05])
    v["eps_max"] = np.array([2e-3, 1e-2, 1e-4, 5e-3])
    v.create_dataset("status", data=strings(["found", "at_least", "below_range", "found"]), dtype=STR)
    v["error_at_eps_max"] = np.array([0.01, 0.003, 0.02, 0.05])
    v["bisection_steps"] = np.array([2, 0, 0, 2], np.int32)
    v.attrs["quantity"], v.attrs["paper_claim"] = "u", 1e-3
    t = f.create_group("studies/thresholds")
    t.attrs.update(dict(threshold_low=0.03, threshold_high=30.0, confirmed="all confirmed"))
    ratio = np.geomspace(1e-4, 1e4, 17)
    for p in ("lambda", "mu"):
        s = t.create_group(p)
        s["ratio"], s["error_zero"], s["error_inf"] = ratio, 0.05 * ratio / (1 + ratio), 0.05 / (1 + ratio)
        s.attrs["fixed_other"] = "the other at its reference value"
    c = t.create_group("crossings")
    c.create_dataset("param", data=strings(["lambda", "lambda", "mu", "mu"]), dtype=STR)
    c.create_dataset("law", data=strings(["0", "inf", "0", "inf"]), dtype=STR)
    c["tau"], c["ratio"] = np.full(4, 0.01), np.array([0.25, 4.0, 0.25, 4.0])
    c.create_dataset("status", data=strings(["found"] * 4), dtype=STR)


def write_timing(f):
    t = f.create_group("studies/timing")
    t.create_dataset("solver", data=strings(["fast", "fast", "relaxation", "relaxation"]), dtype=STR)
    t.create_dataset("level", data=strings(["coarse", "fine"] * 2), dtype=STR)
    t["time_s"], t["error"] = np.array([1e-3, 1e-2, 0.1, 1.0]), np.array([1e-2, 1e-3, 1e-2, 1e-3])


def write_timing_extras(f):
    """The groups the full S5 adds: meshes and ratios, linear solves, growth fits, targets, shortcuts."""
    t = f["studies/timing"]
    t.create_dataset("mesh", data=strings(["bar-32", "bar-64"] * 2), dtype=STR)
    t["unknowns"], t["tolerance"] = np.array([2144, 8384] * 2), np.array([1e-10] * 4)
    t["converged"], t["ratio_to_linear"] = np.array([1, 1, 1, 1]), np.array([2.0, 3.0, 20.0, 30.0])
    lin = t.create_group("linear")
    lin.create_dataset("level", data=strings(["bar-32", "bar-64"]), dtype=STR)
    lin["unknowns"], lin["time_s"] = np.array([2144, 8384]), np.array([5e-4, 3e-3])
    sc = t.create_group("scaling")
    sc.create_dataset("solver", data=strings(["fast", "linear"]), dtype=STR)
    sc["exponent"], sc["exponent_stderr"], sc["points"] = np.array([1.5, 1.3]), np.array([0.1, 0.1]), np.array([3, 3])
    tg = t.create_group("targets")
    for name, values in (("target", ["limit-mode solve / linear", "relaxation / fast"]), ("goal", ["<= 1.5", ">= 100"]),
                         ("measured", ["1.2", "9.7"])):
        tg.create_dataset(name, data=strings(values), dtype=STR)
    tg["met"] = np.array([1, 0])
    sk = t.create_group("skip")
    sk.create_dataset("shortcut", data=strings(["factorisation_reuse_table3"]), dtype=STR)
    sk.create_dataset("scenes", data=strings(["bar, 6 rows"]), dtype=STR)
    sk["time_with_s"], sk["time_without_s"], sk["saving"], sk["difference"] = [0.02], [0.1], [5.0], [0.0]


def write_stress(f):
    """Two stress scenes: one converged as claimed, one that wrote NaN (which the report must flag)."""
    g = f.create_group("studies/stress")
    for name, values in (("scene", ["friction.f1.fast", "thickness.bar-layer-eps1e-08"]),
                         ("group", ["friction", "thickness"]),
                         ("description", ["bar limit, f = 1", "bar layer, eps 1e-8"]), ("solver", ["fast", "fast"]),
                         ("outcome", ["converged", "non-finite values"]), ("expected", ["converged", ""]),
                         ("message", ["converged after 7 steps", "NaN in the iterate"]), ("counts", ["3/14/15", ""])):
        g.create_dataset(name, data=strings(values), dtype=STR)
    g["iterations"], g["residual"] = np.array([7, 300]), np.array([1e-13, -1.0])
    g["condition_estimate"], g["time_s"], g["finite"] = np.array([400.0, 1e18]), np.array([0.02, 7.0]), np.array([1, 0])


def write_scene_study(f):
    """S2 and S3 on a scene file (verify's lap joint, SPEC §5): /studies/scene/<name>."""
    g = f.create_group("studies/scene/lap-joint")
    eps = np.array([0.1, 0.01, 0.001, 0.0001])
    g["eps"] = eps
    for q in ("u", "jump_N", "jump_T", "sigma_N", "sigma_T"):
        g["e_" + q] = 0.03 * eps / 0.1
        g.attrs["p_" + q], g.attrs["p_" + q + "_stderr"], g.attrs["fitted_" + q] = 1.0, 0.01, 1
        g.attrs["p_floor_" + q], g.attrs["floor_" + q], g.attrs["fitted_floor_" + q] = 1.0, 0.0, 1
    g["status_diff"], g["converged"] = np.array([0, 0, 1, 1]), np.array([1, 1, 1, 1])
    g.create_dataset("layer_scene", data=strings([f"lap-joint-layer-eps{e:g}-fast" for e in eps]), dtype=STR)
    g.attrs["scene_file"], g.attrs["table1_case"], g.attrs["p_predicted"] = "lap_joint.json", "d", 1.0
    v = g.create_group("validity")
    v["tau"], v["eps_max"], v["error_at_eps_max"] = np.array([0.01, 0.05]), np.array([0.0316, 0.1]), np.array([0.0095, 0.03])
    v["eps_beyond"], v["bisection_steps"], v["converged"] = np.array([0.0562, 0.0]), np.array([2, 0]), np.array([1, 1])
    v.create_dataset("status", data=strings(["found", "at_least"]), dtype=STR)


def write_validity_map(f, name="a-joint"):
    """A validity map of 2 x 2 cells at one nu (studies/drivers/validity_map_output.cpp's layout): one
    cell the paper's rule gives another law, one that did not converge."""
    g = f.create_group(f"studies/validity_map/{name}")
    t, E = np.array([1e-2, 1e-1, 1e-2, 1e-1]), np.array([1e-3, 1e-3, 1e-1, 1e-1])
    g["t_over_L"], g["E_ratio"], g["nu"] = t, E, np.full(4, 0.45)
    g["converged"] = np.array([1, 1, 1, 0])
    g["rule_solved"] = np.array([0, 1, 0, 0])
    g["law_case"], g["rule_case"] = strings(["d", "d", "d", "d"]), strings(["d", "c", "d", "d"])
    for q in ("reactions", "u", "peel_at_d", "shear_at_d", "sigma_N", "sigma_T"):
        g[f"measured_{q}"] = 1e-3 * t / 1e-2
        g[f"estimate_{q}"] = 1.2e-3 * t / 1e-2
        g[f"interior_{q}"] = 1e-3 * t / 1e-2
        g[f"resolved_{q}"] = np.array([1, 1, 0, 1])
        g[f"ends_resolved_{q}"] = np.array([0, 1, 0, 1])
        g[f"within_{q}"] = np.array([1, 1, 0, 0])
        g[f"rule_{q}"] = np.array([-1.0, 1.0, -1.0, -1.0])
        g[f"order1_{q}"] = np.array([2e-4, 4e-3, 1e-5, 1e-4])  # order 1 <= order 0 / 3 at the first cell only
        g[f"order1_h_{q}"] = np.array([3e-4, 4e-3, 2e-5, 2e-4])
        g[f"order1_ratio_{q}"] = g[f"order1_{q}"][()] / g[f"measured_{q}"][()]
        g[f"order1_resolved_{q}"] = np.array([1, 1, 0, 0])
    for k, v in dict(characteristic_length=1.4, E_a=70000.0, peak_distance=0.5, peak_distance_reason="two elements",
                     h=0.25, h_fine=0.125, factor=2.0, wall_time_s=3.0, wall_time_ranks=1, wall_time_threads=1).items():
        g.attrs[k] = v


def write_checks(f, checks):
    g = f.create_group("checks")
    g.create_dataset("id", data=strings([c[0] for c in checks]), dtype=STR)
    g["pass"] = np.array([c[1] for c in checks], np.int32)
    for i, name in enumerate(("expected", "got", "tolerance"), start=2):
        g.create_dataset(name, data=strings([c[i] for c in checks]), dtype=STR)


PASSING_CHECKS = [("table3.row1.fast.baseline", 1, "3/14/15", "3/14/15", "exact"),
                  ("convergence.d.rate", 1, "p = 1 +- 0.15", "0.98", "0.15"),
                  ("validity.b.tau1pct.converged", 1, "converged", "yes", ""),
                  ("thresholds.solves_converged", 1, "0", "0", ""),
                  ("dovetail.d.limit.converged", 1, "residual <= 1e-10", "1e-13", "1e-10")]
FAILING_CHECK = ("table3.row2.relaxation.baseline", 0, "2/6/24", "2/7/23", "exact")


def write_results(path, layout=True, failing=False, complete=True, version=2):
    """A results file; `complete` adds every study group, otherwise only table3 (a quick run)."""
    with h5py.File(path, "w") as f:
        if layout:
            f.attrs["layout"] = "thinlayer-results"
            f.attrs["layout_version"] = version
        for row in range(1, 7):
            write_bar_scene(f, row, "fast")
            write_bar_scene(f, row, "relaxation")
        write_table3_study(f, with_sensitivity=complete)
        write_checks(f, PASSING_CHECKS + ([FAILING_CHECK] if failing else []))
        if not complete:
            return
        for row in (1, 2):
            for eps in (1e-2, 1e-4):
                write_bar_layer_scene(f, row, eps)
        env = f.create_group("environment")
        for k, v in dict(compiler="GCC 12", eigen="3.4.0", suitesparse="5.12.0", gmsh="4.8.4", hdf5="1.10.8",
                         commit="abc123").items():
            env.attrs[k] = v
        eps = [1e-2, 1e-3, 1e-4]
        for case, gamma, delta, lam in (("b", 1.5, 1.0, 0.0), ("d", 1.0, 1.0, 4500.0)):
            limit_id, layer_ids = write_dovetail_scenes(f, case, gamma, delta, lam, 5400.0, eps)
            write_convergence_study(f, case, limit_id, layer_ids, eps, p_fit=1.0 if case == "d" else 0.5,
                                    passed=True)
        write_cauchy_rates(f, "b", 0.5, passed=True)
        write_validity_map(f)
        write_cauchy_rates(f, "d", 0.0, passed=False, measurable=False)
        write_floor(f)
        write_controls(f)
        write_validity_and_thresholds(f)
        write_timing(f)
        write_timing_extras(f)
        write_stress(f)
        write_scene_study(f)


# --- The tests -----------------------------------------------------------------------------

def run_report(results, out_dir):
    return subprocess.run([sys.executable, MAKE_REPORT, results, out_dir], capture_output=True, text=True,
                          timeout=300)


class ReportTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory(prefix="test_report-")
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.dir, name)

    def assertBadInput(self, results, out_dir):
        r = run_report(results, out_dir)
        self.assertEqual(r.returncode, 2, r.stderr)
        lines = r.stderr.strip().splitlines()
        self.assertEqual(len(lines), 1, r.stderr)
        self.assertTrue(lines[0].startswith("make_report: "), r.stderr)
        return lines[0]

    def assertNothingLeftBehind(self):
        """No half-built report: only the inputs and any earlier report remain."""
        leftovers = [os.path.join(root, n) for root, dirs, files in os.walk(self.dir) for n in dirs + files
                     if ".building-" in n or ".previous-" in n]
        self.assertEqual(leftovers, [])

    def listing(self, folder):
        """Every file under folder with its bytes."""
        result = {}
        for root, _, files in os.walk(folder):
            for name in files:
                with open(os.path.join(root, name), "rb") as content:
                    result[os.path.relpath(os.path.join(root, name), folder)] = content.read()
        return result

    def test_complete_file_gives_every_figure(self):
        write_results(self.path("results.h5"))
        out = self.path("report")
        r = run_report(self.path("results.h5"), out)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "index.html"), encoding="utf-8") as page:
            html = page.read()
        images = re.findall(r'<img src="([^"]+)"', html)
        # Figs. 13, 14, 6-7, one convergence figure per case, thresholds, timing.
        self.assertGreaterEqual(len(images), 7, images)
        for src in images:
            self.assertTrue(os.path.isfile(os.path.join(out, src)), src)
        self.assertEqual(sorted(os.listdir(os.path.join(out, "figures"))),
                         sorted(os.path.basename(s) for s in images))
        self.assertEqual(re.findall(r"[^>]*: not in this results file", html), [])
        self.assertIn("5 checks, all pass", html)
        # The stress scene that wrote NaN is flagged; the converged one is not.
        self.assertRegex(html, r'<tr class="failrow">(<td[^>]*>[^<]*</td>){1}<td class="l">bar layer, eps 1e-8<')
        self.assertNotRegex(html, r'<tr class="failrow">(<td[^>]*>[^<]*</td>){1}<td class="l">bar limit, f = 1<')
        self.assertIn("Targets of issue 5", html)
        self.assertIn("factorisation_reuse_table3", html)
        # The scene-file study: its validity table, a bisected and a lower-bound row.
        self.assertIn("<b>0.0316</b>", html)
        self.assertIn("<b>≥ 0.1</b>", html)
        # S2's rates: a passing case, a case with no converged tail, the floor against h.
        self.assertIn("figures/convergence_cauchy.png", images)
        self.assertIn("figures/convergence_floor.png", images)
        rates = html[html.index('id="rates"'):]
        self.assertRegex(rates, r'<tr class="failrow"><td[^>]*>\(d\)</td>.*?not measurable <span class="fail">FAIL</span>')
        self.assertRegex(rates, r'<tr><td[^>]*>\(b\)</td><td[^>]*>0.5</td><td[^>]*>0.50 ± 0.01 <span class="pass">PASS</span>')
        self.assertIn("3.00e-03 (1.0e-06)", rates)  # the floor at h = 0.1 and its ε-part
        # S2's controls: the quadrature's figure and table, the two selections' spreads.
        controls = html[html.index('id="controls"'):html.index('id="validity"')]
        self.assertIn("figures/control_quadrature.png", images)
        self.assertIn("-0.25 ± 0.01 (derived -0.25)", controls)
        self.assertIn("-0.30 ± 0.01", controls)  # selective integration's rate of σ_N away
        self.assertIn("1.0e-12 / 3.0e-04", controls)
        self.assertIn("2.5e-05 / 3.0e-04", controls)
        # Film admissibility: the scenes that slid more than an element are listed, the others not.
        film = html[html.index('id="film"'):html.index('id="scenes"')]
        self.assertRegex(film, r"\d+ of \d+ layer scenes stray outside the assumptions")
        self.assertIn("55.8", film)
        self.assertNotIn("dovetail-layer-", film)
        self.assertNothingLeftBehind()

    def test_without_layout_attributes_the_file_is_called_foreign(self):
        write_results(self.path("old.h5"), layout=False)
        message = self.assertBadInput(self.path("old.h5"), self.path("report"))
        self.assertIn("foreign", message)
        self.assertNotIn("older", message)
        self.assertFalse(os.path.exists(self.path("report")))
        self.assertNothingLeftBehind()

    def test_reads_the_current_and_the_previous_layout_refuses_an_older_one(self):
        for version in (1, 2):
            write_results(self.path(f"v{version}.h5"), complete=False, version=version)
            r = run_report(self.path(f"v{version}.h5"), self.path(f"report{version}"))
            self.assertEqual(r.returncode, 0, r.stderr)
        write_results(self.path("v0.h5"), complete=False, version=0)
        self.assertIn("older", self.assertBadInput(self.path("v0.h5"), self.path("report0")))

    def test_writes_only_its_own_files_into_the_folder_of_its_input(self):
        """Issue 15: the report once deleted every file in OUT_DIR, its input included."""
        write_results(self.path("results.h5"), complete=False)
        with open(self.path("notes.txt"), "w") as notes:
            notes.write("the user's notes")
        os.makedirs(self.path("sub"))
        with open(self.path(os.path.join("sub", "data.csv")), "w") as data:
            data.write("1,2")
        before = self.listing(self.dir)
        r = run_report(self.path("results.h5"), self.dir)
        self.assertEqual(r.returncode, 0, r.stderr)
        after = self.listing(self.dir)
        for name, content in before.items():
            self.assertEqual(after.get(name), content, name)
        added = sorted(set(after) - set(before))
        self.assertIn("index.html", added)
        self.assertTrue(all(n == "index.html" or n.startswith("figures" + os.sep) for n in added), added)
        self.assertNothingLeftBehind()

    def test_refuses_to_replace_an_index_html_it_did_not_write(self):
        write_results(self.path("results.h5"), complete=False)
        out = self.path("site")
        os.makedirs(out)
        with open(os.path.join(out, "index.html"), "w") as page_file:
            page_file.write("<html>the user's own page</html>")
        self.assertIn("not a report this script wrote", self.assertBadInput(self.path("results.h5"), out))
        with open(os.path.join(out, "index.html")) as page_file:
            self.assertEqual(page_file.read(), "<html>the user's own page</html>")
        self.assertEqual(os.listdir(out), ["index.html"])

    def test_bad_inputs_leave_an_existing_report_alone(self):
        out = self.path("report")
        os.makedirs(out)
        with open(os.path.join(out, "index.html"), "w") as previous:
            previous.write("previous report")
        with open(self.path("not.h5"), "w") as junk:
            junk.write("not HDF5")
        with h5py.File(self.path("foreign.h5"), "w") as f:
            f.attrs["layout"] = "something-else"
        with h5py.File(self.path("newer.h5"), "w") as f:
            f.attrs["layout"], f.attrs["layout_version"] = "thinlayer-results", 3
        for name in ("missing.h5", "not.h5", "foreign.h5", "newer.h5"):
            self.assertBadInput(self.path(name), out)
            with open(os.path.join(out, "index.html")) as page:
                self.assertEqual(page.read(), "previous report", name)
        self.assertNothingLeftBehind()

    def test_failing_check_shows_as_failing(self):
        write_results(self.path("results.h5"), failing=True, complete=False)
        out = self.path("report")
        r = run_report(self.path("results.h5"), out)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "index.html"), encoding="utf-8") as page:
            html = page.read()
        self.assertIn("6 checks, 1 FAIL", html)
        self.assertIn('class="failtext"', html)
        # The failing check is spelled out in red, in the summary and beside Table 3.
        failing_rows = re.findall(r'<tr class="failrow">(.*?)</tr>', html, re.S)
        self.assertTrue(any(FAILING_CHECK[0] in row and '<span class="fail">FAIL</span>' in row
                            for row in failing_rows), failing_rows)

    def test_quick_run_says_what_is_absent(self):
        write_results(self.path("quick.h5"), complete=False)
        out = self.path("report")
        r = run_report(self.path("quick.h5"), out)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "index.html"), encoding="utf-8") as page:
            html = page.read()
        for absent in ("/studies/convergence", "/studies/convergence/&lt;case&gt;/cauchy", "/studies/validity",
                       "/studies/thresholds", "/studies/timing",
                       "/studies/stress",
                       "/environment", "/studies/table3/sensitivity"):
            self.assertRegex(html, re.escape(absent) + r"[^<]*\): not in this results file")

    def test_replaces_an_existing_report_and_only_its_figures(self):
        """The previous report's figures that the new one lacks go; a user's file stays."""
        write_results(self.path("results.h5"))
        out = self.path("report")
        self.assertEqual(run_report(self.path("results.h5"), out).returncode, 0)
        before = set(os.listdir(os.path.join(out, "figures")))
        with open(os.path.join(out, "figures", "mine.txt"), "w") as mine:
            mine.write("mine")
        write_results(self.path("quick.h5"), complete=False)
        r = run_report(self.path("quick.h5"), out)
        self.assertEqual(r.returncode, 0, r.stderr)
        after = set(os.listdir(os.path.join(out, "figures")))
        self.assertIn("mine.txt", after)
        self.assertLess(len(after), len(before) + 1)  # the figures of the complete file are gone
        with open(os.path.join(out, "index.html"), encoding="utf-8") as page_file:
            shown = set(re.findall(r'<img src="figures/([^"]+)"', page_file.read()))
        self.assertEqual(after - {"mine.txt"}, shown)
        self.assertNothingLeftBehind()

    def test_a_validity_map_file_gets_the_maps_report(self):
        """A file whose only study is a validity map: its report, a figure per quantity and the estimate's."""
        with h5py.File(self.path("map.h5"), "w") as f:
            f.attrs["layout"] = "thinlayer-results"
            f.attrs["layout_version"] = 2
            write_validity_map(f)
            write_checks(f, [])
        out = self.path("map_report")
        r = run_report(self.path("map.h5"), out)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "index.html"), encoding="utf-8") as page:
            html = page.read()
        self.assertIn("<title>thinlayer validity map: a-joint</title>", html)
        for q in ("reactions", "u", "peel_at_d", "shear_at_d", "estimate"):
            self.assertIn(f'figures/validity_map_a_joint_{q}.png', html)
            self.assertTrue(os.path.isfile(os.path.join(out, "figures", f"validity_map_a_joint_{q}.png")), q)
        self.assertIn("Where the paper's 3 % / 30x rule picks a 0 or ∞ law", html)  # the one cell it changes
        self.assertIn("4 cells, 3 converged", html)  # the failed cell counted, not dropped
        # Order one: the two converged cells above the floor, the first within a third of order 0.
        self.assertIn("Order one: the layer at h/2 against the first-order answer u1", html)
        self.assertIn('<td class="l">u</td><td>2</td><td>1</td>', html)
        self.assertNothingLeftBehind()


if __name__ == "__main__":
    unittest.main()

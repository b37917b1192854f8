"""Section 5: convergence of the layer model to the limit law (study S2), per dovetail case:
the distances e_q(ε) with the fitted and the predicted rate, and the status of each node of S
at every ε beside the limit law's."""

import h5py
import matplotlib.pyplot as plt
import numpy as np

from checks import checks_block, compact_verdict, with_prefix
from html_parts import absent, esc, how_to_read, num, section, table, verdict
from plotting import label_minor_log_ticks, status_legend, status_strip
from results_file import array, attr, group, strings
from scenes import arc_length, scene_status

GLOBAL = ("u", "jump_N", "jump_T", "sigma_N", "sigma_T")
AWAY = tuple(q + "_away" for q in GLOBAL)
COLORS = dict(zip(GLOBAL, ("k", "#1f77b4", "#2ca02c", "#d62728", "#9467bd")))
LABELS = {"u": "u (adherents)", "jump_N": "[u]_N", "jump_T": "[u]_T", "sigma_N": "σ_N", "sigma_T": "σ_T"}


def render(ctx):
    title = "5. Convergence to the limit law (study S2)"
    g = group(ctx.f, "studies/convergence")
    if g is None:
        return section("convergence", title, absent("The convergence study (/studies/convergence)"))
    primary = attr(g, "primary_quantity", "u_away")
    radius = attr(g, "corner_radius")
    body = [how_to_read(
        "For each dovetail case, both modes at every ε. e_q: relative discrete L² distance between the "
        "layer model and the limit law for the quantity q — the adherents' displacements u (nodes present "
        "in both modes) and the interface fields [u]_N, [u]_T, σ_N, σ_T — over the whole of S (left panel) "
        f"and farther than {num(radius)} mm from the slot corners (<em>_away</em>, middle panel). On one mesh "
        "this distance levels off at a floor set by the corners, so its fits (thick grey line: e_∞ + C ε^p of "
        f"<code>{esc(primary)}</code>; dashed: the predicted slope through the data's centre) are shown for "
        "comparison only: the rates are checked on the layer model's Cauchy differences and the floor is "
        "measured apart (next section). Right panel: status of each node along S (arc length from the top of the "
        "left flank, down the flank, along the bottom, up the right flank), one strip per ε and the limit law; "
        "'diff' = stored number of nodes whose combined status differs from the limit's (black dots: those "
        "nodes; dotted lines: the slot corners).")]
    info = [f"solver tolerance {num(attr(g, 'tolerance'))}"]
    effect = attr(g, "solver_tolerance_effect")
    if effect is not None:
        info.append(f"distances move by at most {num(effect, 2)} (relative) when a scene is re-solved tighter")
    body.append(f"<p>{esc('; '.join(info))}.</p>")
    cases = case_groups(g)
    body.append(summary_table(ctx, g, cases, primary))
    body.append(checks_block(ctx.checks, "convergence.", "the convergence study"))
    body.append(rates_table(g, cases))
    for case in cases:
        body.append(case_figure(ctx, g[case], case, primary))
    return section("convergence", title, "\n".join(body))


def case_groups(g):
    """The case letters under /studies/convergence (its other subgroups, like `floor`, are not cases)."""
    return sorted(k for k in g.keys() if isinstance(g[k], h5py.Group) and len(k) == 1)


def summary_table(ctx, g, cases, primary):
    rows, classes = [], []
    for case in cases:
        c = g[case]
        diff = array(c, "status_diff") if "status_diff" in c else []
        mine = with_prefix(ctx.checks, f"convergence.{case}.")
        failed = any(not ch.passed for ch in mine)
        rows.append([f"({esc(case)})", num(attr(c, "gamma")), num(attr(c, "delta")), num(attr(c, "p_predicted")),
                     rate_text(attr(c, "p_fit"), attr(c, "p_stderr")), num(attr(c, "C_fit"), 3),
                     " ".join(str(int(d)) for d in diff),
                     compact_verdict(mine) if ctx.checks is not None else "—"])
        classes.append("failrow" if failed else "")
    return table(["case", "γ", "δ", "predicted p", f"fitted p of the distance ({esc(primary)}, for comparison)", "C",
                  "status diff per ε", "checks (rates: next section)"], rows, left_columns=(0, 6, 7),
                 row_classes=classes)


def rate_text(p, stderr):
    if p is None:
        return "—"
    return f"{p:.2f} ± {stderr:.2f}" if stderr is not None else f"{p:.2f}"


def rates_table(g, cases):
    quantities = GLOBAL + AWAY
    rows = []
    for case in cases:
        c = g[case]
        row = [f"({esc(case)})", num(attr(c, "p_predicted"))]
        for q in quantities:
            p, se = attr(c, "p_" + q), attr(c, f"p_{q}_stderr")
            fitted = attr(c, "fitted_" + q, 1)
            row.append(rate_text(p, se) if fitted else "—")
        rows.append(row)
    return ("<p>Fitted rate p ± standard error for every quantity:</p>"
            + table(["case", "predicted"] + [esc(q) for q in quantities], rows, css_class="small"))


def case_figure(ctx, c, case, primary):
    eps = array(c, "eps")
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2), gridspec_kw={"width_ratios": [1, 1, 1.35]})
    for ax, quantities, where in ((axes[0], GLOBAL, "whole S"), (axes[1], AWAY, "away from the corners")):
        for q in quantities:
            if "e_" + q not in c:
                continue
            e = array(c, "e_" + q)
            ok = (e > 0) & np.isfinite(e)
            if not ok.any():
                continue
            base = q.replace("_away", "")
            p = attr(c, "p_" + q)
            label = LABELS[base] + (f"  p = {p:.2f}" if p is not None else "")
            ax.loglog(eps[ok], e[ok], "o-", color=COLORS[base], ms=4, lw=1.2, label=label)
            if q == primary:
                draw_rates(ax, c, eps[ok], e[ok])
        ax.set_xlabel("layer thickness ε (mm)")
        ax.set_ylabel("relative L² distance e_q (–)")
        ax.set_title(f"case ({case}): {where}")
        ax.legend(fontsize=7, loc="best")
        label_minor_log_ticks(ax)
    strip(ctx, axes[2], c, case)
    fig.tight_layout()
    caption = (f"Case ({esc(case)}), γ = {num(attr(c, 'gamma'))}, δ = {num(attr(c, 'delta'))}: predicted p = "
               f"{num(attr(c, 'p_predicted'))}; the distance's fitted p({esc(primary)}) = "
               f"{rate_text(attr(c, 'p_fit'), attr(c, 'p_stderr'))}, for comparison (the floor flattens it)")
    return f"<h3>Case ({esc(case)})</h3>" + ctx.figures.save(fig, f"convergence_{case}", f"convergence case {case}",
                                                              caption)


def draw_rates(ax, c, eps, e):
    """The fitted curve e_∞ + C ε^p (the study fits a floor, attribute floor_fit; 0 in older
    files) and a line of the predicted slope through the data's centre, above the same floor."""
    p_fit, c_fit, p_pred = attr(c, "p_fit"), attr(c, "C_fit"), attr(c, "p_predicted")
    floor = attr(c, "floor_fit") or 0.0
    grid = np.geomspace(eps.min(), eps.max(), 20)
    if p_fit is not None and c_fit:
        label = f"fit: {floor:.2g} + {c_fit:.2g} ε^{p_fit:.2f}" if floor > 0 else f"fit: {c_fit:.2g} ε^{p_fit:.2f}"
        ax.loglog(grid, floor + c_fit * grid ** p_fit, "k-", lw=2, alpha=0.6, label=label)
    if p_pred is not None:
        above = np.clip(e - floor, 1e-300, None)
        centre_eps, centre_e = np.exp(np.mean(np.log(eps))), np.exp(np.mean(np.log(above)))
        ax.loglog(grid, floor + centre_e * (grid / centre_eps) ** p_pred, "k--", lw=1.5,
                  label=f"predicted slope {p_pred:g}" + (" (above the floor)" if floor > 0 else ""))


def corners(ctx, scene_id, min_turn_deg=20.0):
    """Arc lengths of the nodes of S where its direction turns (the slot corners)."""
    if not scene_id or scene_id not in ctx.f["scenes"]:
        return []
    x, _ = scene_status(ctx.f, scene_id)
    d = np.diff(x, axis=0)
    angle = np.degrees(np.arctan2(d[:, 1], d[:, 0]))
    turn = np.abs((np.diff(angle) + 180.0) % 360.0 - 180.0)
    return list(arc_length(x)[1:-1][turn > min_turn_deg])


def strip(ctx, ax, c, case):
    rows, labels = [], []
    limit_id = attr(c, "limit_scene")
    if limit_id and limit_id in ctx.f["scenes"]:
        x, status = scene_status(ctx.f, limit_id)
        rows.append((arc_length(x), status))
        labels.append("limit law")
    eps = array(c, "eps")
    diff = array(c, "status_diff") if "status_diff" in c else [None] * len(eps)
    ids = strings(c["layer_scene"]) if "layer_scene" in c else []
    missing = 0
    for k in np.argsort(eps):  # thinnest first, next to the limit
        if k < len(ids) and ids[k] in ctx.f["scenes"]:
            x, status = scene_status(ctx.f, ids[k])
            rows.append((arc_length(x), status))
            labels.append(f"ε = {eps[k]:.3g}" + (f" (diff {int(diff[k])})" if diff[k] is not None else ""))
        else:
            missing += 1
    if not rows:
        ax.text(0.5, 0.5, "no scene stored", ha="center", va="center", transform=ax.transAxes)
        ax.set_axis_off()
        return
    status_strip(ax, rows, labels)
    for s in corners(ctx, limit_id):
        ax.axvline(s, color="k", ls=":", lw=1)
        ax.annotate("corner", (s, 0), xycoords=("data", "axes fraction"), xytext=(2, 2), textcoords="offset points",
                    fontsize=7)
    ax.set_xlabel("arc length along S (mm)")
    ax.set_title(f"case ({case}): status along S" + (f" ({missing} scenes not stored)" if missing else ""))
    status_legend(ax, loc="upper center", bbox_to_anchor=(0.5, -0.18), ncol=3, fontsize=8)

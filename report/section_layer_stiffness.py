"""Section 4: analogues of the paper's Figs. 6 and 7 — the layer's apparent stiffness
σ_N/[u]_N and σ_T/[u]_T against ε, converging to the limit law's K_N and K_T."""

import math

import matplotlib.pyplot as plt
import numpy as np

from across_layer import across_layer, stiffness_ratios
from html_parts import absent, esc, how_to_read, num, section, table
from plotting import label_minor_log_ticks

COLORS = {"a": "#7f7f7f", "b": "#1f77b4", "c": "#2ca02c", "d": "#d62728", "e": "#9467bd",
          "f": "#8c564b", "g": "#e377c2", "h": "#bcbd22", "i": "#17becf"}


def limit_stiffness(scene):
    """K_N = λ̄ + 2μ̄ (2μ̄ in case b, where λ̄ = 0) and K_T = μ̄, from a scene's attributes."""
    return scene.lambda_bar + 2 * scene.mu_bar, scene.mu_bar


def finite_positive(k):
    return k > 0 and math.isfinite(k)


def layer_scenes_by_case(ctx):
    """One dovetail layer scene per (case, ε): converged first, then the tightest tolerance."""
    chosen = {}
    for s in ctx.scenes:
        if s.case != "dovetail" or s.mode != "layer" or s.eps <= 0:
            continue
        key = (s.law_case, s.eps)
        rank = (not s.converged, float(s.attrs.get("tolerance", 1.0)), s.id)
        if key not in chosen or rank < chosen[key][0]:
            chosen[key] = (rank, s)
    by_case = {}
    for (case, _), (_, s) in sorted(chosen.items()):
        by_case.setdefault(case, []).append(s)
    return by_case


def render(ctx):
    title = "4. Apparent stiffness of the layer (Figs. 6 and 7)"
    body = [how_to_read(
        "For each dovetail layer scene we take the jump <em>across the whole layer</em>: the "
        "difference of the two adherents' displacements at matched points of S+ and S- (read from "
        "<code>u</code> at the adherents' nodes; the stored face jumps only decide which of the two "
        "coincident nodes belongs to which body). Its normal and tangential parts J_N, J_T use the limit "
        "law's signs, so the law predicts −σ_N = K_N J_N at contact nodes and −σ_T = K_T J_T at stick "
        "nodes. Plotted: the median over nodes of the node-wise ratios −σ_N/J_N (nodes in contact) and "
        "−σ_T/J_T (stick nodes), σ taken on S+, with bars from the first to the third quartile over "
        "those nodes. Dashed: K_N = λ̄ + 2μ̄ (2μ̄ in case b) and K_T = μ̄ "
        "from the scenes' stored λ̄, μ̄ (daN/mm³). Only cases whose K is finite and non-zero are drawn: "
        "for the others the ratio has no finite limit to approach.")]
    by_case = layer_scenes_by_case(ctx)
    if not by_case:
        body.append(absent("Dovetail layer-mode scenes"))
        return section("stiffness", title, "\n".join(body))
    results, skipped = {}, []
    for case, scenes in by_case.items():
        k_n, k_t = limit_stiffness(scenes[0])
        if not (finite_positive(k_n) or finite_positive(k_t)):
            continue
        points = []
        for s in scenes:
            try:
                normal, tangential = stiffness_ratios(across_layer(ctx.f, s.id))
            except ValueError as e:  # a face point without mesh nodes: leave the scene out, say so
                skipped.append(f"{s.id}: {e}")
                continue
            points.append((s.eps, normal, tangential, s.converged))
        results[case] = (k_n, k_t, points)
    if not results:
        body.append(absent("Dovetail layer scenes of a case with finite, non-zero K_N or K_T"))
        return section("stiffness", title, "\n".join(body))
    body.append(plot(ctx, results))
    if skipped:
        body.append('<p class="failtext">Left out (the across-layer jump could not be read):</p><ul>'
                    + "".join(f"<li>{esc(x)}</li>" for x in skipped) + "</ul>")
    body.append(values_table(results))
    return section("stiffness", title, "\n".join(body))


def quartiles(values):
    values = values[np.isfinite(values) & (values > 0)]
    if len(values) == 0:
        return None
    q1, med, q3 = np.percentile(values, [25, 50, 75])
    return med, q1, q3, len(values)


def plot(ctx, results):
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.6))
    for which, ax, symbol, k_index in ((1, axes[0], "N", 0), (2, axes[1], "T", 1)):
        for case, (k_n, k_t, points) in sorted(results.items()):
            k = (k_n, k_t)[k_index]
            if not finite_positive(k):
                continue
            # points hold (eps, normal ratios, tangential ratios, converged): `which` picks one.
            rows = [(pt[0], quartiles(pt[which])) for pt in points]
            rows = [(eps, q) for eps, q in rows if q is not None]
            if not rows:
                continue
            eps = np.array([r[0] for r in rows])
            med = np.array([r[1][0] for r in rows])
            low = med - np.array([r[1][1] for r in rows])
            high = np.array([r[1][2] for r in rows]) - med
            color = COLORS.get(case, "k")
            ax.errorbar(eps, med, yerr=[low, high], fmt="o-", color=color, capsize=3, ms=4,
                        label=f"case ({case}), layer")
            ax.axhline(k, color=color, ls="--", lw=1.2, label=f"K_{symbol} of ({case}) = {num(k)}")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("layer thickness ε (mm)")
        ax.set_ylabel(f"−σ_{symbol} / J_{symbol}  (daN/mm³)")
        ax.legend(fontsize=8)
        label_minor_log_ticks(ax)
    axes[0].set_title("normal: analogue of Fig. 6 (paper: case b)")
    axes[1].set_title("tangential: analogue of Fig. 7 (paper: case d)")
    fig.tight_layout()
    return ctx.figures.save(fig, "fig06_07_layer_stiffness", "apparent stiffness of the layer against eps",
                            "Median node-wise ratio of stress to across-layer jump (quartile bars) against ε; "
                            "dashed: the limit law's stiffness.")


def values_table(results):
    rows = []
    for case, (k_n, k_t, points) in sorted(results.items()):
        for eps, normal, tangential, converged in points:
            qn, qt = quartiles(normal), quartiles(tangential)
            rows.append([f"({esc(case)})", num(eps), cell(qn), num(k_n), cell(qt), num(k_t),
                         "" if converged else '<span class="failtext">not converged</span>'])
    return ("<details><summary>the values (median [quartiles] over n nodes)</summary>"
            + table(["case", "ε (mm)", "−σ_N/J_N (daN/mm³)", "K_N", "−σ_T/J_T (daN/mm³)", "K_T", ""],
                    rows, css_class="small", left_columns=(0, 6))
            + "</details>")


def cell(q):
    if q is None:
        return "—"
    med, q1, q3, n = q
    return f"{med:.4g} [{q1:.3g}, {q3:.3g}] n={n}"

"""The engineer's validity map (SPEC §3 S3, studies/drivers/validity_map.h): per joint, ν_g and
quantity, the distance of the finite spring law of a glue at its own thickness to the meshed layer of
the same glue over (t/L, E_g/E_a), at h/2 — contours of log10 of the distance with the 1 % and 5 %
lines, the cells the mesh does not resolve dotted and those that did not converge crossed; the paper's
3 % / 30x rule (SPEC §1.3) outlined where it picks a 0 or ∞ law, with what that costs; and SPEC §3 S6's
limit-mode estimate against the measured distance."""

import matplotlib.pyplot as plt
import numpy as np

from checks import checks_block
from html_parts import absent, esc, how_to_read, num, section, table
from results_file import array, attr, group, strings

QUANTITIES = ("reactions", "u", "peel_at_d", "shear_at_d", "sigma_N", "sigma_T")
LABELS = {"reactions": "the reactions", "u": "the adherents' displacements",
          "peel_at_d": "the peak peel at d from the ends", "shear_at_d": "the peak shear at d from the ends",
          "sigma_N": "σ_N over the bondlines (S2's norm)", "sigma_T": "σ_T over the bondlines (S2's norm)"}
MAPPED = ("reactions", "u", "peel_at_d", "shear_at_d")  # SPEC §3 S3's quantities: a figure each


def render(ctx, number="7b"):
    g = group(ctx.f, "studies/validity_map")
    title = f"{number}. The engineer's validity map"
    if g is None:
        return section("validity_map", title, absent("The validity map (/studies/validity_map)"))
    body = [how_to_read(
        "Each joint's every glued bondline given an engineer's glue (E_g, ν_g) of thickness t, over t/L (L: SPEC "
        "§1.3's characteristic length) and E_g/E_a (E_a: the adherents' Young's modulus); in each cell the finite "
        "spring law of that glue at its own t (K_N = (λ_g + 2μ_g)/t, K_T = μ_g/t) against the meshed layer of the "
        "same glue, on the scene's mesh (h) and on half its element size (h/2). The contours are log10 of the "
        "relative distance at h/2, the white lines 1 % and 5 %. Dotted: not resolved — the mesh moves the "
        "distance by more than half between h and h/2, or the mesh has fewer than 4 elements over the joint's "
        "shear-lag length √(E*_a L t/μ_g). Each cell is a tile: a cell that failed blanks its own tile only. "
        "Crossed: a scene of the cell did not converge (counted, never dropped; why: the table below the maps). Outlined in black: where the paper's 3 % / 30x rule would pick a 0 or ∞ law instead; the "
        "table below each map gives what that costs.")]
    for name in sorted(g):
        body.append(joint_block(ctx, g[name], name))
    body.append(checks_block(ctx.checks, "validity_map.", "the validity maps"))
    return section("validity_map", title, "\n".join(body))


def joint_block(ctx, s, name):
    t, E, nu = array(s, "t_over_L"), array(s, "E_ratio"), array(s, "nu")
    converged = array(s, "converged")
    out = [f"<h3>{esc(name)}</h3>",
           f"<p>L = {num(attr(s, 'characteristic_length'))} mm, E_a = {num(attr(s, 'E_a'))}; peaks at d = "
           f"{num(attr(s, 'peak_distance'))} mm from each bondline end ({esc(attr(s, 'peak_distance_reason', ''))}); "
           f"h = {num(attr(s, 'h'))} mm, h/2 = {num(attr(s, 'h_fine'))} mm; {len(t)} cells, "
           f"{int(np.sum(converged))} converged; wall time {num(attr(s, 'wall_time_s'))} s on "
           f"{int(attr(s, 'wall_time_ranks', 1))} rank(s) × {int(attr(s, 'wall_time_threads', 1))} thread(s).</p>"]
    for q in MAPPED:
        out.append(map_figure(ctx, s, name, q))
    out.append(failure_table(s))
    out.append(rule_table(s))
    out.append(estimate_figure(ctx, s, name))
    out.append(estimate_table(s))
    out.append(order_one_table(s))
    return "\n".join(out)


def grid(s, nu_value, q):
    """The cells of one ν as 2D arrays over (E index, t index)."""
    t, E, nu = array(s, "t_over_L"), array(s, "E_ratio"), array(s, "nu")
    ts, Es = np.unique(t), np.unique(E)
    shape = (len(Es), len(ts))
    out = {k: np.full(shape, np.nan) for k in ("measured", "resolved", "converged", "rule")}
    for i in np.flatnonzero(nu == nu_value):
        a, b = np.searchsorted(Es, E[i]), np.searchsorted(ts, t[i])
        out["measured"][a, b] = array(s, f"measured_{q}")[i]
        out["resolved"][a, b] = array(s, f"resolved_{q}")[i]
        out["converged"][a, b] = array(s, "converged")[i]
        out["rule"][a, b] = array(s, "rule_solved")[i]
    return ts, Es, out


def map_figure(ctx, s, name, q):
    nus = np.unique(array(s, "nu"))
    fig, axes = plt.subplots(1, len(nus), figsize=(max(4.8 * len(nus), 7.0), 4.3), squeeze=False)
    # The colour levels span this quantity's values (half decades), so that a map whose distances stay
    # far below 1 % is not one colour; the 1 % and 5 % lines are drawn where the values reach them.
    measured = array(s, f"measured_{q}")
    values = np.log10(np.clip(measured[(array(s, "converged") > 0) & np.isfinite(measured)], 1e-7, None))
    lo = np.floor(2 * values.min()) / 2 if len(values) else -6
    hi = max(np.ceil(2 * values.max()) / 2 if len(values) else 0, lo + 1)
    levels = np.arange(lo, hi + 0.01, 0.5)
    for ax, nu_value in zip(axes[0], nus):
        ts, Es, g = grid(s, nu_value, q)
        X, Y = np.meshgrid(np.log10(ts), np.log10(Es))
        Z = np.log10(np.clip(g["measured"], 1e-7, None))
        Z = np.where((g["converged"] > 0) & np.isfinite(g["measured"]), Z, np.nan)
        # One tile per cell, centred on it: a cell that failed (or whose quantity is not judged) blanks
        # its own tile only — a contour fill blanks every quad touching it, a quarter of a 3 x 3 map.
        tiles = ax.pcolormesh(edges(np.log10(ts)), edges(np.log10(Es)), np.ma.masked_invalid(Z), cmap="viridis",
                              vmin=levels[0], vmax=levels[-1], shading="flat")
        fig.colorbar(tiles, ax=ax, label="log10 distance")
        if len(ts) > 1 and len(Es) > 1 and np.isfinite(Z).sum() >= 4:
            reached = [v for v in (np.log10(0.01), np.log10(0.05)) if np.nanmin(Z) < v < np.nanmax(Z)]
            if reached:  # the lines between cell centres, broken only next to a missing cell
                lines = ax.contour(X, Y, Z, levels=reached, colors="white", linewidths=1.5, linestyles="solid")
                ax.clabel(lines, fmt={np.log10(0.01): "1 %", np.log10(0.05): "5 %"}, fontsize=8)
        unresolved = (g["resolved"] == 0) & (g["converged"] > 0)
        ax.plot(X[unresolved], Y[unresolved], "k.", ms=4, label="not resolved")
        failed = g["converged"] == 0
        ax.plot(X[failed], Y[failed], "rx", ms=8, mew=2, label="not converged (why: the table below)")
        rule = g["rule"] > 0
        ax.plot(X[rule], Y[rule], "s", mfc="none", mec="black", ms=11, label="the 3 % / 30x rule: 0 or ∞")
        ax.set_xlabel("log10 t/L")
        ax.set_ylabel("log10 E_g/E_a")
        ax.set_title(f"{name}, ν_g = {nu_value:g}")
        ax.margins(0.06)
        ax.grid(False)
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, fontsize=7, loc="lower center", ncol=3)
    fig.suptitle(f"The finite law against the layer: {LABELS[q]}")
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    return ctx.figures.save(fig, f"validity_map_{safe(name)}_{q}",
                            f"validity map of {name}: {LABELS[q]}",
                            f"log10 of the relative distance of {esc(LABELS[q])} at h/2 (largest: "
                            f"{num(10 ** values.max() if len(values) else float('nan'))}); white lines 1 % and 5 % "
                            f"where it reaches them.")


def edges(centres):
    """The edges of tiles centred on sorted centres: midway between them, half a step beyond the ends."""
    if len(centres) == 1:
        return np.array([centres[0] - 0.5, centres[0] + 0.5])
    mid = 0.5 * (centres[1:] + centres[:-1])
    return np.concatenate(([2 * centres[0] - mid[0]], mid, [2 * centres[-1] - mid[-1]]))


def failure_table(s):
    """Every cell that did not converge, with why (each scene's verdict, as the terminal prints it)."""
    if "failure" not in s:
        return ""
    failure = strings(s["failure"])
    t, E, nu, converged = array(s, "t_over_L"), array(s, "E_ratio"), array(s, "nu"), array(s, "converged")
    rows = [[num(t[i]), num(E[i]), num(nu[i]), esc(failure[i] or "(no reason recorded)")]
            for i in range(len(t)) if converged[i] == 0 or failure[i]]
    if not rows:
        return ""
    return ("<p>The cells that did not converge (crossed in the maps), and why: each scene's verdict (one rule for "
            "'converged', core/solvers/stop_verdict.h). Their distances are not used.</p>" +
            table(["t/L", "E_g/E_a", "ν_g", "why"], rows, css_class="small", left_columns=(3,)))


def safe(name):
    return "".join(c if c.isalnum() else "_" for c in name)


def rule_table(s):
    law, rule, solved = strings(s["law_case"]), strings(s["rule_case"]), array(s, "rule_solved")
    t, E, nu = array(s, "t_over_L"), array(s, "E_ratio"), array(s, "nu")
    rows = []
    for i in np.flatnonzero(solved > 0):
        rows.append([num(t[i]), num(E[i]), num(nu[i]), esc(law[i]), esc(rule[i])] +
                    [num(array(s, f"measured_{q}")[i]) + " → " + num(array(s, f"rule_{q}")[i]) for q in MAPPED])
    if not rows:
        return "<p>The paper's 3 % / 30x rule picks the finite law at every cell.</p>"
    return ("<p>Where the paper's 3 % / 30x rule picks a 0 or ∞ law: the finite law's distance to the layer → the "
            "rule's law's distance to the layer (relative, at h/2; the rule's measured against the layer).</p>" +
            table(["t/L", "E_g/E_a", "ν_g", "finite law", "rule"] + list(MAPPED), rows, css_class="small"))


def estimate_figure(ctx, s, name):
    fig, ax = plt.subplots(figsize=(5.4, 4.4))
    colours = dict(zip(QUANTITIES, ("C0", "C1", "C2", "C3", "C4", "C5")))
    for q in QUANTITIES:
        m, resolved = array(s, f"measured_{q}"), array(s, f"resolved_{q}")
        ends = array(s, f"ends_resolved_{q}")
        judged = np.where(ends > 0, array(s, f"estimate_{q}"), array(s, f"interior_{q}"))
        ok = (resolved > 0) & (array(s, "converged") > 0) & (m > 0) & (judged > 0)
        ax.loglog(m[ok], judged[ok], "o", ms=4, color=colours[q], label=q)
    lims = [1e-6, 1]
    ax.plot(lims, lims, "k-", lw=1)
    ax.plot(lims, [2 * x for x in lims], "k--", lw=0.8)
    ax.plot(lims, [x / 2 for x in lims], "k--", lw=0.8)
    ax.set_xlim(lims)
    ax.set_ylim(lims)
    ax.set_xlabel("measured (the layer at h/2)")
    ax.set_ylabel("SPEC 3 S6's estimate (limit mode alone)")
    ax.set_title(f"{name}: the estimate against the layer")
    ax.legend(fontsize=7)
    fig.tight_layout()
    return ctx.figures.save(fig, f"validity_map_{safe(name)}_estimate", f"{name}: estimate against measured",
                            "Cells above the mesh floor; the dashed lines: a factor 2. Where the mesh does not resolve "
                            "the layer's end zone (h/2 > 3t) the estimate shown is the one without its end cells.")


def estimate_table(s):
    rows = []
    converged = array(s, "converged") > 0
    for q in QUANTITIES:
        # The cells the terminal counts: converged at every level and above the mesh floor.
        resolved = (array(s, f"resolved_{q}") > 0) & converged
        within, ends = array(s, f"within_{q}"), array(s, f"ends_resolved_{q}")
        rows.append([esc(q), str(int(np.sum(resolved))), str(int(np.sum(resolved & (within > 0)))),
                     str(int(np.sum(resolved & (ends > 0))))])
    return ("<p>SPEC 3 S6 judged on the map: at the converged cells above the mesh floor, the estimate within a "
            f"factor {num(attr(s, 'factor'))} of the measured distance (a quantity fixed by statics is not judged: "
            "no cell).</p>" +
            table(["quantity", "cells above the floor", "within the factor", "of which ends resolved (h/2 ≤ 3t)"], rows))


def order_one_table(s):
    """Order one: the layer's distance to the first-order answer u1 beside its distance to the law's u0."""
    if "order1_u" not in s:
        return ""
    rows = []
    for q in QUANTITIES:
        m, o1, resolved = array(s, f"measured_{q}"), array(s, f"order1_{q}"), array(s, f"resolved_{q}")
        above = array(s, f"order1_resolved_{q}")
        ok = (resolved > 0) & (array(s, "converged") > 0)
        ratio = o1[ok] / np.where(m[ok] > 0, m[ok], np.nan)
        rows.append([esc(q), str(int(np.sum(ok))), str(int(np.sum(ok & (3 * o1 <= m)))),
                     num(float(np.nanmedian(ratio))) if np.isfinite(ratio).any() else "–",
                     str(int(np.sum(ok & (above > 0))))])
    return ("<p>Order one: the layer at h/2 against the first-order answer u1 (the estimate's answer itself, "
            "without its end cells where h/2 > 3t) beside its distance to the law's answer (order 0), at the cells "
            "above the mesh floor. Where the mesh still moves the order-1 distance by more than half between h and "
            "h/2, it is the mesh's, not u1's (studies/limit_error_estimate.md, \"Order one\").</p>" +
            table(["quantity", "cells above the floor", "order 1 ≤ order 0 / 3", "median order 1 / order 0",
                   "order 1 above its own floor"], rows))

"""Section 5b: the rates of study S2, from the layer model's Cauchy differences along a
geometric ε grid (where the mesh floor cancels), and the mesh floor itself against h."""

import matplotlib.pyplot as plt
import numpy as np

from checks import checks_block
from html_parts import absent, esc, how_to_read, num, section, table, verdict
from plotting import label_minor_log_ticks
from results_file import array, attr, group

LABELS = {"R_top": "R_top (reaction)", "u": "u", "u_away": "u away", "sigma_N_away": "σ_N away",
          "sigma_T_away": "σ_T away", "sigma_N": "σ_N", "sigma_T": "σ_T", "jump_N": "[u]_N", "jump_T": "[u]_T"}
COLORS = ("k", "#7f7f7f", "#1f77b4", "#d62728", "#9467bd", "#2ca02c", "#ff7f0e")


def render(ctx):
    title = "5b. Convergence rates and the mesh floor (study S2)"
    g = group(ctx.f, "studies/convergence")
    cases = [k for k in sorted(g.keys()) if len(k) == 1 and "cauchy" in g[k]] if g is not None else []
    if not cases:
        return section("rates", title, absent("The rate study (/studies/convergence/<case>/cauchy)"))
    first = g[cases[0]]["cauchy"]
    checked = [q for q in (attr(first, "checked") or "").split(",") if q]
    body = [how_to_read(
        "The rate p of each case from the Cauchy differences of the layer model, ‖q(ε_k) − q(ε_{k+1})‖ on a "
        f"geometric grid of ratio {num(attr(first, 'grid_ratio'))}, which fall like C ε_k^p while any "
        "ε-independent part (the mesh floor at the slot corners) cancels. Differences are relative to the "
        "distances' scales (tenon-top reaction, adherents' displacements, stresses on S away from the corners). "
        "Fitted on the tail: both scenes at ε ≤ 1e-4 and converged to the SPEC tolerance, and below the last "
        "change of a combined status between converged neighbours (the expansion holds on one set of statuses; "
        "where that rule removes differences, the fit across them is shown in brackets), at least 3 of them; "
        "else 'not measurable'. PASS/FAIL is the stored verdict (|p − predicted| ≤ 0.15); "
        "studies/convergence_rates.md gives the cause of every miss and its control experiment (section 5c).")]
    body.append(rates_table(g, cases, checked))
    body.append(local_slopes(g, cases, checked, ctx.checks))
    body.append(checks_block([c for c in (ctx.checks or []) if ".rate." in c.id], "convergence.",
                             "the rate checks"))
    body.append(cauchy_figure(ctx, g, cases, checked))
    body.append(floor_part(ctx, g))
    return section("rates", title, "\n".join(body))


def rate_cell(c, q):
    text = f"{attr(c, 'p_' + q):.2f} ± {attr(c, f'p_{q}_stderr'):.2f}" if attr(c, "fitted_" + q, 0) else "not measurable"
    if attr(c, f"fitted_{q}_any_status", 0) and "in_tail_" + q in c:
        any_status = f"{attr(c, f'p_{q}_any_status'):.2f} ± {attr(c, f'p_{q}_any_status_stderr'):.2f}"
        if any_status != text and np.any(array(c, "status_changes") > 0):
            text += f" ({any_status} across a status change)"
    return text


def local_slopes(g, cases, checked, checks):
    """The slope between each pair of neighbouring differences, for the cases with a failed rate
    check: a rate still drifting along the tail (pre-asymptotic) shows here."""
    failed = sorted({c.id.split(".")[1] for c in (checks or []) if ".rate." in c.id and not c.passed})
    failed = [case for case in failed if case in cases]
    if not failed:
        return ""
    rows = []
    for case in failed:
        c = g[case]["cauchy"]
        eps = array(c, "eps")[:-1]
        for q in checked:
            d, tail = array(c, "d_" + q), array(c, "in_tail_" + q).astype(bool)
            slopes = []
            for k in range(len(d) - 1):
                if tail[k] and tail[k + 1]:
                    slopes.append(f"{np.log(d[k] / d[k + 1]) / np.log(eps[k] / eps[k + 1]):.2f}")
            rows.append([f"({esc(case)})", esc(LABELS.get(q, q)), " → ".join(slopes) or "—"])
    return ("<p>Local slopes along the tail (from the thickest pair to the thinnest) of the cases with a failed "
            "rate check:</p>" + table(["case", "quantity", "local slopes"], rows, css_class="small",
                                      left_columns=(0, 1, 2)))


def rates_table(g, cases, checked):
    rows, classes = [], []
    for case in cases:
        c = g[case]["cauchy"]
        row = [f"({esc(case)})", num(attr(c, "p_predicted"))]
        failed = False
        for q in checked:
            passed = attr(c, "pass_" + q)
            failed = failed or passed == 0
            row.append(rate_cell(c, q) + (" " + verdict(bool(passed)) if passed is not None else ""))
        converged = array(c, "converged")
        row.append(f"{int(np.sum(converged))} of {len(converged)}")
        rows.append(row)
        classes.append("failrow" if failed else "")
    return table(["case", "predicted p"] + [esc(LABELS.get(q, q)) for q in checked] + ["grid scenes converged"],
                 rows, row_classes=classes)


def cauchy_figure(ctx, g, cases, checked):
    columns = 3
    rows = (len(cases) + columns - 1) // columns
    fig, axes = plt.subplots(rows, columns, figsize=(15, 4.0 * rows), squeeze=False)
    for ax in axes.flat[len(cases):]:
        ax.set_axis_off()
    for ax, case in zip(axes.flat, cases):
        cauchy_panel(ax, g[case]["cauchy"], case, checked)
    fig.tight_layout()
    caption = ("Cauchy differences against ε_k (the thicker scene of each pair): filled markers are the fitted "
               "tail, hollow ones outside it (thicker than the tail, or at or above a status change); a cross marks "
               "a difference with an unconverged scene. For each quantity, in its colour: solid line, the fit over "
               "its tail; dashed, the predicted slope through the tail's centre.")
    return ctx.figures.save(fig, "convergence_cauchy", "Cauchy differences per case", caption)


def cauchy_panel(ax, c, case, checked):
    eps, converged = array(c, "eps"), array(c, "converged").astype(bool)
    eps_k = eps[:-1]
    both = converged[:-1] & converged[1:]
    p_pred = attr(c, "p_predicted")
    for q, color in zip(checked, COLORS):
        if "d_" + q not in c:
            continue
        d, tail = array(c, "d_" + q), array(c, "in_tail_" + q).astype(bool)
        ok = (d > 0) & np.isfinite(d)
        fitted = attr(c, "fitted_" + q, 0)
        label = LABELS.get(q, q) + (f": p = {attr(c, 'p_' + q):.2f}" if fitted else ": not measurable")
        ax.loglog(eps_k[ok], d[ok], "-", color=color, lw=0.6, alpha=0.4)
        ax.loglog(eps_k[ok & tail], d[ok & tail], "o", color=color, ms=5, label=label)
        ax.loglog(eps_k[ok & ~tail & both], d[ok & ~tail & both], "o", mfc="none", color=color, ms=5)
        ax.loglog(eps_k[ok & ~both], d[ok & ~both], "x", color=color, ms=6)
        if fitted and (ok & tail).any():
            # The fit (solid) and the predicted slope through the tail's centre (dashed), per quantity.
            x = eps_k[ok & tail]
            grid = np.geomspace(x.min(), x.max(), 10)
            ax.loglog(grid, attr(c, "C_" + q) * grid ** attr(c, "p_" + q), "-", color=color, lw=1.6, alpha=0.8)
            centre_x, centre_y = np.exp(np.mean(np.log(x))), np.exp(np.mean(np.log(d[ok & tail])))
            ax.loglog(grid, centre_y * (grid / centre_x) ** p_pred, "--", color=color, lw=1.0)
    ax.set_title(f"case ({case}), predicted p = {num(attr(c, 'p_predicted'))}")
    ax.set_xlabel("ε_k (mm)")
    ax.set_ylabel("‖q(ε_k) − q(ε_k+1)‖ (relative)")
    ax.legend(fontsize=7, loc="best")
    label_minor_log_ticks(ax)


def floor_part(ctx, g):
    out = ["<h3>The mesh floor against h</h3>"]
    if "floor" not in g:
        return "\n".join(out + [absent("The floor study (/studies/convergence/floor; verify --quick skips it)")])
    f = g["floor"]
    h, nodes, converged = array(f, "h"), array(f, "S_nodes"), array(f, "converged")
    quantities = [k[len("floor_"):] for k in f.keys() if k.startswith("floor_")]
    quantities = [q for q in LABELS if q in quantities]
    out.append(how_to_read(
        f"Case ({esc(attr(f, 'law_case'))}) at ε = {num(attr(f, 'eps'))} against the limit law, at three interface "
        "spacings h along S: the distance there is the mesh floor, which must shrink with h. In brackets, the "
        f"bound on the ε-part still in it (its Cauchy difference to ε = {num(attr(f, 'eps_previous'))}, summed "
        "over the geometric tail). Rate q from a least-squares fit of log floor = log C + q log h."))
    rows = []
    for k in range(len(h)):
        row = [num(h[k]), str(int(nodes[k]))]
        for q in quantities:
            row.append(f"{array(f, 'floor_' + q)[k]:.2e} ({array(f, 'eps_part_' + q)[k]:.1e})")
        row.append("yes" if converged[k] else '<span class="failtext">no</span>')
        rows.append(row)
    rows.append(["rate in h", ""] + [f"{attr(f, 'rate_' + q):.2f} ± {attr(f, 'rate_' + q + '_stderr'):.2f}"
                                     if attr(f, "fitted_" + q, 0) else "—" for q in quantities] + [""])
    out.append(table(["h (mm)", "S nodes"] + [esc(LABELS[q]) for q in quantities] + ["converged"], rows,
                     css_class="small"))
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    for q, color in zip(("R_top", "u", "u_away", "sigma_N", "sigma_N_away", "sigma_T", "sigma_T_away"),
                        COLORS + ("#17becf",)):
        if q not in quantities:
            continue
        ax.loglog(h, array(f, "floor_" + q), "o-", color=color,
                  label=f"{LABELS[q]}  q = {attr(f, 'rate_' + q):.2f}")
        ax.loglog(h, array(f, "eps_part_" + q), "x:", color=color, ms=5, lw=0.6)
    ax.set_xlabel("interface spacing h (mm)")
    ax.set_ylabel("distance to the limit law (relative)")
    ax.set_title("mesh floor (o) and its ε-part (x)")
    ax.legend(fontsize=7, loc="best")
    label_minor_log_ticks(ax)
    fig.tight_layout()
    out.append(ctx.figures.save(fig, "convergence_floor", "mesh floor against h",
                                "The floor of each quantity against h (circles) and the bound on the ε-part left in "
                                "it (crosses): the floor is the mesh's, not the layer's."))
    out.append(checks_block(ctx.checks, "convergence.floor.", "the floor study"))
    return "\n".join(out)

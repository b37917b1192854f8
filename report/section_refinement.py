"""S2 under mesh refinement (SPEC §3 S2 item 3; `study convergence --refine`,
studies/drivers/refinement_study.h): per case and quantity, the rate of the layer model from its Cauchy
differences where the rate grid ends, at h, h/2 and h/4 along S, and the verdict ("established" or
"not established: <cause>"); a figure per case with the local slopes against ε at each mesh and the
prediction's band; the scenes without an answer; the floor under refinement; the slowest scenes."""

import h5py
import matplotlib.pyplot as plt
import numpy as np

from checks import checks_block
from html_parts import absent, esc, how_to_read, num, section, table
from results_file import array, attr, group, strings

LABELS = {"R_top": "R_top (reaction)", "u": "u", "u_away": "u away", "sigma_N_away": "σ_N away",
          "sigma_T_away": "σ_T away", "sigma_N": "σ_N", "sigma_T": "σ_T"}
MESH_STYLE = (("#1f77b4", "o"), ("#d62728", "s"), ("#2ca02c", "^"), ("#9467bd", "D"))
ANSWERED = ("converged", "round-off floor")


def render(ctx, number="1"):
    title = f"{number}. The rates under mesh refinement (S2)"
    g = group(ctx.f, "studies/convergence/refinement")
    if g is None:
        return section("refinement", title, absent("The refinement study (/studies/convergence/refinement)"))
    eps, meshes = array(g, "eps"), strings(g["meshes"])
    checked = [q for q in (attr(g, "checked") or "").split(",") if q]
    body = [how_to_read(
        f"Each dovetail case's layer model on the rate grid ε = {num(eps[0])} … {num(eps[-1])} at the meshes "
        f"{', '.join(meshes)} along S, every scene solved to residual {num(attr(g, 'tolerance'))} by "
        f"{esc(attr(g, 'solver_identity'))} under a wall-time cap of {num(attr(g, 'scene_cap_s'))} s, with both "
        "selections of the layer (spring on its minus or plus face, SPEC §1.5). A Cauchy difference "
        "‖q(ε_k) − q(ε_k+1)‖ counts when both its scenes have an answer (converged, or at their proven round-off "
        f"floor), it exceeds {num(attr(g, 'spread_factor'))} times the two selections' spread, ε_k ≤ "
        f"{num(attr(g, 'eps_max'))}, and no combined status changes below it. The rate at a mesh is the Cauchy fit "
        f"of the last {attr(g, 'fitted_count')} counted differences in a row (in brackets its last two local "
        "slopes; 'to ε' where the run ends before the grid does). Established: within "
        f"{num(attr(g, 'rate_tolerance'))} of the prediction at h, h/2 and h/4, the last two local slopes within "
        f"{num(attr(g, 'settle'))} of each other (SPEC §3 S2 item 3); otherwise the cause.")]
    body.append(verdict_table(g))
    body.append(checks_block(ctx.checks, "convergence.refine.", "the rates under refinement"))
    cases = refined_cases(g)
    for case in cases:
        body.append(slope_figure(ctx, g, case, eps, checked))
    body.append(unanswered(g))
    body.append(floor_part(ctx, g, cases))
    body.append(slowest(g))
    return section("refinement", title, "\n".join(body))


def refined_cases(g):
    """The case letters of the study: its one-letter groups."""
    return sorted(k for k in g.keys() if len(k) == 1 and isinstance(g[k], h5py.Group))


def verdict_table(g):
    v = g["verdicts"]
    cases, quantities = strings(v["case"]), strings(v["quantity"])
    rates, causes = strings(v["rates"]), strings(v["cause"])
    established, predicted = array(v, "established"), array(v, "p_predicted")
    rows, classes = [], []
    for i in range(len(cases)):
        rows.append([f"({esc(cases[i])})", esc(LABELS.get(quantities[i], quantities[i])), num(predicted[i]),
                     esc(rates[i]), "established" if established[i] else "not established: " + esc(causes[i])])
        classes.append("pass" if established[i] else "fail")
    return table(["case", "quantity", "predicted", "rate (last local slopes) at each mesh", "verdict"], rows,
                 css_class="small", left_columns=(0, 1, 3, 4), row_classes=classes)


def levels_of(g, case):
    """The case's mesh groups (r1, r2, r4 ...), coarsest first."""
    return [g[case][name] for name in sorted(g[case], key=lambda n: int(n[1:]))]


def slope_figure(ctx, g, case, eps, checked):
    levels = levels_of(g, case)
    verdicts = g["verdicts"]
    p_pred = float(array(verdicts, "p_predicted")[strings(verdicts["case"]).index(case)])
    tolerance = float(attr(g, "rate_tolerance"))
    fig, axes = plt.subplots(1, len(checked), figsize=(3.4 * len(checked), 3.3), squeeze=False, sharey=True)
    for ax, q in zip(axes[0], checked):
        ax.axhspan(p_pred - tolerance, p_pred + tolerance, color="0.85", zorder=0)
        ax.axhline(p_pred, color="0.4", lw=0.8, ls="--", zorder=1)
        for level, (color, marker) in zip(levels, MESH_STYLE):
            d = array(level, "d_" + q)
            # Local slopes of every pair of neighbouring differences that both exist (the grid is
            # geometric: the slope is the log ratio), hollow; those of the run read, filled.
            x, s = [], []
            for k in range(len(d) - 1):
                if np.isfinite(d[k]) and np.isfinite(d[k + 1]) and d[k] > 0 and d[k + 1] > 0:
                    x.append(eps[k + 1])
                    s.append(np.log(d[k] / d[k + 1]) / np.log(eps[k] / eps[k + 1]))
            ax.semilogx(x, s, marker, mfc="none", color=color, ms=5, lw=0)
            first, slopes = int(attr(level, "run_first_" + q, -1)), array(level, "local_slopes_" + q)
            if first >= 0 and len(slopes):
                ax.semilogx(eps[first + 1:first + 1 + len(slopes)], slopes, marker + "-", color=color, ms=5,
                            label=f"{attr(level, 'mesh')}: p = {attr(level, 'p_' + q):.2f}")
            else:
                ax.semilogx([], [], marker, color=color, label=f"{attr(level, 'mesh')}: no rate")
        ax.set_title(LABELS.get(q, q), fontsize=9)
        ax.set_xlabel("ε (the scene between the two differences)", fontsize=8)
        ax.invert_xaxis()
        ax.set_ylim(max(-0.5, p_pred - 1.0), p_pred + 1.0)
        ax.legend(fontsize=7, loc="best")
    axes[0][0].set_ylabel("local slope")
    fig.suptitle(f"case ({case}): local slopes of the Cauchy differences, predicted p = {p_pred:g} ± {tolerance:g}",
                 fontsize=10)
    fig.tight_layout()
    caption = (f"Case ({esc(case)}): the slope between each pair of neighbouring Cauchy differences against ε, at each "
               "mesh (colour); filled and joined, the run the rate is read on; hollow, pairs outside it (a difference "
               "left out by the rule). Grey band: the prediction ± the tolerance.")
    return ctx.figures.save(fig, f"refinement_slopes_{case}", f"local slopes, case {case}", caption)


def unanswered(g):
    s = g["scenes"]
    state = strings(s["state"])
    keep = [i for i, x in enumerate(state) if x not in ANSWERED]
    if not keep:
        return "<p>Every scene has an answer (converged, or at its proven round-off floor).</p>"
    cols = {name: (strings(s[name]) if s[name].dtype.kind in "OS" else array(s, name))
            for name in ("case", "mesh", "mode", "eps", "selection", "state", "detail", "residual",
                         "residual_floor", "wall_time_s", "cpu_time_s", "film_slip_over_h", "removes", "solver")}
    rows = [[f"({esc(cols['case'][i])})", esc(cols["mesh"][i]), esc(cols["mode"][i]),
             num(cols["eps"][i]) if cols["mode"][i] == "layer" else "", esc(cols["selection"][i]),
             esc(cols["state"][i]), esc(cols["detail"][i]), num(cols["residual"][i]), num(cols["residual_floor"][i]),
             f'{num(cols["wall_time_s"][i])} ({num(cols["cpu_time_s"][i])} CPU)', num(cols["film_slip_over_h"][i]), esc(cols["removes"][i]),
             esc(cols["solver"][i])] for i in keep]
    return (f"<p>{len(keep)} scene(s) without an answer — never fitted, never replaced by a best iterate; each "
            "removes the Cauchy differences named (or, for the plus-face selection, the spread that judges them):</p>"
            + table(["case", "mesh", "mode", "ε", "selection", "state", "stop cause / why", "residual", "floor",
                     "time [s]", "film slip / h", "removes", "solver"], rows, css_class="small",
                    left_columns=(0, 1, 2, 4, 5, 6, 11, 12)))


def floor_part(ctx, g, cases):
    f = g["floor"]
    fc, mesh, h = strings(f["case"]), strings(f["mesh"]), array(f, "h")
    quantities = ("R_top", "u", "sigma_N", "sigma_T")
    rates = g["floor_rates"]
    rate_of = {(c, q): (r, e) for c, q, r, e in zip(strings(rates["case"]), strings(rates["quantity"]),
                                                    array(rates, "rate"), array(rates, "rate_stderr"))}
    rows = []
    for i in range(len(fc)):
        rows.append([f"({esc(fc[i])})", esc(mesh[i]), num(h[i]), str(int(array(f, "S_nodes")[i])), num(array(f, "eps")[i])]
                    + [f"{num(array(f, 'floor_' + q)[i])} ({num(array(f, 'eps_part_' + q)[i], 2)})" for q in quantities])
    for c in cases:
        rows.append([f"({esc(c)})", "rate in h", "", "", ""] +
                    [("n/a" if not np.isfinite(rate_of[(c, q)][0]) else
                      f"{rate_of[(c, q)][0]:.2f} ± {rate_of[(c, q)][1]:.2f}") for q in quantities])
    fig, axes = plt.subplots(1, len(quantities), figsize=(3.4 * len(quantities), 3.2), squeeze=False)
    for ax, q in zip(axes[0], quantities):
        for c in cases:
            sel = [i for i in range(len(fc)) if fc[i] == c and np.isfinite(array(f, "floor_" + q)[i])]
            if sel:
                ax.loglog(h[sel], array(f, "floor_" + q)[sel], "o-", ms=4, lw=0.8, label=f"({c})")
        ax.set_title(LABELS.get(q, q), fontsize=9)
        ax.set_xlabel("h along S", fontsize=8)
        ax.set_xticks(sorted(set(h)))
        ax.set_xticklabels([f"{x:g}" for x in sorted(set(h))], fontsize=8)
        ax.minorticks_off()
        ax.invert_xaxis()
    axes[0][0].set_ylabel("floor (relative)")
    axes[0][-1].legend(fontsize=7, ncol=2)
    fig.tight_layout()
    return ("<p>The floor (SPEC §3 S2 item 2): the layer at the thinnest ε with an answer (and its thicker neighbour) "
            "against the limit law on the same mesh; in brackets the bound on its ε-part (the Cauchy difference to the "
            "thicker neighbour summed over the geometric tail at the predicted rate). It must shrink with h.</p>"
            + table(["case", "mesh", "h", "S nodes", "ε"] + [LABELS[q] for q in quantities], rows, css_class="small",
                    left_columns=(0, 1))
            + ctx.figures.save(fig, "refinement_floor", "floor against h",
                               "The floor of each quantity against h, one line per case."))


def slowest(g):
    s = g["scenes"]
    t = array(s, "wall_time_s")
    order = np.argsort(-t)[:10]
    cols = {name: strings(s[name]) for name in ("case", "mesh", "mode", "selection", "state")}
    e = array(s, "eps")
    cpu = array(s, "cpu_time_s")
    rows = [[num(t[i]), num(cpu[i]), f"({esc(cols['case'][i])})", esc(cols["mesh"][i]), esc(cols["mode"][i]),
             num(e[i]) if cols["mode"][i] == "layer" else "", esc(cols["selection"][i]), esc(cols["state"][i])]
            for i in order if t[i] > 0]
    solved = t[np.array([x != "not solved" for x in cols["state"]])]
    return (f"<p>{len(t)} scenes, {len(solved)} solved, {solved.sum():.0f} s of solving in all, {cpu.sum():.0f} s of CPU "
            "(sums over the workers; the run's wall time is in its log; on a shared machine the CPU time is what a "
            "scene took, the wall time also how loaded the machine was). The ten slowest:</p>"
            + table(["wall [s]", "CPU [s]", "case", "mesh", "mode", "ε", "selection", "state"], rows, css_class="small",
                    left_columns=(2, 3, 4, 6, 7)))

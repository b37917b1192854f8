"""Section 7: run time against error per solver (study S5), from /studies/timing."""

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.lines import Line2D

from checks import checks_block
from html_parts import absent, esc, how_to_read, num, section, table
from results_file import array, group, strings


def render(ctx):
    title = "7. Run time against error (study S5)"
    g = group(ctx.f, "studies/timing")
    if g is None:
        return section("timing", title, absent("The run-time study (/studies/timing)"))
    solver, level = strings(g["solver"]), strings(g["level"])
    time_s, error = array(g, "time_s"), array(g, "error")
    body = [how_to_read(
        "Each point is one solve: its wall time (s) against its error relative to a tightly converged "
        "reference, both on logarithmic axes; colour = solver, marker = mesh (for the relaxation and the peers, "
        "a line joins their residual tolerances on one mesh). Errors at 1e-16 are round-off: the fast solver's "
        "last step is an exact linear solve. "
        "Lower left is better: a solver whose line lies left of another's reaches the same error sooner.")]
    # One line per solver and mesh level (the relaxation's points at one level are its
    # tolerances); files without `contact_nodes` get one line per solver.
    # One colour per solver, one marker per mesh; a line joins a solver's points on one mesh (for
    # the relaxation and the peers, its residual tolerances).
    nodes = array(g, "contact_nodes") if "contact_nodes" in g else np.zeros(len(solver))
    meshes = strings(g["mesh"]) if "mesh" in g else [str(int(n)) for n in nodes]
    solvers = sorted(set(solver))
    colour = {name: f"C{i % 10}" for i, name in enumerate(solvers)}
    markers = "os^vDP*Xh<>"
    marker = {m: markers[i % len(markers)] for i, m in enumerate(dict.fromkeys(meshes))}
    fig, ax = plt.subplots(figsize=(9, 5))
    for name in solvers:
        for m in marker:
            k = [i for i in range(len(solver)) if solver[i] == name and meshes[i] == m]
            ok = sorted((i for i in k if time_s[i] > 0 and error[i] > 0 and np.isfinite(error[i])),
                        key=lambda i: time_s[i])
            if ok:
                ax.loglog(time_s[ok], error[ok], "-", marker=marker[m], color=colour[name], alpha=0.85)
    handles = [Line2D([], [], color=colour[n], lw=2, label=n) for n in solvers]
    handles += [Line2D([], [], color="gray", lw=0, marker=marker[m], label=m) for m in marker]
    ax.legend(handles=handles, fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax.set_xlabel("wall time (s)")
    ax.set_ylabel("relative error to the reference (–)")
    fig.tight_layout()
    body.append(ctx.figures.save(fig, "timing", "run time against error", "Wall time against error, per solver."))
    ratio = array(g, "ratio_to_linear") if "ratio_to_linear" in g else np.full(len(solver), np.nan)
    rows = [[esc(solver[i]), esc(level[i]), num(time_s[i], 3), num(error[i], 3) if error[i] > 0 else "—",
             num(ratio[i], 3)] for i in range(len(solver))]
    body.append(table(["solver", "level", "time (s)", "error (–)", "time / linear solve"], rows, css_class="small",
                      left_columns=(0, 1)))
    body.append(scaling_part(ctx, g, solver, time_s))
    body.append(targets_part(g))
    body.append(skip_part(g))
    body.append(checks_block(ctx.checks, "timing.", "the run-time study"))
    return section("timing", title, "\n".join(body))


def scaling_part(ctx, g, solver, time_s):
    """Time against the number of unknowns on the bar's levels, with the fitted exponents."""
    if "scaling" not in g or "unknowns" not in g or "mesh" not in g:
        return ""
    mesh, unknowns = strings(g["mesh"]), array(g, "unknowns")
    tolerance = array(g, "tolerance")
    lin = g["linear"]
    fits = g["scaling"]
    exponent = {name: (p, se) for name, p, se in zip(strings(fits["solver"]), array(fits, "exponent"),
                                                      array(fits, "exponent_stderr"))}
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    lin_level, lin_n, lin_t = strings(lin["level"]), array(lin, "unknowns"), array(lin, "time_s")
    bar = [i for i in range(len(lin_level)) if lin_level[i].startswith("bar-")]
    if bar:
        p = exponent.get("linear", (np.nan, np.nan))
        ax.loglog(lin_n[bar], lin_t[bar], "ks--", label=f"linear solve (p = {p[0]:.2f} ± {p[1]:.2f})")
    for name in sorted(set(solver)):
        converged = array(g, "converged")
        k = [i for i in range(len(solver)) if solver[i] == name and mesh[i].startswith("bar-")
             and tolerance[i] in (0, 1e-10) and converged[i]]
        if len(k) < 2:
            continue
        k.sort(key=lambda i: unknowns[i])
        p = exponent.get(name)
        label = name + (f" (p = {p[0]:.2f} ± {p[1]:.2f})" if p else "")
        ax.loglog(unknowns[k], time_s[k], "o-", label=label)
    ax.set_xlabel("unknowns (free DOFs of the bar)")
    ax.set_ylabel("wall time (s)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    return ctx.figures.save(fig, "timing_scaling", "time against unknowns",
                            "Wall time against the number of unknowns on the bar's levels (residual 1e-10), "
                            "and the exponent p of t ≈ C n<sup>p</sup> fitted on log–log axes.")


def targets_part(g):
    if "targets" not in g:
        return ""
    t = g["targets"]
    met = array(t, "met")
    rows = [[esc(a), esc(b), esc(c), "met" if m else "<b>not met</b>"]
            for a, b, c, m in zip(strings(t["target"]), strings(t["goal"]), strings(t["measured"]), met)]
    return ("<h3>Targets of issue 5 (goals, reported honestly; not tests)</h3>\n"
            + table(["target", "goal", "measured", ""], rows, css_class="small", left_columns=(0, 1, 2, 3),
                    row_classes=["" if m else "failrow" for m in met]))


def skip_part(g):
    if "skip" not in g:
        return ""
    k = g["skip"]
    rows = [[esc(name), esc(scenes), num(w, 3), num(wo, 3), num(sv, 2) + "×", num(d, 2)]
            for name, scenes, w, wo, sv, d in zip(strings(k["shortcut"]), strings(k["scenes"]),
                                                  array(k, "time_with_s"), array(k, "time_without_s"),
                                                  array(k, "saving"), array(k, "difference"))]
    return ("<h3>Skip what a scene doesn't need</h3>\n<p>Each shortcut of the fast solver timed with and without "
            "it (medians); <i>difference</i> is the largest relative change of the displacement it causes, "
            "which must stay at round-off.</p>\n"
            + table(["shortcut", "scenes", "with (s)", "without (s)", "saving", "difference"], rows,
                    css_class="small", left_columns=(0, 1)))

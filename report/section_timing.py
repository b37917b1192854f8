"""Section 7: run time against error per solver (study S5), from /studies/timing."""

import matplotlib.pyplot as plt
import numpy as np

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
        "reference, both on logarithmic axes; one line per solver and mesh level (for the relaxation, its points "
        "are its residual tolerances). "
        "Lower left is better: a solver whose line lies left of another's reaches the same error sooner.")]
    # One line per solver and mesh level (the relaxation's points at one level are its
    # tolerances); files without `contact_nodes` get one line per solver.
    nodes = array(g, "contact_nodes") if "contact_nodes" in g else np.zeros(len(solver))
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    for name, n in sorted(set(zip(solver, nodes))):
        k = [i for i in range(len(solver)) if solver[i] == name and nodes[i] == n]
        ok = [i for i in k if time_s[i] > 0 and error[i] > 0 and np.isfinite(error[i])]
        if not ok:
            continue
        ok.sort(key=lambda i: time_s[i])
        line, = ax.loglog(time_s[ok], error[ok], "o-", label=f"{name}, {int(n)} contact nodes" if n else name)
        for i in ok:
            ax.annotate(level[i], (time_s[i], error[i]), fontsize=7, xytext=(3, 3), textcoords="offset points",
                        color=line.get_color())
    ax.set_xlabel("wall time (s)")
    ax.set_ylabel("relative error to the reference (–)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    body.append(ctx.figures.save(fig, "timing", "run time against error", "Wall time against error, per solver."))
    rows = [[esc(solver[i]), esc(level[i]), num(time_s[i], 3), num(error[i], 3)] for i in range(len(solver))]
    body.append(table(["solver", "level", "time (s)", "error (–)"], rows, css_class="small", left_columns=(0, 1)))
    body.append(checks_block(ctx.checks, "timing.", "the run-time study"))
    return section("timing", title, "\n".join(body))

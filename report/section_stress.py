"""Section 8: the stress tests of numerical stability (study S5), from /studies/stress."""

import numpy as np

from checks import checks_block
from html_parts import absent, esc, how_to_read, num, section, table
from results_file import array, group, strings

# The stop causes of core/solvers/solve_report.h, and how each row is coloured.
NAMED = ("converged", "iteration cap", "singular system", "loss of accuracy", "round-off floor", "layer adrift")


def render(ctx):
    title = "8. Stress tests of numerical stability (study S5)"
    g = group(ctx.f, "studies/stress")
    if g is None:
        return section("stress", title, absent("The stress study (/studies/stress)"))
    scene, group_name, what = strings(g["scene"]), strings(g["group"]), strings(g["description"])
    solver, outcome, expected = strings(g["solver"]), strings(g["outcome"]), strings(g["expected"])
    message, counts = strings(g["message"]), strings(g["counts"])
    iterations, residual = array(g, "iterations"), array(g, "residual")
    condition, time_s, finite = array(g, "condition_estimate"), array(g, "time_s"), array(g, "finite")
    body = [how_to_read(
        "Each row is one scene pushed to an edge: a layer down to ε = 1e-8, a layer 1e-12 times softer than the "
        "adherents, friction from 0 to 10, distorted meshes, loads that open the whole interface, deliberately "
        "capped solves. A scene must converge to its residual or stop with a named cause (iteration cap, singular "
        "system, loss of accuracy, round-off floor, layer adrift), with the condition estimate of its last linear system; none may write NaN or "
        "Inf. <b>expected</b> is the outcome the project claims for that scene (blank: any named cause). "
        "Counts are gap/slide/stick on S (layer mode: through both faces).")]
    rows, classes = [], []
    for i in range(len(scene)):
        named = outcome[i] in NAMED and finite[i] == 1
        met = not expected[i] or outcome[i] == expected[i]
        classes.append("" if named and met else "failrow")
        rows.append([esc(group_name[i]), esc(what[i]), esc(solver[i]), esc(outcome[i]), esc(expected[i] or "—"),
                     num(iterations[i]), num(residual[i]) if residual[i] >= 0 else "NaN/Inf",
                     num(condition[i], 2) if condition[i] > 0 else "—", num(time_s[i], 3), esc(counts[i]),
                     f'<span title="{esc(message[i])}">{esc(message[i][:90])}</span>'])
    body.append(table(["group", "scene", "solver", "outcome", "expected", "iterations", "residual",
                       "condition", "time (s)", "gap/slide/stick", "solver's message (hover for all)"],
                      rows, css_class="small", left_columns=(0, 1, 2, 3, 4, 9, 10), row_classes=classes))
    slowest = int(np.argmax(time_s)) if len(time_s) else None
    if slowest is not None:
        body.append(f"<p>{len(scene)} scenes; the slowest took {num(time_s[slowest], 3)} s "
                    f"({esc(what[slowest])}): none hangs, every solver stops at its cap.</p>")
    body.append(checks_block(ctx.checks, "stress.", "the stress study"))
    return section("stress", title, "\n".join(body))

"""Section 3: analogues of the paper's Figs. 13 and 14 — the normal and tangential
displacement along AD for the six Table 3 rows (bar, limit mode, fast solver), over the
status of each node."""

import matplotlib.pyplot as plt

from html_parts import absent, how_to_read, num, section
from plotting import status_bands, status_legend
from scenes import read_interface


def render(ctx):
    body = [how_to_read(
        "One panel per row of Table 3 (bar, limit mode, fast solver, default mesh). The curve is the "
        "interface jump at the 32 contact nodes of AD against x, the distance from A in mm; the "
        "background colour is each node's stored status (grey gap, orange slide, blue stick). "
        "Sign convention (SPEC §1.2): on AD, [u]_N = −u₂, positive is interpenetration (negative: the "
        "bar lifts off the foundation), and [u]_T = u₁. <b>The vertical scales differ from panel to "
        "panel</b> (they can differ by orders of magnitude): read the shape and the transitions from "
        "the curve and the size from the axis. The paper observes that the normal displacement changes "
        "little with K_N and K_T while a small K_T = μ̄ makes the tangential one grow: compare.")]
    rows = bar_rows(ctx)
    if not rows:
        body.append(absent("Bar limit-mode scenes of the Table 3 rows (fast solver)"))
        return section("bar", "3. Displacements along AD (Figs. 13 and 14)", "\n".join(body))
    for quantity, name, label, paper in (
            ("jump_N", "fig13_normal_displacement", "[u]_N (mm)", "Fig. 13: normal displacement along AD"),
            ("jump_T", "fig14_tangential_displacement", "[u]_T (mm)", "Fig. 14: tangential displacement along AD")):
        fig, axes = plt.subplots(2, 3, figsize=(13, 6), sharex=True)
        for ax, (row, scene, data) in zip(axes.flat, rows):
            x = data["x"][:, 0]
            status_bands(ax, x, data["status"])
            ax.plot(x, data[quantity], "k.-", lw=1.2, ms=4)
            ax.set_title(f"row {row}: μ̄ = {num(scene.mu_bar)}, λ̄ = {num(scene.lambda_bar)} daN/mm³", fontsize=9)
            ax.ticklabel_format(axis="y", style="sci", scilimits=(-2, 3))
            ax.set_xlim(0, 40)
        for ax in axes.flat[len(rows):]:
            ax.set_visible(False)
        for ax in axes[-1]:
            ax.set_xlabel("x along AD (mm from A)")
        for ax in axes[:, 0]:
            ax.set_ylabel(label)
        status_legend(axes.flat[0], loc="best", fontsize=8)
        fig.suptitle(f"Analogue of the paper's {paper}")
        fig.tight_layout()
        body.append(ctx.figures.save(fig, name, paper,
                                     f"{paper}: {label} against x, status of each node as background."))
    return section("bar", "3. Displacements along AD (Figs. 13 and 14)", "\n".join(body))


def bar_rows(ctx):
    """(row, scene, interface S) for each Table 3 row, preferring the default 32×32 mesh."""
    rows = []
    for row in range(1, 7):
        candidates = [s for s in ctx.scenes if s.case == "bar" and s.mode == "limit" and s.solver == "fast"
                      and s.law_case == f"table3-row-{row}"]
        candidates.sort(key=lambda s: (s.attrs.get("nx") != 32 or s.attrs.get("ny") != 32, s.id))
        if candidates:
            rows.append((row, candidates[0], read_interface(ctx.f, candidates[0].id, "S")))
    return rows

"""Section 5c: the control experiments behind S2's rates (SPEC §3 S2: a rate that differs from its
prediction is explained by a control, not a refit). Two are stored by the run:
- the quadrature of the nearly incompressible layer (case (e)): the layer with selective
  integration beside the rule's full integration (cases/layer_quadrature.h), its node-to-node
  zigzag of σ_N along the right flank, the zigzag's reach against the derived ε^(−1/4), and the
  Cauchy differences of σ_N away from the corners for both;
- the two selections of the floating layer (cases (e), (f)): their spread at one ε beside the
  Cauchy difference to the next ε."""

import matplotlib.pyplot as plt
import numpy as np

from checks import checks_block
from html_parts import absent, esc, how_to_read, num, section, table
from plotting import label_minor_log_ticks
from results_file import array, attr, group, strings

TITLE = "5c. Controls behind the rates (study S2)"
# The dovetail slot's right flank (L units): from its bottom corner, where the zigzag starts, to its top.
BOTTOM_RIGHT_CORNER, TOP_RIGHT_CORNER = np.array([0.6, -0.5]), np.array([0.4, 0.0])


def render(ctx):
    g = group(ctx.f, "studies/convergence/controls")
    if g is None:
        return section("controls", TITLE, absent("The controls (/studies/convergence/controls)"))
    body = []
    if "quadrature" in g:
        body.append(quadrature_part(ctx, g["quadrature"]))
    if "selection" in g:
        body.append(selection_part(ctx, g["selection"]))
    return section("controls", TITLE, "\n".join(body))


def quadrature_part(ctx, q):
    case = attr(q, "law_case")
    sel, rule = q["selective"], q["rule"]
    eps = array(q, "eps")
    out = ["<h3>The layer's quadrature: the zigzag of selective integration</h3>", how_to_read(
        f"Case ({esc(case)}) solved twice at each ε: with selective integration of the layer's λ part (the cell "
        "centre; what the cases with a bounded zigzag keep) and with the rule's full 2×2 integration "
        "(cases/layer_quadrature.h). Selective integration sees only the mean of each cell's two columns of the "
        "through-thickness compression, so a zigzag of the columns is held by μ_ε and the adherents alone; where "
        "λ_ε/ε → ∞ faster than μ_ε/ε (cases e, f) its reach up the flank grows like ε^(−1/4) nodes (derived in "
        "studies/convergence_rates.md). Left: σ_N on S+ up the right flank from the slot's bottom corner. Middle: "
        "the reach ℓ_z of the zigzag selective integration adds (decay length of the alternating part of the "
        "difference of the two, in nodes), with its fitted slope and the derived −1/4. Right: the Cauchy "
        "differences of σ_N away from the corners for both (filled: both scenes converged), with a slope fitted "
        "over every pair: one thickness per decade leaves too few converged pairs for the rate study's tail "
        "rule, so these slopes are shown, not checked (the rate study's own grid gives the checked rate).")]
    rows = []
    for k in range(len(eps)):
        last = k + 1 == len(eps)
        rows.append([num(eps[k]), f"{array(sel, 'zigzag_rms')[k]:.3f}", f"{array(rule, 'zigzag_rms')[k]:.3f}",
                     "—" if not np.isfinite(array(q, 'reach')[k]) else f"{array(q, 'reach')[k]:.2f}",
                     "" if last else f"{array(sel, 'd_sigma_N_away')[k]:.2e}",
                     "" if last else f"{array(rule, 'd_sigma_N_away')[k]:.2e}",
                     converged_text(array(sel, "converged")[k]), converged_text(array(rule, "converged")[k])])
    rows.append(["rate / exponent", "", "", fit_text(q, "reach_exponent", "reach_fitted") +
                 f" (derived {num(attr(q, 'predicted_reach_exponent'))})",
                 fit_text(sel, "slope_sigma_N_away", "fitted"), fit_text(rule, "slope_sigma_N_away", "fitted"), "", ""])
    out.append(table(["ε (mm)", "zigzag rms, selective (daN/mm²)", "zigzag rms, rule", "reach ℓ_z (nodes)",
                      "Δσ_N away, selective", "Δσ_N away, rule", "selective converged", "rule converged"], rows,
                     css_class="small"))
    out.append(quadrature_figure(ctx, q, case))
    return "\n".join(out)


def converged_text(flag):
    return "yes" if flag else '<span class="failtext">no</span>'


def fit_text(node, name, fitted):
    if not attr(node, fitted, 0):
        return "not measurable"
    return f"{attr(node, name):.2f} ± {attr(node, name + '_stderr'):.2f}"


def flank_profile(ctx, scene_id):
    """(distance from the bottom corner, σ_N on S+) along the right flank, or None."""
    if scene_id not in ctx.f["scenes"]:
        return None
    interface = ctx.f["scenes"][scene_id]["interface"]
    x = array(interface["S-"], "x")  # the base's side: the limit mode's positions of S
    sigma = array(interface["S+"], "sigma_N")[: len(x)]
    along = (TOP_RIGHT_CORNER - BOTTOM_RIGHT_CORNER) / np.linalg.norm(TOP_RIGHT_CORNER - BOTTOM_RIGHT_CORNER)
    rel = x - BOTTOM_RIGHT_CORNER
    s_all, off = rel @ along, np.abs(rel[:, 0] * along[1] - rel[:, 1] * along[0])
    on_flank = (off < 1e-6) & (s_all > 1e-6) & (s_all < np.linalg.norm(TOP_RIGHT_CORNER - BOTTOM_RIGHT_CORNER) - 1e-6)
    s = s_all[on_flank]
    order = np.argsort(s)
    return s[order], sigma[on_flank][order]


def quadrature_figure(ctx, q, case):
    eps = array(q, "eps")
    sel_ids, rule_ids = strings(q["selective"]["layer_scene"]), strings(q["rule"]["layer_scene"])
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2))
    shown = sorted({0, len(eps) // 2, len(eps) - 1})
    for k, color in zip(shown, ("#1f77b4", "#ff7f0e", "#2ca02c")):
        for ids, style, name in ((sel_ids, "--", "selective"), (rule_ids, "-", "rule")):
            profile = flank_profile(ctx, ids[k])
            if profile is not None:
                axes[0].plot(profile[0], profile[1], style, color=color, marker=".", ms=4, lw=1,
                             label=f"ε = {eps[k]:.0e}, {name}")
    axes[0].set_xlabel("distance from the slot's bottom corner along the right flank (mm)")
    axes[0].set_ylabel("σ_N on S+ (daN/mm²)")
    axes[0].set_title(f"case ({case}): σ_N up the right flank")
    axes[0].legend(fontsize=7)

    reach = array(q, "reach")
    ok = np.isfinite(reach) & (reach > 0)
    axes[1].loglog(eps[ok], reach[ok], "ko", label="measured")
    if attr(q, "reach_fitted", 0) and ok.sum() >= 2:
        grid = np.geomspace(eps[ok].min(), eps[ok].max(), 10)
        p = attr(q, "reach_exponent")
        centre_x, centre_y = np.exp(np.mean(np.log(eps[ok]))), np.exp(np.mean(np.log(reach[ok])))
        axes[1].loglog(grid, centre_y * (grid / centre_x) ** p, "k-", alpha=0.5, lw=2, label=f"fit q = {p:.2f}")
        pred = attr(q, "predicted_reach_exponent")
        axes[1].loglog(grid, centre_y * (grid / centre_x) ** pred, "k--", label=f"derived {pred:g}")
    axes[1].set_xlabel("ε (mm)")
    axes[1].set_ylabel("reach ℓ_z of the zigzag (nodes)")
    axes[1].set_title("the zigzag's reach up the flank")
    axes[1].legend(fontsize=7)
    label_minor_log_ticks(axes[1])

    eps_k = eps[:-1]
    for side, color in (("selective", "#d62728"), ("rule", "#1f77b4")):
        d = array(q[side], "d_sigma_N_away")
        converged = array(q[side], "converged").astype(bool)
        both = converged[:-1] & converged[1:]
        rate = fit_text(q[side], "slope_sigma_N_away", "fitted")
        axes[2].loglog(eps_k, d, "-", color=color, lw=0.8, alpha=0.6)
        axes[2].loglog(eps_k[both], d[both], "o", color=color, label=f"{side}: slope {rate}")
        axes[2].loglog(eps_k[~both], d[~both], "o", mfc="none", color=color)
    axes[2].set_xlabel("ε_k (mm)")
    axes[2].set_ylabel("‖σ_N(ε_k) − σ_N(ε_k+1)‖ away from the corners (relative)")
    axes[2].set_title("Cauchy differences of σ_N away")
    axes[2].legend(fontsize=7)
    label_minor_log_ticks(axes[2])
    fig.tight_layout()
    caption = ("Selective integration (dashed, red) against the rule's full integration (solid, blue): the "
               "zigzag starts at the bottom corner and reaches further up the flank as ε falls, so σ_N away "
               "from the corners does not converge on any ε a double-precision solve reaches; with full "
               "integration its differences fall at the predicted rate.")
    return ctx.figures.save(fig, "control_quadrature", "quadrature control", caption)


def selection_part(ctx, s):
    quantities = [k[len("spread_"):] for k in s.keys() if k.startswith("spread_")]
    out = ["<h3>The two selections of the floating layer</h3>", how_to_read(
        "At each ε the layer solved with the selection spring on its minus face (the default) and on its plus "
        "face (SPEC §1.5: any point of the solution set is an answer). Each cell: the spread between the two "
        "selections / the Cauchy difference from this ε to the next one of the study's grid, relative, as in "
        f"the rate study. The check: every spread ≤ {num(attr(s, 'agreement'))} with both selections converged "
        "(rule rows). The selective row is the quadrature the rule replaced, shown for comparison.")]
    cases, quad, eps = strings(s["case"]), strings(s["quadrature"]), array(s, "eps")
    converged = array(s, "converged")
    rows = []
    for i in range(len(cases)):
        row = [f"({esc(cases[i])})", esc(quad[i]), num(eps[i])]
        for qn in quantities:
            row.append(f"{array(s, 'spread_' + qn)[i]:.1e} / {array(s, 'cauchy_' + qn)[i]:.1e}")
        row.append(converged_text(converged[i]))
        rows.append(row)
    out.append(table(["case", "quadrature", "ε (mm)"] + [esc(qn) for qn in quantities] + ["both converged"], rows,
                     css_class="small"))
    mine = None if ctx.checks is None else [c for c in ctx.checks if c.id.endswith(".selections_agree")]
    out.append(checks_block(mine, "convergence.", "the selection control"))
    return "\n".join(out)

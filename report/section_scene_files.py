"""Section 9: the user's own joints (scene files, SPEC §5) — for each scene studied, the distance
between its layer and limit modes against ε with the fitted rates (study S2), and the largest ε
at which the limit law stays within τ (study S3). verify runs the shipped single-lap shear
joint (cases/lap_joint)."""

import re

import matplotlib.pyplot as plt
import numpy as np

from checks import checks_block
from html_parts import absent, esc, how_to_read, num, section, table
from plotting import label_minor_log_ticks
from results_file import array, attr, group, strings

QUANTITIES = ("u", "jump_N", "jump_T", "sigma_N", "sigma_T")
LABELS = {"u": "adherents' u", "jump_N": "[u]_N across the layer", "jump_T": "[u]_T across the layer",
          "sigma_N": "σ_N on S", "sigma_T": "σ_T on S"}
STATUS_TEXT = {"found": "found by bisection", "at_least": "within τ at every sampled ε: a lower bound",
               "below_range": "not within τ even at the smallest ε"}


def render(ctx):
    g = group(ctx.f, "studies/scene")
    if g is None:
        return section("scenes", "9. Your own joint: scene files",
                       absent("A scene-file study (/studies/scene)"))
    body = []
    for name in sorted(g):
        body.append(scene_block(ctx, g[name], name))
    body.append(checks_block(ctx.checks, "scene.", "the scene-file studies"))
    return section("scenes", "9. Your own joint: scene files", "\n".join(body))


def rate_text(p, stderr, fitted):
    if not fitted:
        return "n/a"
    return f"{p:.2f} ± {stderr:.2f}"


def scene_block(ctx, s, name):
    eps = array(s, "eps")
    law = attr(s, "table1_case", "?")
    predicted = attr(s, "p_predicted")
    out = [f"<h3>{esc(name)} <small>({esc(attr(s, 'scene_file', ''))})</small></h3>",
           how_to_read(
               f"Both modes of the scene on one mesh: the limit law (Table 1 case ({esc(law)})) against the meshed "
               "layer of thickness ε, whose plus adherent's interface nodes moved by ε along the normal. "
               "Relative discrete L² distances of the adherents' displacements, of the jumps across the layer and of "
               "the stresses on the plus face; <i>diff</i>: nodes of S whose combined status differs from the limit's. "
               "Rates p of e ≈ C ε^p (plain) and e ≈ e_∞ + C ε^p (floored: the floor is the misfit at the ends of "
               "the bondline, which shrinks with the element size, not with ε); p (Cauchy): from the layer model's own "
               "differences between neighbouring ε, d_k ≈ C ε_k^p (1 − (ε_k+1/ε_k)^p), where the floor cancels."
               + (f" The asymptotics predict p = {num(predicted)} for these exponents (studies/convergence_rates.md)."
                  if predicted is not None and predicted >= 0 else ""))]
    header = ["ε (mm)"] + [LABELS[q] for q in QUANTITIES] + ["diff", "converged"]
    diff, converged = array(s, "status_diff"), array(s, "converged")
    rows = []
    for i in range(len(eps)):
        rows.append([num(eps[i])] + [f"{array(s, 'e_' + q)[i]:.2e}" for q in QUANTITIES] +
                    [str(int(diff[i])), "yes" if converged[i] else '<span class="failtext">no</span>'])
    rows.append(["p (plain)"] + [rate_text(attr(s, "p_" + q), attr(s, "p_" + q + "_stderr", 0), attr(s, "fitted_" + q))
                                 for q in QUANTITIES] + ["", ""])
    rows.append(["p (floored)"] + [rate_text(attr(s, "p_floor_" + q), 0, attr(s, "fitted_floor_" + q)).replace(" ± 0.00", "")
                                   for q in QUANTITIES] + ["", ""])
    rows.append(["e_∞"] + [f"{attr(s, 'floor_' + q, 0):.2e}" if attr(s, "fitted_floor_" + q) else "n/a"
                           for q in QUANTITIES] + ["", ""])
    if "cauchy" in s:  # the layer model's own differences along ε: the floor cancels
        c = s["cauchy"]
        rows.append(["p (Cauchy)"] + [rate_text(attr(c, "p_" + q), attr(c, "p_" + q + "_stderr", 0), attr(c, "fitted_" + q))
                                      for q in QUANTITIES] + ["", ""])
    out.append(table(header, rows))
    out.append(scene_figure(ctx, s, name, eps))
    if "validity" in s:
        out.append(validity_table(s["validity"]))
    return "\n".join(out)


def scene_figure(ctx, s, name, eps):
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for q in QUANTITIES:
        e = array(s, "e_" + q)
        ok = (e > 0) & np.isfinite(e)
        if ok.any():
            ax.loglog(eps[ok], e[ok], "o-", ms=4, lw=1.2, label=f"{LABELS[q]}  p = {attr(s, 'p_' + q, 0):.2f}")
    ax.set_xlabel("layer thickness ε (mm)")
    ax.set_ylabel("relative L² distance (–)")
    ax.set_title(f"{name}: layer mode against the limit law")
    ax.legend(fontsize=7, loc="best")
    label_minor_log_ticks(ax)
    fig.tight_layout()
    slug = re.sub(r"[^A-Za-z0-9_-]", "_", name)
    return ctx.figures.save(fig, f"scene_{slug}", f"scene {name} convergence",
                            f"{esc(name)}: distances between the modes against ε (log–log)")


def validity_table(v):
    tau, eps_max, status = array(v, "tau"), array(v, "eps_max"), strings(v["status"])
    error, beyond, steps = array(v, "error_at_eps_max"), array(v, "eps_beyond"), array(v, "bisection_steps")
    quantity = strings(v["quantity"]) if "quantity" in v else ["u"] * len(tau)  # before issue 35: u only
    rows = []
    for i in range(len(tau)):
        value = {"found": f"{eps_max[i]:.3g}", "at_least": f"≥ {eps_max[i]:.3g}",
                 "below_range": f"&lt; {eps_max[i]:.3g}"}.get(status[i], f"{eps_max[i]:.3g}")
        rows.append([esc(quantity[i]), f"{tau[i] * 100:g} %", f"<b>{value}</b>", f"{error[i]:.2e}",
                     f"{beyond[i]:.3g}" if status[i] == "found" else "—", STATUS_TEXT.get(status[i], esc(status[i])),
                     str(int(steps[i]))])
    return ("<p>Thickness validity (S3), per quantity (the reactions, the adherents' displacements u, the peak peel and "
            "shear at a stated distance from the bondline ends): the largest ε (mm) up to which the limit law stays "
            "within τ of the layer model at every sampled thickness.</p>" +
            table(["quantity", "τ", "ε_max (mm)", "error at ε_max", "first ε beyond", "status", "bisection steps"], rows,
                  left_columns=(0,)))

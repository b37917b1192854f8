"""Section 6: the thickness below which the limit law is valid (study S3) and the paper's
3 % / 30× classification thresholds (study S4)."""

import matplotlib.pyplot as plt
import numpy as np

from checks import checks_block
from html_parts import absent, esc, how_to_read, num, section, table
from results_file import array, attr, group, strings

STATUS_TEXT = {
    "found": "found by bisection",
    "at_least": "within τ at every sampled ε: a lower bound",
    "below_range": "not within τ even at the smallest ε",
}


def render(ctx):
    body = ["<h3>Thickness validity (study S3)</h3>", validity(ctx),
            checks_block(ctx.checks, "validity.", "the validity study"),
            "<h3>Classification thresholds (study S4)</h3>", thresholds(ctx),
            checks_block(ctx.checks, "thresholds.", "the thresholds study")]
    return section("validity", "6. Validity of the limit law", "\n".join(body))


def validity(ctx):
    g = group(ctx.f, "studies/validity")
    if g is None:
        return absent("The validity study (/studies/validity)")
    claim = attr(g, "paper_claim")
    cases, tau = strings(g["case"]), array(g, "tau")
    eps_max, status = array(g, "eps_max"), strings(g["status"])
    error = array(g, "error_at_eps_max") if "error_at_eps_max" in g else np.full(len(cases), np.nan)
    steps = array(g, "bisection_steps") if "bisection_steps" in g else np.zeros(len(cases), int)
    converged = array(g, "converged") if "converged" in g else np.ones(len(cases), int)
    # Files before the validity study measured several quantities have one, named by an attribute.
    quantity = strings(g["quantity"]) if "quantity" in g else [attr(g, "quantity", "u")] * len(cases)
    out = [how_to_read(
        "For each case, determined quantity and tolerance τ: ε_max, the largest layer thickness (mm) at which "
        "the limit law stays within τ of the layer model, measured on that quantity's relative distance "
        "(<code>u</code> the adherents' displacements, <code>R_top</code> the tenon-top reaction, "
        "<code>sigma_N</code>, <code>sigma_T</code> the stresses on S), found by bisection on log ε between the "
        "sampled thicknesses. '≥': within τ at every sampled ε, so ε_max is only a lower bound; '&lt;': not "
        "within τ even at the smallest ε. "
        f"The paper claims validity up to ε = {num(claim)} mm; the last column says whether this run's "
        "ε_max reaches that (information, not a check).")]
    taus = sorted(set(float(t) for t in tau))
    for q in list(dict.fromkeys(quantity)):
        rows = []
        for case in sorted(set(cases)):
            row = [f"({esc(case)})"]
            reach = []
            for t in taus:
                k = [i for i in range(len(cases)) if cases[i] == case and float(tau[i]) == t and quantity[i] == q]
                if not k:
                    row.append("—")
                    continue
                i = k[0]
                row.append(validity_cell(eps_max[i], status[i], error[i], steps[i], converged[i]))
                reach.append(f"τ {t:g}: " + reaches(eps_max[i], status[i], claim))
            row.append("<br>".join(reach))
            rows.append(row)
        out.append(f"<h4>on <code>{esc(q)}</code></h4>")
        out.append(table(["case"] + [f"τ = {t:g} ({t * 100:g} %)" for t in taus] + [f"valid at ε = {num(claim)}?"],
                         rows, left_columns=tuple(range(len(taus) + 2))))
    return "\n".join(out)


def validity_cell(eps_max, status, error, steps, converged):
    if status == "found":
        value = f"ε_max = {eps_max:.3g} mm"
    elif status == "at_least":
        value = f"ε_max ≥ {eps_max:.3g} mm"
    elif status == "below_range":
        value = f"ε_max &lt; {eps_max:.3g} mm" if eps_max > 0 else "below the smallest ε"
    else:
        value = f"{eps_max:.3g} ({esc(status)})"
    detail = [STATUS_TEXT.get(status, esc(status))]
    if np.isfinite(error):
        detail.append(f"error there {error:.2g}")
    detail.append(f"{int(steps)} bisection steps")
    text = f"<b>{value}</b><br><small>{'; '.join(detail)}</small>"
    if not converged:
        text += '<br><span class="failtext">a scene did not converge</span>'
    return text


def reaches(eps_max, status, claim):
    if claim is None:
        return "—"
    if status == "below_range":
        return "no"
    if eps_max >= claim:
        return "yes"
    return "no" if status == "found" else "unknown"


def thresholds(ctx):
    g = group(ctx.f, "studies/thresholds")
    if g is None:
        return absent("The thresholds study (/studies/thresholds)")
    crossings = group(g, "crossings")
    low = attr(g, "threshold_low", attr(crossings, "threshold_low", 0.03) if crossings is not None else 0.03)
    high = attr(g, "threshold_high", attr(crossings, "threshold_high", 30.0) if crossings is not None else 30.0)
    taus = sorted(set(float(t) for t in array(crossings, "tau"))) if crossings is not None else [0.01, 0.05]
    out = [how_to_read(
        "Dovetail, limit mode. The finite law (λ̄, μ̄) is replaced by the 0 law and by the ∞ law, and the "
        "relative error of that replacement is plotted against the ratio λ̄/(λ_m/L) (left) or μ̄/(μ_m/L) "
        f"(right), the other parameter held fixed. The paper (§3.3) says 0 is good enough below {num(low)} and "
        f"∞ above {num(high)} (dotted vertical lines). Dashed horizontal lines: τ = "
        f"{', '.join(f'{t * 100:g} %' for t in taus)}. Where a curve crosses a τ line is the threshold this run "
        "measures (marked, and listed in the table below).")]
    params = [p for p in ("lambda", "mu") if group(g, p) is not None]
    if not params:
        out.append(absent("The threshold sweeps (/studies/thresholds/lambda, /mu)"))
    else:
        out.append(threshold_plot(ctx, g, params, low, high, taus, crossings))
    out.append(crossings_table(g, crossings))
    return "\n".join(out)


def threshold_plot(ctx, g, params, low, high, taus, crossings):
    fig, axes = plt.subplots(1, len(params), figsize=(6.5 * len(params), 4.6), squeeze=False)
    symbol = {"lambda": "λ̄ / (λ_m/L)", "mu": "μ̄ / (μ_m/L)"}
    for ax, p in zip(axes[0], params):
        s = g[p]
        ratio = array(s, "ratio")
        for name, law, color in (("error_zero", "0", "#1f77b4"), ("error_inf", "inf", "#d62728")):
            e = array(s, name)
            ok = (e > 0) & np.isfinite(e)
            ax.loglog(ratio[ok], e[ok], "o-", ms=3, color=color,
                      label=f"replaced by the {'0' if law == '0' else '∞'} law")
            if crossings is not None:
                mark_crossings(ax, crossings, p, law, color)
        for x in (low, high):
            ax.axvline(x, color="k", ls=":", lw=1.2)
            ax.annotate(f"paper: {x:g}", (x, 1), xycoords=("data", "axes fraction"), xytext=(3, -12),
                        textcoords="offset points", fontsize=7)
        for t in taus:
            ax.axhline(t, color="#555", ls="--", lw=1)
            ax.annotate(f"τ = {t * 100:g} %", (ax.get_xlim()[0], t), fontsize=7, va="bottom")
        ax.set_xlabel(f"{symbol[p]} (–)")
        ax.set_ylabel("relative error of the replacement (–)")
        ax.set_title(f"sweep of {'λ̄' if p == 'lambda' else 'μ̄'}; {attr(s, 'fixed_other', '')}", fontsize=9)
        ax.legend(fontsize=8, loc="best")
    fig.tight_layout()
    return ctx.figures.save(fig, "thresholds", "threshold sweeps",
                            "Error of replacing the finite law by the 0 or ∞ law against the stiffness ratio; "
                            f"dotted: the paper's {num(low)} and {num(high)}; dashed: τ.")


def mark_crossings(ax, crossings, param, law, color):
    params, laws = strings(crossings["param"]), strings(crossings["law"])
    ratio, tau, status = array(crossings, "ratio"), array(crossings, "tau"), strings(crossings["status"])
    for i in range(len(params)):
        if params[i] == param and laws[i] == law and status[i] == "found":
            ax.plot([ratio[i]], [tau[i]], "D", color=color, ms=7, mec="k")


def crossings_table(g, crossings):
    if crossings is None:
        return absent("The threshold crossings (/studies/thresholds/crossings)")
    params, laws = strings(crossings["param"]), strings(crossings["law"])
    tau, ratio, status = array(crossings, "tau"), array(crossings, "ratio"), strings(crossings["status"])
    at = array(crossings, "error_at_threshold") if "error_at_threshold" in crossings else None
    confirmed = array(crossings, "confirmed") if "confirmed" in crossings else None
    rows, classes = [], []
    for i in range(len(params)):
        row = [esc(params[i]), "∞" if laws[i] == "inf" else esc(laws[i]), f"{tau[i] * 100:g} %", num(ratio[i]),
               esc(status[i])]
        if at is not None:
            row.append(num(at[i], 2))
        if confirmed is not None:
            row.append('<span class="passtext">confirmed</span>' if confirmed[i]
                       else '<span class="failtext">not confirmed</span>')
        rows.append(row)
        classes.append("failrow" if confirmed is not None and not confirmed[i] else "")
    header = ["parameter", "law", "τ", "crossing ratio", "status"]
    if at is not None:
        header.append("error at the paper's threshold")
    if confirmed is not None:
        header.append("paper's threshold (stored)")
    out = [table(header, rows, left_columns=(0, 1, 4), row_classes=classes)]
    summary = attr(g, "confirmed", attr(crossings, "confirmed"))
    if summary:
        out.append(f"<details><summary>the stored summary</summary><small>{esc(summary)}</small></details>")
    out.append("<p><small>Crossing ratio: where the error of the replacement crosses τ; with status other than "
               "'found' it is the end of the sweep (e.g. 'always': within τ over the whole sweep).</small></p>")
    return "\n".join(out)

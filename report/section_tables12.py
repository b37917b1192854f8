"""Section 2a: Tables 1 and 2 of the paper, rebuilt from the dovetail scenes' attributes.

Table 1 places each limit scene by the class of its stored λ̄ and μ̄ (0, finite, ∞) and shows
the case letter the scene carries; Table 2 places each scene by its stored γ, δ. Beside each
cell is the paper's letter for that cell, so a misplaced law would show as a mismatch.
"""

import math

from checks import checks_block
from html_parts import absent, esc, how_to_read, num, table

# The paper's Table 1: (μ̄ class, λ̄ class) -> case letter and the law in words (§1.2).
PAPER_TABLE1 = {
    ("0", "inf"): ("e", "Signorini, σ_T = 0"),
    ("0", "finite"): ("c", "σ_N = −λ̄[u]_N⁺, σ_T = 0"),
    ("0", "0"): ("a", "σ = 0"),
    ("finite", "inf"): ("f", "Signorini + spring μ̄ then Coulomb"),
    ("finite", "finite"): ("d", "σ_N = −(λ̄+2μ̄)[u]_N⁺ + spring μ̄ then Coulomb"),
    ("finite", "0"): ("b", "σ_N = −2μ̄[u]_N⁺ + spring μ̄ then Coulomb"),
    ("inf", "inf"): ("i", "Signorini + Coulomb"),
    ("inf", "finite"): ("h", "Signorini + Coulomb"),
    ("inf", "0"): ("g", "Signorini + Coulomb"),
}
# The paper's Table 2: (δ, γ) -> case letter.
PAPER_TABLE2 = {(1.5, 0.5): "e", (1.5, 1.0): "c", (1.5, 1.5): "a",
                (1.0, 0.5): "f", (1.0, 1.0): "d", (1.0, 1.5): "b",
                (0.5, 0.5): "i", (0.5, 1.0): "h", (0.5, 1.5): "g"}
CLASS_ORDER_MU = ("0", "finite", "inf")
CLASS_ORDER_LAMBDA = ("inf", "finite", "0")
CLASS_LABEL = {"0": "= 0", "finite": "finite", "inf": "= ∞"}


def stiffness_class(value):
    if value == 0:
        return "0"
    if math.isinf(value):
        return "inf"
    return "finite"


def render(ctx):
    dovetail = [s for s in ctx.scenes if s.case == "dovetail"]
    body = ["<h3>Table 1: the nine limit laws</h3>", how_to_read(
        "Rows: the class of μ̄ = lim μ_ε/ε, columns: the class of λ̄ = lim λ_ε/ε (daN/mm³), as in the "
        "paper. Each dovetail <em>limit</em> scene is placed by the class of its stored "
        "<code>lambda_bar</code>, <code>mu_bar</code> and shows its stored <code>law_case</code> and "
        "values; the paper's letter for the cell is printed beside it. A letter that differs from the "
        "paper's would mean the run assigned a law to the wrong cell.")]
    body.append(table1(dovetail))
    body += ["<h3>Table 2: the nine dovetail cases</h3>", how_to_read(
        "λ_ε = ε^γ λ_g, μ_ε = ε^δ μ_g. Each dovetail scene (both modes) is placed by its stored "
        "<code>gamma</code>, <code>delta</code>; the cell lists the case letters found there, the "
        "paper's letter, and the thicknesses ε solved in layer mode.")]
    body.append(table2(dovetail))
    body.append(checks_block(ctx.checks, "dovetail.", "the dovetail scenes"))
    return "\n".join(body)


def table1(dovetail):
    limits = [s for s in dovetail if s.mode == "limit"]
    if not limits:
        return absent("Dovetail limit-mode scenes (for Table 1)")
    cells = {}
    for s in limits:
        key = (stiffness_class(s.mu_bar), stiffness_class(s.lambda_bar))
        cells.setdefault(key, {})[s.law_case] = s
    rows = []
    for mu in CLASS_ORDER_MU:
        row = [f"μ̄ {CLASS_LABEL[mu]}"]
        for lam in CLASS_ORDER_LAMBDA:
            paper_letter, law = PAPER_TABLE1[(mu, lam)]
            found = cells.get((mu, lam), {})
            if found:
                run = "; ".join(f"<b>({esc(c)})</b> λ̄ = {num(s.lambda_bar)}, μ̄ = {num(s.mu_bar)}"
                                for c, s in sorted(found.items()))
            else:
                run = '<span class="absent">no scene</span>'
            row.append(f"paper ({paper_letter}): {esc(law)}<br>run: {run}")
        rows.append(row)
    header = [""] + [f"λ̄ {CLASS_LABEL[c]}" for c in CLASS_ORDER_LAMBDA]
    return table(header, rows, left_columns=(0, 1, 2, 3))


def table2(dovetail):
    if not dovetail:
        return absent("Dovetail scenes (for Table 2)")
    cells = {}
    for s in dovetail:
        key = (round(s.delta, 6), round(s.gamma, 6))
        entry = cells.setdefault(key, {})
        letters = entry.setdefault(s.law_case, set())
        if s.mode == "layer":
            letters.add(s.eps)
    rows = []
    for delta in (1.5, 1.0, 0.5):
        row = [f"δ = {delta:g}"]
        for gamma in (0.5, 1.0, 1.5):
            found = cells.pop((delta, gamma), {})
            parts = []
            for letter, eps in sorted(found.items()):
                eps_text = (f"{len(eps)} ε from {min(eps):.3g} to {max(eps):.3g} mm" if eps else "limit only")
                parts.append(f"<b>({esc(letter)})</b> {eps_text}")
            run = "<br>".join(parts) if parts else '<span class="absent">no scene</span>'
            row.append(f"paper ({PAPER_TABLE2[(delta, gamma)]})<br>run: {run}")
        rows.append(row)
    out = [table([""] + [f"γ = {g:g}" for g in (0.5, 1.0, 1.5)], rows, left_columns=(0, 1, 2, 3))]
    if cells:  # scenes at exponents outside the paper's grid (e.g. a user's own γ, δ)
        extra = ", ".join(f"γ = {g:g}, δ = {d:g}: {', '.join(sorted(v))}" for (d, g), v in sorted(cells.items()))
        out.append(f"<p>Other exponents in this file: {esc(extra)}.</p>")
    return "\n".join(out)

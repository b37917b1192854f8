"""Section 2b: Table 3 of the paper (the bar, study S1) — the paper's counts, the project's
regression baseline and both solvers' counts, the layer mode at decreasing ε, the
sensitivity study that explains the differences from the paper, and the transitions along
AD under mesh refinement. Everything from /studies/table3 and the bar scenes."""

import numpy as np

from checks import checks_block, compact_verdict, with_prefix
from html_parts import absent, esc, how_to_read, num, table
from results_file import array, attr, group, strings
from scenes import find

CONTACT_NODE_SPACING_MM = 40.0 / 32  # the paper's 32 contact nodes along AD (L = 40 mm)


def counts(g, prefix, i):
    return f"{int(g[prefix + '_gap'][i])}/{int(g[prefix + '_slide'][i])}/{int(g[prefix + '_stick'][i])}"


def render(ctx):
    g = group(ctx.f, "studies/table3")
    body = ["<h3>Table 3: the bar's interface, gap / slide / stick nodes out of 32</h3>"]
    if g is None:
        body.append(absent("The Table 3 study (/studies/table3)"))
        return "\n".join(body)
    body.append(how_to_read(
        "Per row of the paper's Table 3 (λ̄, μ̄ in daN/mm³): the paper's counts, the project's "
        "<b>regression baseline</b> (its own converged counts for Q1 32×32, plane strain, SPEC §2.1.1), "
        "and what the fast and the relaxation solver got in this run. The checks require both solvers "
        "to equal the baseline exactly, to converge, and to agree with each other; they do not compare "
        "with the paper, whose counts the stated model does not reproduce row for row (the sensitivity "
        "study below shows which model variants do). |Δ[u]|/|[u]|: relative L² distance between the "
        "two solvers' interface jumps. Times are medians of repeated solves."))
    body.append(rows_table(ctx, g))
    body.append(checks_block(ctx.checks, "table3.", "Table 3"))
    body.append(layer_table(ctx))
    body.append(sensitivity(g))
    body.append(refinement(g))
    return "\n".join(body)


def row_stiffness(ctx, row):
    """λ̄, μ̄ of a Table 3 row, from its limit scene (the rows table does not repeat them)."""
    for s in find(ctx.scenes, case="bar", mode="limit", law_case=f"table3-row-{row}"):
        return s.lambda_bar, s.mu_bar
    return None, None


def rows_table(ctx, g):
    r = group(g, "rows")
    if r is None:
        return absent("The Table 3 rows (/studies/table3/rows)")
    rows, classes = [], []
    for i, row in enumerate(array(r, "row")):
        row = int(row)
        lam, mu = row_stiffness(ctx, row)
        mine = with_prefix(ctx.checks, f"table3.row{row}.")
        paper, base = counts(r, "paper", i), counts(r, "baseline", i)
        paper_cell = paper if paper == base else f'{paper} <span class="note">(≠ baseline)</span>'
        rows.append([str(row), num(mu), num(lam), paper_cell, base, counts(r, "fast", i), counts(r, "relaxation", i),
                     f"{int(r['fast_iterations'][i])}", num(r["fast_residual"][i], 2), num(r["fast_time_s"][i], 2),
                     f"{int(r['relaxation_iterations'][i])}", num(r["relaxation_residual"][i], 2),
                     num(r["relaxation_time_s"][i], 2), num(r["interface_jump_distance"][i], 2),
                     compact_verdict(mine) if ctx.checks is not None else "—"])
        classes.append("failrow" if any(not c.passed for c in mine) else "")
    header = ["row", "μ̄", "λ̄", "paper", "baseline", "fast", "relaxation", "fast it", "fast residual",
              "fast time (s)", "relax. sweeps", "relax. residual", "relax. time (s)", "|Δ[u]|/|[u]|", "checks"]
    return table(header, rows, left_columns=(14,), row_classes=classes)


def layer_table(ctx):
    """The bar's layer mode at decreasing ε: combined counts against the limit baseline."""
    out = ["<h3>Table 3 in layer mode: the meshed layer under AD</h3>"]
    layer = [s for s in ctx.scenes if s.case == "bar" and s.mode == "layer" and s.law_case.startswith("table3-row-")]
    if not layer:
        out.append(absent("Bar layer-mode scenes"))
        return "\n".join(out)
    out.append(how_to_read(
        "A layer of thickness ε (mm) under AD with λ_ε = ε λ̄, μ_ε = ε μ̄, Signorini–Coulomb on both "
        "faces. Counts are of the stored <code>combined_status</code> (a node is gap if either face is "
        "open, else slide if either face slides, else stick); they should approach the limit mode's "
        "counts (the fast solver's, left) as ε decreases."))
    eps_values = sorted({s.eps for s in layer}, reverse=True)
    rows = []
    for row in sorted({int(s.law_case.rsplit("-", 1)[1]) for s in layer}):
        limit = find(ctx.scenes, case="bar", mode="limit", law_case=f"table3-row-{row}", solver="fast")
        cells = [str(row), status_counts(ctx.f["scenes"][limit[0].id]["interface"]["S"]["status"][()])
                 if limit else "—"]
        for eps in eps_values:
            match = [s for s in layer if s.law_case == f"table3-row-{row}" and s.eps == eps]
            if match:
                s = match[0]
                text = status_counts(ctx.f["scenes"][s.id]["combined_status"][()])
                if not s.converged:
                    text += ' <span class="failtext">not converged</span>'
                cells.append(text)
            else:
                cells.append("—")
        rows.append(cells)
    out.append(table(["row", "limit (fast)"] + [f"ε = {e:g} mm" for e in eps_values], rows))
    return "\n".join(out)


def status_counts(status):
    status = np.asarray(status)
    return f"{int((status == 0).sum())}/{int((status == 1).sum())}/{int((status == 2).sum())}"


# The sensitivity study's factors, in the order the SPEC lists them.
FACTORS = (("plane", "plane"), ("element", "element"), ("ny", "ny"), ("nx", "nx"), ("scale", "s"))


def sensitivity(g):
    out = ["<h3>Sensitivity: which model variants reproduce which paper row</h3>"]
    s = group(g, "sensitivity")
    if s is None:
        out.append(absent("The sensitivity study (/studies/table3/sensitivity; a quick run skips it)"))
        return "\n".join(out)
    cols = {}
    for name, _ in FACTORS:
        cols[name] = strings(s[name]) if s[name].dtype.kind in "SOU" else list(array(s, name))
    row, match, conv = array(s, "row"), array(s, "matches_paper"), array(s, "converged")
    gap, slide, stick = array(s, "gap"), array(s, "slide"), array(s, "stick")
    out.append(how_to_read(
        f"{len(row)} solves: every combination of plane hypothesis, element (P1 with either diagonal), "
        "ny, nx and a scale factor s on λ̄ and μ̄, for each row. <code>matches_paper</code> (stored) says "
        "whether a variant's counts equal the paper's row. Per row: how many variants match, how the "
        "matches spread over each factor's levels (a level with no match cannot explain the paper), "
        "and a few matching variants."))
    levels = {name: sorted(set(cols[name]), key=level_key) for name, _ in FACTORS}
    header = ["row", "matching / variants", "not converged"]
    for name, label in FACTORS:
        header += [f"{label} {level_text(v)}" for v in levels[name]]
    header.append("examples")
    rows = []
    for r in sorted(set(int(v) for v in row)):
        mask = row == r
        hit = mask & (match == 1)
        cells = [str(r), f"{int(hit.sum())} / {int(mask.sum())}", str(int((mask & (conv == 0)).sum()))]
        for name, _ in FACTORS:
            values = np.array(cols[name], dtype=object)
            cells += [str(int((hit & (values == v)).sum())) for v in levels[name]]
        examples = [variant_text(cols, k) + f" → {gap[k]}/{slide[k]}/{stick[k]}" for k in np.flatnonzero(hit)[:3]]
        cells.append("<br>".join(esc(e) for e in examples) or "none")
        rows.append(cells)
    out.append(table(header, rows, css_class="small", left_columns=(len(header) - 1,)))
    return "\n".join(out)


def level_key(v):
    return (0, float(v)) if not isinstance(v, str) else (1, v)


def level_text(v):
    return f"{float(v):g}" if not isinstance(v, str) else v


def variant_text(cols, k):
    return (f"plane {cols['plane'][k]}, {cols['element'][k]}, {int(cols['nx'][k])}×{int(cols['ny'][k])}, "
            f"s {float(cols['scale'][k]):g}")


def paper_interval(nodes_before):
    """Where a transition after `nodes_before` contact nodes (from A) lies, in mm from A."""
    return (nodes_before - 1) * CONTACT_NODE_SPACING_MM, nodes_before * CONTACT_NODE_SPACING_MM


def refinement(g):
    out = ["<h3>Transitions along AD under mesh refinement (mm from A)</h3>"]
    ref = group(g, "refinement")
    if ref is None:
        out.append(absent("The refinement study (/studies/table3/refinement; a quick run skips it)"))
        return "\n".join(out)
    n = [int(v) for v in array(ref, "n")]
    missing = attr(g, "missing_transition_mm", -1.0)
    out.append(how_to_read(
        "The gap–contact and stick–slip transitions of the default model (Q1, plane strain) on "
        f"n×n meshes, n = {', '.join(map(str, n))}: a value that settles as n grows is the converged "
        "position. 'none': no such transition. The paper's column is where its counts put the transition, "
        f"between two of its 32 contact nodes {CONTACT_NODE_SPACING_MM:g} mm apart."))
    r = group(g, "rows")
    paper = {}
    if r is not None:
        for i, row in enumerate(array(r, "row")):
            gp, sl, st = int(r["paper_gap"][i]), int(r["paper_slide"][i]), int(r["paper_stick"][i])
            paper[int(row)] = (paper_interval(gp) if gp and (sl or st) else None,
                               paper_interval(gp + sl) if sl and st else None)
    rows = []
    for name in sorted((k for k in ref.keys() if k.startswith("row")), key=lambda k: int(k[3:])):
        row = int(name[3:])
        gc, ss = array(ref[name], "gap_contact_mm"), array(ref[name], "stick_slip_mm")
        pg, ps = paper.get(row, (None, None))
        rows.append([str(row)] + [position(v, missing) for v in gc] + [interval(pg)]
                    + [position(v, missing) for v in ss] + [interval(ps)])
    header = (["row"] + [f"gap–contact n={k}" for k in n] + ["paper"]
              + [f"stick–slip n={k}" for k in n] + ["paper"])
    out.append(table(header, rows, css_class="small"))
    return "\n".join(out)


def position(value, missing):
    return "none" if value == missing or value < 0 else f"{value:.2f}"


def interval(iv):
    return "none" if iv is None else f"[{iv[0]:g}, {iv[1]:g}]"

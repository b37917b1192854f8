"""The report of one scene-file study, about that joint (SPEC §5, "the answer drawn"), as an engineer
reads it (issue 35): the joint and the law of its glue at each thickness, the verdict one line per
quantity, the deformed joint framed on its bondlines, peel and shear on both faces of the layer
against the law and the classical closed forms, the glue's stress field along the bondline, the
bondline ends (their singular corners and the stresses at a stated distance), the distances with
their rates and mesh dependence, and what the layer's answer assumes. Everything is read from
/studies/scene/<name> and the scenes it names. `sections(ctx)` gives the numbered sections."""

import re

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection

from checks import checks_block
from html_parts import esc, how_to_read, num, section, table
from joint_fields import bondline_fields, scene_units, study_scene_ids
from results_file import array, attr, strings
import section_scene_files

BODY_COLORS = ("#4a7fc1", "#e08a3c", "#5aa55a", "#9b6bc1", "#c1605a", "#7aa8b8", "#b8a04a")
LAYER_COLOR = "#d62728"
VERDICT_LABELS = {"reactions": "reactions", "u": "adherents' displacements",
                  "peel_at_d": "peak peel at d from the ends", "shear_at_d": "peak shear at d from the ends"}


def slug(name):
    return re.sub(r"[^A-Za-z0-9_-]", "_", name)


def mm(x):
    """A thickness as a reader writes it: 0.02, not 0.020000000000000004."""
    return f"{float(x):.3g}"


def samples(ctx, study):
    """(eps, layer scene group, limit scene group) of every sample, by decreasing ε."""
    eps = array(study, "eps")
    layers, limits = study_scene_ids(study, "layer_scene"), study_scene_ids(study, "limit_scene")
    if not limits:  # an older file: one limit scene
        limits = [attr(study, "limit_scene")] * len(layers)
    scenes = ctx.f["scenes"]
    return [(float(e), scenes[a], scenes[b]) for e, a, b in zip(eps, layers, limits) if a in scenes and b in scenes]


def nominal_index(study, pairs):
    """The sample of the glue's own thickness (an engineer's glue), else the thickest."""
    if attr(study, "nominal_sample") is not None:
        return min(int(attr(study, "nominal_sample")), len(pairs) - 1)
    floor = study.get("floor")
    if attr(study, "family") == "engineer" and floor is not None and len(array(floor, "eps")):
        t = float(array(floor, "eps")[0])
        return int(np.argmin([abs(np.log(e / t)) for e, _, _ in pairs]))
    return 0


def short_id(scene):
    return scene.name.split("/")[-1]


def bondline_groups_of(scene):
    interface = scene["interface"]
    if "S" in interface or "S+" in interface:
        return [("", interface)]
    return [(n, interface[n]) for n in interface]


# ---------------------------------------------------------------------------------------------
# The joint and its law

def joint_block(study, pairs, nominal):
    eps, _, limit = pairs[nominal]
    stress, force = scene_units(limit)
    engineer = attr(study, "family") == "engineer"
    out = [how_to_read(
        f"The joint of scene file <code>{esc(attr(study, 'scene_file', ''))}</code> ({esc(attr(study, 'units', 'mm-daN'))}: "
        f"lengths in mm, stresses in {esc(stress)}, forces in {esc(force)} per mm of thickness). Both modes on one mesh: "
        "the <b>limit law</b> on each bondline, and the <b>meshed layer</b> of thickness ε whose plus adherent moved away "
        "from the minus one by ε to make room for it. " +
        ("Its glue is an engineer's glue (fixed E, ν): at each thickness t the same glue, and its own finite springs "
         "at that t, K_N = (λ_g + 2μ_g)/t, K_T = μ_g/t (SPEC §1.3: never a 0 or ∞ cut-off); the paper's 3 % / 30× rule "
         "is shown beside it as what that rule would choose." if engineer
         else "Its glue is the paper's scaled family (λ_ε = ε^γ λ_g, μ_ε = ε^δ μ_g): one limit law for every ε."))]
    rows = []
    for bname, g in bondline_groups_of(limit):
        glue_text = esc(attr(g, "glue", ""))
        if attr(g, "glue_E") is not None:
            glue_text = (f"E = {num(attr(g, 'glue_E'))} {esc(stress)}, ν = {num(attr(g, 'glue_nu'))}, "
                         f"t = {mm(attr(g, 'glue_thickness'))} mm")
        elif attr(g, "gamma") is not None:
            glue_text = (f"γ = {num(attr(g, 'gamma'))}, δ = {num(attr(g, 'delta'))}, λ_g = {num(attr(g, 'lambda_g'))}, "
                         f"μ_g = {num(attr(g, 'mu_g'))}")
        rows.append([esc(bname or attr(g, "group", "")), esc(attr(g, "plus", "")), esc(attr(g, "minus", "")),
                     esc(f"{attr(g, 'face_plus', '')}/{attr(g, 'face_minus', '')}"), glue_text,
                     esc(attr(g, "law", "")) + f" ({esc(attr(g, 'law_case', ''))})"])
    out.append(table(["bondline", "plus", "minus", "faces plus/minus", "glue", "limit law"], rows,
                     left_columns=(0, 1, 2, 3, 4, 5)))
    out.append(law_table(pairs, nominal, stress, engineer))
    out.append(f"<p>Characteristic length L = {num(attr(study, 'characteristic_length'))} mm "
               f"({esc(attr(limit, 'characteristic_length_description', ''))}).</p>")
    out.append(loads_table(limit, stress, force))
    return "\n".join(out)


def law_table(pairs, nominal, stress, engineer):
    """The law's own values at each thickness the study visits (each sample's limit scene)."""
    rows = []
    for i, (eps, _, limit) in enumerate(pairs):
        for bname, g in bondline_groups_of(limit):
            lam, mu = attr(g, "lambda_bar"), attr(g, "mu_bar")
            K_N = lam + 2 * mu if lam is not None and mu is not None else None
            classified = attr(g, "classified_law_case")
            mark = " <b>(the glue's own)</b>" if i == nominal and engineer else ""
            five = lambda x: "—" if x is None else "∞" if np.isinf(x) else f"{x:.5g}"  # the law's own values, to 5 digits
            rows.append([mm(eps) + mark, esc(bname or "S"), esc(attr(g, "law_case", "")), five(lam), five(mu), five(K_N),
                         five(mu), esc(classified) if classified is not None else "—"])
    unit = f"{esc(stress)}/mm"
    return ("<p>The limit law at each thickness ε of the study (its own limit scene): λ̄, μ̄ and the springs "
            f"K_N = λ̄ + 2μ̄, K_T = μ̄ in {unit}; the last column is the class the paper's 3 % / 30× rule would have "
            "chosen (not solved here; <code>solve --mode limit</code> says what it would cost).</p>" +
            table(["ε (mm)", "bondline", "class", f"λ̄ ({unit})", f"μ̄ ({unit})", f"K_N ({unit})", f"K_T ({unit})",
                   "the rule's class"], rows, css_class="small", left_columns=(0, 1)))


def loads_table(scene, stress, force):
    rows = []
    total = np.zeros(2)
    if "loads" in scene:
        for group in scene["loads"]:
            g = scene["loads"][group]
            value = array(g, "value")
            resultant = array(g, "resultant")
            total += resultant
            rows.append([esc(group), esc(attr(g, "kind", "")), ", ".join(num(v, 4) for v in value),
                         f"({num(resultant[0], 5)}, {num(resultant[1], 5)})"])
    if "supports" in scene:
        for group in scene["supports"]:
            g = scene["supports"][group]
            u, held = array(g, "u"), array(g, "held")
            value = ", ".join(num(u[c], 4) if held[c] else "free" for c in range(2))
            R = array(scene["reactions"], group) if group in scene.get("reactions", {}) else np.zeros(2)
            total += R
            rows.append([esc(group), "support u (mm)", value, f"({num(R[0], 5)}, {num(R[1], 5)}) reaction"])
    rows.append(["<b>sum</b>", "", "", f"({num(total[0], 3)}, {num(total[1], 3)})"])
    return ("<p>Loads and supports of the limit scene; the resultants (applied loads) and reactions, in "
            f"{esc(force)}/mm, sum to zero where the solve balanced them.</p>" +
            table(["group", "kind", f"value ({esc(stress)}, or {esc(force)}/mm for a force)", f"force ({esc(force)}/mm)"],
                  rows, left_columns=(0, 1, 2)))


# ---------------------------------------------------------------------------------------------
# The verdict

def verdict_block(study, pairs):
    d = attr(study, "peak_distance")
    v = study.get("validity")
    if v is None:
        return "<p>(No validity study: run <code>study validity --scene</code>.)</p>"
    tau, eps_max, status = array(v, "tau"), array(v, "eps_max"), strings(v["status"])
    error = array(v, "error_at_eps_max")
    quantity = strings(v["quantity"]) if "quantity" in v else ["u"] * len(tau)
    why_not = strings(v["why_not_judged"]) if "why_not_judged" in v else [""] * len(tau)
    floor = study.get("floor")
    lines = []
    for q in dict.fromkeys(quantity):
        parts = []
        for i in range(len(tau)):
            if quantity[i] != q:
                continue
            value = {"found": f"up to ε = <b>{eps_max[i]:.3g} mm</b>",
                     "at_least": f"at every sampled ε, up to at least <b>{eps_max[i]:.3g} mm</b>",
                     "below_range": f"at no sampled ε (not even {eps_max[i]:.3g} mm)"}.get(status[i], esc(status[i]))
            if status[i] == "not_judged":  # one reason for the quantity, not one per tau
                parts = [f"not judged: {esc(why_not[i])}"]
                continue
            parts.append(f"within {tau[i] * 100:g} % {value} ({error[i]:.2g})")
        label = VERDICT_LABELS.get(q, q).replace("at d", f"at d = {mm(d)} mm" if d is not None else "at d")
        mesh = ""
        if floor is not None and ("verdict_" + q) in floor and np.isfinite(array(floor, "verdict_" + q)).any():
            h, e = array(floor, "h"), array(floor, "verdict_" + q)
            mesh = (f"<br><small>on the mesh, at ε = {mm(array(floor, 'eps')[0])} mm: "
                    + ", ".join(f"{e[k]:.2g} at h = {num(h[k])} mm" for k in range(len(h))) + "</small>")
        lines.append(f"<li><b>{esc(label)}</b>: {'; '.join(parts)}{mesh}</li>")
    lines.append("<li><b>the corners themselves</b> (the nodes at the bondline ends): singular in the layer model, their "
                 "values grow as the mesh is refined (below, 'The bondline ends'); not judged.</li>")
    text = ("<p><b>Verdict.</b> Can the limit law stand in for the glue layer of this joint? One line per quantity: the "
            "largest ε up to which the limit law stays within τ of the meshed layer at every sampled thickness "
            "(the distance there in brackets), and below it the same distance at the glue's own thickness on the "
            "study's mesh refined twice: where it moves, the verdict measures the mesh as well. A peak at d is resolved "
            "by the mesh only where d spans a few elements and the thinner lines' end zones (they shrink with ε): a "
            "peak 'at no sampled ε' may be the mesh's at the thinnest ε — refine mesh_size.interface to tell. What is "
            "judged: each reaction component statics does not fix, on its own size; a peak at d as |layer − law| over the "
            "law's largest |σ_N| (peel) or |σ_T| (shear) on the bondlines, never a pointwise ratio.</p><ul>"
            + "".join(lines) + "</ul>")
    if d is not None:
        text += (f"<p>d = {mm(d)} mm: {esc(attr(study, 'peak_distance_description', ''))}.</p>")
    text += verdict_samples_table(study)
    return text


def verdict_samples_table(study):
    quantities = [q for q in ("reactions", "u", "peel_at_d", "shear_at_d") if "verdict_" + q in study]
    if not quantities:
        return ""
    eps = array(study, "eps")
    rows = [[mm(eps[i])] + [f"{array(study, 'verdict_' + q)[i]:.2e}" for q in quantities] for i in range(len(eps))]
    return ("<details><summary>the verdict's quantities at every sampled ε (relative distance of the layer to the law)"
            "</summary>" + table(["ε (mm)"] + [VERDICT_LABELS[q] for q in quantities], rows, css_class="small") +
            "</details>")


# ---------------------------------------------------------------------------------------------
# The joint deformed: the whole joint, then its bondlines zoomed

def deformed_shape(ctx, name, scenes_and_titles):
    """The whole joint of each scene, each across the page and framed tight on it, then their
    bondlines zoomed side by side; coloured by body, the displacements magnified so that the largest
    is a tenth of the zoom window."""
    n = len(scenes_and_titles)
    first = scenes_and_titles[0][0]
    nodes0 = array(first, "mesh/nodes")
    lo, hi = nodes0.min(axis=0), nodes0.max(axis=0)
    extent = np.maximum(hi - lo, 1e-12)
    # The zoom: the bondlines' bounding box, with a margin of a fifth of their length.
    xs = np.vstack([b.x for b in bondline_fields(first)])
    blo, bhi = xs.min(axis=0), xs.max(axis=0)
    margin = 0.2 * max(np.ptp(xs, axis=0).max(), 1e-12)
    zlo, zhi = blo - margin, bhi + margin
    zext = zhi - zlo
    u_max = max(np.abs(array(s, "u")).max() for s, _ in scenes_and_titles)
    scale = 0.1 * zext.min() / u_max if u_max > 0 else 1.0
    width = 13.0
    whole_h = float(np.clip(width * 0.9 * extent[1] / extent[0], 0.9, 4.0)) + 0.7
    zoom_h = float(np.clip(width / n * 0.85 * zext[1] / zext[0], 2.0, 5.0)) + 0.7
    fig = plt.figure(figsize=(width, n * whole_h + zoom_h + 0.6))
    grid = fig.add_gridspec(n + 1, n, height_ratios=[whole_h] * n + [zoom_h])
    for k, (s, title) in enumerate(scenes_and_titles):
        nodes, u, cells = array(s, "mesh/nodes"), array(s, "u"), array(s, "mesh/cells")
        body = array(s, "mesh/cell_body")
        names = strings(s["mesh/body_names"])
        moved = nodes + scale * u
        colors = [LAYER_COLOR if names[b].startswith("layer") else BODY_COLORS[b % len(BODY_COLORS)] for b in body]
        for ax, window, what in ((fig.add_subplot(grid[k, :]), (lo, hi), "the whole joint"),
                                 (fig.add_subplot(grid[n, k]), (zlo, zhi), "its bondlines zoomed")):
            ax.add_collection(PolyCollection([nodes[c[c >= 0]] for c in cells], facecolors="none", edgecolors="#cccccc",
                                             linewidths=0.3))
            ax.add_collection(PolyCollection([moved[c[c >= 0]] for c in cells], facecolors=colors, edgecolors="#333333",
                                             linewidths=0.15, alpha=0.85))
            pad = 0.02 * (window[1] - window[0]) + (scale * u_max if what == "the whole joint" else 0)
            ax.set_xlim(window[0][0] - pad[0], window[1][0] + pad[0])
            ax.set_ylim(window[0][1] - pad[1], window[1][1] + pad[1])
            ax.set_aspect("equal")
            ax.set_xlabel("x (mm)")
            ax.set_ylabel("y (mm)")
            ax.set_title(f"{title} — {what}", fontsize=9)
            if what == "the whole joint":
                handles = [plt.Rectangle((0, 0), 1, 1, color=LAYER_COLOR if nm.startswith("layer")
                                         else BODY_COLORS[i % len(BODY_COLORS)]) for i, nm in enumerate(names)]
                ax.legend(handles, names, fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    fig.suptitle(f"{name}: deformed shape, displacements × {scale:.3g} (grey: at rest)", fontsize=10)
    fig.tight_layout()
    return ctx.figures.save(fig, f"joint_{slug(name)}_shape", f"{name} deformed shape",
                            f"{esc(name)}: the deformed joint coloured by body (the layers red), displacements magnified "
                            f"× {scale:.3g} (the largest is a tenth of the zoom window): the whole joint of each mode "
                            "across the page, then their bondlines zoomed side by side; first the limit law, then the "
                            "meshed layer at the glue's own thickness.")


# ---------------------------------------------------------------------------------------------
# Along the bondlines: both faces, the law, the closed forms

def closed_forms(study, bname):
    """The closed-form curves of a bondline (s, {label: values}) and the joint's name, or None."""
    cf = study.get("closed_forms")
    if cf is None:
        return None
    key = bname or "S"
    if key not in cf:
        return None
    g = cf[key]
    curves = {"shear": {}, "peel": {}}
    if "volkersen_shear" in g:
        curves["shear"]["Volkersen (shear lag)"] = array(g, "volkersen_shear")
    if "goland_reissner_shear" in g:
        # Its bending factor is the linear statics' of the joint's own supports (the model is linear);
        # one k for both ends: where the supports are not symmetric the label says the mean is drawn.
        k0, k1 = attr(g, "k_start"), attr(g, "k_end")
        asymmetric = k0 is not None and k1 is not None and abs(k0 - k1) > 0.01 * abs(attr(g, "k", 1.0))
        label = (f"Goland–Reissner, linear k = {attr(g, 'k'):.3g}"
                 + (f" (ends {k0:.3g} / {k1:.3g}: symmetric form, their mean)" if asymmetric else ""))
        curves["shear"][label] = array(g, "goland_reissner_shear")
        curves["peel"][label] = array(g, "goland_reissner_peel")
    return array(g, "s"), curves, attr(cf, "joint", ""), (attr(g, "start", ""), attr(g, "end", ""))


def chosen_samples(pairs, nominal):
    """The thickest sample, the glue's own and the thinnest: one panel column each."""
    picks = []
    for i in (0, nominal, len(pairs) - 1):
        if i not in picks:
            picks.append(i)
    return picks


def bondline_figures(ctx, study, name, pairs, nominal):
    """Per bondline: peel and shear against arc length, one panel per chosen thickness (each its own
    axis), the layer's two faces against the limit law, and at the glue's own thickness the classical
    closed forms; then the jumps across at that thickness."""
    stress, _ = scene_units(pairs[0][2])
    bondlines = [b.name for b in bondline_fields(pairs[0][2])]
    picks = chosen_samples(pairs, nominal)
    out = []
    for k, bname in enumerate(bondlines):
        fig, axes = plt.subplots(2, len(picks), figsize=(4.4 * len(picks) + 1.5, 6.4), squeeze=False)
        forms = closed_forms(study, bname)
        for col, i in enumerate(picks):
            eps, layer, limit = pairs[i]
            lay, lim = bondline_fields(layer)[k], bondline_fields(limit)[k]
            for row, (q, label) in enumerate((("N", f"peel σ_N ({stress}; > 0 tension)"), ("T", f"shear σ_T ({stress})"))):
                ax = axes[row, col]
                ax.plot(lay.s, getattr(lay, "sigma_" + q), "-", color="#1f77b4", lw=1.6, label="layer: plus face")
                ax.plot(lay.s, getattr(lay, "sigma_" + q + "_minus"), "-", color="#ff7f0e", lw=1.2,
                        label="layer: minus face")
                ax.plot(lim.s, getattr(lim, "sigma_" + q), "--", color="k", lw=1.2, label="limit law at this ε")
                if forms is not None and i == nominal:
                    s_cf, curves, _, _ = forms
                    for (cname, values), style in zip(curves["peel" if q == "N" else "shear"].items(), (":", "-.")):
                        ax.plot(s_cf, values, style, color="#2ca02c" if "Volkersen" in cname else "#9467bd", lw=1.5,
                                label=cname)
                ax.axhline(0, color="#888", lw=0.5)
                ax.set_ylabel(label)
                ax.set_title(f"ε = {mm(eps)} mm" + (" (the glue's own)" if i == nominal else ""), fontsize=9)
                ax.autoscale(axis="y")
                if row == 1:
                    ends = forms[3] if forms is not None else ("", "")
                    ax.set_xlabel("arc length s along the bondline (mm)" +
                                  (f"\ns = 0: {ends[0]}\nfar end: {ends[1]}" if ends[0] else ""), fontsize=8)
            axes[0, col].legend(fontsize=6.5, loc="best")
            if forms is not None and i == nominal:
                axes[1, col].legend(fontsize=6.5, loc="best")
        fig.suptitle(f"{name}: bondline {bname or 'S'} — both faces of the layer against the limit law"
                     + (" and the classical closed forms" if forms is not None else ""), fontsize=10)
        fig.tight_layout()
        cf_text = ""
        if forms is not None:
            cf_text = (f" At the glue's own thickness the classical closed forms of a {esc(forms[2])} are drawn beside "
                       "them (assumptions below).")
        out.append(ctx.figures.save(
            fig, f"joint_{slug(name)}_bondline_{slug(bname or 'S')}", f"{name} bondline {bname} stresses",
            f"{esc(name)}, bondline <b>{esc(bname or 'S')}</b>: peel and shear against the arc length (from its first "
            "node) at the thickest, the glue's own and the thinnest ε of the study, each panel on its own axis; the "
            "layer's plus face (on the plus adherent) and minus face (on the minus adherent) — they differ near the "
            "layer's ends, where the worse one breaks — against the limit law at that ε." + cf_text))
        out.append(jump_figure(ctx, name, pairs, nominal, k, bname))
    cf = study.get("closed_forms")
    if cf is not None:
        if attr(cf, "joint"):
            rows = []
            for key in cf:
                g = cf[key]
                linear = attr(g, "k") is not None
                rows.append([esc(key), num(attr(g, "P"), 4), num(attr(g, "overlap"), 4), num(attr(g, "t_1"), 3),
                             num(attr(g, "t_2"), 3), num(attr(g, "omega"), 4),
                             (f"{num(attr(g, 'k'), 3)} (ends {num(attr(g, 'k_start'), 3)} / {num(attr(g, 'k_end'), 3)})"
                              if linear else esc(attr(g, "goland_reissner_why_not", "") or "—")),
                             num(attr(g, "k_nonlinear"), 3) if linear else "—",
                             num(attr(g, "lambda"), 3) if attr(g, "lambda") is not None else "—"])
            out.append(f"<p>Closed forms ({esc(attr(cf, 'joint'))}): {esc(attr(cf, 'assumptions', ''))}. The bending "
                       "factor drawn is the linear statics' of this joint's supports, at either end of the overlap; "
                       "Goland–Reissner's own k (geometrically nonlinear, for symmetric pinned ends) changes with the "
                       "load and is not the linear model's: shown second, not drawn.</p>" +
                       table(["bondline", "P (force/mm)", "overlap (mm)", "t₁ (mm)", "t₂ (mm)", "ω (1/mm)",
                              "k, linear (ends)", "GR's nonlinear k at P", "λ (peel)"], rows, css_class="small"))
        elif attr(cf, "why_not"):
            out.append(f"<p>No classical closed form drawn: {esc(attr(cf, 'why_not'))}.</p>")
    return "\n".join(out)


def jump_figure(ctx, name, pairs, nominal, k, bname):
    eps, layer, limit = pairs[nominal]
    lay, lim = bondline_fields(layer)[k], bondline_fields(limit)[k]
    fig, axes = plt.subplots(1, 2, figsize=(11, 3.2))
    for ax, q, label in ((axes[0], "jump_N", "[u]_N across (mm; < 0 opening)"), (axes[1], "jump_T", "[u]_T across (mm)")):
        ax.plot(lay.s, getattr(lay, q), "-", color="#1f77b4", lw=1.6, label=f"layer, ε = {mm(eps)} mm")
        ax.plot(lim.s, getattr(lim, q), "--", color="k", lw=1.2, label="limit law")
        ax.axhline(0, color="#888", lw=0.5)
        ax.set_ylabel(label)
        ax.set_xlabel("arc length s along the bondline (mm)")
    axes[0].legend(fontsize=7)
    fig.suptitle(f"{name}: bondline {bname or 'S'} — the jumps across at the glue's own thickness", fontsize=10)
    fig.tight_layout()
    return ctx.figures.save(fig, f"joint_{slug(name)}_jumps_{slug(bname or 'S')}", f"{name} bondline {bname} jumps",
                            f"{esc(name)}, bondline <b>{esc(bname or 'S')}</b>: the jumps across the whole bondline (in "
                            "layer mode across the layer, from the adherents' nodes), the layer against the limit law.")


# ---------------------------------------------------------------------------------------------
# The glue's stress field along the bondline

def glue_field(ctx, name, pairs, nominal):
    """The layer's cells at the glue's own thickness, in the bondline's frame: arc length along it,
    position across the layer; coloured by the peel σ_nn and the shear σ_nt at each cell's centre."""
    eps, layer, _ = pairs[nominal]
    if "mesh/cell_stress" not in layer:
        return "<p>(This results file has no cell stresses.)</p>"
    stress, _ = scene_units(layer)
    nodes, cells = array(layer, "mesh/nodes"), array(layer, "mesh/cells")
    body, names = array(layer, "mesh/cell_body"), strings(layer["mesh/body_names"])
    sig = array(layer, "mesh/cell_stress")
    fields = bondline_fields(layer)
    groups = bondline_groups_of(layer)
    out = []
    for k, (bname, _) in enumerate(groups):
        layer_name = "layer-" + bname if bname else "layer"
        if layer_name not in names:
            continue
        b = names.index(layer_name)
        mine = np.where(body == b)[0]
        f = fields[k]
        origin, n = f.x[0], f.normal[0]
        t = np.array([n[1], -n[0]])
        if np.dot(f.x[-1] - origin, t) < 0:
            t = -t
        polys, peel, shear = [], [], []
        for c in mine:
            corners = nodes[cells[c][cells[c] >= 0]] - origin
            polys.append(np.column_stack([corners @ t, corners @ n]))
            s11, s22, s12 = sig[c]
            S = np.array([[s11, s12], [s12, s22]])
            peel.append(n @ S @ n)
            shear.append(t @ S @ n)
        fig, axes = plt.subplots(2, 1, figsize=(12, 4.6), sharex=True)
        for ax, values, label, cmap in ((axes[0], peel, "peel σ_nn", "RdBu_r"), (axes[1], shear, "shear σ_nt", "PuOr_r")):
            values = np.asarray(values)
            vmax = np.abs(values).max() or 1.0
            pc = PolyCollection(polys, array=values, cmap=cmap, edgecolors="face", linewidths=0.1)
            pc.set_clim(-vmax, vmax)
            ax.add_collection(pc)
            ax.autoscale_view()
            ax.set_ylabel("across the layer (mm)")
            fig.colorbar(pc, ax=ax, label=f"{label} ({stress})", pad=0.01)
        axes[1].set_xlabel("along the bondline (mm, from its first node)")
        fig.suptitle(f"{name}: the glue of bondline {bname or 'S'} at ε = {mm(eps)} mm, its stresses at each cell "
                     "(thickness stretched)", fontsize=10)
        fig.tight_layout()
        out.append(ctx.figures.save(
            fig, f"joint_{slug(name)}_glue_{slug(bname or 'S')}", f"{name} glue stress field {bname}",
            f"{esc(name)}, the glue of bondline <b>{esc(bname or 'S')}</b> at its own thickness: peel σ_nn and shear "
            "σ_nt at each cell of the meshed layer, in the bondline's frame (along it, and across the layer, the "
            "thickness stretched to be seen). Uniform across the layer in the middle of the overlap, as the limit law "
            "assumes; at the ends the free faces of the layer bend the field over about one thickness."))
    return "\n".join(out)


# ---------------------------------------------------------------------------------------------
# The bondline ends: corners and a stated distance

def ends_block(ctx, name, study, pairs):
    ends = study.get("ends")
    d = attr(study, "peak_distance")
    stress, _ = scene_units(pairs[0][2])
    out = []
    if ends is not None and d is not None:
        eps = array(study, "eps")
        fig, axes = plt.subplots(1, 2, figsize=(11, 3.8))
        for ax, q, label in ((axes[0], "peel", "peak peel"), (axes[1], "shear", "peak shear")):
            for mode, style in (("layer", "o-"), ("limit", "s--")):
                ax.semilogx(eps, array(ends, f"{mode}_{q}_at_d"), style, ms=4, label=f"{mode}, at d = {mm(d)} mm")
                ax.semilogx(eps, array(ends, f"{mode}_{q}_corner"), style, ms=3, alpha=0.45,
                            label=f"{mode}, at the corner node")
            ax.set_xlabel("layer thickness ε (mm)")
            ax.set_ylabel(f"{label} ({stress})")
            ax.legend(fontsize=7)
        fig.suptitle(f"{name}: the bondline ends against ε, at d = {mm(d)} mm and at the corners", fontsize=10)
        fig.tight_layout()
        out.append(ctx.figures.save(
            fig, f"joint_{slug(name)}_peaks", f"{name} peaks",
            f"{esc(name)}: the largest peel and shear of every bondline at d = {mm(d)} mm from its ends (the worse face "
            "of the layer), and at the corner nodes themselves (pale), against ε, both modes."))
    floor = study.get("floor")
    if floor is not None and "layer_shear_corner" in floor:
        h = array(floor, "h")
        rows = []
        for i in range(len(h)):
            rows.append([num(h[i])] + [num(array(floor, f"{m}_{q}")[i], 4) for q in
                                       ("peel_corner", "peel_at_d", "shear_corner", "shear_at_d") for m in ("layer", "limit")])
        out.append(f"<p>Under mesh refinement at ε = {mm(array(floor, 'eps')[0])} mm: the layer model's corner is "
                   "singular — its value grows as h shrinks, and is not a value of the joint — while at d from the "
                   "ends both modes converge; the verdict compares them there.</p>" +
                   table(["h (mm)", "corner peel: layer", "limit", f"peel at d: layer", "limit", "corner shear: layer",
                          "limit", "shear at d: layer", "limit"], rows, css_class="small"))
    return "\n".join(out)


def floor_block(study):
    f = study.get("floor")
    if f is None:
        return ""
    h, nodes = array(f, "h"), array(f, "S_nodes")
    quantities = section_scene_files.QUANTITIES
    engineer = attr(study, "family") == "engineer"
    rows = []
    for i in range(len(h)):
        rows.append([num(h[i]), str(int(nodes[i]))] + [f"{array(f, 'floor_' + q)[i]:.2e}" for q in quantities])
    rows.append(["rate in h", ""] + [section_scene_files.rate_text(attr(f, "rate_" + q), attr(f, "rate_" + q + "_stderr", 0),
                                                                   attr(f, "fitted_" + q)) for q in quantities])
    eps = array(f, "eps")[0]
    text = (f"<p>The mesh dependence of the distances: both modes at ε = {mm(eps)} mm "
            + ("(the glue's own thickness: the joint as glued)" if engineer else "(far below the grid: the mesh floor proper)")
            + ", the scene re-meshed with the element size h along the bondlines halved twice.</p>")
    return text + table(["h (mm)", "nodes on S"] + [section_scene_files.LABELS[q] for q in quantities], rows)


# ---------------------------------------------------------------------------------------------
# What the layer's answer assumes

def answer_block(ctx, pairs):
    rows = []
    for eps, layer, limit in pairs:
        for s in (limit, layer):
            a = s.attrs
            film = a.get("film_slip_over_h")
            rows.append([esc(short_id(s)), mm(eps) if attr(s, "mode") == "layer" else "—",
                         f"{float(film):.3g}" if film is not None else "— (no contact face)",
                         f"{float(attr(s, 'film_strain_max')):.3g}" if "film_strain_max" in a else "—",
                         f"{float(attr(s, 'glue_strain_max')):.3g}" if "glue_strain_max" in a else "—",
                         f"{100 * float(attr(s, 'displacement_over_size')):.3g} %" if "displacement_over_size" in a else "—",
                         f"{float(attr(s, 'slip_over_h')):.3g}" if "slip_over_h" in a else "—"])
    return (how_to_read(
        "One meaning per number. <b>slip / h</b>: the largest slip on a contact face of the layer over the element "
        "size along S (the node-to-node pairing needs less than 1; a bonded face does not slip). <b>film strain</b>: "
        "the largest strain of a layer held by contact alone (the paper's film; the model is one of small strains: "
        "warned above 0.01). <b>glue strain</b>: the largest strain of a glued layer — a load level of a linear elastic "
        "glue, not a defect. <b>|u| / size</b>: the largest displacement of an adherent over its size (the model is "
        "linear: warned above 5 %). <b>limit slip / h</b>: the largest slip on the limit law's bondlines.") +
        table(["scene", "ε (mm)", "slip / h", "film strain", "glue strain", "|u| / size", "limit slip / h"], rows,
              css_class="small", left_columns=(0,)))


# ---------------------------------------------------------------------------------------------

def sections(ctx, first_number=2):
    """[(anchor, navigation label, html)] of every scene study in the file, numbered from first_number."""
    g = ctx.f["studies"]["scene"]
    out = []
    number = first_number

    def add(anchor, label, title, body):
        nonlocal number
        out.append((anchor, label, section(anchor, f"{number}. {title}", body)))
        number += 1

    for name in sorted(g):
        study = g[name]
        pairs = samples(ctx, study)
        tag = slug(name)
        if not pairs:
            add(f"joint-{tag}", name, f"The joint '{name}'", "<p class=\"absent\">No scenes of this study stored.</p>")
            continue
        nominal = nominal_index(study, pairs)
        eps, layer, limit = pairs[nominal]
        add(f"joint-{tag}", "The joint", f"The joint '{name}' and the law of its glue", joint_block(study, pairs, nominal))
        add(f"verdict-{tag}", "Verdict", "The verdict, per quantity",
            verdict_block(study, pairs) + checks_block(ctx.checks, "scene.", "this joint"))
        add(f"shape-{tag}", "Deformed", "The joint deformed",
            deformed_shape(ctx, name, [(limit, f"limit law ({short_id(limit)})"),
                                       (layer, f"meshed layer, ε = {mm(eps)} mm ({short_id(layer)})")]))
        add(f"bondlines-{tag}", "Bondlines", "Along the bondlines: peel and shear on both faces",
            bondline_figures(ctx, study, name, pairs, nominal))
        add(f"glue-{tag}", "Glue field", "The glue's stress field along the bondline", glue_field(ctx, name, pairs, nominal))
        add(f"ends-{tag}", "Ends", "The bondline ends: the corners and a stated distance from them",
            ends_block(ctx, name, study, pairs))
        add(f"distances-{tag}", "Distances", "Layer against limit law: the distances, their rates and the mesh",
            section_scene_files.scene_block(ctx, study, name) + floor_block(study) +
            "<p>The bondline fields of every scene are also in <code>bondline_fields.csv</code> beside "
            "<code>results.h5</code> (one row per bondline node and scene).</p>")
        add(f"answer-{tag}", "Assumptions", "What the answers assume: films, glue strain, small displacements",
            answer_block(ctx, pairs))
    return out


def render(ctx):
    """The whole joint report body (every section of sections(), in order)."""
    return "\n".join(html for _, _, html in sections(ctx))

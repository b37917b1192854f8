"""The report of one scene-file study, about that joint (SPEC §5, "the answer drawn"): the joint and
its loads, its deformed shape coloured by body, the stresses and jumps along each bondline (the
layer at each thickness against the limit law), the peak stresses at the bondline ends and how
they converge, the distances between the modes with their rates and mesh floor, and the validity
verdict. Everything is read from /studies/scene/<name> and the scenes it names."""

import re

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection

from checks import checks_block
from html_parts import esc, how_to_read, num, section, table
from joint_fields import bondline_fields, peaks, scene_units, study_scene_ids
from results_file import array, attr, strings
import section_scene_files

BODY_COLORS = ("#4a7fc1", "#e08a3c", "#5aa55a", "#9b6bc1", "#c1605a", "#7aa8b8", "#b8a04a")
LAYER_COLOR = "#d62728"


def slug(name):
    return re.sub(r"[^A-Za-z0-9_-]", "_", name)


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
    floor = study.get("floor")
    if attr(study, "family") == "engineer" and floor is not None and len(array(floor, "eps")):
        t = float(array(floor, "eps")[0])
        return int(np.argmin([abs(np.log(e / t)) for e, _, _ in pairs]))
    return 0


def joint_summary(ctx, study, name, pairs):
    limit = pairs[0][2]
    stress, force = scene_units(limit)
    out = [how_to_read(
        f"The joint of scene file <code>{esc(attr(study, 'scene_file', ''))}</code> ({esc(attr(study, 'units', 'mm-daN'))}: "
        f"lengths in mm, stresses in {esc(stress)}, forces in {esc(force)} per mm of thickness). Both modes on one mesh: "
        "the <b>limit law</b> on each bondline, and the <b>meshed layer</b> of thickness ε whose plus adherent moved away "
        "from the minus one by ε to make room for it. " +
        ("Its glue is an engineer's glue (fixed E, ν): at each thickness t the same glue, and its own finite springs "
         "at that t, K_N = (λ_g + 2μ_g)/t, K_T = μ_g/t (SPEC §1.3: never a 0 or ∞ cut-off)." if attr(study, "family") == "engineer"
         else "Its glue is the paper's scaled family (λ_ε = ε^γ λ_g, μ_ε = ε^δ μ_g): one limit law for every ε."))]
    rows = []
    for bname, g in bondline_groups_of(limit):
        glue = attr(g, "glue", "")
        glue_text = esc(glue)
        if attr(g, "glue_E") is not None:
            glue_text = (f"E = {num(attr(g, 'glue_E'))} {esc(stress)}, ν = {num(attr(g, 'glue_nu'))}, "
                         f"t = {num(attr(g, 'glue_thickness'))} mm")
        elif attr(g, "gamma") is not None:
            glue_text = (f"γ = {num(attr(g, 'gamma'))}, δ = {num(attr(g, 'delta'))}, λ_g = {num(attr(g, 'lambda_g'))}, "
                         f"μ_g = {num(attr(g, 'mu_g'))}")
        rows.append([esc(bname or attr(g, "group", "")), esc(attr(g, "plus", "")), esc(attr(g, "minus", "")),
                     esc(f"{attr(g, 'face_plus', '')}/{attr(g, 'face_minus', '')}"), glue_text,
                     esc(attr(g, "law", "")) + f" ({esc(attr(g, 'law_case', ''))})",
                     num(attr(g, "lambda_bar")), num(attr(g, "mu_bar"))])
    out.append(table(["bondline", "plus", "minus", "faces plus/minus", "glue", f"limit law (at the first sample)",
                      f"λ̄ ({esc(stress)}/mm)", f"μ̄ ({esc(stress)}/mm)"], rows, left_columns=(0, 1, 2, 3, 4, 5)))
    out.append(f"<p>Characteristic length L = {num(attr(study, 'characteristic_length'))} mm "
               f"({esc(attr(limit, 'characteristic_length_description', ''))}).</p>")
    out.append(loads_table(limit, stress, force))
    return "\n".join(out)


def bondline_groups_of(scene):
    interface = scene["interface"]
    if "S" in interface or "S+" in interface:
        return [("", interface)]
    return [(n, interface[n]) for n in interface]


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


def deformed_shape(ctx, name, scenes_and_titles):
    """The deformed meshes, coloured by body, side by side; the same magnification for all."""
    extent = np.max([np.ptp(array(s, "mesh/nodes"), axis=0) for s, _ in scenes_and_titles], axis=0)
    size = extent.max()
    # One panel per scene, stacked for a long joint, side by side for a compact one.
    n = len(scenes_and_titles)
    wide = extent[0] > 1.6 * extent[1]
    rows, cols = (n, 1) if wide else (1, n)
    panel_w = 11.0 if wide else 5.5
    panel_h = min(5.0, max(1.8, panel_w * extent[1] / max(extent[0], 1e-300))) + 1.0
    fig, axes = plt.subplots(rows, cols, figsize=(panel_w * cols, panel_h * rows), squeeze=False)
    u_max = max(np.abs(array(s, "u")).max() for s, _ in scenes_and_titles)
    scale = 0.05 * size / u_max if u_max > 0 else 1.0
    for ax, (s, title) in zip(axes.flat, scenes_and_titles):
        nodes, u, cells = array(s, "mesh/nodes"), array(s, "u"), array(s, "mesh/cells")
        body = array(s, "mesh/cell_body")
        names = strings(s["mesh/body_names"])
        moved = nodes + scale * u
        polygons = [moved[c[c >= 0]] for c in cells]
        colors = [LAYER_COLOR if names[b].startswith("layer") else BODY_COLORS[b % len(BODY_COLORS)] for b in body]
        ax.add_collection(PolyCollection([nodes[c[c >= 0]] for c in cells], facecolors="none", edgecolors="#dddddd",
                                         linewidths=0.3))
        ax.add_collection(PolyCollection(polygons, facecolors=colors, edgecolors="#333333", linewidths=0.15, alpha=0.85))
        ax.autoscale_view()
        ax.set_aspect("equal")
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("x (mm)")
        ax.set_ylabel("y (mm)")
        handles = [plt.Rectangle((0, 0), 1, 1, color=LAYER_COLOR if n.startswith("layer") else BODY_COLORS[i % len(BODY_COLORS)])
                   for i, n in enumerate(names)]
        ax.legend(handles, names, fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    fig.suptitle(f"{name}: deformed shape, displacements × {scale:.3g} (grey: at rest)", fontsize=10)
    fig.tight_layout()
    return ctx.figures.save(fig, f"joint_{slug(name)}_shape", f"{name} deformed shape",
                            f"{esc(name)}: the deformed shape coloured by body (the layers red), displacements magnified "
                            f"× {scale:.3g}; first the limit law, then the meshed layer.")


def bondline_figures(ctx, name, pairs, nominal):
    """Per bondline: peel σ_N, shear σ_T, [u]_N and [u]_T against arc length; the layer at each ε
    (solid) against the limit law (dashed; per ε for an engineer's glue, whose law changes with t)."""
    limits_differ = len({p[2].name for p in pairs}) > 1
    stress, _ = scene_units(pairs[0][2])
    bondlines = [b.name for b in bondline_fields(pairs[0][2])]
    cmap = plt.get_cmap("viridis")
    out = []
    for k, bname in enumerate(bondlines):
        fig, axes = plt.subplots(2, 2, figsize=(11, 6.4), sharex=True)
        panels = (("sigma_N", f"peel σ_N ({stress}; > 0 tension)"), ("sigma_T", f"shear σ_T ({stress})"),
                  ("jump_N", "[u]_N across (mm; < 0 opening)"), ("jump_T", "[u]_T across (mm)"))
        drawn_limits = set()
        for i, (eps, layer, limit) in enumerate(pairs):
            color = cmap(i / max(1, len(pairs) - 1))
            lay = bondline_fields(layer)[k]
            lim = bondline_fields(limit)[k]
            width = 2.0 if i == nominal else 1.0
            for ax, (q, _) in zip(axes.flat, panels):
                ax.plot(lay.s, getattr(lay, q), "-", color=color, lw=width, label=f"layer ε = {eps:.3g} mm" if q == "sigma_N" else None)
                if limits_differ:
                    ax.plot(lim.s, getattr(lim, q), "--", color=color, lw=0.9)
                elif limit.name not in drawn_limits:
                    ax.plot(lim.s, getattr(lim, q), "--", color="k", lw=1.4, label="limit law" if q == "sigma_N" else None)
            drawn_limits.add(limit.name)
        for ax, (q, label) in zip(axes.flat, panels):
            ax.set_ylabel(label)
            ax.axhline(0, color="#888", lw=0.5)
        for ax in axes[1]:
            ax.set_xlabel("arc length s along the bondline (mm)")
        if limits_differ:
            axes[0, 0].plot([], [], "--", color="k", label="limit law at that ε (same colour)")
        axes[0, 0].legend(fontsize=7, loc="best")
        fig.suptitle(f"{name}: bondline {bname or 'S'} — the layer at each ε (solid) against the limit law (dashed)",
                     fontsize=10)
        fig.tight_layout()
        out.append(ctx.figures.save(
            fig, f"joint_{slug(name)}_bondline_{slug(bname or 'S')}", f"{name} bondline {bname} fields",
            f"{esc(name)}, bondline <b>{esc(bname or 'S')}</b>: peel and shear stresses on the plus adherent's face and "
            "the jumps across the bondline against the arc length (from its first node). The thick line is the "
            "glue's own thickness (or the thickest sample)."))
    return "\n".join(out)


def peak_block(ctx, name, study, pairs):
    """The peak peel and shear of every bondline against ε, both modes, and against h (mesh floor)."""
    p = study.get("peaks")
    if p is None:
        return ""
    scene, mode, bondline = strings(p["scene"]), strings(p["mode"]), strings(p["bondline"])
    eps, h, peel, shear = array(p, "eps"), array(p, "h"), array(p, "peel"), array(p, "shear")
    s_peel, s_shear = array(p, "s_peel"), array(p, "s_shear")
    stress, _ = scene_units(pairs[0][2])
    h0 = attr(study, "h_interface", 0.0)
    sample_ids = {pr[1].name.split("/")[-1] for pr in pairs} | {pr[2].name.split("/")[-1] for pr in pairs}
    limit_eps = {pr[2].name.split("/")[-1]: pr[0] for pr in pairs}
    fig, axes = plt.subplots(1, 2, figsize=(11, 3.8))
    rows = []
    for b in sorted(set(bondline)):
        for quantity, ax, values in (("peel", axes[0], peel), ("shear", axes[1], shear)):
            lay = [(eps[i], values[i]) for i in range(len(scene)) if bondline[i] == b and mode[i] == "layer"
                   and scene[i] in sample_ids]
            lim = sorted((limit_eps.get(scene[i], 0.0), values[i]) for i in range(len(scene))
                         if bondline[i] == b and mode[i] == "limit" and scene[i] in sample_ids)
            lay.sort()
            if lay:
                ax.semilogx([e for e, _ in lay], [v for _, v in lay], "o-", ms=4, label=f"{b}: layer")
            if len(lim) > 1:
                ax.semilogx([e for e, _ in lim], [v for _, v in lim], "s--", ms=3, label=f"{b}: limit law at that ε")
            elif lim:
                ax.axhline(lim[0][1], ls="--", lw=1, color="k", label=f"{b}: limit law")
        for i in range(len(scene)):
            if bondline[i] == b and scene[i] in sample_ids:
                rows.append([esc(b), esc(mode[i]), num(eps[i]) if mode[i] == "layer" else "—", num(peel[i], 4),
                             num(s_peel[i], 4), num(shear[i], 4), num(s_shear[i], 4)])
    for ax, q in zip(axes, ("peak peel max σ_N⁺", "peak shear max |σ_T|")):
        ax.set_xlabel("layer thickness ε (mm)")
        ax.set_ylabel(f"{q} ({stress})")
        ax.legend(fontsize=7)
    fig.suptitle(f"{name}: peak stresses on the bondlines (at their ends) against ε", fontsize=10)
    fig.tight_layout()
    out = [ctx.figures.save(fig, f"joint_{slug(name)}_peaks", f"{name} peaks",
                            f"{esc(name)}: the largest peel (tension) and shear stress of each bondline, the layer at "
                            "each ε against the limit law.")]
    out.append("<details><summary>the peaks, scene by scene (s: where, arc length in mm)</summary>" +
               table(["bondline", "mode", "ε (mm)", f"peel ({esc(stress)})", "s", f"shear ({esc(stress)})", "s"], rows,
                     css_class="small", left_columns=(0, 1)) + "</details>")
    # Under mesh refinement (the floor study's scenes: ids ending in -h<h>)
    floor_rows = []
    for i in range(len(scene)):
        if "-h" in scene[i] and scene[i] not in sample_ids:
            floor_rows.append([esc(bondline[i]), esc(mode[i]), num(h[i]), num(eps[i]) if mode[i] == "layer" else "—",
                               num(peel[i], 4), num(shear[i], 4)])
    if floor_rows:
        out.append(f"<p>The peaks under mesh refinement (element size h along the bondlines; the study's own mesh "
                   f"h = {num(h0)} mm). Peaks at the ends of a bondline converge only where the law keeps the stresses "
                   "bounded (finite K); against a rigid bond or at a layer's corners they grow as h shrinks.</p>")
        out.append(table(["bondline", "mode", "h (mm)", "ε (mm)", f"peel ({esc(stress)})", f"shear ({esc(stress)})"],
                         floor_rows, css_class="small", left_columns=(0, 1)))
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
    text = (f"<p>The mesh dependence of the distances: both modes at ε = {num(eps)} mm "
            + ("(the glue's own thickness: the joint as glued)" if engineer else "(far below the grid: the mesh floor proper)")
            + ", the scene re-meshed with the element size h along the bondlines halved twice. Where a distance does not "
            "change with h, the verdict below measures the model; where it does, it measures the mesh as well.</p>")
    return text + table(["h (mm)", "nodes on S"] + [section_scene_files.LABELS[q] for q in quantities], rows)


def verdict_block(study):
    v = study.get("validity")
    if v is None:
        return "<p>(No validity study: run <code>study validity --scene</code>.)</p>"
    tau, eps_max, status = array(v, "tau"), array(v, "eps_max"), strings(v["status"])
    lines = []
    for i in range(len(tau)):
        value = {"found": f"up to ε = <b>{eps_max[i]:.3g} mm</b>",
                 "at_least": f"at every sampled ε, up to at least <b>{eps_max[i]:.3g} mm</b>",
                 "below_range": f"at no sampled ε (not even {eps_max[i]:.3g} mm)"}.get(status[i], esc(status[i]))
        lines.append(f"<li>within τ = {tau[i] * 100:g} % of the layer model (the adherents' displacements): {value}</li>")
    floor = ""
    if attr(v, "mesh_floor_u") is not None:
        floor = (f"<p>Mesh floor of that distance: {attr(v, 'mesh_floor_u'):.2e} at h = {num(attr(v, 'mesh_floor_h'))} mm, "
                 f"{attr(v, 'mesh_floor_u_finest'):.2e} at h = {num(attr(v, 'mesh_floor_h_finest'))} mm. "
                 f"{esc(attr(v, 'mesh_floor_note', ''))}.</p>")
    return ("<p><b>Verdict.</b> The limit law can stand in for the glue layer of this joint:</p><ul>" + "".join(lines) +
            "</ul>" + floor)


def render(ctx):
    """The whole joint report body: one block per scene study in the file (normally one)."""
    g = ctx.f["studies"]["scene"]
    parts = []
    for name in sorted(g):
        study = g[name]
        pairs = samples(ctx, study)
        if not pairs:
            parts.append(section(f"joint-{slug(name)}", name, "<p class=\"absent\">No scenes of this study stored.</p>"))
            continue
        nominal = nominal_index(study, pairs)
        eps, layer, limit = pairs[nominal]
        body = [joint_summary(ctx, study, name, pairs),
                "<h3>The verdict</h3>", verdict_block(study),
                checks_block(ctx.checks, "scene.", "this joint"),
                "<h3>The joint deformed</h3>",
                deformed_shape(ctx, name, [(limit, f"limit law ({limit.name.split('/')[-1]})"),
                                           (layer, f"meshed layer, ε = {eps:.3g} mm ({layer.name.split('/')[-1]})")]),
                "<h3>Along the bondlines: peel, shear and the jumps</h3>",
                bondline_figures(ctx, name, pairs, nominal),
                "<h3>Peak stresses at the bondline ends</h3>",
                peak_block(ctx, name, study, pairs),
                "<h3>Layer against limit law: the distances, their rates and the mesh</h3>",
                section_scene_files.scene_block(ctx, study, name),
                floor_block(study),
                "<p>The bondline fields of every scene are also in <code>bondline_fields.csv</code> beside "
                "<code>results.h5</code> (one row per bondline node and scene).</p>"]
        parts.append(section(f"joint-{slug(name)}", f"The joint '{name}'", "\n".join(body)))
    return "\n".join(parts)

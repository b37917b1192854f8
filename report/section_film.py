"""Film admissibility (SPEC §1.5): the layer scenes of the file whose answer strays from the
discrete model's assumptions -- a film that slid more than one element along S (the node-to-node
pairing needs less) or strained more than 1e-2 (a small-strain model). Read from each layer scene's
attributes film_slip_over_h and film_strain_max."""

import numpy as np

from html_parts import absent, esc, how_to_read, num, section, table

SLIP_WARNING = 1.0     # elements along S (cases/film_admissibility.h)
STRAIN_WARNING = 1e-2  # strain


def film_rows(scenes):
    """(scene, slip over h, strain) of every layer scene that carries the two numbers."""
    rows = []
    for s in scenes:
        if s.mode != "layer" or "film_slip_over_h" not in s.attrs:
            continue
        rows.append((s, float(s.attrs["film_slip_over_h"]), float(s.attrs.get("film_strain_max", np.nan))))
    return rows


def render(ctx, anchor="film", title="8b. Film admissibility (SPEC §1.5)"):
    rows = film_rows(ctx.scenes)
    if not rows:
        return section(anchor, title, absent("Layer scenes with film_slip_over_h (a results file written before issue 25)"))
    outside = [r for r in rows if r[1] > SLIP_WARNING or r[2] > STRAIN_WARNING]
    body = [how_to_read(
        "A layer whose faces are open or slide can be pushed along by forces of order ε against a membrane of "
        "stiffness order ε² and travel far. That is an answer of the discrete model, but outside its assumptions: "
        "the node-to-node pairing of the interfaces needs slips below the element size along S, and the model is "
        "one of small strains. Listed: the layer scenes whose largest slip on a face exceeds one element "
        f"(<b>slip/h</b> &gt; {SLIP_WARNING:g}) or whose largest principal strain exceeds {STRAIN_WARNING:g}. "
        "Their stresses on S and reactions are still the discrete model's answer; their film is not physical.")]
    body.append(f"<p>{len(outside)} of {len(rows)} layer scenes stray outside the assumptions; the largest slip is "
                f"{num(max(r[1] for r in rows), 3)} elements, the largest strain {num(max(r[2] for r in rows), 3)}.</p>")
    if outside:
        outside.sort(key=lambda r: -r[1])
        body.append(table(["scene", "case", "ε", "slip / h", "largest strain", "converged"],
                          [[esc(s.id), esc(s.law_case or s.case), num(s.eps, 3), num(slip, 3), num(strain, 3),
                            "yes" if s.converged else "no"] for s, slip, strain in outside],
                          css_class="small", left_columns=(0, 1)))
    return section(anchor, title, "\n".join(body))

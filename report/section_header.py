"""Section 1: the run at a glance — every stored check (failed ones first, in red), what the
file holds, scenes that did not converge, and the build environment."""

from collections import Counter

from checks import checks_table, count_text
from html_parts import absent, esc, how_to_read, num, section, table
from results_file import attr, group

# The environment attributes a reviewer looks for first; any other stored one follows.
ENVIRONMENT_ORDER = ("commit", "compiler", "build_type", "eigen", "suitesparse", "cholmod", "gmsh", "hdf5")


def render(ctx):
    body = [how_to_read(
        "The verdict of every check the run stored in <code>/checks</code> (the same checks as "
        "<code>summary.json</code>): a check is PASS or FAIL exactly as the run decided it; this "
        "report never re-decides one. Each later section repeats the checks that concern it. "
        "Below: what the results file holds, and the versions it was built with.")]
    body.append(run_summary(ctx))
    body.append("<h3>Contents of the results file</h3>")
    body.append(contents(ctx))
    body.append("<h3>Environment</h3>")
    body.append(environment(ctx))
    return section("summary", "1. Run summary", "\n".join(body))


def run_summary(ctx):
    if ctx.checks is None:
        return absent("The run's checks (/checks)")
    failed = [c for c in ctx.checks if not c.passed]
    head = f'<p style="font-size:1.3em">{count_text(ctx.checks)}'
    head += (f" ({len(ctx.checks) - len(failed)} passed, {len(failed)} failed).</p>")
    out = [head]
    if failed:
        out.append('<p class="failtext">Failed checks:</p>')
        out.append(checks_table(failed, css_class=""))
    by_prefix = Counter(c.id.split(".")[0] for c in ctx.checks)
    failed_by_prefix = Counter(c.id.split(".")[0] for c in failed)
    rows = [[esc(p), str(n), (f'<span class="failtext">{failed_by_prefix[p]}</span>'
                              if failed_by_prefix[p] else '<span class="passtext">0</span>')]
            for p, n in sorted(by_prefix.items())]
    out.append(table(["checks of", "count", "failed"], rows))
    out.append(f"<details><summary>show all {len(ctx.checks)} checks</summary>{checks_table(ctx.checks)}</details>")
    return "\n".join(out)


def contents(ctx):
    f = ctx.f
    out = [f"<p>File <code>{esc(ctx.path)}</code>, layout <code>{esc(attr(f, 'layout'))}</code> "
           f"version {esc(attr(f, 'layout_version'))}.</p>"]
    kinds = Counter((s.case, s.mode, s.solver) for s in ctx.scenes)
    rows = [[esc(c), esc(m), esc(sv), str(n)] for (c, m, sv), n in sorted(kinds.items())]
    if rows:
        out.append(table(["case", "mode", "solver", "scenes"], rows, left_columns=(0, 1, 2)))
    else:
        out.append(absent("Scenes (/scenes)"))
    unconverged = [s for s in ctx.scenes if not s.converged]
    if unconverged:
        out.append(f'<p class="failtext">{len(unconverged)} of {len(ctx.scenes)} stored scenes did not '
                   f"converge (attribute <code>converged = 0</code>):</p>")
        out.append(table(["scene", "residual", "tolerance"],
                         [[esc(s.id), num(s.residual), num(s.attrs.get("tolerance"))] for s in unconverged],
                         css_class="small"))
    elif ctx.scenes:
        out.append(f'<p class="passtext">All {len(ctx.scenes)} stored scenes converged '
                   f"(attribute <code>converged = 1</code>).</p>")
    studies = group(f, "studies")
    names = sorted(studies.keys()) if studies is not None else []
    out.append("<p>Studies stored: " + (", ".join(f"<code>{esc(n)}</code>" for n in names) or "none")
               + ".</p>")
    return "\n".join(out)


def environment(ctx):
    g = group(ctx.f, "environment")
    if g is None:
        return absent("The build environment (/environment: compiler, library versions, commit)")
    names = [n for n in ENVIRONMENT_ORDER if n in g.attrs] + sorted(n for n in g.attrs if n not in ENVIRONMENT_ORDER)
    missing = [n for n in ("commit", "compiler", "eigen", "suitesparse", "gmsh", "hdf5") if n not in g.attrs]
    out = [table(["", "value"], [[esc(n), esc(attr(g, n))] for n in names], left_columns=(0, 1))]
    if missing:
        out.append(f'<p class="absent">Not recorded: {esc(", ".join(missing))}.</p>')
    return "\n".join(out)

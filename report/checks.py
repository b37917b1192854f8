"""The run's checks as stored in /checks: the only source of PASS/FAIL in the report.

Every pass/fail mark comes from the stored `pass` flag; the report never re-decides a check.
Sections show the checks that concern them by id prefix ("table3.", "convergence.", ...).
"""

from dataclasses import dataclass

from html_parts import esc, table, verdict
from results_file import array, group, strings


@dataclass
class Check:
    id: str
    passed: bool
    expected: str
    got: str
    tolerance: str


def load_checks(f):
    """The stored checks, or None when the file has no /checks group."""
    g = group(f, "checks")
    if g is None:
        return None
    ids = strings(g["id"])
    passed = array(g, "pass").reshape(-1)
    n = len(ids)

    def column(name):
        return strings(g[name]) if name in g else [""] * n
    expected, got, tolerance = column("expected"), column("got"), column("tolerance")
    if len(passed) != n or len(expected) != n or len(got) != n or len(tolerance) != n:
        raise ValueError("/checks: datasets id, pass, expected, got, tolerance differ in length")
    return [Check(ids[i], bool(passed[i]), expected[i], got[i], tolerance[i]) for i in range(n)]


def with_prefix(checks, prefix):
    return [c for c in (checks or []) if c.id.startswith(prefix)]


def count_text(checks):
    """'12 checks, all pass' / '12 checks, 2 FAIL' with the colour of the verdict."""
    failed = sum(not c.passed for c in checks)
    if failed == 0:
        return f'<span class="passtext">{plural(len(checks))}, all pass</span>'
    return f'<span class="failtext">{plural(len(checks))}, {failed} FAIL</span>'


def plural(n):
    return f"{n} check" if n == 1 else f"{n} checks"


def checks_table(checks, css_class="small"):
    rows, classes = [], []
    for c in checks:
        rows.append([esc(c.id), verdict(c.passed), esc(c.expected), esc(c.got), esc(c.tolerance)])
        classes.append("" if c.passed else "failrow")
    return table(["check", "result", "expected", "got", "tolerance"], rows, css_class,
                 left_columns=(0, 2, 3), row_classes=classes)


def checks_block(checks, prefix, what):
    """The checks whose id starts with `prefix`, shown beside the table they concern:
    a one-line count, the failed ones spelled out, all of them behind a click."""
    if checks is None:
        return f'<p class="absent">Checks for {esc(what)}: /checks is not in this results file.</p>'
    mine = with_prefix(checks, prefix)
    if not mine:
        return f'<p class="absent">No check with id prefix <code>{esc(prefix)}</code> in this results file.</p>'
    failed = [c for c in mine if not c.passed]
    out = [f'<div class="checks">Checks <code>{esc(prefix)}*</code>: {count_text(mine)}.']
    if failed:
        out.append(checks_table(failed))
    out.append(f"<details><summary>show {plural(len(mine))}</summary>{checks_table(mine)}</details></div>")
    return "\n".join(out)


def compact_verdict(checks):
    """A table cell for a handful of checks: PASS with their number, or FAIL naming the
    failed ones (ids without their common prefix would be ambiguous, so they stay whole)."""
    if not checks:
        return '<span class="absent">no check</span>'
    failed = [c for c in checks if not c.passed]
    if not failed:
        return f'{verdict(True)} {len(checks)}/{len(checks)}'
    names = "<br>".join(esc(c.id) + ": got " + esc(c.got) for c in failed)
    return f'{verdict(False)} {len(checks) - len(failed)}/{len(checks)}<br><small>{names}</small>'

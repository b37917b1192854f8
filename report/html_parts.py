"""Small HTML building blocks: escaping, tables, pass/fail marks, sections, figures.

Cells and bodies are HTML strings; anything that came from the results file goes through
`esc` (or `num`) first. (Not named html.py: that would shadow the standard module.)
"""

import html
import math

STYLE = """
body { font-family: system-ui, sans-serif; max-width: 1300px; margin: 1em auto; padding: 0 1em;
       color: #222; line-height: 1.4; }
h1 { margin-bottom: 0.2em; }
h2 { border-bottom: 2px solid #bbb; padding-bottom: 0.2em; margin-top: 2em; }
h3 { margin-bottom: 0.3em; }
p.how { background: #f4f6f8; border-left: 4px solid #8aa; padding: 0.4em 0.8em; }
p.absent { color: #666; font-style: italic; }
table { border-collapse: collapse; margin: 0.5em 0 1em 0; font-size: 0.9em; }
th, td { border: 1px solid #ccc; padding: 0.2em 0.5em; text-align: right; vertical-align: top; }
td { white-space: nowrap; }
td.l { white-space: normal; }
th { background: #eef0f2; }
td.l, th.l { text-align: left; }
table.small { font-size: 0.8em; }
.pass { color: #fff; background: #2a8a2a; font-weight: bold; padding: 0 0.4em; border-radius: 3px; }
.fail { color: #fff; background: #c62828; font-weight: bold; padding: 0 0.4em; border-radius: 3px; }
.passtext { color: #2a8a2a; font-weight: bold; }
.failtext { color: #c62828; font-weight: bold; }
.note { color: #8a5a00; }
tr.failrow td { background: #fdecea; }
.checks { margin: 0.3em 0 1em 0; }
figure { margin: 0.5em 0 1.5em 0; }
figure img { max-width: 100%; border: 1px solid #ddd; }
figcaption { font-size: 0.9em; color: #444; }
nav a { margin-right: 1em; }
code { background: #f2f2f2; padding: 0 0.2em; }
"""


def esc(value):
    return html.escape(str(value), quote=True)


def num(value, digits=3):
    """A number for a table cell: ∞ for inf, — for a missing value, %g otherwise."""
    if value is None:
        return "—"
    try:
        x = float(value)
    except (TypeError, ValueError):
        return esc(value)
    if math.isnan(x):
        return "—"
    if math.isinf(x):
        return "∞" if x > 0 else "−∞"
    if x == int(x) and abs(x) < 1e6:
        return str(int(x))
    return f"{x:.{digits}g}"


def verdict(passed):
    return '<span class="pass">PASS</span>' if passed else '<span class="fail">FAIL</span>'


def table(header, rows, css_class="", left_columns=(0,), row_classes=None):
    """A table; `header` and every cell are HTML strings. Columns in `left_columns` are
    left-aligned (names, text); the others right-aligned (numbers)."""
    def cell(tag, i, content):
        align = ' class="l"' if i in left_columns else ""
        return f"<{tag}{align}>{content}</{tag}>"
    out = [f'<table class="{css_class}">' if css_class else "<table>"]
    out.append("<tr>" + "".join(cell("th", i, h) for i, h in enumerate(header)) + "</tr>")
    for k, row in enumerate(rows):
        cls = row_classes[k] if row_classes else ""
        out.append((f'<tr class="{cls}">' if cls else "<tr>")
                   + "".join(cell("td", i, c) for i, c in enumerate(row)) + "</tr>")
    out.append("</table>")
    return "\n".join(out)


def how_to_read(text_html):
    """The short 'what is shown and how to read it' paragraph at the top of a section."""
    return f'<p class="how">{text_html}</p>'


def absent(what):
    return f'<p class="absent">{esc(what)}: not in this results file.</p>'


def section(anchor, title, body):
    return f'<section id="{esc(anchor)}">\n<h2>{esc(title)}</h2>\n{body}\n</section>'


def figure(src, alt, caption_html=""):
    cap = f"<figcaption>{caption_html}</figcaption>" if caption_html else ""
    return f'<figure><img src="{esc(src)}" alt="{esc(alt)}">{cap}</figure>'


def page(title, nav, body):
    links = " ".join(f'<a href="#{esc(a)}">{esc(t)}</a>' for a, t in nav)
    return (f"<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            f"<title>{esc(title)}</title><style>{STYLE}</style></head>\n<body>\n"
            f"<h1>{esc(title)}</h1>\n<nav>{links}</nav>\n{body}\n</body></html>\n")

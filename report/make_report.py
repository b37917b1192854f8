#!/usr/bin/python3
"""The thinlayer verification report: an HTML page with figures, read only from a results file.

    /usr/bin/python3 report/make_report.py RESULTS.h5 OUT_DIR

writes OUT_DIR/index.html and OUT_DIR/figures/*.png. The report is built in a temporary
sibling of OUT_DIR and renamed onto it only once complete, so OUT_DIR is either the previous
report or the new one, never half of one. A missing or unreadable file, a file that is not a
thinlayer results file, or an older layout: one line on stderr, exit status 2, nothing
written. (Run with Debian's /usr/bin/python3, which sees python3-matplotlib and python3-h5py.)
"""

import os
import shutil
import sys
import tempfile
import time
import traceback

# The helper modules sit beside this script, whatever the working directory; no __pycache__
# is left in the source tree.
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import section_bar_profiles  # noqa: E402
import section_convergence  # noqa: E402
import section_header  # noqa: E402
import section_layer_stiffness  # noqa: E402
import section_table3  # noqa: E402
import section_tables12  # noqa: E402
import section_stress  # noqa: E402
import section_timing  # noqa: E402
import section_validity  # noqa: E402
from checks import load_checks  # noqa: E402
from context import Context  # noqa: E402
from html_parts import page, section  # noqa: E402
from plotting import FigureWriter  # noqa: E402
from results_file import ReportError, open_results  # noqa: E402
from scenes import index_scenes  # noqa: E402

USAGE = "usage: make_report.py RESULTS.h5 OUT_DIR"
EXIT_BAD_INPUT = 2


def paper_tables(ctx):
    """Section 2 gathers the three tables of the paper."""
    return section("tables", "2. The paper's tables", section_tables12.render(ctx) + "\n" + section_table3.render(ctx))


# (anchor, navigation label, renderer): the order of the page.
SECTIONS = (
    ("summary", "Summary", section_header.render),
    ("tables", "Tables 1–3", paper_tables),
    ("bar", "Figs. 13–14", section_bar_profiles.render),
    ("stiffness", "Figs. 6–7", section_layer_stiffness.render),
    ("convergence", "Convergence", section_convergence.render),
    ("validity", "Validity", section_validity.render),
    ("timing", "Run time", section_timing.render),
    ("stress", "Stress tests", section_stress.render),
)


class SectionError(Exception):
    """A section could not be built from the file (a malformed or incomplete group)."""


def write_report(f, results_path, out_dir):
    """Write index.html and figures/ into out_dir (an empty directory)."""
    def build(label, step):
        try:
            return step()
        except Exception as e:  # name the part: the reviewer must know what broke
            if os.environ.get("THINLAYER_REPORT_DEBUG"):
                traceback.print_exc()
            raise SectionError(f"{label}: {type(e).__name__}: {e}") from e

    ctx = build("reading /scenes and /checks",
                lambda: Context(path=results_path, f=f, scenes=index_scenes(f), checks=load_checks(f),
                                figures=FigureWriter(out_dir)))
    parts = [build(f"section '{label}'", lambda: render(ctx)) for _, label, render in SECTIONS]
    html = page("thinlayer verification report", [(a, label) for a, label, _ in SECTIONS], "\n".join(parts))
    with open(os.path.join(out_dir, "index.html"), "w", encoding="utf-8") as out:
        out.write(html)


def replace_directory(built, target):
    """Put the finished report `built` where `target` is, replacing any previous report."""
    if not os.path.lexists(target):
        os.rename(built, target)
        return
    previous = tempfile.mkdtemp(prefix="." + os.path.basename(target) + ".previous-", dir=os.path.dirname(target))
    os.rmdir(previous)  # only its unique name is wanted
    os.rename(target, previous)
    try:
        os.rename(built, target)
    except OSError:
        os.rename(previous, target)  # put the old report back rather than leave nothing
        raise
    shutil.rmtree(previous, ignore_errors=True)


def make_report(results_path, out_dir):
    out_dir = os.path.abspath(out_dir)
    if os.path.lexists(out_dir) and not os.path.isdir(out_dir):
        raise ReportError(f"{out_dir}: exists and is not a directory")
    with open_results(results_path) as f:  # refuses a bad file before anything is written
        parent = os.path.dirname(out_dir)
        try:
            os.makedirs(parent, exist_ok=True)
            building = tempfile.mkdtemp(prefix="." + os.path.basename(out_dir) + ".building-", dir=parent)
        except OSError as e:
            raise ReportError(f"cannot write beside {out_dir}: {e.strerror or e}") from None
        try:
            write_report(f, results_path, building)
            replace_directory(building, out_dir)
        except BaseException:
            shutil.rmtree(building, ignore_errors=True)
            raise


def main(argv):
    if len(argv) == 2 and argv[1] in ("-h", "--help"):
        print(USAGE + "\n" + __doc__)
        return 0
    if len(argv) != 3:
        print(f"make_report: expected 2 arguments, got {len(argv) - 1}; {USAGE}", file=sys.stderr)
        return EXIT_BAD_INPUT
    start = time.monotonic()
    try:
        make_report(argv[1], argv[2])
    except ReportError as e:
        print(f"make_report: {e}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except SectionError as e:
        print(f"make_report: {argv[1]}: {e}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except OSError as e:
        print(f"make_report: {e}", file=sys.stderr)
        return EXIT_BAD_INPUT
    print(f"wrote {os.path.join(argv[2], 'index.html')} in {time.monotonic() - start:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

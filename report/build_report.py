#!/usr/bin/python3
"""The thinlayer verification report, built: an HTML page with figures, read only from a results file.

Run by make_report.py (the command), in a process of its own: whatever reading a damaged results
file does to this process (a crash in HDF5, a loop), make_report.py says so in one line and
removes what this process left (SPEC §4).

    /usr/bin/python3 report/build_report.py RESULTS.h5 OUT_DIR

writes OUT_DIR/index.html and OUT_DIR/figures/*.png, and nothing else (SPEC §4, "Nothing
lost"): every other file in OUT_DIR -- its input, summary.json, the user's notes -- is left as
it was. The report is built in a hidden temporary folder inside OUT_DIR; once complete, its
figures and index.html are renamed into place (index.html last, through a symbolic link if it
is one), then the previous report's figures that the new one does not have are removed. The
previous report's files are known from its index.html, which must be one this script wrote
(its title); a file in the way that the report did not write is refused, not replaced.
A missing or unreadable file, a file that is not a thinlayer results file (foreign), or an
older layout: one line on stderr, exit status 2, nothing written. SIGTERM, SIGINT and SIGHUP remove
the half-built report. (Run with Debian's /usr/bin/python3, which sees python3-matplotlib
and python3-h5py.)
"""

import os
import shutil
import signal
import sys
import time
import traceback

# The helper modules sit beside this script, whatever the working directory; no __pycache__
# is left in the source tree.
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import parallel_sections  # noqa: E402
import section_bar_profiles  # noqa: E402
import section_controls  # noqa: E402
import section_convergence  # noqa: E402
import section_convergence_rates  # noqa: E402
import section_film  # noqa: E402
import section_header  # noqa: E402
import section_joint  # noqa: E402
import section_layer_stiffness  # noqa: E402
import section_refinement  # noqa: E402
import section_scene_files  # noqa: E402
import section_table3  # noqa: E402
import section_tables12  # noqa: E402
import section_stress  # noqa: E402
import section_timing  # noqa: E402
import section_validity  # noqa: E402
import section_validity_map  # noqa: E402
from checks import load_checks  # noqa: E402
from context import Context  # noqa: E402
from html_parts import page, section  # noqa: E402
from plotting import FigureWriter  # noqa: E402
from report_folder import JOINT_TITLE, MAP_TITLE, REFINEMENT_TITLE, TITLE, FolderError, check_folder  # noqa: E402
from results_file import ReportError, open_results  # noqa: E402
from scenes import index_scenes  # noqa: E402

USAGE = "usage: make_report.py RESULTS.h5 OUT_DIR [--time-limit SECONDS]"
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
    ("rates", "Rates", section_convergence_rates.render),
    ("controls", "Controls", section_controls.render),
    ("validity", "Validity", section_validity.render),
    ("validity_map", "Validity map", section_validity_map.render),
    ("timing", "Run time", section_timing.render),
    ("stress", "Stress tests", section_stress.render),
    ("film", "Film", section_film.render),
    ("scenes", "Your own joint", section_scene_files.render),
)


# Rendered by a second process, beside the others (parallel_sections.py): the slowest section.
IN_HELPER = {"convergence"}

# A file whose only study is a scene-file study (`study validity --scene`) gets the report of that
# joint instead of the verification report's empty sections (SPEC §5).
# Its sections are numbered 1, 2, 3 ... in order: the run summary, then the joint's own
# (section_joint.sections: the joint and its law, the verdict, ..., what the answers assume).
JOINT_SECTIONS = (
    ("summary", "Summary", section_header.render),
)


def is_joint_file(f):
    studies = f.get("studies")
    return studies is not None and set(studies.keys()) == {"scene"}


# A file whose only study is a validity map (`study validity-map --scene`) gets the map's report.
MAP_SECTIONS = (
    ("summary", "Summary", section_header.render),
    ("validity_map", "Validity map", lambda ctx: section_validity_map.render(ctx, number="2")),  # after "1. Run summary"
)


def is_map_file(f):
    studies = f.get("studies")
    return studies is not None and set(studies.keys()) == {"validity_map"}


# A file whose only study is S2 under mesh refinement (`study convergence --refine`) gets its own report.
REFINEMENT_SECTIONS = (
    ("summary", "Summary", section_header.render),
    ("refinement", "Rates under refinement", section_refinement.render),
)


def is_refinement_file(f):
    studies = f.get("studies")
    return (studies is not None and set(studies.keys()) == {"convergence"}
            and set(studies["convergence"].keys()) == {"refinement"})


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
    joint = is_joint_file(f)
    mapped = is_map_file(f)
    refined = is_refinement_file(f)
    sections = (JOINT_SECTIONS if joint else MAP_SECTIONS if mapped else REFINEMENT_SECTIONS if refined
                else SECTIONS)
    helper, answer = parallel_sections.start(
        results_path, out_dir, [(label, render) for anchor, label, render in sections if anchor in IN_HELPER])
    try:
        mine = {anchor: build(f"section '{label}'", lambda: render(ctx))
                for anchor, label, render in sections if anchor not in IN_HELPER}
        helper_parts, error = parallel_sections.finish(helper, answer)
    finally:
        parallel_sections.stop(helper)
    if error:
        raise SectionError(f"section '{error[0]}': {error[1]}")
    from_helper = dict(zip([anchor for anchor, _, _ in sections if anchor in IN_HELPER], helper_parts))
    parts = [mine[anchor] if anchor in mine else from_helper[anchor] for anchor, _, _ in sections]
    nav = [(a, label) for a, label, _ in sections]
    if joint:
        for anchor, label, html in build("the joint's sections", lambda: section_joint.sections(ctx, len(sections) + 1)):
            parts.append(html)
            nav.append((anchor, label))
    title = (f"{JOINT_TITLE}: {', '.join(sorted(f['studies']['scene']))}" if joint else
             f"{MAP_TITLE}: {', '.join(sorted(f['studies']['validity_map']))}" if mapped else
             f"{REFINEMENT_TITLE}: {', '.join(section_refinement.refined_cases(f['studies']['convergence']['refinement']))}"
             if refined else TITLE)
    html = page(title, nav, "\n".join(parts))
    with open(os.path.join(out_dir, "index.html"), "w", encoding="utf-8") as out:
        out.write(html)


def check_input_is_safe(results_path, out_dir):
    """The report never writes over its own input."""
    source = os.path.realpath(results_path)
    if source == os.path.realpath(os.path.join(out_dir, "index.html")) or \
            os.path.dirname(source) == os.path.realpath(os.path.join(out_dir, "figures")):
        raise ReportError(f"{results_path}: the report would write over its own input; "
                          f"choose another OUT_DIR")


def install(built, out_dir, previous):
    """Move the finished report `built` into out_dir: figures, then index.html."""
    figures = os.path.join(out_dir, "figures")
    new = sorted(os.listdir(os.path.join(built, "figures")))
    if os.path.lexists(figures) and not os.path.isdir(figures):
        raise ReportError(f"{figures}: exists and is not a directory")
    for name in new:
        if os.path.lexists(os.path.join(figures, name)) and name not in (previous or set()):
            raise ReportError(f"{os.path.join(figures, name)}: exists and was not written by this report; "
                              f"move it or choose another folder")
    os.makedirs(figures, exist_ok=True)
    for name in new:
        os.replace(os.path.join(built, "figures", name), os.path.join(figures, name))
    os.replace(os.path.join(built, "index.html"), os.path.realpath(os.path.join(out_dir, "index.html")))
    for name in sorted((previous or set()) - set(new)):  # the earlier report's, no longer shown
        try:
            os.remove(os.path.join(figures, name))
        except FileNotFoundError:
            pass


def make_report(results_path, out_dir):
    out_dir = os.path.abspath(out_dir)
    check_folder(out_dir)
    with open_results(results_path) as f:  # refuses a bad file before anything is written
        check_input_is_safe(results_path, out_dir)
        previous = check_folder(out_dir)
        created = not os.path.lexists(out_dir)
        # The half-built report's name is known before it exists, so that a signal arriving just
        # after it is made (the hostile matrix kills the report as soon as it appears) finds it.
        building = os.path.join(out_dir, f".report-building-{os.getpid()}-{time.monotonic_ns()}")
        try:
            try:
                os.makedirs(out_dir, exist_ok=True)
                os.mkdir(building)
            except OSError as e:
                raise ReportError(f"cannot write in {out_dir}: {e.strerror or e}") from None
            write_report(f, results_path, building)
            install(building, out_dir, previous)
        except BaseException:
            shutil.rmtree(building, ignore_errors=True)
            if created:
                shutil.rmtree(out_dir, ignore_errors=True)  # it held nothing but this report
            raise
        shutil.rmtree(building, ignore_errors=True)


class Interrupted(BaseException):
    """SIGINT or SIGTERM, as an exception: the half-built report is removed on the way out."""

    def __init__(self, signum):
        super().__init__(f"signal {signum}")
        self.signum = signum


def stop_on_signal(signum, _frame):
    raise Interrupted(signum)


def main(argv):
    if len(argv) == 2 and argv[1] in ("-h", "--help"):
        print(USAGE + "\n" + __doc__)
        return 0
    if len(argv) != 3:
        print(f"make_report: expected 2 arguments, got {len(argv) - 1}; {USAGE}", file=sys.stderr)
        return EXIT_BAD_INPUT
    start = time.monotonic()
    for signum in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        signal.signal(signum, stop_on_signal)
    try:
        make_report(argv[1], argv[2])
    except Interrupted as e:  # cleaned up; now die of the signal, as the caller expects
        signal.signal(e.signum, signal.SIG_DFL)
        os.kill(os.getpid(), e.signum)
    except (ReportError, FolderError) as e:
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


def exit_now(status):
    """Ends the process without the interpreter's teardown: HDF5's own clean-up at exit has looped
    for ever on a damaged file after the report had said what it found (make_report.py's clock
    then added a second line)."""
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(status)


if __name__ == "__main__":
    exit_now(main(sys.argv))

"""The report's folder: what may be there before a report is written into it (SPEC §4, "Nothing lost").

A report writes OUT_DIR/index.html and OUT_DIR/figures/*.png and nothing else. An index.html
already there must be one this script wrote (its title); the figures folder must be a folder.
Checked twice: by `thinlayer` before a study's work (make_report.py --check-folder), so that a
folder the report would refuse is refused before the hours of solving, not after; and by the
report itself when it writes (the folder may have changed meanwhile).
"""

import os
import re

TITLE = "thinlayer verification report"
JOINT_TITLE = "thinlayer joint report"
MAP_TITLE = "thinlayer validity map"
REFINEMENT_TITLE = "thinlayer rates under refinement"


class FolderError(Exception):
    """A folder the report may not write into: the message is the one line printed on stderr."""


def previous_figures(index_path):
    """The figures an earlier report in this folder wrote (named in its index.html), or
    None when there is no earlier report. A file there that this script did not write is
    refused."""
    if not os.path.lexists(index_path):
        return None
    try:
        with open(index_path, encoding="utf-8") as page_file:
            html = page_file.read()
    except (OSError, UnicodeDecodeError) as e:
        raise FolderError(f"{index_path}: exists and is not a report this script wrote ({e}); "
                          f"move it or choose another folder") from None
    if f"<title>{TITLE}</title>" not in html and not re.search(f"<title>({JOINT_TITLE}|{MAP_TITLE}|{REFINEMENT_TITLE}): [^<]*</title>", html):
        raise FolderError(f"{index_path}: exists and is not a report this script wrote; "
                          f"move it or choose another folder")
    return set(re.findall(r'<img src="figures/([^"/]+\.png)"', html))


def check_folder(out_dir):
    """Refuses (FolderError) an OUT_DIR the report could not write into, or only by replacing what
    it did not write; returns the earlier report's figures (None if there is none)."""
    out_dir = os.path.abspath(out_dir)
    if os.path.lexists(out_dir) and not os.path.isdir(out_dir):
        raise FolderError(f"{out_dir}: exists and is not a directory")
    previous = previous_figures(os.path.join(out_dir, "index.html"))
    figures = os.path.join(out_dir, "figures")
    if os.path.lexists(figures) and not os.path.isdir(figures):
        raise FolderError(f"{figures}: exists and is not a directory")
    existing = out_dir
    while not os.path.lexists(existing):
        existing = os.path.dirname(existing)
    if not os.access(existing, os.W_OK | os.X_OK):
        raise FolderError(f"cannot write in {out_dir}: {existing} is not writable")
    return previous

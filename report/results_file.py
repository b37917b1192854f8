"""Opening a thinlayer results file (SPEC §4) and reading its values as plain Python.

The report reads nothing but this file, so everything that decides whether the file can be
read at all lives here: a missing, unreadable, foreign or older file, or one that would make
HDF5 read another file (refuse_other_files), is refused with one line (`ReportError`) before
anything is written.
"""

import os

import h5py
import numpy as np

LAYOUT = "thinlayer-results"
# Version 2 (issue 15) adds to version 1 only what describes the data (units, the status
# legend, node_plus/node_minus, mesh/cell_body, mesh/cell_stress) and makes `solve` files
# results files; the report reads both. Version 0 (no version attribute) is older.
LAYOUT_VERSION = 2
READABLE_VERSIONS = (1, 2)


class ReportError(Exception):
    """An input the report refuses: the message is the one line printed on stderr."""


def text(value):
    """An HDF5 string (attribute or dataset element) as str; h5py gives bytes or str."""
    if isinstance(value, bytes):
        return value.decode("utf-8", "replace")
    if isinstance(value, np.ndarray) and value.shape == ():
        return text(value[()])
    return str(value)


def open_results(path):
    """The h5py.File of a thinlayer results file of the layout this report understands."""
    if not os.path.exists(path):
        raise ReportError(f"{path}: no such file")
    if not os.path.isfile(path):
        raise ReportError(f"{path}: not a file")
    if not os.access(path, os.R_OK):
        raise ReportError(f"{path}: not readable (permission denied)")
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        raise ReportError(f"{path}: not a readable HDF5 file ({first_line(e)})") from None
    try:
        check_layout(f, path)
        refuse_other_files(f, path)
    except ReportError:
        f.close()
        raise
    return f


def shown(value):
    """A value from the file as a message shows it: one line, control characters (C0, DEL, C1,
    line and paragraph separators, bidirectional overrides) as \\uXXXX -- the rule of thinlayer's
    messages (core/io/shown_text.h)."""
    return "".join(f"\\u{ord(c):04x}" if ord(c) < 0x20 or 0x7f <= ord(c) <= 0x9f or c in "\u2028\u2029"
                   or 0x202a <= ord(c) <= 0x202e or 0x2066 <= ord(c) <= 0x2069 else c for c in str(value))


def refuse_other_files(f, path):
    """The report opens the one file it is given (SPEC §4): a results file that would make HDF5
    read another -- an external link (a group member that names an object of another file), a
    dataset with external storage (its bytes in other files: /etc/passwd read as /checks/got) or a
    virtual dataset (mapped from other datasets, of this file or others) -- is refused before
    any of its values is read. thinlayer writes none of these. Every member of every group is
    looked at as a link (get(..., getlink=True)), never followed unless it is a hard link; each
    group and dataset once (a hard link back to a parent group is no loop)."""
    try:
        walk_links(f, path)
    except ReportError:
        raise
    except Exception as e:  # h5py's errors on a damaged file: OSError, KeyError, ValueError, ...
        raise ReportError(f"{path}: not a readable results file ({shown(first_line(e))})") from None


def walk_links(f, path):
    seen = {h5py.h5o.get_info(f.id).addr}
    groups = [(f, "/")]
    while groups:
        node, where = groups.pop()
        for name in node:
            member = f"{where.rstrip('/')}/{name}"
            link = node.get(name, getlink=True)
            if isinstance(link, h5py.ExternalLink):
                raise ReportError(f"{path}: {shown(member)} is an external link to '{shown(link.filename)}': the report reads "
                                  f"this file only, and thinlayer writes no such link")
            if not isinstance(link, h5py.HardLink):
                continue  # a soft link names an object of this file, looked at where it lies
            obj = node.get(name)
            if obj is None:
                raise ReportError(f"{path}: {shown(member)} cannot be read (a damaged results file?)")
            address = h5py.h5o.get_info(obj.id).addr
            if address in seen:
                continue
            seen.add(address)
            if isinstance(obj, h5py.Group):
                groups.append((obj, member))
            elif isinstance(obj, h5py.Dataset):
                refuse_other_storage(obj, member, path)


def refuse_other_storage(dataset, member, path):
    """A dataset whose bytes lie in other files (external storage) or other datasets (virtual)."""
    plist = dataset.id.get_create_plist()
    if plist.get_external_count() > 0:
        name = plist.get_external(0)[0]
        name = name.decode("utf-8", "replace") if isinstance(name, bytes) else str(name)
        raise ReportError(f"{path}: {shown(member)} keeps its values in another file ('{shown(name)}', external storage): the "
                          f"report reads this file only, and thinlayer writes no such dataset")
    if plist.get_layout() == h5py.h5d.VIRTUAL:
        raise ReportError(f"{path}: {shown(member)} is a virtual dataset (its values mapped from other datasets, of "
                          f"this file or others): the report reads this file only, and thinlayer writes none")


def check_layout(f, path):
    """Refuse a file whose root attributes do not name this layout and version."""
    if "layout" not in f.attrs:
        # Whatever its groups: thinlayer has written the attribute on every results file since
        # layout 1, and on every --out file since layout 2.
        raise ReportError(f"{path}: a foreign HDF5 file, not a thinlayer results file (no root "
                          f"attribute 'layout'; a `thinlayer solve` file from before layout 2 "
                          f"has none either: re-run it)")
    layout = text(f.attrs["layout"])
    if layout != LAYOUT:
        raise ReportError(f"{path}: a foreign HDF5 file, not a thinlayer results file "
                          f"(layout = {layout!r}, expected {LAYOUT!r})")
    if "layout_version" not in f.attrs:
        raise ReportError(f"{path}: an older thinlayer results layout (no root attribute "
                          f"'layout_version')")
    try:
        version = int(np.asarray(f.attrs["layout_version"]).item())
    except (TypeError, ValueError):
        raise ReportError(f"{path}: unreadable layout_version "
                          f"{text(f.attrs['layout_version'])!r}") from None
    if version < min(READABLE_VERSIONS):
        raise ReportError(f"{path}: an older thinlayer results layout (version {version}, "
                          f"this report reads versions {READABLE_VERSIONS[0]} to {LAYOUT_VERSION}); "
                          f"re-run thinlayer to write version {LAYOUT_VERSION}")
    if version > LAYOUT_VERSION:
        raise ReportError(f"{path}: a newer thinlayer results layout (version {version}, "
                          f"this report reads version {LAYOUT_VERSION}); update report/")


def first_line(error):
    lines = str(error).strip().splitlines()
    return lines[0] if lines else type(error).__name__


def attr(node, name, default=None):
    """An attribute as str / float / int, or `default` when the writer did not store it."""
    if name not in node.attrs:
        return default
    value = node.attrs[name]
    if isinstance(value, (bytes, str)):
        return text(value)
    value = np.asarray(value)
    if value.dtype.kind in "SOU":
        return text(value.reshape(-1)[0]) if value.size else default
    if value.size != 1:
        return value
    item = value.item()
    return item


def strings(dataset):
    """A dataset of strings as a list of str."""
    return [text(v) for v in np.asarray(dataset[()]).reshape(-1)]


def array(node, name):
    """A numeric dataset as a numpy array (the whole dataset is small in this layout)."""
    return np.asarray(node[name][()])


def group(f, path):
    """The group at `path`, or None when this results file has no such group."""
    node = f.get(path)
    return node if isinstance(node, h5py.Group) else None

#!/usr/bin/env python3
"""Compares two thinlayer results files dataset by dataset and attribute by attribute.

usage: compare_results.py A.h5 B.h5

Everything must be equal — the same groups, datasets, attributes, shapes, dtypes and values,
bit for bit (NaN equal to NaN) — except what measures time (any name containing "time": wall_time_s,
setup_time_s, fast_time_s, ...) and the root attribute `ranks` (how many MPI ranks wrote the file).
Prints every difference and exits 1 if there is one, 0 otherwise.
"""
import sys

import h5py
import numpy as np


def is_timing(name):
    return "time" in name.rsplit("/", 1)[-1]


def same(a, b):
    a, b = np.asarray(a), np.asarray(b)
    if a.shape != b.shape or a.dtype != b.dtype:
        return False
    if a.dtype.kind == "f":
        return np.array_equal(a, b, equal_nan=True)
    return np.array_equal(a, b)


def compare_attrs(path, a, b, differences):
    for name in sorted(set(a.attrs) | set(b.attrs)):
        if is_timing(name) or (path == "/" and name == "ranks"):
            continue
        if name not in a.attrs or name not in b.attrs:
            differences.append(f"{path} attribute {name}: only in one file")
        elif not same(a.attrs[name], b.attrs[name]):
            differences.append(f"{path} attribute {name}: {a.attrs[name]!r} != {b.attrs[name]!r}")


def compare(a_file, b_file):
    differences = []
    names = {"A": [], "B": []}
    a_file.visit(names["A"].append)
    b_file.visit(names["B"].append)
    compare_attrs("/", a_file, b_file, differences)
    for name in sorted(set(names["A"]) | set(names["B"])):
        if name not in a_file or name not in b_file:
            differences.append(f"/{name}: only in one file")
            continue
        a, b = a_file[name], b_file[name]
        compare_attrs("/" + name, a, b, differences)
        if isinstance(a, h5py.Dataset) != isinstance(b, h5py.Dataset):
            differences.append(f"/{name}: a dataset in one file, a group in the other")
        elif isinstance(a, h5py.Dataset) and not is_timing(name) and not same(a[()], b[()]):
            differences.append(f"/{name}: values differ")
    return differences, len(names["A"])


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with h5py.File(sys.argv[1], "r") as a, h5py.File(sys.argv[2], "r") as b:
        differences, objects = compare(a, b)
    for d in differences:
        print(d)
    print(f"{objects} objects compared, {len(differences)} differences")
    sys.exit(1 if differences else 0)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""The order-one gate on validity maps (issue 45): is the meshed layer an order closer to the
first-order answer u1 than to the limit law's answer u0?

Reads the CSVs `thinlayer study validity-map --scene FILE --out DIR` writes (DIR/validity_map_<name>.csv)
and prints, per joint and quantity, at the cells above the mesh floor (resolved_<q> = 1, converged):
  - pass: the order-1 distance order1_<q> <= measured_<q> / 3 (order 0's), and how many of the misses
    have an order-1 distance the mesh still moves by more than half (order1_resolved_<q> = 0: there the
    mesh floor, not u1, may be what is measured);
  - the slopes along t/L, least squares on log-log within each (E_g/E_a, nu_g) column of at least 3
    resolved cells: order 0 on measured_<q>, order 1 on order1_<q> where it is above its own floor
    (order1_resolved_<q> = 1) — the median over the columns, and one slope over all of them with an
    intercept per column — and order 1 on every resolved cell as measured (pooled; where order 1 is
    at its mesh floor this is the floor's slope, not u1's);
  - the decision: GO where >= 80 % pass and the order-1 slope (the pooled one) is >= 1.7.
Usage: order_one_gate.py CSV [CSV ...]
"""
import csv
import math
import statistics
import sys

QUANTITIES = ["reactions", "u", "peel_at_d", "shear_at_d", "sigma_N", "sigma_T"]


def rows_of(path):
    with open(path, newline="") as f:
        lines = [line for line in f if not line.startswith("#")]
    return list(csv.DictReader(lines))


def slope(points):
    """Least-squares slope of log y on log x; None with fewer than 3 points."""
    if len(points) < 3:
        return None
    xs = [math.log(x) for x, _ in points]
    ys = [math.log(y) for _, y in points]
    mx, my = statistics.fmean(xs), statistics.fmean(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else None


def pooled_slope(columns):
    """One slope over every column of >= 3 points, each column its own intercept."""
    sxy = sxx = 0.0
    for points in columns:
        if len(points) < 3:
            continue
        xs = [math.log(x) for x, _ in points]
        ys = [math.log(y) for _, y in points]
        mx, my = statistics.fmean(xs), statistics.fmean(ys)
        sxx += sum((x - mx) ** 2 for x in xs)
        sxy += sum((x - mx) * (y - my) for x, y in zip(xs, ys))
    return sxy / sxx if sxx > 0 else None


def fmt(v):
    return "-" if v is None else f"{v:.2f}"


def gate(path):
    rows = rows_of(path)
    name = path.split("validity_map_")[-1].removesuffix(".csv")
    out = []
    for q in QUANTITIES:
        resolved = [r for r in rows if r["converged"] == "1" and r[f"resolved_{q}"] == "1"]
        passing = [r for r in resolved if 3 * float(r[f"order1_{q}"]) <= float(r[f"measured_{q}"])]
        misses_at_floor = sum(1 for r in resolved if r not in passing and r[f"order1_resolved_{q}"] == "0")
        columns0, columns1, columns1_all = {}, {}, {}
        for r in resolved:
            key = (r["E_ratio"], r["nu"])
            t = float(r["t_over_L"])
            if float(r[f"measured_{q}"]) > 0:
                columns0.setdefault(key, []).append((t, float(r[f"measured_{q}"])))
            if float(r[f"order1_{q}"]) > 0:
                columns1_all.setdefault(key, []).append((t, float(r[f"order1_{q}"])))
                if r[f"order1_resolved_{q}"] == "1":
                    columns1.setdefault(key, []).append((t, float(r[f"order1_{q}"])))
        s0 = [s for s in (slope(p) for p in columns0.values()) if s is not None]
        s1 = [s for s in (slope(p) for p in columns1.values()) if s is not None]
        p0, p1 = pooled_slope(columns0.values()), pooled_slope(columns1.values())
        p1_all = pooled_slope(columns1_all.values())
        fraction = len(passing) / len(resolved) if resolved else 0.0
        go = bool(resolved) and fraction >= 0.8 and p1 is not None and p1 >= 1.7
        ratios = sorted(float(r[f"order1_ratio_{q}"]) for r in resolved)
        out.append((name, q, len(passing), len(resolved), fraction, misses_at_floor,
                    statistics.median(ratios) if ratios else None,
                    statistics.median(s0) if s0 else None, p0, len(s0),
                    statistics.median(s1) if s1 else None, p1, len(s1), p1_all, go))
    return out


def main(paths):
    print("| joint | quantity | order 1 <= order 0 / 3 | of which misses at order 1's mesh floor | median ratio "
          "| slope order 0 (median, pooled, columns) | slope order 1 above its floor (median, pooled, columns) "
          "| slope order 1 as measured (pooled) | decision |")
    print("|---|---|---|---|---|---|---|---|---|")
    for path in paths:
        for (name, q, n_pass, n_res, frac, floor, median, m0, p0, c0, m1, p1, c1, p1_all, go) in gate(path):
            print(f"| {name} | {q} | {n_pass}/{n_res} ({100 * frac:.0f} %) | {floor} | {fmt(median)} "
                  f"| {fmt(m0)}, {fmt(p0)}, {c0} | {fmt(m1)}, {fmt(p1)}, {c1} | {fmt(p1_all)} | {'GO' if go else 'stop'} |")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: order_one_gate.py CSV [CSV ...]")
    main(sys.argv[1:])

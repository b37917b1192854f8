#!/usr/bin/env python3
"""Projects a study's wall time on K MPI ranks from one one-process run.

usage: THINLAYER_SCENE_TIMES=times.tsv build/thinlayer study NAME ...   (one process)
       scripts/project_scaling.py times.tsv WALL_SECONDS [K ...]

times.tsv has one line per scene: batch tag, batch number, label, cost estimate, measured
seconds, rank.
For each K the batches are assigned as SceneBatch does (longest first on the cost
estimates), and each batch lasts as long as its busiest rank with the measured times; what
the run spent outside the scenes (meshing, factorising the shared bulks, post-processing,
writing) is added unchanged, since every rank does it (or rank 0 alone). The gather is left
out: its bytes (the scenes' records) take well under a second on a cluster's network.
Prints the per-scene time distribution and the projected wall time and speed-up per K.
"""
import statistics
import sys


def batches(path):
    """The scenes of each batch, in the order of the batches."""
    out = {}
    for line in open(path):
        _, batch, label, cost, seconds, _ = line.rstrip("\n").split("\t")
        out.setdefault(batch, []).append((label, float(cost), float(seconds)))
    return list(out.values())


def makespan(batch, ranks):
    load_estimate, load_measured = [0.0] * ranks, [0.0] * ranks
    for _, cost, seconds in sorted(batch, key=lambda t: -t[1]):
        r = min(range(ranks), key=lambda k: load_estimate[k])
        load_estimate[r] += cost
        load_measured[r] += seconds
    return max(load_measured)


def main():
    path, wall = sys.argv[1], float(sys.argv[2])
    ks = [int(k) for k in sys.argv[3:]] or [1, 2, 8, 32, 128]
    bs = batches(path)
    times = sorted(s for b in bs for _, _, s in b)
    total = sum(times)
    serial = wall - total
    print(f"{len(times)} scenes in {len(bs)} batches: {total:.1f} s of scenes, {serial:.1f} s outside them")
    q = lambda p: times[min(len(times) - 1, int(p * len(times)))]
    print(f"per scene: median {statistics.median(times):.3g} s, 90% {q(0.9):.3g} s, max {times[-1]:.3g} s; "
          f"the longest 5% take {sum(times[int(0.95 * len(times)):]) / total:.0%} of the time")
    for k in ks:
        t = serial + sum(makespan(b, k) for b in bs)
        print(f"K = {k:4d}: {t:8.1f} s, speed-up {wall / t:5.2f}")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""scripts/status_change_control.py on a synthetic results file: one node of S whose status
changes along the rate grid spoils the slope of σ_T's Cauchy differences, and the script's
control (the differences without that node) recovers the rate the other nodes follow.

    /usr/bin/python3 tests/test_status_change_control.py
"""

import os
import re
import subprocess
import sys
import tempfile
import unittest

import h5py
import numpy as np

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts", "status_change_control.py")


def write_file(path, jump_node=True):
    """Case g on a 5-point rate grid: σ_T on S+ = 0.3 ε^0.5 along a flank away from the corners;
    node 5 (if `jump_node`) changes status between the 2nd and 3rd thickness and its stress jumps."""
    eps = 10.0 ** (-np.arange(8, 13) / 2)
    x = np.column_stack([np.linspace(0.45, 0.55, 11), np.linspace(-0.12, -0.38, 11)])  # right flank, away
    with h5py.File(path, "w") as f:
        c = f.create_group("studies/convergence/g/cauchy")
        c["eps"], c["converged"] = eps, np.ones(len(eps), np.int32)
        for k, e in enumerate(eps):
            g = f.create_group(f"scenes/dovetail-layer-g-eps{e:g}-h0.025-fast")
            g.attrs.update(dict(mode="layer", law_case="g", eps=e))
            sigma_t = 0.3 * np.sqrt(e) * np.ones(len(x))
            status = np.full(len(x), 2, np.int32)
            if jump_node and k >= 2:
                sigma_t[5] += 0.05  # the node slides from the third thickness on
                status[5] = 1
            g["interface/S+/x"], g["interface/S+/sigma_T"] = x, sigma_t
            g["interface/S+/sigma_N"] = -np.ones(len(x))
            g["combined_status"] = status


def run(path):
    return subprocess.run([sys.executable, SCRIPT, path, "g"], capture_output=True, text=True, timeout=60)


def slopes(stdout):
    return [float(v) for v in re.findall(r"slope on the tail, [^:]*: ([-0-9.]+)", stdout)]


class StatusChangeControlTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory(prefix="test_status_change-")
        self.path = os.path.join(self.tmp.name, "results.h5")

    def tearDown(self):
        self.tmp.cleanup()

    def test_the_changing_node_spoils_the_slope_and_the_control_recovers_it(self):
        write_file(self.path)
        r = run(self.path)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("status of S node(s) [5] changes", r.stdout)
        all_nodes, settled = slopes(r.stdout)
        self.assertGreater(abs(all_nodes - 0.5), 0.15)  # the jump is not a power law of ε
        self.assertAlmostEqual(settled, 0.5, places=6)

    def test_without_a_change_both_slopes_are_the_rate(self):
        write_file(self.path, jump_node=False)
        r = run(self.path)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertNotIn("changes", r.stdout.split("case g")[0])
        for p in slopes(r.stdout):
            self.assertAlmostEqual(p, 0.5, places=6)

    def test_a_file_without_the_rate_study_is_refused(self):
        with h5py.File(self.path, "w") as f:
            f.create_group("scenes")
        r = run(self.path)
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("no /studies/convergence/g/cauchy", r.stderr)


if __name__ == "__main__":
    unittest.main()

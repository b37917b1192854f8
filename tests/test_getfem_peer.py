#!/usr/bin/python3
"""scripts/getfem_peer.py's --starts: `both`, as its help offers, runs GetFEM from rest and from the
bonded solve on the same exported problem (it ended in a KeyError, `samples["both"]`); a start it
does not know is refused in one line, exit 2, before anything is exported.

    /usr/bin/python3 tests/test_getfem_peer.py EXPORTER SCENE

EXPORTER is build/thinlayer_export_problem, SCENE the friction-held lap (cases/friction_lap).
"""

import os
import re
import subprocess
import sys
import tempfile
import unittest

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts", "getfem_peer.py")
EXPORTER, SCENE = None, None


def peer(*arguments, workdir=None):
    command = [sys.executable, SCRIPT, "--exporter", EXPORTER, "--scene", SCENE, "--sizes", "1",
               "--repeat", "1", *arguments]
    if workdir:
        command += ["--workdir", workdir]
    return subprocess.run(command, capture_output=True, text=True, timeout=600)


class StartsTest(unittest.TestCase):
    def test_both_runs_each_start_once_and_the_check_still_judges_the_bonded_one(self):
        r = peer("--starts", "both", "--check")
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertNotIn("Traceback", r.stderr)
        # One line per start, in the order of `rest,bonded`, each judged by thinlayer's SPEC residual.
        starts = re.findall(r"^  GetFEM from (\w+): .*SPEC residual \S+", r.stdout, re.M)
        self.assertEqual(starts, ["rest", "bonded"], r.stdout)
        self.assertIn("CHECK PASSED", r.stdout)

    def test_an_unknown_start_is_one_line_and_exit_2_with_nothing_exported(self):
        with tempfile.TemporaryDirectory(prefix="test_getfem_peer-") as workdir:
            for value in ("sideways", "rest,", "rest,both,x"):
                with self.subTest(value=value):
                    r = peer("--starts", value, workdir=workdir)
                    self.assertEqual(r.returncode, 2, r.stdout + r.stderr)
                    self.assertEqual(r.stdout, "")
                    errors = [l for l in r.stderr.splitlines() if l.startswith("getfem_peer.py: error:")]
                    self.assertEqual(len(errors), 1, r.stderr)
                    self.assertIn("expected rest, bonded or both", errors[0])
                    self.assertEqual(os.listdir(workdir), [])


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit("usage: test_getfem_peer.py EXPORTER SCENE")
    EXPORTER, SCENE = sys.argv[1], sys.argv[2]
    unittest.main(argv=sys.argv[:1])

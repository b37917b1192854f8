"""A command run in its own session, and what of it is left afterwards (the hostile matrices,
tests/test_hostile_inputs.py and tests/test_scene_inputs.py: no process of a run may outlive it)."""

import os
import subprocess
import time


def session_processes(session):
    """The processes still alive in a session (a run's children, if any survived it)."""
    alive = []
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            with open(f"/proc/{pid}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[3]) == session and fields[0] != "Z":
            alive.append(int(pid))
    return alive


def run_in_session(argv, cwd, timeout=120, env=None, preexec=None):
    """Runs argv in its own session (with `env`, and `preexec` run in the child before it starts);
    returns the completed process and the session's survivors."""
    p = subprocess.Popen(argv, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         start_new_session=True, env=env, preexec_fn=preexec)
    out, err = p.communicate(timeout=timeout)
    time.sleep(0.05)
    return subprocess.CompletedProcess(argv, p.returncode, out, err), session_processes(p.pid)

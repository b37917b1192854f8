#!/usr/bin/python3
"""The thinlayer verification report: an HTML page with figures, read only from a results file.

    /usr/bin/python3 report/make_report.py RESULTS.h5 OUT_DIR [--time-limit SECONDS]
    /usr/bin/python3 report/make_report.py --check-folder OUT_DIR

writes OUT_DIR/index.html and OUT_DIR/figures/*.png, and nothing else (build_report.py says how).
With --check-folder it writes nothing: it says whether OUT_DIR would be refused (report_folder.py),
so that `thinlayer` refuses it before a study's work, not after.

A results file handed to the report is untrusted input (SPEC §4): a damaged one has crashed
HDF5 inside h5py (a signal, which no Python code can catch) or kept it looping. So this command
reads nothing itself: it runs build_report.py in a process of its own and waits for it, at most
--time-limit seconds (default 1800: the verification report takes about a minute). When that
process ends by a crash or runs out of time, this one says so in one line, removes the
half-built report it left (its `.report-building-<pid>-*` folder, and OUT_DIR if the run made it
and it holds nothing else), and exits with status 2. On SIGINT, SIGTERM or SIGHUP it ends that
process at once (SIGKILL), removes the same, and dies of the same signal.
"""

import os
import shutil
import signal
import subprocess
import sys

BUILDER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "build_report.py")
USAGE = "usage: make_report.py RESULTS.h5 OUT_DIR [--time-limit SECONDS] | --check-folder OUT_DIR"
EXIT_BAD_INPUT = 2
DEFAULT_TIME_LIMIT_S = 1800.0


def time_limit(argv):
    """(the arguments for the builder, the time limit in seconds): --time-limit S is ours."""
    args, limit = [], DEFAULT_TIME_LIMIT_S
    k = 0
    while k < len(argv):
        if argv[k] == "--time-limit":
            if k + 1 == len(argv):
                raise ValueError("--time-limit needs a number of seconds")
            try:
                limit = float(argv[k + 1])
            except ValueError:
                raise ValueError(f"--time-limit: not a number: {argv[k + 1]!r}") from None
            if not 0 < limit <= 1e6:
                raise ValueError(f"--time-limit must be in (0, 1e6] seconds, got {argv[k + 1]}")
            k += 2
            continue
        args.append(argv[k])
        k += 1
    return args, limit


def remove_leftovers(child_pid, out_dir, made_out_dir):
    """What a builder that could not clean up left: its half-built report, and OUT_DIR if this run
    made it and nothing else is in it."""
    if not out_dir or not os.path.isdir(out_dir):
        return
    prefix = f".report-building-{child_pid}-"
    for name in os.listdir(out_dir):
        if name.startswith(prefix):
            shutil.rmtree(os.path.join(out_dir, name), ignore_errors=True)
    if made_out_dir:
        try:
            os.rmdir(out_dir)  # only if empty: never a file of the user's
        except OSError:
            pass


def check_folder_only(argv):
    """--check-folder OUT_DIR: exit 0 if a report may be written there, else one line and exit 2."""
    sys.dont_write_bytecode = True
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from report_folder import FolderError, check_folder
    if len(argv) != 3:
        print(f"make_report: --check-folder takes one folder; {USAGE}", file=sys.stderr)
        return EXIT_BAD_INPUT
    try:
        check_folder(argv[2])
    except FolderError as e:
        print(f"make_report: {e}", file=sys.stderr)
        return EXIT_BAD_INPUT
    return 0


def main(argv):
    if len(argv) >= 2 and argv[1] == "--check-folder":
        return check_folder_only(argv)
    try:
        args, limit = time_limit(argv[1:])
    except ValueError as e:
        print(f"make_report: {e}; {USAGE}", file=sys.stderr)
        return EXIT_BAD_INPUT
    results = args[0] if args else ""
    out_dir = os.path.abspath(args[1]) if len(args) == 2 and args[0] not in ("-h", "--help") else None
    made_out_dir = out_dir is not None and not os.path.lexists(out_dir)
    # Its own process group: whatever it starts (the report's helper process) can be ended with it.
    child = subprocess.Popen([sys.executable, BUILDER, *args], process_group=0)
    interrupted = []

    # The builder (and its helper) end at once, wherever they are: a signal turned into an exception
    # inside matplotlib left it half-way and came out as a section's AttributeError. What they left
    # is removed here, then this process dies of the same signal.
    def stop(signum, _frame):
        interrupted.append(signum)
        try:
            os.killpg(child.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass

    for signum in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        signal.signal(signum, stop)
    try:
        status = child.wait(timeout=limit)
        timed_out = False
    except subprocess.TimeoutExpired:
        timed_out = True
        status = None
    if timed_out or (status is not None and status < 0):
        try:
            os.killpg(child.pid, signal.SIGKILL)  # the builder and any helper it left
        except ProcessLookupError:
            pass
        child.wait()
        remove_leftovers(child.pid, out_dir, made_out_dir)
    if interrupted:  # die of the same signal, as the caller expects
        signal.signal(interrupted[0], signal.SIG_DFL)
        os.kill(os.getpid(), interrupted[0])
    if timed_out:
        print(f"make_report: {results}: the report did not finish within {limit:g} s (--time-limit): a damaged "
              f"results file? Nothing written", file=sys.stderr)
        return EXIT_BAD_INPUT
    if status < 0:
        name = signal.Signals(-status).name if -status in signal.valid_signals() else f"signal {-status}"
        print(f"make_report: {results}: reading it crashed the report ({name}): a damaged results file? "
              f"Nothing written", file=sys.stderr)
        return EXIT_BAD_INPUT
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv))

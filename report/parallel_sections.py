"""Sections rendered in a second process, beside the main one: `verify` ends with the report on a
machine whose two cores are then idle, and section 5 (a figure per dovetail case) takes about as
long as the sections after it together. The helper process opens the results file itself (an
HDF5 handle is not shared across processes), renders its sections into the same folder (their
figures have their own names) and sends back their HTML."""

import multiprocessing

from checks import load_checks
from context import Context
from plotting import FigureWriter
from results_file import open_results
from scenes import index_scenes


def render_sections(results_path, out_dir, renders):
    """(the HTML of each (label, render) in `renders`, None), or (None, (label, error)) for the
    first section that fails."""
    with open_results(results_path) as f:
        ctx = Context(path=results_path, f=f, scenes=index_scenes(f), checks=load_checks(f),
                      figures=FigureWriter(out_dir))
        parts = []
        for label, render in renders:
            try:
                parts.append(render(ctx))
            except Exception as e:  # the parent names the section, as it does for its own
                return None, (label, f"{type(e).__name__}: {e}")
        return parts, None


def _run(sender, results_path, out_dir, renders):
    sender.send(render_sections(results_path, out_dir, renders))
    sender.close()


def start(results_path, out_dir, renders):
    """Starts the helper in a fresh interpreter ('spawn': nothing of this process's HDF5 or
    matplotlib state is inherited); returns (process, receiving end of its pipe)."""
    context = multiprocessing.get_context("spawn")
    receiver, sender = context.Pipe(duplex=False)
    process = context.Process(target=_run, args=(sender, results_path, out_dir, renders), daemon=True)
    process.start()
    sender.close()
    return process, receiver


def finish(process, receiver):
    """The helper's (parts, error); a helper that died without answering is an error too."""
    try:
        result = receiver.recv()
    except EOFError:
        result = None, ("helper process", f"exited with status {process.exitcode} before answering")
    process.join()
    return result


def stop(process):
    """Ends the helper if it still runs (an error or a signal in the main process)."""
    if process.is_alive():
        process.terminate()
    process.join()

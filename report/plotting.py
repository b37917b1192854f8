"""matplotlib set-up shared by every figure: the headless backend, one colour per contact
status, status bands and strips, and saving a figure into the report's figures/ folder."""

import os

import matplotlib

matplotlib.use("Agg")  # headless: the report runs on build machines without a display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402
from matplotlib.ticker import LogFormatterSciNotation  # noqa: E402

from html_parts import figure  # noqa: E402

# Status codes of SPEC §4: 0 gap, 1 slide, 2 stick. Colours chosen to stay distinct in grey
# and for red-green colour blindness (pass/fail red and green are kept for the checks).
STATUS_NAMES = ("gap", "slide", "stick")
STATUS_COLORS = ("#d9d9d9", "#f6a04d", "#4a7fc1")
STATUS_CMAP = ListedColormap(STATUS_COLORS)

plt.rcParams.update({"figure.dpi": 100, "savefig.dpi": 100, "font.size": 9,
                     "axes.grid": True, "grid.alpha": 0.3})


def status_legend(ax, **kwargs):
    handles = [Patch(facecolor=c, edgecolor="#888", label=n) for n, c in zip(STATUS_NAMES, STATUS_COLORS)]
    return ax.legend(handles=handles, **kwargs)


def label_minor_log_ticks(ax):
    """Label some minor ticks of log axes spanning up to two decades: matplotlib's default
    labels only powers of ten there, which can leave an axis with a single number."""
    for axis in (ax.xaxis, ax.yaxis):
        if axis.get_scale() == "log":
            axis.set_minor_formatter(LogFormatterSciNotation(labelOnlyBase=False, minor_thresholds=(2, 1.2)))


def cell_edges(s):
    """Edges of the spans that the points `s` (sorted positions) stand for: the midpoints
    between neighbours, and half a spacing beyond the ends."""
    s = np.asarray(s, dtype=float)
    if len(s) == 1:
        return np.array([s[0] - 0.5, s[0] + 0.5])
    mid = 0.5 * (s[1:] + s[:-1])
    return np.concatenate([[s[0] - (mid[0] - s[0])], mid, [s[-1] + (s[-1] - mid[-1])]])


def status_bands(ax, s, status, alpha=0.45):
    """Colour the background of `ax` by the status of the node nearest to each abscissa."""
    edges = cell_edges(s)
    for k, st in enumerate(np.asarray(status, dtype=int)):
        if 0 <= st <= 2:
            ax.axvspan(edges[k], edges[k + 1], color=STATUS_COLORS[st], alpha=alpha, lw=0, zorder=0)


def status_strip(ax, rows, labels, reference=0):
    """One horizontal strip per (positions, statuses) pair of `rows`, top to bottom. Nodes
    whose status differs from the row `reference` (same node count) get a black dot, so a
    few differing nodes among many stay visible."""
    ref_status = np.asarray(rows[reference][1]) if rows else None
    for i, (s, status) in enumerate(rows):
        edges = cell_edges(s)
        status = np.asarray(status)
        ax.pcolormesh(edges, [i - 0.4, i + 0.4], status.astype(float)[None, :], cmap=STATUS_CMAP,
                      vmin=-0.5, vmax=2.5, shading="flat")
        if i != reference and len(status) == len(ref_status):
            differ = np.flatnonzero(status != ref_status)
            ax.plot(np.asarray(s)[differ], np.full(len(differ), i), "k.", ms=5)
    ax.set_yticks(range(len(rows)))
    ax.set_yticklabels(labels)
    ax.set_ylim(len(rows) - 0.5, -0.5)
    ax.grid(False)


class FigureWriter:
    """Saves figures as figures/<name>.png under the report being built and returns the
    <figure> HTML that shows them."""

    def __init__(self, out_dir):
        self.out_dir = out_dir
        self.fig_dir = os.path.join(out_dir, "figures")
        os.makedirs(self.fig_dir, exist_ok=True)

    def save(self, fig, name, alt, caption_html=""):
        path = os.path.join(self.fig_dir, name + ".png")
        fig.savefig(path)  # every figure calls tight_layout, which keeps legends and labels inside
        plt.close(fig)
        return figure("figures/" + name + ".png", alt, caption_html)

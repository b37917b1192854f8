"""What every section of the report is given: the open results file, its scene index, its
checks and the writer of figures."""

from dataclasses import dataclass

import h5py

from plotting import FigureWriter


@dataclass
class Context:
    path: str                 # the results file, as given on the command line
    f: h5py.File              # open read-only
    scenes: list              # scenes.Scene for every /scenes/<id>, attributes only
    checks: list              # checks.Check for every stored check, or None without /checks
    figures: FigureWriter     # saves figures/<name>.png into the report being built

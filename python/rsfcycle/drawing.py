# SPDX-License-Identifier: LGPL-2.1-or-later
"""What every figure of the package shares: Matplotlib without a display,
the run folder's profile and series as the figures read them, entries of
parameters.prm, the event window a figure shows, saving a figure
(rsfcycle.plot and rsfcycle.wedge_plots draw with them)."""

import math

from rsfcycle import run

UM = 1e6  # m -> micrometres


def _pyplot():
    """matplotlib.pyplot with the Agg backend."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


Profile = run.Profile


def profile(folder):
    """base-profile.csv of a run folder as a Profile (run.base_profile)."""
    return run.base_profile(folder)


def series(folder):
    """time-series.csv as a dict column -> numpy array; a last row cut
    short (a file being written) is left out."""
    table = run.time_series(folder)
    table = table.dropna(subset=[table.columns[-1]])
    if table.empty:
        raise ValueError(f"{folder}/time-series.csv: no complete row")
    return {name: table[name].to_numpy(float) for name in table.columns}


def number(parameters, key, default):
    """A float entry of parameters (run.parameters), `default` where it is
    absent or not a number."""
    try:
        return float(parameters[key])
    except (KeyError, ValueError):
        return default


def plate_rate(parameters):
    """v0 [m/s]: Wedge/Convergence rate, |Mesh file/Load velocity| or
    Spring slider/Load point velocity, whichever the scene uses."""
    scene = parameters.get("Scene", "wedge")
    if scene == "mesh-file" and "Mesh file/Load velocity" in parameters:
        parts = [float(x) for x in
                 parameters["Mesh file/Load velocity"].split(",")]
        return math.hypot(*parts)
    if scene == "spring-slider":
        return number(parameters, "Spring slider/Load point velocity", 1e-6)
    return number(parameters, "Wedge/Convergence rate", 50e-6)


def kind(parameters):
    """Which figures a run gets: 'wedge-2d', 'wedge-3d' or 'cycles'."""
    if parameters.get("Scene", "wedge") == "wedge":
        return "wedge-3d" if parameters.get("Dimension", "2").strip() == "3" \
            else "wedge-2d"
    return "cycles"


def savefig(fig, path, dpi=130):
    """Write a figure, close it and say so."""
    fig.savefig(path, dpi=dpi)
    _pyplot().close(fig)
    print("wrote", path)
    return path


def event_window(events, t_last, n, pad=None):
    """((t0, t1), the events) around the last n events that ended by
    t_last, padded by half their median recurrence; (None, []) without a
    complete event."""
    import numpy as np
    done = [e for e in events if math.isfinite(e.end) and e.end <= t_last]
    if not done:
        return None, []
    shown = done[-n:]
    recurrences = [e.recurrence for e in shown if math.isfinite(e.recurrence)]
    if pad is None:
        pad = 0.5 * (float(np.median(recurrences)) if recurrences else 1.0)
    return (shown[0].start - pad, min(shown[-1].end + pad, t_last)), shown

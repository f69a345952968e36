"""Figures of runs compared (`slipfront-client compare`) beside the velocity and speed
figures: the slip fronts overlaid (arrival time against x1, as the front line of the map),
and one parameter against one metric, a point per run — each run in its colour and its
method's line style and marker (common.METHOD_STYLES), named by its legend text
(compare.compare_labels)."""

import numpy as np

from .common import colours, method_style, new_figure


def plot_fronts(results, labels, title=None):
    fig, ax = new_figure()
    data = {}
    for colour, result, label in zip(colours(len(results)), results, labels):
        known = np.isfinite(result.arrival_time)
        order = np.argsort(result.front_x1[known])
        x, t = result.front_x1[known][order], result.arrival_time[known][order]
        data[label] = {"x1": x, "arrival_time": t}
        style = method_style(result.spec, result.metrics)
        ax.plot(x, t, color=colour, lw=1.2, ls=style["ls"], label=label)
    ax.set_xlabel("x1 [m]")
    ax.set_ylabel("arrival time of the front [s]")
    ax.set_title(title or "Slip front")
    if ax.lines:
        ax.legend(fontsize="small", loc="upper left")
    return fig, data


def _log_scale(values):
    """A log axis for positive numbers spanning more than a decade and a half."""
    v = [x for x in values if isinstance(x, (int, float))]
    return len(v) > 1 and min(v) > 0 and max(v) / min(v) > 30


def plot_scatter(jobs, labels, xs, ys, x_name, y_name, title=None):
    """One point per job (its JSON: the method from its spec) at (xs[i], ys[i]); jobs with
    None in either are left out. Text values on x (the method) are categories."""
    fig, ax = new_figure()
    data = {}
    drawn = [(c, j, lab, x, y) for c, j, lab, x, y in
             zip(colours(len(jobs)), jobs, labels, xs, ys) if x is not None and y is not None]
    categories = sorted({str(x) for *_, x, _ in drawn if isinstance(x, str)})
    for colour, job, label, x, y in drawn:
        at = categories.index(x) if isinstance(x, str) else x
        data[label] = {"x": x, "y": y}
        style = method_style(job.get("spec"), job.get("metrics"))
        ax.plot([at], [y], ls="none", marker=style["marker"], ms=9, color=colour,
                markeredgecolor="#1d2733", label=label)
    if categories:
        ax.set_xticks(range(len(categories)), categories)
        ax.set_xlim(-0.5, len(categories) - 0.5)
    elif _log_scale([x for *_, x, _ in drawn]):
        ax.set_xscale("log")
    if _log_scale([y for *_, y in drawn]):
        ax.set_yscale("log")
    ax.set_xlabel(x_name)
    ax.set_ylabel(y_name)
    ax.set_title(title or f"{y_name} against {x_name}")
    if drawn:
        ax.legend(fontsize="small")
    else:
        ax.text(0.5, 0.5, "no run has both values", transform=ax.transAxes, ha="center")
    return fig, data

"""Figure output shared by the plots: a headless backend, a consistent look, and saving
one figure in several formats."""

import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from ..errors import UsageError  # noqa: E402

FORMATS = ("png", "pdf", "svg")


def parse_formats(text):
    """'png,pdf' -> ['png', 'pdf']; UsageError for anything else."""
    formats = [f.strip().lower() for f in text.split(",") if f.strip()]
    bad = [f for f in formats if f not in FORMATS]
    if bad or not formats:
        raise UsageError(f"--format {text!r}: choose from {', '.join(FORMATS)} (comma-separated)")
    return formats


def new_figure(width=6.4, height=4.2, ncols=None):
    """A figure and its axes: one axes, or with `ncols` a list of that many side by side."""
    fig, ax = plt.subplots(1, ncols or 1, figsize=(width, height), constrained_layout=True,
                           squeeze=False)
    return fig, (list(ax[0]) if ncols else ax[0][0])


def colours(n, cmap="viridis"):
    """n distinguishable colours (dark to light, as the paper's colour ramps)."""
    cm = plt.get_cmap(cmap)
    return [cm(0.85 * i / max(n - 1, 1)) for i in range(n)]


# One line style and marker per method, so that FE and BI runs of one scene overlaid read apart
# at a glance (their labels say the method too; the web view uses the same: run_labels.js).
METHOD_STYLES = {"fe": {"ls": "-", "marker": "o"}, "spectral_bi": {"ls": "--", "marker": "s"}}


def method_style(spec, metrics=None):
    """{ls, marker} of a run's method (its spec's, else its metrics', else FE)."""
    method = (spec or {}).get("method") or (metrics or {}).get("method") or "fe"
    return METHOD_STYLES.get(method, METHOD_STYLES["fe"])


def save_figure(fig, out_dir, stem, formats, dpi=150):
    """Write `out_dir/stem.<fmt>` for every format; return the paths; close the figure."""
    os.makedirs(out_dir, exist_ok=True)
    paths = []
    for fmt in formats:
        path = os.path.join(out_dir, f"{stem}.{fmt}")
        fig.savefig(path, dpi=dpi)
        paths.append(path)
    plt.close(fig)
    return paths

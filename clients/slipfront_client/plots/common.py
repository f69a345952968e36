"""Figure output shared by the plots: a headless backend, a consistent look, and saving
one figure in several formats."""

import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from .. import methods  # noqa: E402
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


def ramp(n, cmap="Blues"):
    """n colours light to dark, the lightest still readable on white (the paper's ramps)."""
    cm = plt.get_cmap(cmap)
    return [cm(0.35 + 0.65 * i / max(n - 1, 1)) for i in range(n)]


def clip_speed_axis(ax, c_p):
    """Rupture-speed axes from 0 to a little above c_p: the nucleation patch's V_r (the
    front jumps across it at once) would otherwise flatten the rest of the curve."""
    ax.set_ylim(0, 1.2 * c_p)


def method_style(spec, metrics=None):
    """{ls, marker} of a run's method (its spec's, else its metrics', else the default), so
    that FE and BI runs of one scene overlaid read apart at a glance (their labels say the
    method too; the styles are methods.STYLES, as the web view's methods.js)."""
    method = (spec or {}).get("method") or (metrics or {}).get("method") or methods.default()
    style = methods.style(method) or methods.style(methods.default())
    return {"ls": style["ls"], "marker": style["marker"]}


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

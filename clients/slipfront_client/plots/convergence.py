"""(d) The convergence map in the L–n_d plane (paper Fig. 3c, 4c): one marker per run,
by convergence status (converged, not_converged, diverged, pending, unknown).

Accepted inputs (`points_from_json`): a list of {L, n_d, status}, or an object holding
such a list under `points`, `runs`, `cells`, `jobs` or `map` (the server's
GET /convergence-map); the status may also be called `convergence`, and L / n_d may sit
in a nested `spec` (friction.L, geometry.nodes_per_meter).
"""

import math

from ..errors import UsageError
from .common import new_figure

MARKERS = {
    "converged": dict(marker="o", color="tab:green", fillstyle="full"),
    "not_converged": dict(marker="X", color="tab:red", fillstyle="full"),
    "diverged": dict(marker="v", color="black", fillstyle="full"),
    "pending": dict(marker="s", color="tab:blue", fillstyle="none"),
    "unknown": dict(marker="o", color="grey", fillstyle="none"),
    "failed": dict(marker="x", color="grey", fillstyle="full"),  # the server's: no measurement
}
LIST_KEYS = ("points", "runs", "cells", "jobs", "map")


def _point(item, where):
    if not isinstance(item, dict):
        raise UsageError(f"{where}: expected an object with L, n_d and status, got {item!r}")
    spec = item.get("spec") or {}
    L = item.get("L", (spec.get("friction") or {}).get("L"))
    n_d = item.get("n_d", item.get("nodes_per_meter",
                                    (spec.get("geometry") or {}).get("nodes_per_meter")))
    status = item.get("convergence", item.get("status", "unknown"))
    if isinstance(status, dict):  # e.g. {"status": "converged", ...}
        status = status.get("status", "unknown")
    if L is None or n_d is None:
        raise UsageError(f"{where}: needs L and n_d, got {item!r}")
    if status not in MARKERS:
        status = "unknown"
    return {"L": float(L), "n_d": float(n_d), "status": status}


def points_from_json(doc, where="convergence map"):
    """Normalise a convergence-map document to [{L, n_d, status}]."""
    items = doc
    if isinstance(doc, dict):
        for key in LIST_KEYS:
            if isinstance(doc.get(key), list):
                items = doc[key]
                break
        else:
            raise UsageError(f"{where}: no list of points under any of {', '.join(LIST_KEYS)}")
    if not isinstance(items, list):
        raise UsageError(f"{where}: expected a list of {{L, n_d, status}}")
    return [_point(item, f"{where}[{i}]") for i, item in enumerate(items)]


def length_text(L):
    """1e-4 -> "1e-4", 5e-05 -> "5e-5", 0.5 -> "0.5": one style for every tick."""
    if L <= 0 or 1e-2 <= L < 1e3:
        return f"{L:g}"
    mantissa, exponent = f"{L:.3e}".split("e")
    return f"{float(mantissa):g}e{int(exponent)}"


def plot_convergence(points, critical_length=None, title=None):
    """Markers by status on log L (vertical) against n_d (horizontal, log); ticks at the
    meshes and lengths run, every marker inside the frame, the legend beside the axes."""
    if not points:
        raise UsageError("convergence map: no runs to draw")
    fig, ax = new_figure(7.2, 4.4)
    data = {s: [] for s in MARKERS}
    for p in points:
        data[p["status"]].append((p["n_d"], p["L"]))
    for status, xy in data.items():
        if xy:
            xs, ys = zip(*xy)
            ax.plot(xs, ys, ls="none", ms=8, label=status.replace("_", " "), **MARKERS[status],
                    clip_on=False)
    ax.set_xscale("log")
    ax.set_yscale("log")
    meshes = sorted({float(p["n_d"]) for p in points})  # ticks at the meshes run, as numbers
    lengths = sorted({float(p["L"]) for p in points})
    # Half a mesh step (a factor 2 ladder: sqrt 2) of margin around the outer markers.
    ax.set_xlim(meshes[0] / 1.45, meshes[-1] * 1.45)
    ax.set_ylim(lengths[0] / 1.6, lengths[-1] * 1.6)
    ax.set_xticks(meshes, [f"{n:g}" for n in meshes])
    ax.set_xticks([], minor=True)
    ax.set_yticks(lengths, [length_text(L) for L in lengths])
    ax.set_yticks([], minor=True)
    ax.grid(True, which="major", color="0.9", lw=0.6)
    ax.set_axisbelow(True)
    if critical_length and math.isfinite(critical_length):
        ax.axhline(critical_length, color="black", ls=":", lw=1,
                   label=f"L_c = {length_text(critical_length)} m")
    ax.set_xlabel("n_d [nodes/m]")
    ax.set_ylabel("L [m]")
    ax.set_title(title or "Convergence map")
    ax.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0)
    data["meshes"], data["lengths"] = meshes, lengths
    return fig, data

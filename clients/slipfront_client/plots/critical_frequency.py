"""The critical length against the event's highest frequency (paper Fig. 6, from runs): the
filter rule L_c(f) = (V* + |V|) / (2 pi f) * sqrt(1/0.98^2 - 1) (eq. 6 with A/A0 = 0.98,
docs/metrics.md "Spectral estimate"), and each run's (spectral_frequency,
spectral_critical_length); the L search's L_c and the paper's 1e-5 m as horizontal lines."""

import numpy as np

from .common import new_figure, ramp

ATTENUATION = 0.98


def critical_length(f, v_star, slip_velocity):
    """The largest L whose filter keeps A/A0 >= 0.98 at frequency f (eq. 6 solved for L)."""
    return (v_star + slip_velocity) / (2 * np.pi * np.asarray(f)) * np.sqrt(
        1 / ATTENUATION ** 2 - 1)


def plot_critical_frequency(points, L_c=None, paper_L_c=1e-5, v_star=1e-4, title=None):
    """`points`: [(label, L, f, spectral L_c, |V|)] of each run."""
    fig, ax = new_figure(6.4, 4.4)
    data = {"points": points}
    if points:
        fs = [p[2] for p in points]
        f = np.logspace(np.log10(min(fs) / 3), np.log10(max(fs) * 3), 200)
        v = float(np.median([p[4] for p in points]))
        ax.loglog(f, critical_length(f, v_star, v), color="grey",
                  label=f"L_c(f), A/A0 = {ATTENUATION:g}, |V| = {v:.3g} m/s")
        top = 30 * max([p[3] for p in points] + [L_c or 0, paper_L_c])
        ax.fill_between(f, critical_length(f, v_star, v), top, color="grey", alpha=0.12,
                        label="L > L_c(f): L acts on the event")
        for colour, (label, L, fr, lc, _) in zip(ramp(len(points), "viridis_r"), points):
            ax.plot([fr], [lc], "o", color=colour, label=label)
    if L_c:
        ax.axhline(L_c, color="C3", lw=1.4, label=f"L search: L_c = {L_c:g} m")
    ax.axhline(paper_L_c, color="C1", ls="--", lw=1.0, label=f"paper: L_c ≈ {paper_L_c:g} m")
    bottom = min([p[3] for p in points] + [L_c or paper_L_c, paper_L_c]) / 10
    ax.set_ylim(bottom, top if points else paper_L_c * 100)
    ax.set_xlabel("highest frequency of the event f (99 % of τ_s power at x1 = 6 m) [Hz]")
    ax.set_ylabel("L [m]")
    ax.set_title(title or "Critical length against the event's frequency")
    ax.legend(fontsize="x-small", loc="lower left")
    return fig, data

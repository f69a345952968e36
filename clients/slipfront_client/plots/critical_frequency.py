"""The critical length against the event's highest frequency (paper Fig. 6, from runs): the
filter rule L_c(f) = (V* + |V|) / (2 pi f) * sqrt(1/0.98^2 - 1) (eq. 6 with A/A0 = 0.98,
docs/metrics.md "Spectral estimate"), and each run's (spectral_frequency,
spectral_critical_length); the L search's L_c and the paper's 1e-5 m as horizontal lines,
each with a star where it meets the rule: the frequency the event must hold for that L_c. Given
`halves`, each run's measured filter: the frequency above which its tau_s amplitude at x1 = 6 m
stays below half that of the plain-Coulomb run (×), beside eq. 6 at A/A0 = 1/2 (dotted) and
the records' Nyquist frequency."""

import numpy as np

from .common import new_figure, ramp

ATTENUATION = 0.98


def critical_length(f, v_star, slip_velocity, attenuation=ATTENUATION):
    """The largest L whose filter keeps A/A0 >= `attenuation` at frequency f (eq. 6 solved
    for L)."""
    return (v_star + slip_velocity) / (2 * np.pi * np.asarray(f)) * np.sqrt(
        1 / attenuation ** 2 - 1)


def frequency_of(L, v_star, slip_velocity):
    """The frequency at which the rule gives `L` (the inverse of critical_length)."""
    return float(critical_length(1.0, v_star, slip_velocity)) / L


def plot_critical_frequency(points, L_c=None, paper_L_c=1e-5, v_star=1e-4, title=None,
                            halves=(), nyquist=None):
    """`points`: [(label, L, f, spectral L_c, |V|)] of each run; `halves`: [(label, L,
    f_half)], the measured half-amplitude frequency of each run against plain Coulomb
    (None where it stays above half up to `nyquist`)."""
    fig, ax = new_figure(8.6, 4.6)
    data = {"points": points, "stars": {}, "halves": list(halves)}
    v = float(np.median([p[4] for p in points])) if points else 3e-3
    lines = [(L, name, colour, ls) for L, name, colour, ls in
             ((L_c, "L search: L_c", "C3", "-"), (paper_L_c, "paper: L_c ≈", "C1", "--")) if L]
    for L, _, _, _ in lines:
        data["stars"][L] = frequency_of(L, v_star, v)
    fs = ([p[2] for p in points] + list(data["stars"].values())
          + [h[2] for h in halves if h[2]] + ([nyquist] if nyquist else []))
    f = np.logspace(np.log10(min(fs) / 3), np.log10(max(fs) * 3), 200)
    top = 30 * max([p[3] for p in points] + [L for L, *_ in lines])
    ax.loglog(f, critical_length(f, v_star, v), color="grey",
              label=f"rule L_c(f): A/A0 = {ATTENUATION:g} at f, |V| = {v:.3g} m/s")
    ax.fill_between(f, critical_length(f, v_star, v), top, color="grey", alpha=0.12,
                    label="L > L_c(f): L acts on the event")
    colours = dict(zip([p[1] for p in points], ramp(len(points), "viridis_r")))
    for label, L, fr, lc, _ in points:
        ax.plot([fr], [lc], "o", color=colours[L], label=label)
    found = [h for h in halves if h[2]]
    if halves:
        ax.loglog(f, critical_length(f, v_star, v, 0.5), color="grey", ls=":",
                  label="eq. 6 at A/A0 = 1/2")
    for i, (label, L, fr) in enumerate(found):
        ax.plot([fr], [L], "x", ms=9, mew=2, color=colours.get(L, "k"),
                label="× measured: τ_s amplitude below ½ of Coulomb's above f" if i == 0 else None)
    if halves and nyquist:
        ax.axvline(nyquist, color="k", lw=0.8, ls="-.",
                   label=f"records' Nyquist {nyquist:.3g} Hz ({len(halves) - len(found)} runs "
                   "never below ½ up to it)")
    for L, name, colour, ls in lines:
        ax.axhline(L, color=colour, ls=ls, lw=1.2, label=f"{name} {L:g} m")
        ax.plot([data["stars"][L]], [L], "*", ms=12, color=colour,
                label=f"  needs f = {data['stars'][L]:.3g} Hz")
    ax.set_ylim(min(L for L, *_ in lines + [(paper_L_c,)]) / 10, top)
    ax.set_xlabel("highest frequency of the event f [Hz] (dots: 99 % of the τ_s power at "
                  "x1 = 6 m)")
    ax.set_ylabel("L [m]")
    ax.set_title(title or "Critical length against the event's frequency")
    ax.legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.01, 1.0))
    return fig, data

"""The frictional strength and its spectrum (paper Fig. 5a, 5c, with the record's spectrum
in place of the paper's periodic test signal 5b): (a) tau_s at x1 = 6 m of the mesh-converged
run of each L; (b) its power spectrum, computed as the spectral estimate of docs/metrics.md
does (end-point line removed, Hann window); (c) the friction filter A/A0 of eq. 6 for each L,
with the meshes' highest eigenfrequencies as dashed vertical lines."""

import numpy as np
import matplotlib.pyplot as plt

from .common import ramp
from .filter_response import amplitude_ratio


def strength_at(result, x1):
    """(time, tau_s) at the interface node nearest `x1`."""
    node = int(np.argmin(np.abs(result.x1 - x1)))
    return result.time, result.strength[:, node]


def power_spectrum(t, signal):
    """(f, power) of a uniformly sampled record: the straight line through its end points
    removed and a Hann window applied (docs/metrics.md "Spectral estimate")."""
    y = np.asarray(signal, float)
    y = y - np.linspace(y[0], y[-1], y.size)
    y = y * np.hanning(y.size)
    dt = float(t[1] - t[0])
    return np.fft.rfftfreq(y.size, dt), np.abs(np.fft.rfft(y)) ** 2


def amplitude_against(result, reference, x1=6.0, smooth_bins=5):
    """(f, A/A_ref): the amplitude spectrum of tau_s at `x1` of `result` over that of
    `reference` (the plain-Coulomb run: what the event is without the regularisation), both
    resampled on the coarser output step over the time both records cover, the ratio
    smoothed geometrically over `smooth_bins` neighbouring frequencies."""
    (t_a, s_a), (t_b, s_b) = strength_at(result, x1), strength_at(reference, x1)
    dt = max(float(t_a[1] - t_a[0]), float(t_b[1] - t_b[0]))
    grid = np.arange(0.0, min(float(t_a[-1]), float(t_b[-1])), dt)
    f, p_a = power_spectrum(grid, np.interp(grid, t_a, s_a))
    _, p_b = power_spectrum(grid, np.interp(grid, t_b, s_b))
    with np.errstate(divide="ignore", invalid="ignore"):
        log_ratio = 0.5 * np.log(p_a / p_b)
    log_ratio[~np.isfinite(log_ratio)] = 0.0
    kernel = np.ones(smooth_bins) / smooth_bins
    return f, np.exp(np.convolve(log_ratio, kernel, mode="same"))


def half_amplitude_frequency(f, ratio):
    """The lowest frequency above which the amplitude ratio stays below 1/2 (the run has lost
    half the reference's amplitude there): the first non-zero frequency if the ratio is below
    1/2 everywhere, None if it is not below 1/2 at the Nyquist frequency."""
    above = np.nonzero(ratio >= 0.5)[0]
    if above.size == 0:
        return float(f[1])
    last = int(above[-1])
    return float(f[last + 1]) if last + 1 < f.size else None


def plot_strength_spectrum(results, meshes, x1=6.0, v_star=1e-4, slip_velocity=3e-3, title=None):
    """`results`: {L: Result}; `meshes`: {label: highest frequency [Hz]}."""
    Ls = sorted(results, reverse=True)
    palette = ramp(len(Ls), "viridis_r")
    fig, (a, b, c) = plt.subplots(1, 3, figsize=(13.5, 3.9), constrained_layout=True)
    data = {"spectra": {}, "f_max": dict(meshes)}
    f_hi = 1.0
    for L, colour in zip(Ls, palette):
        r = results[L]
        if r.strength.size == 0 or r.time.size < 4:
            continue
        t, s = strength_at(r, x1)
        if not np.ptp(s) > 0:
            continue  # no event at x1 (no rupture): nothing to analyse
        a.plot(t, s * 1e3, color=colour, lw=1.0, label=f"L = {L:g} m")
        f, p = power_spectrum(t, s)
        data["spectra"][L] = (f, p)
        keep = f > 0
        b.loglog(f[keep], p[keep] / p[keep].max(), color=colour, lw=1.0, label=f"L = {L:g} m")
        f_hi = max(f_hi, float(f[-1]))
    a.set_title(f"(a) strength τ_s at x1 = {x1:g} m", fontsize="medium")
    a.set_xlabel("t [s]")
    a.set_ylabel(r"$\tau_s$ [mPa]")
    a.legend(fontsize="x-small")
    b.set_title("(b) its power spectrum (normalised)", fontsize="medium")
    b.set_xlabel("f [Hz]")
    b.set_ylabel("power / peak")
    b.set_ylim(1e-12, 2)
    f = np.logspace(-2, np.log10(max(f_hi, max(meshes.values(), default=1.0)) * 2), 400)
    for L, colour in zip(Ls, palette):
        c.plot(f, amplitude_ratio(f, L, v_star, slip_velocity), color=colour, lw=1.0,
               label=f"L = {L:g} m")
    for label, f_max in sorted(meshes.items(), key=lambda kv: kv[1]):
        for ax in (b, c):
            ax.axvline(f_max, color="grey", ls="--", lw=0.8)
        c.text(f_max, 1.02, label, rotation=90, ha="right", va="bottom", fontsize="x-small",
               color="grey")
    c.set_xscale("log")
    c.set_ylim(0, 1.2)
    c.set_title(f"(c) filter A/A0, |V| = {slip_velocity:g} m/s", fontsize="medium")
    c.set_xlabel("f [Hz]")
    c.set_ylabel("A/A0")
    c.legend(fontsize="x-small", loc="lower left")
    if title:
        fig.suptitle(title)
    return fig, data

"""The length fit of paper Sec. 6 (docs/length-fit.md): the measured frictional stress, the
fitted strength (eq. 1) and the Coulomb strength mu p against time (the slipping samples, the
ones fitted, marked), and the contact pressure's power spectrum with the measured critical
frequency f_m and the 99 % power frequency."""

import numpy as np

from .common import new_figure


def plot_length_fit(answer, title=None):
    """`answer`: the JSON of POST /api/v1/length-fits. Returns (figure, data)."""
    series, spectrum = answer["series"], answer["spectrum"]
    fit, verdict = answer["fit"], answer["verdict"]
    t = np.asarray(series["time"], dtype=float)
    measured = np.asarray(series["frictional_stress"], dtype=float)
    fitted = np.asarray(series["fitted_stress"], dtype=float)
    coulomb = np.asarray(series["coulomb_strength"], dtype=float)
    slipping = np.asarray(series["slipping"], dtype=bool)
    f = np.asarray(spectrum["frequency"], dtype=float)
    power = np.asarray(spectrum["power"], dtype=float)
    f_m = answer["critical_frequency"]["f_m"]

    fig, (left, right) = new_figure(width=11, height=4.2, ncols=2)
    left.plot(t, measured, color="0.55", lw=1.0, label="measured")
    left.plot(t[slipping], measured[slipping], ".", color="0.25", ms=3, label="measured, slipping")
    left.plot(t, coulomb, color="#1f77b4", lw=0.8, ls="--", label="mu p (Coulomb)")
    left.plot(t, fitted, color="#d62728", lw=1.4,
              label=f"fitted strength: L = {fit['L']:.3g} m, mu = {fit['mu']:.4g}")
    left.set_xlabel("t [s]")
    left.set_ylabel("frictional stress [Pa]")
    left.legend(fontsize="small")

    shown = power > 0
    right.loglog(f[shown], power[shown], color="#1f77b4", lw=1.0)
    right.axvline(f_m, color="#d62728", ls="--", lw=1.2, label=f"f_m = {f_m:.3g} Hz")
    if spectrum.get("frequency_99"):
        right.axvline(spectrum["frequency_99"], color="0.4", ls=":", lw=1.2,
                      label=f"99 % of the power below {spectrum['frequency_99']:.3g} Hz")
    right.set_xlabel("f [Hz]")
    right.set_ylabel("fraction of the power")
    right.set_title(f"{100 * verdict['power_above_f_m']:.3g} % of the power above f_m",
                    fontsize="small")
    right.legend(fontsize="small", loc="lower left")
    fig.suptitle(title or verdict["text"], fontsize="medium")
    return fig, {"time": t, "measured": measured, "fitted": fitted, "coulomb": coulomb,
                 "frequency": f,
                 "power": power, "f_m": f_m}

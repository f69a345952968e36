#!/usr/bin/python3
"""Why do small L not converge? Time step, mesh and the mesh-scale oscillation.

For L = 5e-6 and 1e-5 m (and plain Coulomb friction) the paper's scene is run at several
mesh densities n_d and time-step safety factors with the `slipfront` CLI. For each run it
prints the metrics (docs/metrics.md) and a measure of the mesh-scale oscillation of the slip velocity
inside the slipping zone:

  * the residual r = V - (V averaged over 0.3 m) along x1 at each sampled time, over the
    slipping zone from x1 = 1 m to 0.3 m behind the front (wavelengths above 0.3 m removed);
  * its dominant wavelength, in metres and in mesh spacings dx (from an FFT with a Hann
    window, among wavelengths below 0.3 m);
  * its rms early in the rupture (t in [2, 2.5] s) and later (t in [3.5, 4] s): a ratio
    late/early below 1 means the oscillation dies out, above 1 that it is sustained.

Runs are kept in --work (JOB.h5 and JOB.json per case), so the script can be stopped and
run again: finished cases are read back, not recomputed. docs/small-l-study.md explains
what the table shows.

usage: /usr/bin/python3 bench/small_l_study.py [--binary build/slipfront]
           [--work /tmp/slipfront-small-l] [--max-nd 160] [--with-320]
           [--figure docs/figures/small_l_study.png]
"""
import argparse
import json
import os
import subprocess
import sys

import h5py
import numpy as np

# (friction, n_d, safety factor). The reference scheme's strength update ("exponential", the pressure of
# the step's end frozen over the step): the time-step ladder at n_d = 40 and 80, the finest
# mesh at the default and at half the default step. The default update ("exponential_ramp",
# the pressure linear over the step): the same ladder. Plain Coulomb friction on 3 meshes.
END, RAMP = {"strength_update": "exponential"}, {"strength_update": "exponential_ramp"}
CASES = [(dict(update, L=L), nd, sf) for update in (END, RAMP) for L in (5e-6, 1e-5)
         for nd, sf in ((40, 0.5), (40, 0.25), (40, 0.125), (80, 0.5), (80, 0.25), (160, 0.5))]
CASES += [(dict(END, L=5e-6), 160, 0.25)]
CASES += [({"law": "coulomb"}, nd, 0.5) for nd in (40, 80, 160)]
# --with-320: the next mesh for both L (about 30-40 min each with 2 threads, 2.7 GB).
CASES_320 = [(dict(RAMP, L=5e-6), 320, 0.5), (dict(RAMP, L=1e-5), 320, 0.5)]

SMOOTHING_LENGTH = 0.3  # m: the residual keeps wavelengths below this
EARLY, LATE = (2.0, 2.5), (3.5, 4.0)  # s: windows of the paper's scene (front at x1 ~ 2-5 m)


def case_name(friction, nd, sf):
    if friction.get("law") == "coulomb":
        law = "coulomb"
    else:
        update = "ramp" if friction["strength_update"] == "exponential_ramp" else "end"
        law = f"{update}_L{friction['L']:g}"
    return f"{law}_nd{nd}_sf{sf:g}"


def run_case(binary, work, friction, nd, sf):
    """Runs one case with the CLI unless its result is already in `work`."""
    name = case_name(friction, nd, sf)
    h5, metrics_path = os.path.join(work, name + ".h5"), os.path.join(work, name + ".json")
    if not (os.path.exists(h5) and os.path.exists(metrics_path)):
        spec = {"name": f"small-L study {name}", "geometry": {"nodes_per_meter": nd},
                "friction": friction, "time": {"safety_factor": sf}}
        job = os.path.join(work, name + ".job.json")
        with open(job, "w") as f:
            json.dump(spec, f)
        print(f"running {name} ...", file=sys.stderr, flush=True)
        out = subprocess.run([binary, "run", job, "--output", h5 + ".part", "--quiet"],
                             check=True, capture_output=True, text=True)
        os.replace(h5 + ".part", h5)
        with open(metrics_path, "w") as f:
            f.write(out.stdout)
    with open(metrics_path) as f:
        return name, json.load(f), h5


def mesh_scale_oscillation(h5_path):
    """Dominant short wavelength (m) and rms of the residual early and late (see above)."""
    with h5py.File(h5_path, "r") as h:
        t = h["interface/time"][:]
        x = h["interface/x1"][:]
        V = h["interface/slip_velocity"]
        dx = x[1] - x[0]
        width = max(3, int(round(SMOOTHING_LENGTH / dx)))
        wavelengths, rms = [], {EARLY: [], LATE: []}
        for window in (EARLY, LATE):
            for i in np.nonzero((t >= window[0]) & (t <= window[1]))[0]:
                v = V[i]
                slipping = np.nonzero(v > 1e-4)[0]
                if len(slipping) == 0:
                    continue
                zone = (x > 1.0) & (x < x[slipping[-1]] - SMOOTHING_LENGTH)
                if zone.sum() < 2 * width:
                    continue
                r = (v - np.convolve(v, np.ones(width) / width, mode="same"))[zone]
                spectrum = np.abs(np.fft.rfft(r * np.hanning(len(r))))
                k = np.fft.rfftfreq(len(r), dx)
                short = k > 1.0 / SMOOTHING_LENGTH
                wavelengths.append(1.0 / k[short][np.argmax(spectrum[short])])
                rms[window].append(np.sqrt(np.mean(r * r)))
        dissipated = h["energy/dissipated"][:]
        external_work = float(h["energy/external_work"][-1])
    mean = lambda a: float(np.mean(a)) if a else float("nan")  # noqa: E731
    return {"dx": dx, "wavelength": float(np.median(wavelengths)) if wavelengths else float("nan"),
            "rms_early": mean(rms[EARLY]), "rms_late": mean(rms[LATE]),
            # The interface only dissipates if the friction/contact work never decreases.
            "dissipation_monotone": bool(np.all(np.diff(dissipated) >= 0.0)),
            "external_work": external_work}


def fmt(value, spec):
    return "—" if value is None or (isinstance(value, float) and np.isnan(value)) else format(value, spec)


def zoom_figure(rows, path):
    """|V| in x1 in [1.5, 6] m, t in [2, 5] s for L = 5e-6 at each mesh (default step)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    picks = [r for r in rows if r[0].startswith("end_L5e-06") and r[0].endswith("sf0.5")]
    if not picks:
        return
    fig, axes = plt.subplots(1, len(picks), figsize=(4.2 * len(picks), 4), squeeze=False)
    for ax, (name, _, h5, _) in zip(axes[0], picks):
        with h5py.File(h5, "r") as h:
            t, x = h["interface/time"][:], h["interface/x1"][:]
            sx, st = (x > 1.5) & (x < 6), (t > 2) & (t < 5)
            V = h["interface/slip_velocity"][np.nonzero(st)[0], :][:, sx]
        image = ax.pcolormesh(x[sx], t[st], 1e3 * V, vmin=0, vmax=12, shading="auto")
        ax.set_title(name.replace("_", " "), fontsize=9)
        ax.set_xlabel("x1 [m]")
    axes[0][0].set_ylabel("t [s]")
    fig.colorbar(image, ax=axes[0].tolist(), label="V [mm/s]")
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    fig.savefig(path, dpi=90)
    print(f"figure: {path}", file=sys.stderr)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default="build/slipfront")
    ap.add_argument("--work", default="/tmp/slipfront-small-l")
    ap.add_argument("--max-nd", type=float, default=160, help="skip finer meshes (80: ~5 min)")
    ap.add_argument("--with-320", action="store_true", help="add n_d = 320 for both L")
    ap.add_argument("--figure", default="docs/figures/small_l_study.png")
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)

    rows = []
    for friction, nd, sf in CASES + (CASES_320 if args.with_320 else []):
        if nd <= args.max_nd or nd == 320 and args.with_320:
            name, m, h5 = run_case(args.binary, args.work, friction, nd, sf)
            rows.append((name, m, h5, mesh_scale_oscillation(h5)))

    print("| run | dt [ms] | outcome | arrest [m] | propagation distance [m] | arrival at 11 m [s] "
          "| max V [mm/s] | oscillation wavelength [m] (dx) | rms early → late [mm/s] "
          "| external work [J/m] | dissipated never decreases | wall [s] |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for name, m, _, osc in rows:
        ratio = osc["rms_late"] / osc["rms_early"] if osc["rms_early"] > 0 else float("nan")
        print(f"| {name} | {1e3 * m['dt']:.3f} | {m['outcome']} | {fmt(m['arrest_position'], '.4g')} "
              f"| {fmt(m['propagation_distance'], '.5g')} | {fmt(m['arrival_time_at_probe'], '.5f')} "
              f"| {1e3 * m['max_slip_velocity']:.2f} | {fmt(osc['wavelength'], '.4f')} "
              f"({fmt(osc['wavelength'] / osc['dx'], '.1f')}) "
              f"| {fmt(1e3 * osc['rms_early'], '.2f')} → {fmt(1e3 * osc['rms_late'], '.2f')} "
              f"(×{fmt(ratio, '.2f')}) | {osc['external_work']:.2e} "
              f"| {'yes' if osc['dissipation_monotone'] else '**no**'} | {m['wall_time_s']:.1f} |")
    if args.figure:
        zoom_figure(rows, args.figure)


if __name__ == "__main__":
    main()

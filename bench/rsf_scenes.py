#!/usr/bin/python3
"""The rate-and-state scenes by both methods at the preset's mesh and finer: station rupture
times (at 0.1 and 0.01 m/s), peak slip rate and its time, final slip, and the wall time.

    /usr/bin/python3 bench/rsf_scenes.py                                 # both SEM2DPACK scenes
    /usr/bin/python3 bench/rsf_scenes.py --preset tpv101_2d --methods spectral_bi --n-d 0.02 0.04
    /usr/bin/python3 bench/rsf_scenes.py --json out.json                 # also as JSON
    /usr/bin/python3 bench/rsf_scenes.py --preset tpv101_2d --n-d 0 --dt-check  # dt halved

Runs `build/slipfront run` on each preset x method x n_d (one after the other, --threads 2),
reads the stations back from the result file (`slipfront stations --threshold`) and prints one
Markdown table per preset, then FE against BI at each mesh (relative difference of the rupture
times) and each method's change from one mesh to the next. `--n-d 0` is the preset's own mesh;
`--dt-check` runs each job again with half the time step (BI `spectral_bi.time_step_factor`, FE
`time.safety_factor`, both 0.5 by default and in every preset) and prints the change of the
rupture times, held against 0.1 %. docs/verification.md "Rate-and-state
friction" holds its output.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(binary, preset, method, n_d, threads, workdir, dt_factor=1.0):
    job = {"preset": preset, "method": method}
    if n_d > 0:
        job["geometry"] = {"nodes_per_meter": n_d}
    if dt_factor != 1.0:  # both defaults 0.5 (solver/params.hpp); no preset sets them
        if method == "spectral_bi":
            job["spectral_bi"] = {"time_step_factor": 0.5 * dt_factor}
        else:
            job["time"] = {"safety_factor": 0.5 * dt_factor}
    path = os.path.join(workdir, f"{preset}-{method}-{n_d:g}-{dt_factor:g}")
    with open(path + ".json", "w") as f:
        json.dump(job, f)
    t0 = time.monotonic()
    out = subprocess.run([binary, "run", path + ".json", "--output", path + ".h5", "--quiet",
                          "--threads", str(threads)], capture_output=True, text=True)
    wall = time.monotonic() - t0
    if out.returncode != 0:
        raise SystemExit(f"{preset} {method} n_d {n_d}: exit {out.returncode}: {out.stderr}")
    metrics = json.loads(out.stdout)
    return {"preset": preset, "method": method, "n_d": n_d, "dt_factor": dt_factor, "wall_s": wall,
            "steps": metrics.get("steps"), "stations": stations(path + ".h5")}


def crossing(time, rate, threshold):
    above = np.nonzero(rate > threshold)[0]
    if above.size == 0:
        return None
    k = int(above[0])
    if k == 0:
        return float(time[0])
    f = min(max((threshold - rate[k - 1]) / (rate[k] - rate[k - 1]), 0.0), 1.0)
    return float(time[k - 1] + f * (time[k] - time[k - 1]))


def stations(path):
    with h5py.File(path, "r") as f:
        g = f["stations"]
        x1, time = g["x1"][()], g["time"][()]
        rate, slip = np.abs(g["slip_rate"][()]), g["slip"][()]
    rows = []
    for s, x in enumerate(x1):
        peak = int(np.argmax(rate[:, s]))
        rows.append({"x1": float(x), "t_0.1": crossing(time, rate[:, s], 0.1),
                     "t_0.01": crossing(time, rate[:, s], 0.01),
                     "peak": float(rate[peak, s]), "peak_time": float(time[peak]),
                     "final_slip": float(slip[-1, s])})
    return rows


def fmt(v, digits=5):
    return "—" if v is None else f"{v:.{digits}g}"


def table(result):
    mesh = (f"n_d = {result['n_d']:g} /m (dx = {1 / result['n_d']:g} m)" if result["n_d"] > 0
            else "the preset's mesh")
    dt = "" if result["dt_factor"] == 1.0 else f", dt x {result['dt_factor']:g}"
    lines = [f"{result['preset']}, {result['method']}, {mesh}{dt}, {result['steps']} steps, "
             f"{result['wall_s']:.1f} s wall",
             "", "| x1 [km] | t (0.1 m/s) [s] | t (0.01 m/s) [s] | peak V [m/s] | at [s] | "
             "final slip [m] |", "| --- | --- | --- | --- | --- | --- |"]
    for r in result["stations"]:
        lines.append(f"| {r['x1'] / 1000:g} | {fmt(r['t_0.1'])} | {fmt(r['t_0.01'])} | "
                     f"{fmt(r['peak'], 4)} | {fmt(r['peak_time'], 4)} | {fmt(r['final_slip'], 4)} |")
    return lines + [""]


def relative(a, b):
    if a is None or b is None or b == 0:
        return "—"
    return f"{(a - b) / b * 100:+.2f} %"


def comparison(results, key, title, pairs):
    lines = [title, "", "| pair | " + " | ".join(f"{r['x1'] / 1000:g} km" for r in
                                                  pairs[0][1]["stations"]) + " |",
             "| --- |" + " --- |" * len(pairs[0][1]["stations"])]
    for label, a, b in pairs:
        cells = [relative(x[key], y[key]) for x, y in zip(a["stations"], b["stations"])]
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    return lines + [""]


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--binary", default=os.path.join(REPO, "build", "slipfront"))
    p.add_argument("--preset", nargs="+", default=["rsf_slip_law_inplane", "rsf_aging_law_inplane"])
    p.add_argument("--methods", nargs="+", default=["spectral_bi", "fe"])
    p.add_argument("--n-d", nargs="+", type=float, default=[0.04, 0.08],
                   help="meshes, nodes per metre (default: the preset's 0.04 and the next finer)")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--json", help="also write every result as JSON to this file")
    p.add_argument("--dt-check", action="store_true",
                   help="also run each job with half the time step and compare")
    args = p.parse_args(argv)
    results = []
    with tempfile.TemporaryDirectory(prefix="slipfront-rsf-") as workdir:
        for preset in args.preset:
            for method in args.methods:
                for n_d in args.n_d:
                    for factor in ([1.0, 0.5] if args.dt_check else [1.0]):
                        r = run(args.binary, preset, method, n_d, args.threads, workdir, factor)
                        results.append(r)
                        print("\n".join(table(r)), flush=True)
    for preset in args.preset:
        own = [r for r in results if r["preset"] == preset and r["dt_factor"] == 1.0]
        by = {(r["method"], r["n_d"]): r for r in own}
        halved = {(r["method"], r["n_d"]): r for r in results
                  if r["preset"] == preset and r["dt_factor"] != 1.0}
        dt_pairs = [(f"{m}, n_d {n:g}: dt/2 − dt", halved[(m, n)], by[(m, n)])
                    for (m, n) in by if (m, n) in halved]
        if dt_pairs:
            print("\n".join(comparison(own, "t_0.1", f"{preset}: half the time step against "
                                       "the preset's, rupture time at 0.1 m/s", dt_pairs)))
        pairs = [(f"FE − BI at n_d {n:g}", by[("fe", n)], by[("spectral_bi", n)])
                 for n in args.n_d if ("fe", n) in by and ("spectral_bi", n) in by]
        if pairs:
            print("\n".join(comparison(own, "t_0.1", f"{preset}: FE against BI, rupture time "
                                       "at 0.1 m/s", pairs)))
        steps = [(f"{m}: n_d {a:g} − {b:g}", by[(m, a)], by[(m, b)]) for m in args.methods
                 for a, b in zip(args.n_d, args.n_d[1:]) if (m, a) in by and (m, b) in by]
        if steps:
            print("\n".join(comparison(own, "t_0.1", f"{preset}: each mesh against the finer "
                                       "one, rupture time at 0.1 m/s", steps)))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())

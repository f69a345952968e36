#!/usr/bin/python3
"""A notebook-style tour of the slipfront Python API (docs/python-api.md), cell by cell.
Each `# %%` block can be pasted into a Jupyter cell; as a script it runs top to bottom
against the server of SLIPFRONT_SERVER (or --server), writing its figures to --out.

    build/slipfront serve --data-dir ./data &
    /usr/bin/python3 clients/examples/notebook_tour.py --out tour

CI runs it against a loopback server (tests/clients/test_package.py). It uses the fast
spectral boundary-integral method: the whole tour takes a few seconds.
"""

import argparse
import os
import sys

try:
    import slipfront_client  # noqa: F401  (installed: pip install ./clients)
except ImportError:  # from a checkout, without installing the package
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--server", help="server URL (default: SLIPFRONT_SERVER, config file)")
parser.add_argument("--out", default="tour", help="directory for the figures")
args = parser.parse_args()
os.makedirs(args.out, exist_ok=True)

# %% Connect: the URL comes from --server, SLIPFRONT_SERVER or ~/.config/slipfront/client.toml
import numpy as np  # noqa: E402

import slipfront_client as sf  # noqa: E402
from slipfront_client.plots import slip_map, speed, velocity  # noqa: E402

api = sf.connect(args.server)
print("slipfront-client", sf.__version__, "talking to", api.base_url)

# %% Submit one run (every field optional; defaults are the paper's scene) and wait for it
scene = {"method": "spectral_bi", "friction": {"L": 5e-5}, "tags": ["tour"]}
job = sf.submit(api, scene, wait=True)
m = job["metrics"]
print(f"job {job['id']}: {m['outcome']}, arrest at {m['arrest_position']:.3f} m, "
      f"{m['wall_time_s']:.2f} s wall")

# %% Load its result file as numpy arrays
result = sf.load_job_result(api, job["id"], path=os.path.join(args.out, job["id"] + ".h5"))
V = result.slip_velocity                      # [n_samples, n_nodes], m/s
print("slip velocity", V.shape, "max |V| =", float(np.nanmax(np.abs(V))), "m/s")
k = int(np.argmin(np.abs(result.x1 - 6.0)))   # the node nearest x1 = 6 m
print(f"V at x1 = {result.x1[k]:.2f} m peaks at t = {result.time[np.argmax(np.abs(V[:, k]))]:.2f} s")

# %% Plot: the x1-t map, V(t) at two points, the rupture speed
for name, (fig, _) in {
        "map": slip_map.plot_map(result),
        "velocity": velocity.plot_velocity([result], positions=(6.0, 10.0)),
        "speed": speed.plot_speed([result]),
}.items():
    path = os.path.join(args.out, f"{name}.png")
    fig.savefig(path, dpi=120)
    print("wrote", path)

# %% A study: the same scene at three L, two meshes each; the server checks convergence
study = sf.run_study(api, base={"method": "spectral_bi"},
                     L=[1e-4, 5e-5, 2e-5], n_d=[10, 20], name="tour study", timeout=600)
print(f"study {study['id']}: {study['status']}, L_c = {study.get('L_c')}")

# %% The run table: filter and sort on any spec field or metric, as a pandas DataFrame
runs = sf.runs_dataframe(api, where=f"study_id={study['id']}", sort="friction.L,spec.geometry.nodes_per_meter")
try:
    columns = ["spec.friction.L", "spec.geometry.nodes_per_meter", "outcome",
               "convergence_status", "metrics.arrest_position", "metrics.wall_time_s"]
    print(runs[columns].to_string())
    arrested = runs[runs["outcome"] == "arrested"]
    print(f"{len(arrested)} of {len(runs)} runs arrested")
except TypeError:  # no pandas: a list of dicts
    for r in runs:
        print(r["spec.friction.L"], r["spec.geometry.nodes_per_meter"], r["outcome"])
far = sf.list_runs(api, where="metrics.arrest_position>10; tag=tour")
print(f"{len(far)} tour run(s) arrested beyond 10 m")

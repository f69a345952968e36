#!/usr/bin/python3
"""The cost of a step of rate-and-state friction against slip weakening, in both methods.

    /usr/bin/python3 bench/rsf_step_cost.py              # n_d 0.04, 3 repeats, one thread
    /usr/bin/python3 bench/rsf_step_cost.py --repeats 5 --threads 2

The scene is `rsf_slip_law_inplane` (docs/presets.md) as it is, and the same scene with
linear slip weakening instead (TPV3's mu_s 0.677, mu_d 0.525, D_c 0.4 m; the same stresses, so
the 81.6 MPa patch, an overstressed
patch here, breaks at once): the same mesh, time step and duration, so the wall time
per step compares the laws. Each job runs by `build/slipfront run` `--repeats` times,
alternating the laws; the median wall time per step (the metrics' wall_time_s over steps, the
set-up excluded by subtracting a run of 1 % of the duration) is printed with the ratio.
docs/performance.md "Rate-and-state friction: cost per step" holds its output.
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Over the preset's friction as a JSON merge patch: the rate-and-state numbers removed.
SLIP_WEAKENING = {"law": "slip_weakening", "mu_s": 0.677, "mu_d": 0.525, "D_c": 0.4,
                  **{k: None for k in ("a", "b", "f0", "v_star", "theta", "initial_slip_rate",
                                       "state_evolution", "initial_state")}}
PROFILES_SW = [{"x1_min": -9999.999, "x1_max": 9999.999, "shear_stress": 70e6}]
NUCLEATION_SW = {"enabled": True, "type": "overstressed_patch", "x1_min": -1499.999,
                 "x1_max": 1499.999, "shear_stress": 81.6e6}


def job(law, method, n_d, duration):
    j = {"preset": "rsf_slip_law_inplane", "method": method,
         "geometry": {"nodes_per_meter": n_d}, "time": {"duration": duration}}
    if law == "slip_weakening":
        j["friction"] = SLIP_WEAKENING
        j["profiles"] = PROFILES_SW
        j["nucleation"] = NUCLEATION_SW
    return j


def run(binary, spec, threads, workdir):
    path = os.path.join(workdir, "job.json")
    with open(path, "w") as f:
        json.dump(spec, f)
    out = subprocess.run([binary, "run", path, "--quiet", "--threads", str(threads)],
                         capture_output=True, text=True)
    if out.returncode != 0:
        raise SystemExit(f"{spec}: exit {out.returncode}: {out.stderr}")
    m = json.loads(out.stdout)
    return m["wall_time_s"], m["steps"]


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--binary", default=os.path.join(REPO, "build", "slipfront"))
    p.add_argument("--methods", nargs="+", default=["spectral_bi", "fe"])
    p.add_argument("--n-d", type=float, default=0.04)
    p.add_argument("--duration", type=float, default=2.5)
    p.add_argument("--threads", type=int, default=1)
    p.add_argument("--repeats", type=int, default=3)
    args = p.parse_args(argv)
    laws = ["slip_weakening", "rate_and_state"]
    print(f"rsf_slip_law_inplane at n_d {args.n_d:g} /m, {args.duration:g} s, "
          f"{args.threads} thread(s), median of {args.repeats}; load "
          f"{open('/proc/loadavg').read().split()[0]}")
    print("| method | law | steps | wall [s] | per step [ms] |\n| --- | --- | --- | --- | --- |")
    with tempfile.TemporaryDirectory(prefix="slipfront-rsfcost-") as workdir:
        for method in args.methods:
            per_step = {}
            for law in laws:
                setup = [run(args.binary, job(law, method, args.n_d, args.duration / 100),
                             args.threads, workdir) for _ in range(args.repeats)]
                full = []
                for _ in range(args.repeats):
                    full.append(run(args.binary, job(law, method, args.n_d, args.duration),
                                    args.threads, workdir))
                wall = statistics.median(w for w, _ in full)
                short = statistics.median(w for w, _ in setup)
                steps, short_steps = full[0][1], setup[0][1]
                per_step[law] = (wall - short) / max(1, steps - short_steps)
                print(f"| {method} | {law} | {steps} | {wall:.2f} | "
                      f"{per_step[law] * 1e3:.3f} |", flush=True)
            ratio = per_step["rate_and_state"] / per_step["slip_weakening"]
            print(f"| {method} | ratio | | | **{ratio:.2f}** |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

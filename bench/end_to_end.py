#!/usr/bin/python3
"""Wall time and peak memory of the paper's L = 5e-5 m run at several mesh densities.

Each run is the CLI with the defaults (h = 20 m, stop on arrest, all cores), no result file
(--output writes the HDF5 file; add --with-output to include it). Peak memory is the child's
maximum resident set size (the whole process), reported per mesh node.

usage: /usr/bin/python3 bench/end_to_end.py [--binary build/slipfront] [--nd 40 80 120]
"""
import argparse
import json
import os
import subprocess
import tempfile
import time


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default="build/slipfront")
    ap.add_argument("--nd", type=float, nargs="+", default=[40, 80, 120])
    ap.add_argument("--with-output", action="store_true")
    args = ap.parse_args()
    print("| n_d | nodes | steps | dt [s] | wall [s] | Mnode-updates/s | peak RSS [MB] | bytes/node | arrest [m] |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    prev = None
    for nd in args.nd:
        spec = {"geometry": {"nodes_per_meter": nd}, "friction": {"L": 5e-5}, "name": f"paper n_d={nd:g}"}
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "job.json")
            with open(path, "w") as f:
                json.dump(spec, f)
            cmd = [args.binary, "run", path, "--quiet"]
            if args.with_output:
                cmd += ["--output", os.path.join(tmp, "out.h5")]
            # Run in a fresh child via a tiny wrapper so that ru_maxrss is this run's alone.
            wrapper = ("import resource,subprocess,sys;r=subprocess.run(sys.argv[1:],capture_output=True,text=True);"
                       "sys.stdout.write(r.stdout);sys.stderr.write(str(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss))")
            t0 = time.time()
            out = subprocess.run(["/usr/bin/python3", "-c", wrapper] + cmd, capture_output=True, text=True, check=True)
            wall_outer = time.time() - t0
        m = json.loads(out.stdout)
        rss_kb = int(out.stderr.strip().splitlines()[-1])
        nodes = m["mesh"]["nx"] * m["mesh"]["ny"]
        rate = nodes * m["steps"] / m["wall_time_s"] / 1e6
        print(f"| {nd:g} | {nodes} | {m['steps']} | {m['dt']:.4g} | {m['wall_time_s']:.2f} (process {wall_outer:.2f}) | "
              f"{rate:.0f} | {rss_kb / 1024:.0f} | {rss_kb * 1024 / nodes:.1f} | {m['arrest_position']:.4f} |")
        if prev:
            import math
            p = math.log(m["wall_time_s"] / prev[1]) / math.log(nd / prev[0])
            print(f"|   | growth n_d {prev[0]:g} -> {nd:g}: wall ~ n_d^{p:.2f} | | | | | | | |")
        prev = (nd, m["wall_time_s"])


if __name__ == "__main__":
    main()

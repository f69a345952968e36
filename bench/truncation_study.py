#!/usr/bin/python3
"""The truncated block against the full block: the paper's run with a perfectly matched layer
on a low block, against h = 20 m with the traction top (the half-space answer of the mesh).

For each n_d, runs the full block and the truncated ones (top_boundary "pml", heights given,
layer of --layer elements) and prints a markdown table: wall time, propagation distance and
arrival time at x1 = 11 m, their differences from the full block against the convergence rule
of docs/metrics.md (propagation distance 0.5 %, arrival time 0.1 %), and the energy error.

usage: /usr/bin/python3 bench/truncation_study.py [--binary build/slipfront] [--nd 20 40]
           [--heights 4 3 2 1] [--layer 20] [--tops pml absorbing] [--threads 2]
           [--repeat 1] [--check]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile


def run(binary, spec):
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(spec, f)
        path = f.name
    try:
        out = subprocess.run([binary, "run", path, "--quiet"], check=True, capture_output=True, text=True)
    finally:
        os.unlink(path)
    return json.loads(out.stdout)


def best_of(binary, spec, repeat):
    runs = [run(binary, spec) for _ in range(repeat)]
    best = min(runs, key=lambda m: m["wall_time_s"])
    return best


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default="build/slipfront")
    ap.add_argument("--nd", type=float, nargs="+", default=[20, 40])
    ap.add_argument("--heights", type=float, nargs="+", default=[4, 3, 2, 1])
    ap.add_argument("--layer", type=int, default=20)
    ap.add_argument("--tops", nargs="+", default=["pml"], help="truncated tops: pml, absorbing")
    ap.add_argument("--L", type=float, default=5e-5)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--repeat", type=int, default=1, help="runs per case; the fastest is kept")
    ap.add_argument("--json", help="write the rows here as JSON")
    ap.add_argument("--check", action="store_true",
                    help="exit 1 unless every truncated run is within the convergence rule and its energy balance closes")
    args = ap.parse_args()

    rows = []
    print("| n_d | top | h [m] | rows stepped | wall [s] | speed-up | propagation [m] | diff [%] | "
          "arrival at 11 m [s] | diff [%] | within rule | energy error | warning |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for nd in args.nd:
        base = {"geometry": {"nodes_per_meter": nd}, "friction": {"L": args.L}, "threads": args.threads,
                "name": "truncation study"}
        cases = [("traction", 20.0)] + [(top, h) for top in args.tops for h in args.heights]
        ref = None
        for top, h in cases:
            spec = json.loads(json.dumps(base))
            spec["geometry"].update({"height": h, "top_boundary": top})
            if top == "pml":
                spec["geometry"]["pml_elements"] = args.layer
            m = best_of(args.binary, spec, args.repeat)
            print(f"ran n_d={nd:g} top={top} h={h:g}: {m['wall_time_s']:.2f} s", file=sys.stderr)
            if ref is None:
                ref = m
            dp = 100 * abs(m["propagation_distance"] - ref["propagation_distance"]) / ref["propagation_distance"]
            at, rt = m["arrival_time_at_probe"], ref["arrival_time_at_probe"]
            dt = float("nan") if at is None else 100 * abs(at - rt) / rt
            ok = dp < 0.5 and dt < 0.1
            rows.append({"nd": nd, "top": top, "h": h, "wall": m["wall_time_s"], "propagation": m["propagation_distance"],
                         "arrival": at, "dp": dp, "dt": dt, "ok": ok, "ny": m["mesh"]["ny"],
                         "energy_error": m.get("energy_error"), "warnings": m["warnings"]})
            print(f"| {nd:g} | {top} | {h:g} | {m['mesh']['ny']} | {m['wall_time_s']:.2f} | "
                  f"{ref['wall_time_s'] / m['wall_time_s']:.2f} | {m['propagation_distance']:.4f} | {dp:.3f} | "
                  f"{at if at is not None else float('nan'):.4f} | {dt:.3f} | {'yes' if ok else 'no'} | "
                  f"{m.get('energy_error', float('nan')):.1e} | {'yes' if m['warnings'] else ''} |", flush=True)
    if args.check:
        bad = [r for r in rows if not r["ok"] or not (r["energy_error"] is not None and r["energy_error"] < 1e-10)]
        if bad:
            print(f"outside the rule: {bad}", file=sys.stderr)
            sys.exit(1)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()

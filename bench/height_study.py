#!/usr/bin/python3
"""How low can the block be? Error against wall time as the height h shrinks.

Runs the paper's L = 5e-5 m job at one mesh density for a range of heights, with the top
keeping its traction (reflecting) and with Lysmer-Kuhlemeyer dashpots (absorbing), plus
"height": "auto". The reference is h = 20 m with a traction top: no reflected wave comes
back before that run ends (2 h / c_p = 23 s > 13.2 s), so it is the half-space answer of
the same mesh. Prints a markdown table and writes a chart.

usage: /usr/bin/python3 bench/height_study.py [--binary build/slipfront] [--nd 40]
           [--heights 20 15 12 10 8 6 4 3] [--out docs/figures/height_study.png]
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


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default="build/slipfront")
    ap.add_argument("--nd", type=float, default=40)
    ap.add_argument("--heights", type=float, nargs="+", default=[20, 15, 12, 10, 8, 6, 4, 3])
    ap.add_argument("--out", default="docs/figures/height_study.png")
    args = ap.parse_args()

    base = {"geometry": {"nodes_per_meter": args.nd}, "friction": {"L": 5e-5}, "name": "height study"}
    rows = []
    for top in ("traction", "absorbing"):
        for h in args.heights:
            spec = json.loads(json.dumps(base))
            spec["geometry"].update({"height": h, "top_boundary": top})
            m = run(args.binary, spec)
            rows.append((top, h, m))
            print(f"ran top={top:9s} h={h:5.1f} m  wall={m['wall_time_s']:6.2f} s  arrest={m['arrest_position']:.4f} m",
                  file=sys.stderr)
    spec = json.loads(json.dumps(base))
    spec["geometry"]["height"] = "auto"
    auto = run(args.binary, spec)
    rows.append(("traction", "auto", auto))

    ref = next(m for top, h, m in rows if top == "traction" and h == max(args.heights))
    print(f"Paper run L = 5e-5 m, n_d = {args.nd:g}; reference: h = {max(args.heights):g} m, traction top "
          f"(arrest {ref['arrest_position']:.4f} m, arrival at x1 = 11 m {ref['arrival_time_at_probe']:.4f} s).\n")
    print("| top | h [m] | wall [s] | arrest x1 [m] | arrest error [%] | arrival at 11 m [s] | arrival error [%] | warning |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    series = {}
    for top, h, m in rows:
        ea = 100 * abs(m["arrest_position"] - ref["arrest_position"]) / ref["arrest_position"]
        at = m["arrival_time_at_probe"]
        et = float("nan") if at is None else 100 * abs(at - ref["arrival_time_at_probe"]) / ref["arrival_time_at_probe"]
        hh = m["mesh"]["height"]
        label = f"auto ({hh:.3g})" if h == "auto" else f"{h:g}"
        print(f"| {top} | {label} | {m['wall_time_s']:.2f} | {m['arrest_position']:.4f} | {ea:.3f} | "
              f"{at if at is not None else float('nan'):.4f} | {et:.3f} | {'yes' if m['warnings'] else ''} |")
        if h != "auto":
            series.setdefault(top, []).append((m["wall_time_s"], max(ea, 1e-4), max(et, 1e-4), h))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, k, title in ((axes[0], 1, "arrest position"), (axes[1], 2, "arrival time at x1 = 11 m")):
        for top, pts in series.items():
            ax.loglog([p[0] for p in pts], [p[k] for p in pts], "o-", label=f"{top} top")
            for p in pts:
                ax.annotate(f"h={p[3]:g}", (p[0], p[k]), fontsize=7, xytext=(3, 3), textcoords="offset points")
        ax.set_xlabel("wall time [s]")
        ax.set_ylabel("relative error [%] (floored at 1e-4)")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.suptitle(f"Paper run L = 5e-5 m, n_d = {args.nd:g}: error vs cost as the block height shrinks")
    fig.tight_layout()
    os.makedirs(os.path.dirname(args.out) or ".", exist_ok=True)
    fig.savefig(args.out, dpi=120)
    print(f"\nchart: {args.out}")


if __name__ == "__main__":
    main()

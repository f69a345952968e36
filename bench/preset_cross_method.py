#!/usr/bin/python3
"""FE against BI on a scene preset: rupture times at the stations and the rupture's extents.

Runs the preset (`slipfront presets NAME`) by the spectral BI method and by FE with two
blocks at the same element size, and prints a markdown table: each station's rupture time
by both methods and their relative difference, the extents of the ruptured stretch (the
smallest and largest x1 the front reached) and their difference relative to the propagation
distance, the wall time of each run. The bars of the cross-method check: rupture times within 1 %, extents
within 2 %. Stations inside an overstressed nucleation patch slip at t ~ 0 by construction
and are listed but not compared; a station that ruptured by one method and not by the other
fails the comparison. The FE blocks are those of the preset (its `fe` members: for the
bimaterial presets 40 m each with absorbing far boundaries standing in for BI's
half-spaces) unless --height says otherwise ("auto" keeps every reflection out, at much more
cost). --width and --duration cut the scene down (centred on x1 = 0; stations outside are
dropped) for a quick check such as the ctest `verification.presets_cross_method`.
Exit status 0 when both bars hold, 1 when not.

usage: /usr/bin/python3 bench/preset_cross_method.py bimaterial_prakash_clifton
           [--binary build/slipfront] [--nd 5] [--height 40|auto] [--threads 2]
           [--width W] [--duration T] [--json-out FILE]
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile


def run(binary, spec, threads):
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(spec, f)
        path = f.name
    try:
        out = subprocess.run([binary, "run", path, "--quiet", "--threads", str(threads)],
                             capture_output=True, text=True)
    finally:
        os.unlink(path)
    if out.returncode not in (0, 3):
        sys.exit(f"slipfront run failed ({out.returncode}): {out.stderr.strip()}")
    return json.loads(out.stdout)


def extents(m):
    if m.get("arrest_position") is None or m.get("propagation_distance") is None:
        return None, None
    return m["arrest_position"] - m["propagation_distance"], m["arrest_position"]


def relative(a, b):
    if a is None or b is None:
        return None
    return abs(a - b) / abs(b) if b != 0 else math.inf


def pct(x):
    return "—" if x is None else f"{100 * x:.3f} %"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("preset")
    ap.add_argument("--binary", default="build/slipfront")
    ap.add_argument("--nd", type=float, help="nodes per metre (default: the preset's)")
    ap.add_argument("--height", help="each FE block's height in m, or auto (default: the "
                    "preset's FE members)")
    ap.add_argument("--width", type=float, help="periodic width in m, centred on x1 = 0 "
                    "(default: the preset's)")
    ap.add_argument("--duration", type=float, help="simulated time in s (default: the preset's)")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--json-out", help="write both runs' metrics here")
    args = ap.parse_args()

    preset = json.loads(subprocess.run([args.binary, "presets", args.preset], check=True,
                                       capture_output=True, text=True).stdout)
    job = {"preset": args.preset, "geometry": {}}
    if args.nd:
        job["geometry"]["nodes_per_meter"] = args.nd
    if args.width:
        job["geometry"].update(width=args.width, x_min=-args.width / 2)
        stations = preset.get("stations", {}).get("x1", [])
        job["stations"] = {"x1": [x for x in stations if abs(x) < args.width / 2]}
        probe = preset.get("probe", {})
        for key in ("arrival_x1", "spectrum_x1"):  # the probes must stay in the domain
            if key in probe and abs(probe[key]) >= args.width / 2:
                job.setdefault("probe", {})[key] = math.copysign(0.4 * args.width, probe[key])
    if args.duration:
        job["time"] = {"duration": args.duration}
    bi = run(args.binary, dict(job, method="spectral_bi"), args.threads)
    fe_job = json.loads(json.dumps(dict(job, method="fe")))
    if args.height:
        height = args.height if args.height == "auto" else float(args.height)
        fe_job["geometry"].update(height=height, top_boundary="absorbing")
        fe_job["lower"] = {"height": height, "bottom_boundary": "absorbing"}
    fe = run(args.binary, fe_job, args.threads)
    if args.json_out:
        with open(args.json_out, "w") as f:
            json.dump({"preset": preset, "bi": bi, "fe": fe}, f, indent=1)

    print(f"### {args.preset}: FE (two blocks, {fe['mesh']['ny']} nodes high each) against BI, "
          f"dx = {bi['mesh']['dx']} m" + (f", width {args.width:g} m" if args.width else "")
          + (f", {args.duration:g} s" if args.duration else "") + "\n")
    print(f"BI: {bi['steps']} steps, dt = {bi['dt']:.4g} s, {bi['wall_time_s']:.1f} s wall, "
          f"outcome {bi['outcome']}; FE: {fe['steps']} steps, dt = {fe['dt']:.4g} s, "
          f"{fe['wall_time_s']:.1f} s wall, {fe['mesh']['nx']} x {fe['mesh']['ny']} nodes per "
          f"block, outcome {fe['outcome']}\n")
    print("| station x1 [m] | rupture time BI [s] | FE [s] | difference |")
    print("| --- | --- | --- | --- |")
    worst_time = 0.0
    patch = preset.get("nucleation", {})
    in_patch = (lambda x: patch.get("x1_min", 1) <= x <= patch.get("x1_max", 0)) \
        if patch.get("type") == "overstressed_patch" else (lambda x: False)
    for s_bi, s_fe in zip(bi.get("stations", []), fe.get("stations", [])):
        fmt = lambda t: "never" if t is None else f"{t:.6f}"  # noqa: E731
        if in_patch(s_bi["x1"]):
            # Overstressed from the start: it slips at t ~ 0 by construction, and a relative
            # difference of two times near zero measures nothing.
            print(f"| {s_bi['x1']:g} | {fmt(s_bi['rupture_time'])} | {fmt(s_fe['rupture_time'])} "
                  "| in the nucleation patch (not compared) |")
            continue
        t_bi, t_fe = s_bi["rupture_time"], s_fe["rupture_time"]
        d = relative(t_fe, t_bi)
        if (t_bi is None) != (t_fe is None):
            d = math.inf  # ruptured by one method only
        if d is not None:
            worst_time = max(worst_time, d)
        print(f"| {s_bi['x1']:g} | {fmt(s_bi['rupture_time'])} | {fmt(s_fe['rupture_time'])} | {pct(d)} |")
    lo_bi, hi_bi = extents(bi)
    lo_fe, hi_fe = extents(fe)
    print("\n| extent | BI [m] | FE [m] | difference / propagation distance |")
    print("| --- | --- | --- | --- |")
    worst_extent = 0.0
    for name, a, b in (("smallest x1", lo_bi, lo_fe), ("largest x1", hi_bi, hi_fe)):
        d = None if a is None or b is None else abs(a - b) / bi["propagation_distance"]
        if d is not None:
            worst_extent = max(worst_extent, d)
        print(f"| {name} | {a} | {b} | {pct(d)} |")
    ok = worst_time <= 0.01 and worst_extent <= 0.02
    print(f"\nlargest rupture-time difference outside the patch {pct(worst_time)} (bar 1 %), largest extent "
          f"difference {pct(worst_extent)} (bar 2 %): {'within' if ok else 'NOT within'} the bars")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""FE against BI on the three scene presets, cut down to run in CI (docs/verification.md 25).

Runs bench/preset_cross_method.py (each preset by both methods at the same element size)
and checks the cross-method bars: station rupture times within 1 %, extents within 2 % of the
propagation distance. The cuts keep what is compared out of reach of what was cut:
- bimaterial_prakash_clifton at dx = 0.1 m, width 200 m, 12 ms (the stations out to
  +-40 m; their rupture times are those of the full 600 m scene to the printed digits);
- bimaterial_slip_weakening at dx = 0.1 m, width 200 m, 25 ms (stations out to +-50 m);
- scec_tpv3_2d at dx = 50 m over 6 s (the full 120 km width; every station, the arrest at the
  +-15 km barrier), and its published behaviour: the front reaches the barrier and stops
  there, sub-Rayleigh between the stations (c_R = 0.9194 c_s for nu = 0.25); and its
  convergence: from dx = 100 m to 50 m each method's rupture times move by less than 1 % and
  the two methods move towards each other.
The full scenes at the presets' own resolution: docs/verification.md.

    /usr/bin/python3 tests/solver/scenes/presets_cross_method.py build/slipfront SOURCE_DIR
"""
import json
import os
import subprocess
import sys
import tempfile

CASES = [
    ("bimaterial_prakash_clifton", ["--nd", "10", "--width", "200", "--duration", "0.012"]),
    ("bimaterial_slip_weakening", ["--nd", "10", "--width", "200", "--duration", "0.025"]),
    ("scec_tpv3_2d", ["--nd", "0.02", "--duration", "6"]),
]
TPV3_COARSE = ["--nd", "0.01", "--duration", "6"]


def compare(binary, source, preset, options, out_dir):
    os.makedirs(out_dir, exist_ok=True)
    out = os.path.join(out_dir, preset + ".json")
    run = subprocess.run([sys.executable, os.path.join(source, "bench", "preset_cross_method.py"),
                          preset, "--binary", binary, "--threads", "1", "--json-out", out]
                         + options, capture_output=True, text=True)
    print(run.stdout)
    if run.returncode not in (0, 1):
        sys.exit(f"{preset}: the comparison failed to run: {run.stderr.strip()}")
    with open(out) as f:
        return run.returncode == 0, json.load(f)


def tpv3_behaviour(runs):
    """The barrier stops the front at |x1| = 15 km; between 7.5 and 12 km the front is
    sub-Rayleigh (c_s = 3464 m/s, nu = 0.25 from c_p = 6000 m/s: c_R = 3184.8 m/s)."""
    failures = []
    for method in ("bi", "fe"):
        m = runs[method]
        lo = m["arrest_position"] - m["propagation_distance"]
        if abs(m["arrest_position"] - 15000) > 1 or abs(lo + 15000) > 1:
            failures.append(f"{method}: front ends at [{lo}, {m['arrest_position']}] m, not the barrier")
        times = {s["x1"]: s["rupture_time"] for s in m["stations"]}
        speed = 4500 / (times[12000] - times[7500])
        print(f"[measure] scec_tpv3_2d {method}: front {speed:.0f} m/s between 7.5 and 12 km "
              f"(c_R = 3184.8 m/s), extents [{lo:g}, {m['arrest_position']:g}] m")
        if not 0.8 * 3184.8 < speed < 3184.8:
            failures.append(f"{method}: front speed {speed:.0f} m/s is not sub-Rayleigh")
    return failures


def station_times(run):
    return {s["x1"]: s["rupture_time"] for s in run["stations"] if s["x1"] != 0}


def tpv3_convergence(coarse, fine):
    """Rupture times at dx = 100 m (coarse) and 50 m (fine): each method's change under
    refinement below 1 %, and the gap between the methods smaller on the finer mesh."""
    failures = []
    for method in ("bi", "fe"):
        a, b = station_times(coarse[method]), station_times(fine[method])
        change = max(abs(b[x] - a[x]) / b[x] for x in b)
        print(f"[measure] scec_tpv3_2d {method}: rupture times change by at most "
              f"{100 * change:.3f} % from dx = 100 m to 50 m")
        if change >= 0.01:
            failures.append(f"{method}: rupture times change by {100 * change:.2f} % (100 -> 50 m)")
    gaps = []
    for runs in (coarse, fine):
        bi, fe = station_times(runs["bi"]), station_times(runs["fe"])
        gaps.append(max(abs(fe[x] - bi[x]) / bi[x] for x in bi))
    print(f"[measure] scec_tpv3_2d: FE-BI gap {100 * gaps[0]:.3f} % at dx = 100 m, "
          f"{100 * gaps[1]:.3f} % at 50 m")
    if not gaps[1] < gaps[0]:
        failures.append("the methods do not approach each other under refinement")
    return failures


def main():
    binary, source = os.path.abspath(sys.argv[1]), sys.argv[2]
    failures = []
    with tempfile.TemporaryDirectory() as out_dir:
        for preset, options in CASES:
            ok, runs = compare(binary, source, preset, options, out_dir)
            if not ok:
                failures.append(f"{preset}: FE and BI differ beyond the bars (table above)")
            if preset == "scec_tpv3_2d":
                failures += tpv3_behaviour(runs)
                _, coarse = compare(binary, source, preset, TPV3_COARSE, out_dir + "/coarse")
                failures += tpv3_convergence(coarse, runs)
    for f in failures:
        print("FAILED:", f)
    print("presets_cross_method:", "passed" if not failures else "failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

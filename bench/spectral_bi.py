#!/usr/bin/python3
"""The spectral boundary-integral (BI) method on the paper's scene: convergence, agreement
with FE, small L, cost (docs/verification.md and docs/performance.md quote its tables).
Over 400 lines on purpose: one script for the method's measurements, each table a function.

Every run is the CLI, `slipfront run JOB.json --quiet` (metrics JSON on stdout), on the
paper's scene (job defaults) with the fields named in its row; the job files are kept in
--work, and the JSON written to --json holds, for every run, the job, the exact command,
the metrics, the peak resident memory of the process, the memory estimate of
`slipfront validate` and the load average just before the run. A run already in --work is
read back, not repeated (--fresh repeats it), so the script can be stopped and restarted.

Sections (all by default; --only picks some):
  a  BI convergence, L = 5e-5 and 5e-6 m: n_d (10..160), time step beta (0.75, 0.5, 0.25,
     0.125 at n_d = 40), memory truncation q (2..32 periods at n_d = 40)
  b  BI against FE where FE converges (L = 1e-4, 5e-5 m; FE n_d = 40 and 80), and L = 1e-3 m
  c  small L by BI: L = 1e-4 .. 1e-6 m along the n_d ladder until convergence (docs/metrics.md);
     plain Coulomb friction too
  d  the BI cost targets (L = 5e-6 m converged < 60 s, the five-L ladder < 2 min,
     L = 5e-5 m at FE n_d = 40 accuracy < 1 s)
  e  BI cost against n_d (growth exponent), FE against BI at the same accuracy
  t  (only when named) re-times the runs d and e quote: --repeats fresh runs each (one for
     FE n_d = 80 and BI n_d >= 160), median wall time, CPU time and the load of each

--quick (the CTest check, about 20-40 s on 2 cores): BI at L = 5e-5 m, n_d = 10, 20, 40 and
FE at n_d = 40; exits non-zero unless BI n_d = 20 -> 40 meets the convergence rule of
docs/metrics.md (propagation distance < 0.5 %, arrival at the probe < 0.1 %) and BI n_d = 40
agrees with FE n_d = 40 within 1 % (arrest position), 0.5 % (arrival at the probe) and 3 %
(peak |V| at x1 = 6 m).

usage: /usr/bin/python3 bench/spectral_bi.py [--binary build/slipfront]
           [--work /tmp/slipfront-bi-bench] [--json bench/results/spectral_bi.json]
           [--only a b c d e] [--max-nd 160] [--with-320] [--fresh] [--quick]
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time

# The convergence rule of docs/metrics.md "Convergence status" (between n_d and 2 n_d).
TOL_DISTANCE, TOL_ARRIVAL = 0.005, 0.001
# The acceptance of BI against FE on the paper's scene.
TOL_ARREST, TOL_PROBE_ARRIVAL, TOL_PEAK_V = 0.01, 0.005, 0.03
METRICS = ("arrest_position", "propagation_distance", "arrival_time_at_probe",
           "max_slip_velocity", "spectral_velocity", "wall_time_s")
ND_LADDER = (10, 20, 40, 80, 160)
SMALL_L = (1e-4, 5e-5, 1e-5, 5e-6, 1e-6)


def loadavg():
    with open("/proc/loadavg") as f:
        return [float(x) for x in f.read().split()[:3]]


class Runner:
    def __init__(self, binary, work, fresh):
        self.binary, self.work, self.fresh = binary, work, fresh
        self.records = {}
        os.makedirs(work, exist_ok=True)

    @staticmethod
    def name(method, L, nd, law="prakash_clifton", beta=None, q=None, probe=None):
        parts = [method, "coulomb" if law == "coulomb" else f"L{L:g}", f"nd{nd:g}"]
        if probe is not None:
            parts.append(f"probe{probe:g}")
        if beta is not None:
            parts.append(f"beta{beta:g}")
        if q is not None:
            parts.append(f"q{q:g}")
        return "_".join(parts)

    @staticmethod
    def spec(method, L, nd, law="prakash_clifton", beta=None, q=None, probe=None):
        friction = {"law": "coulomb"} if law == "coulomb" else {"L": L}
        spec = {"geometry": {"nodes_per_meter": nd}, "friction": friction}
        if probe is not None:
            spec["probe"] = {"arrival_x1": probe}
        if method == "spectral_bi":
            spec["method"] = "spectral_bi"
            options = {}
            if beta is not None:
                options["time_step_factor"] = beta
            if q is not None:
                options["memory_periods"] = q
            if options:
                spec["spectral_bi"] = options
        return spec

    def run(self, method, L, nd, law="prakash_clifton", beta=None, q=None, output=False, probe=None):
        """One run (or its record from --work). output: also write the HDF5 result and read
        the peak |V| at the spectrum probe from /probes (Coulomb runs have no
        spectral_velocity metric)."""
        name = self.name(method, L, nd, law, beta, q, probe)
        if name in self.records:
            return self.records[name]
        spec = dict(self.spec(method, L, nd, law, beta, q, probe), name=f"bench/spectral_bi.py {name}")
        job = os.path.join(self.work, name + ".job.json")
        record_path = os.path.join(self.work, name + ".record.json")
        if not self.fresh and os.path.exists(record_path):
            with open(record_path) as f:
                record = json.load(f)
            if not output or record.get("probe_peak_velocity") is not None:
                self.records[name] = record
                return record
        with open(job, "w") as f:
            json.dump(spec, f, indent=1)
        h5 = os.path.join(self.work, name + ".h5")
        command = [self.binary, "run", job, "--quiet"] + (["--output", h5] if output else [])
        validate = subprocess.run([self.binary, "validate", job], capture_output=True, text=True)
        estimate = None
        for line in validate.stdout.splitlines():
            if line.startswith("memory_estimate_bytes:"):
                estimate = float(line.split(":")[1].split()[0])
        load = loadavg()
        print(f"running {name} (load {load[0]:.2f}) ...", file=sys.stderr, flush=True)
        t0 = time.time()
        # Reaped with os.wait4 so that ru_maxrss is this child's alone.
        with open(os.path.join(self.work, name + ".stderr"), "w+") as err_file:
            child = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=err_file, text=True)
            out = child.stdout.read()
            _, status, usage = os.wait4(child.pid, 0)
            child.returncode = os.waitstatus_to_exitcode(status)
            err_file.seek(0)
            err = err_file.read()
        wall_outer = time.time() - t0
        rss_kb = usage.ru_maxrss
        if child.returncode in (0, 3):  # 3: the run diverged (metrics still printed)
            metrics = json.loads(out)
        else:  # recorded, not fatal: the tables show the failure
            print(f"{' '.join(command)} failed ({child.returncode}): {err.strip()}", file=sys.stderr)
            metrics = {"outcome": f"failed (exit {child.returncode})", "steps": 0, "wall_time_s": wall_outer,
                       "mesh": {"nx": 0}, "message": err.strip()[-500:]}
        record = {"name": name, "method": method, "L": L, "n_d": nd, "law": law,
                  "beta": beta, "q": q, "job": spec, "command": " ".join(command),
                  "loadavg_before": load, "loadavg_after": loadavg(),
                  "process_wall_s": wall_outer, "cpu_s": usage.ru_utime + usage.ru_stime, "peak_rss_mb": rss_kb / 1024 if rss_kb else None,
                  "memory_estimate_bytes": estimate, "metrics": metrics,
                  "date_utc": time.strftime("%Y-%m-%d %H:%M:%S", time.gmtime())}
        if output:
            record["probe_peak_velocity"] = probe_peak(h5)
            os.remove(h5)
        with open(record_path, "w") as f:
            json.dump(record, f, indent=1)
        self.records[name] = record
        return record


def probe_peak(h5):
    import h5py
    import numpy as np
    with h5py.File(h5, "r") as f:
        return float(np.max(np.abs(f["probes/slip_velocity_spectrum"][:])))


def m(record, key):
    if key == "peak_v6":  # peak |V| at x1 = 6 m: the metric, or /probes for Coulomb runs
        value = record["metrics"].get("spectral_velocity")
        if value is None or (isinstance(value, float) and math.isnan(value)):
            value = record.get("probe_peak_velocity")
        return float("nan") if value is None else value
    if key == "wall_time_s":
        return record["metrics"]["wall_time_s"]
    value = record["metrics"].get(key)
    return float("nan") if value is None else value


def rel(a, b):
    if a is None or b is None or b == 0 or any(isinstance(v, float) and math.isnan(v) for v in (a, b)):
        return float("nan")
    return (a - b) / b


def f(value, spec=".5g"):
    if value is None or (isinstance(value, float) and (math.isnan(value) or math.isinf(value))):
        return "—"
    return format(value, spec)


def pct(value, digits=3):
    return "—" if value is None or math.isnan(value) else f"{100 * value:.{digits}f} %"


def load_text(record):
    return f"{record['loadavg_before'][0]:.2f}"


# ------------------------------------------------------------------------------------------
def convergence_table(title, records, axis, axis_label, dx_of=None):
    """records: ordered by refinement. Prints values, successive differences and observed
    orders; returns the rows as data."""
    keys = ("arrest_position", "propagation_distance", "arrival_time_at_probe",
            "max_slip_velocity", "peak_v6")
    print(f"\n#### {title}\n")
    print(f"| {axis_label} | outcome | arrest [m] | propagation [m] | arrival at 11 m [s] "
          "| max V [mm/s] | peak V at 6 m [mm/s] | steps | wall [s] | load |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for r in records:
        print(f"| {r[axis]:g} | {r['metrics']['outcome']} | {f(m(r, 'arrest_position'), '.4f')} "
              f"| {f(m(r, 'propagation_distance'), '.4f')} | {f(m(r, 'arrival_time_at_probe'), '.5f')} "
              f"| {f(1e3 * m(r, 'max_slip_velocity'), '.4f')} | {f(1e3 * m(r, 'peak_v6'), '.4f')} "
              f"| {r['metrics']['steps']} | {m(r, 'wall_time_s'):.2f} | {load_text(r)} |")
    diffs = []
    for a, b in zip(records, records[1:]):
        row = {"from": a[axis], "to": b[axis]}
        for k in keys:
            row[k] = rel(m(b, k), m(a, k))
        if dx_of:
            row["arrest_shift_in_dx"] = (m(b, "arrest_position") - m(a, "arrest_position")) / dx_of(b)
        diffs.append(row)
    orders = []
    for d1, d2 in zip(diffs, diffs[1:]):
        row = {"over": f"{d1['from']:g}-{d1['to']:g}-{d2['to']:g}"}
        for k in keys:
            a, b = abs(d1[k]), abs(d2[k])
            ratio = math.log(d1["from"] / d1["to"]) if d1["from"] != d1["to"] else 1.0
            row[k] = math.log(a / b) / abs(ratio) if a > 0 and b > 0 else float("nan")
        orders.append(row)
    print(f"\nSuccessive relative differences (value at the next {axis_label} minus this one, "
          "over this one) and observed order p = log(|d_i| / |d_i+1|) / log(refinement ratio):\n")
    print("| step | arrest | (in dx of the finer) | propagation | arrival at 11 m | max V | peak V at 6 m |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for d in diffs:
        shift = f(d.get("arrest_shift_in_dx"), '+.2f') if dx_of else "—"
        print(f"| {d['from']:g} → {d['to']:g} | {pct(d['arrest_position'])} | {shift} "
              f"| {pct(d['propagation_distance'])} | {pct(d['arrival_time_at_probe'], 4)} "
              f"| {pct(d['max_slip_velocity'])} | {pct(d['peak_v6'])} |")
    for o in orders:
        print(f"| order {o['over']} | p = {f(o['arrest_position'], '.2f')} | | "
              f"p = {f(o['propagation_distance'], '.2f')} | p = {f(o['arrival_time_at_probe'], '.2f')} "
              f"| p = {f(o['max_slip_velocity'], '.2f')} | p = {f(o['peak_v6'], '.2f')} |")
    return {"runs": [r["name"] for r in records], "differences": diffs, "orders": orders}


def section_a(runner, args, out):
    out["a"] = {}
    for L in (5e-5, 5e-6):
        nds = [nd for nd in ND_LADDER if nd <= args.max_nd]
        rs = [runner.run("spectral_bi", L, nd) for nd in nds]
        out["a"][f"L{L:g}_nd"] = convergence_table(
            f"a. BI, L = {L:g} m: refinement of n_d (beta 0.5, q 8)", rs, "n_d", "n_d",
            dx_of=lambda r: 1.0 / r["n_d"])
        rs = []
        for beta in (0.75, 0.5, 0.25, 0.125) + ((0.0625,) if args.fine_beta else ()):
            r = runner.run("spectral_bi", L, 40, beta=None if beta == 0.5 else beta)
            r = dict(r, beta=beta)
            rs.append(r)
        out["a"][f"L{L:g}_beta"] = convergence_table(
            f"a. BI, L = {L:g} m: refinement of dt = beta dx / c_s (n_d = 40, q 8)", rs, "beta",
            "beta", dx_of=lambda r: 1.0 / r["n_d"])
        rs = []
        for q in (2, 4, 8, 16, 32):
            r = runner.run("spectral_bi", L, 40, q=None if q == 8 else q)
            rs.append(dict(r, q=q))
        # q grows: the "refinement ratio" is 1/2 per step; the order is in 1/q.
        rows = [dict(r, inv_q=1.0 / r["q"]) for r in rs]
        out["a"][f"L{L:g}_q"] = convergence_table(
            f"a. BI, L = {L:g} m: memory truncation after q mode periods (n_d = 40, beta 0.5)",
            rows, "q", "q", dx_of=lambda r: 1.0 / r["n_d"])


def section_b(runner, args, out):
    print("\n#### b. BI against FE on the paper's scene\n")
    print("Relative difference (FE − BI)/BI; acceptance: arrest 1 %, "
          "arrival at 11 m 0.5 %, peak |V| at x1 = 6 m 3 %.\n")
    print("| L [m] | FE n_d | BI n_d | FE arrest / BI arrest [m] | diff | FE / BI arrival [s] | diff "
          "| FE / BI peak V at 6 m [mm/s] | diff | within |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    rows = []
    bi_nds = [nd for nd in (40, 80, 160) if nd <= args.max_nd]
    for L in (1e-4, 5e-5):
        for fe_nd in (40, 80):
            fe = runner.run("fe", L, fe_nd)
            for bi_nd in bi_nds:
                bi = runner.run("spectral_bi", L, bi_nd)
                d = {k: rel(m(fe, k), m(bi, k)) for k in ("arrest_position", "arrival_time_at_probe", "peak_v6")}
                ok = (abs(d["arrest_position"]) <= TOL_ARREST and abs(d["arrival_time_at_probe"]) <= TOL_PROBE_ARRIVAL
                      and abs(d["peak_v6"]) <= TOL_PEAK_V)
                rows.append({"L": L, "fe": fe["name"], "bi": bi["name"], "diff": d, "within": ok})
                print(f"| {L:g} | {fe_nd} | {bi_nd} | {m(fe, 'arrest_position'):.4f} / {m(bi, 'arrest_position'):.4f} "
                      f"| {pct(d['arrest_position'])} | {m(fe, 'arrival_time_at_probe'):.5f} / "
                      f"{m(bi, 'arrival_time_at_probe'):.5f} | {pct(d['arrival_time_at_probe'])} "
                      f"| {1e3 * m(fe, 'peak_v6'):.4f} / {1e3 * m(bi, 'peak_v6'):.4f} | {pct(d['peak_v6'])} "
                      f"| {'yes' if ok else '**no**'} |")
    print("\nL = 1e-3 m (paper: no rupture):\n")
    print("| method | n_d | outcome | max V [m/s] | wall [s] | load |")
    print("| --- | --- | --- | --- | --- | --- |")
    none = []
    for method, nd in (("fe", 40), ("spectral_bi", 40), ("spectral_bi", 160 if args.max_nd >= 160 else 40)):
        r = runner.run(method, 1e-3, nd)
        if r["name"] in [x["name"] for x in none]:
            continue
        none.append(r)
        print(f"| {method} | {nd} | {r['metrics']['outcome']} | {m(r, 'max_slip_velocity'):.3g} "
              f"| {m(r, 'wall_time_s'):.2f} | {load_text(r)} |")
    out["b"] = {"comparisons": rows, "no_rupture": [{"run": r["name"], "outcome": r["metrics"]["outcome"],
                                                      "max_slip_velocity": m(r, "max_slip_velocity")} for r in none]}


def converged_pair(a, b):
    dd = rel(m(b, "propagation_distance"), m(a, "propagation_distance"))
    da = rel(m(b, "arrival_time_at_probe"), m(a, "arrival_time_at_probe"))
    return abs(dd) < TOL_DISTANCE and abs(da) < TOL_ARRIVAL, dd, da


def ladder(runner, args, L, law="prakash_clifton", method="spectral_bi", output=False, probe=None):
    """Runs the n_d ladder until n_d and 2 n_d meet the convergence rule; returns (runs,
    converged n_d)."""
    nds = list(ND_LADDER) + ([320] if args.with_320 else [])
    runs, found = [], None
    for nd in nds:
        if nd > args.max_nd and not (nd == 320 and args.with_320):
            break
        runs.append(runner.run(method, L, nd, law=law, output=output, probe=probe))
        if nd >= 160 and all(math.isnan(m(r, "arrival_time_at_probe")) for r in runs):
            break  # the front never reaches the probe: the arrival rule cannot be met
        if len(runs) >= 2 and converged_pair(runs[-2], runs[-1])[0]:
            found = runs[-2]["n_d"]
            break
    return runs, found


def section_c(runner, args, out):
    print("\n#### c. Small L by BI (beta 0.5, q 8): the n_d ladder until convergence (docs/metrics.md)\n")
    print("| friction | n_d | outcome | arrest [m] | propagation [m] | Δ to next n_d | arrival at 11 m [s] "
          "| Δ to next n_d | peak V at 6 m [mm/s] | wall [s] | load |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    out["c"] = []
    # The last two rows: where the front arrests at or before the probe (x1 = 11 m), its
    # arrival there is undefined or the time the front creeps onto its last node; the same
    # ladders with the probe at x1 = 10 m, inside the ruptured stretch.
    cases = [(L, "prakash_clifton", None) for L in SMALL_L] + [(None, "coulomb", None)]
    cases += [(1e-6, "prakash_clifton", 10.0), (None, "coulomb", 10.0)]
    for L, law, probe in cases:
        runs, found = ladder(runner, args, L, law, output=(law == "coulomb"), probe=probe)
        label = ("Coulomb" if law == "coulomb" else f"L = {L:g}") + (f", probe at {probe:g} m" if probe else "")
        for i, r in enumerate(runs):
            if i + 1 < len(runs):
                _, dd, da = converged_pair(r, runs[i + 1])
            else:
                dd = da = float("nan")
            print(f"| {label} | {r['n_d']} | {r['metrics']['outcome']} | {f(m(r, 'arrest_position'), '.4f')} "
                  f"| {f(m(r, 'propagation_distance'), '.4f')} | {pct(dd)} "
                  f"| {f(m(r, 'arrival_time_at_probe'), '.5f')} | {pct(da, 4)} "
                  f"| {f(1e3 * m(r, 'peak_v6'), '.4f')} "
                  f"| {m(r, 'wall_time_s'):.2f} | {load_text(r)} |")
        print(f"| {label} | **converged from n_d = {found if found else 'none within the ladder'}** | | | | | | | | | |")
        out["c"].append({"L": L, "law": law, "probe": probe, "runs": [r["name"] for r in runs],
                         "converged_nd": found})


def section_d(runner, args, out):
    print("\n#### d. Targets (the BI cost targets)\n")
    d = {}
    # 1. L = 5e-6 m converged: the pair (n_d, 2 n_d) that shows it.
    runs, found = ladder(runner, args, 5e-6)
    if found:
        pair = [r for r in runs if r["n_d"] in (found, 2 * found)]
        total = sum(m(r, "wall_time_s") for r in pair)
        ladder_total = sum(m(r, "wall_time_s") for r in runs)
        d["L5e-6"] = {"pair": [r["name"] for r in pair], "wall_s": total, "ladder_wall_s": ladder_total,
                      "met": total < 60, "loads": [r["loadavg_before"][0] for r in pair]}
        print(f"- L = 5e-6 m converged: n_d = {found} → {2 * found}: "
              + " + ".join(f"{m(r, 'wall_time_s'):.2f} s (load {load_text(r)})" for r in pair)
              + f" = **{total:.2f} s** (whole ladder from n_d = 10: {ladder_total:.2f} s); "
              f"target < 60 s: {'met' if total < 60 else '**not met**'}")
    else:
        print("- L = 5e-6 m: not converged within the ladder")
    # 2. The five-L ladder.
    total_pairs = total_ladders = 0.0
    detail = []
    for L in SMALL_L:
        runs, found = ladder(runner, args, L)
        ladder_wall = sum(m(r, "wall_time_s") for r in runs)
        pair_wall = sum(m(r, "wall_time_s") for r in runs if found and r["n_d"] in (found, 2 * found))
        total_pairs += pair_wall
        total_ladders += ladder_wall
        detail.append({"L": L, "converged_nd": found, "pair_wall_s": pair_wall, "ladder_wall_s": ladder_wall})
    d["five_L"] = {"per_L": detail, "pairs_wall_s": total_pairs, "ladders_wall_s": total_ladders,
                   "met": total_ladders < 120}
    print(f"- the five-L BI ladder (L = {', '.join(f'{L:g}' for L in SMALL_L)} m), each L from n_d = 10 up to "
          f"the pair that converges: **{total_ladders:.1f} s** (only the converged pairs: {total_pairs:.1f} s); "
          f"target < 120 s: {'met' if total_ladders < 120 else '**not met**'}")
    # 3. L = 5e-5 m at the accuracy of FE n_d = 40.
    fe40, fe80 = runner.run("fe", 5e-5, 40), runner.run("fe", 5e-5, 80)
    keys = ("propagation_distance", "arrival_time_at_probe", "arrest_position", "peak_v6")
    fe_err = {k: abs(rel(m(fe40, k), m(fe80, k))) for k in keys}
    bi_ref = runner.run("spectral_bi", 5e-5, max(nd for nd in ND_LADDER if nd <= args.max_nd))
    # Both methods' arrival times converge at first order: their Richardson limits
    # (2 f(dx/2) - f(dx)) from the two finest runs of each method.
    bi_half = runner.run("spectral_bi", 5e-5, bi_ref["n_d"] / 2)
    lim_fe = 2 * m(fe80, "arrival_time_at_probe") - m(fe40, "arrival_time_at_probe")
    lim_bi = 2 * m(bi_ref, "arrival_time_at_probe") - m(bi_half, "arrival_time_at_probe")
    d["arrival_limits"] = {"fe_40_80": lim_fe, "bi_" + f"{bi_half['n_d']:g}_{bi_ref['n_d']:g}": lim_bi,
                           "fe40_error_vs_fe_limit": rel(m(fe40, "arrival_time_at_probe"), lim_fe),
                           "fe40_error_vs_bi_limit": rel(m(fe40, "arrival_time_at_probe"), lim_bi)}
    print(f"- arrival at 11 m, first-order Richardson limits: FE (n_d 40, 80) {lim_fe:.5f} s, BI (n_d "
          f"{bi_half['n_d']:g}, {bi_ref['n_d']:g}) {lim_bi:.5f} s (differ by {pct(rel(lim_fe, lim_bi), 4)}); "
          f"FE n_d = 40 is {pct(rel(m(fe40, 'arrival_time_at_probe'), lim_fe), 4)} from its own limit")
    print("- L = 5e-5 m: FE n_d = 40 against FE n_d = 80: "
          + ", ".join(f"{k} {pct(v)}" for k, v in fe_err.items())
          + f". BI candidates against BI n_d = {bi_ref['n_d']} (and against FE n_d = 80):\n")
    print("| BI run | wall [s] | load | propagation | arrival at 11 m | arrest | peak V at 6 m "
          "| vs FE 80: propagation | arrival | no larger than FE 40's (propagation, arrival) |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    cands = []
    for nd in (10, 15, 20, 30, 40, 80):
        for beta in (1.0, 0.75, 0.5, 0.25, 0.125):
            for q in (2, 4, 8):
                if nd > 20 and (beta, q) not in ((0.5, 8), (1.0, 4), (0.25, 8), (0.125, 8)):
                    continue
                if beta < 0.5 and q != 8 or nd == 80 and beta != 0.5:
                    continue
                r = runner.run("spectral_bi", 5e-5, nd, beta=None if beta == 0.5 else beta, q=None if q == 8 else q)
                err = {k: abs(rel(m(r, k), m(bi_ref, k))) for k in keys}
                err_fe = {k: abs(rel(m(r, k), m(fe80, k))) for k in keys}
                ok = (r["metrics"]["outcome"] == "arrested" and err["propagation_distance"] <= fe_err["propagation_distance"]
                      and err["arrival_time_at_probe"] <= fe_err["arrival_time_at_probe"])
                cands.append({"run": r["name"], "wall_s": m(r, "wall_time_s"), "err": err, "err_vs_fe80": err_fe, "ok": ok})
                print(f"| {r['name']} | {m(r, 'wall_time_s'):.3f} | {load_text(r)} | {pct(err['propagation_distance'])} "
                      f"| {pct(err['arrival_time_at_probe'])} | {pct(err['arrest_position'])} | {pct(err['peak_v6'])} "
                      f"| {pct(err_fe['propagation_distance'])} | {pct(err_fe['arrival_time_at_probe'])} "
                      f"| {'yes' if ok else 'no'} |")
    good = sorted((c for c in cands if c["ok"]), key=lambda c: c["wall_s"])
    d["L5e-5_at_fe40_accuracy"] = {"fe40_error_vs_fe80": fe_err, "bi_reference": bi_ref["name"],
                                   "candidates": cands, "cheapest": good[0] if good else None,
                                   "met": bool(good) and good[0]["wall_s"] < 1.0,
                                   "fe40_wall_s": m(fe40, "wall_time_s")}
    if good:
        print(f"\n- cheapest BI run at least as accurate as FE n_d = 40: **{good[0]['run']}, {good[0]['wall_s']:.3f} s** "
              f"(FE n_d = 40: {m(fe40, 'wall_time_s'):.2f} s, load {load_text(fe40)}); target < 1 s: "
              f"{'met' if good[0]['wall_s'] < 1 else '**not met**'}")
    out["d"] = d


def section_e(runner, args, out):
    print("\n#### e. BI cost against n_d (L = 5e-5 m, beta 0.5, q 8, 2 threads)\n")
    print("| n_d | nodes N | steps | wall [s] | load | µs per step | peak RSS [MB] | estimate (validate) [MB] | growth |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    nds = [nd for nd in ND_LADDER if nd <= args.max_nd] + ([320] if args.with_320 else [])
    rows, prev = [], None
    for nd in nds:
        r = runner.run("spectral_bi", 5e-5, nd)
        w, steps = m(r, "wall_time_s"), r["metrics"]["steps"]
        growth = math.log(w / prev[1]) / math.log(nd / prev[0]) if prev else float("nan")
        rows.append({"n_d": nd, "nodes": r["metrics"]["mesh"]["nx"], "steps": steps, "wall_s": w,
                     "peak_rss_mb": r["peak_rss_mb"], "estimate_mb": (r["memory_estimate_bytes"] or 0) / 1e6,
                     "growth_exponent": growth, "load": r["loadavg_before"][0]})
        print(f"| {nd} | {r['metrics']['mesh']['nx']} | {steps} | {w:.3f} | {load_text(r)} | {1e6 * w / steps:.1f} "
              f"| {f(r['peak_rss_mb'], '.1f')} | {(r['memory_estimate_bytes'] or 0) / 1e6:.1f} | "
              f"{'n_d^' + format(growth, '.2f') if prev else ''} |")
        prev = (nd, w)
    fit = None
    if len(rows) >= 3:
        import numpy as np
        big = [r for r in rows if r["n_d"] >= 40]
        fit = float(np.polyfit(np.log([r["n_d"] for r in big]), np.log([r["wall_s"] for r in big]), 1)[0])
        print(f"\nLeast-squares growth over n_d ≥ 40: wall ∝ n_d^{fit:.2f}")
    print("\nFE against BI at the same accuracy (L = 5e-5 m; error = max of |Δ propagation| and "
          "|Δ arrival at 11 m| against BI n_d = 160):\n")
    print("| method | n_d | wall [s] | load | peak RSS [MB] | error propagation | error arrival |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    ref = runner.run("spectral_bi", 5e-5, max(nd for nd in ND_LADDER if nd <= args.max_nd))
    same = []
    for method, nd in (("fe", 20), ("fe", 40), ("fe", 80), ("spectral_bi", 10), ("spectral_bi", 20),
                       ("spectral_bi", 40), ("spectral_bi", 80)):
        if nd > args.max_nd:
            continue
        r = runner.run(method, 5e-5, nd)
        ep = abs(rel(m(r, "propagation_distance"), m(ref, "propagation_distance")))
        ea = abs(rel(m(r, "arrival_time_at_probe"), m(ref, "arrival_time_at_probe")))
        same.append({"run": r["name"], "wall_s": m(r, "wall_time_s"), "rss_mb": r["peak_rss_mb"],
                     "err_propagation": ep, "err_arrival": ea, "load": r["loadavg_before"][0]})
        print(f"| {method} | {nd} | {m(r, 'wall_time_s'):.2f} | {load_text(r)} | {f(r['peak_rss_mb'], '.0f')} "
              f"| {pct(ep)} | {pct(ea, 4)} |")
    out["e"] = {"cost": rows, "fit_exponent_nd_ge_40": fit, "same_accuracy": same}


def section_t(runner, args, out):
    """Re-times the runs the targets and the cost table quote: each run repeated (--repeats)
    in a fresh work dir, the median wall time reported with the load of each repeat."""
    print(f"\n#### t. Timings ({args.repeats} repeats, median; fresh runs)\n")
    print("| run | wall median [s] | walls [s] | CPU median [s] | load (1 min) at each |")
    print("| --- | --- | --- | --- | --- |")
    cases = [("spectral_bi", L, nd, None) for L in SMALL_L for nd in (10, 20, 40)]
    cases += [("spectral_bi", 1e-6, 80, None), ("spectral_bi", 1e-6, 160, None),
              ("spectral_bi", 5e-5, 80, None), ("spectral_bi", 5e-5, 160, None),
              ("spectral_bi", 5e-5, 20, 0.125), ("spectral_bi", 5e-5, 40, 0.25),
              ("spectral_bi", 5e-5, 15, 0.125), ("fe", 5e-5, 20, None), ("fe", 5e-5, 40, None),
              ("fe", 5e-5, 80, None)]
    if args.with_320:
        cases.append(("spectral_bi", 5e-5, 320, None))
    rows = {}
    for method, L, nd, beta in cases:
        repeats = 1 if (nd >= 160 or (method == "fe" and nd >= 80)) else args.repeats
        recs = []
        for i in range(repeats):
            rr = Runner(runner.binary, os.path.join(runner.work, "timing", f"rep{i}"), True)
            recs.append(rr.run(method, L, nd, beta=beta))
        walls = sorted(m(r, "wall_time_s") for r in recs)
        cpus = sorted(r["cpu_s"] for r in recs)
        name = recs[0]["name"]
        rows[name] = {"walls": walls, "median": walls[len(walls) // 2], "cpu_median": cpus[len(cpus) // 2],
                      "loads": [r["loadavg_before"][0] for r in recs],
                      "commands": [r["command"] for r in recs]}
        print(f"| {name} | {rows[name]['median']:.3f} | {', '.join(f'{w:.3f}' for w in walls)} "
              f"| {rows[name]['cpu_median']:.3f} | {', '.join(f'{x:.2f}' for x in rows[name]['loads'])} |")
    out["t"] = rows


# ------------------------------------------------------------------------------------------
def quick(runner):
    """The CTest check: BI convergence at L = 5e-5 m and agreement with FE at n_d = 40."""
    bi = [runner.run("spectral_bi", 5e-5, nd) for nd in (10, 20, 40)]
    fe = runner.run("fe", 5e-5, 40)
    out = {"bi_ladder": convergence_table("quick: BI, L = 5e-5 m", bi, "n_d", "n_d",
                                          dx_of=lambda r: 1.0 / r["n_d"])}
    failures = []
    ok, dd, da = converged_pair(bi[1], bi[2])
    out["bi_20_40"] = {"propagation": dd, "arrival": da, "converged": ok}
    print(f"\nBI n_d 20 → 40: propagation {pct(dd)} (< 0.5 %), arrival {pct(da, 4)} (< 0.1 %): "
          f"{'converged' if ok else 'NOT converged'}")
    if not ok:
        failures.append("BI n_d = 20 -> 40 does not meet the convergence rule")
    for r in bi + [fe]:
        if r["metrics"]["outcome"] != "arrested":
            failures.append(f"{r['name']}: outcome {r['metrics']['outcome']}")
    d = {k: rel(m(fe, k), m(bi[2], k)) for k in ("arrest_position", "arrival_time_at_probe", "peak_v6")}
    tol = {"arrest_position": TOL_ARREST, "arrival_time_at_probe": TOL_PROBE_ARRIVAL, "peak_v6": TOL_PEAK_V}
    for k, v in d.items():
        good = abs(v) <= tol[k]
        print(f"FE n_d 40 vs BI n_d 40, {k}: {m(fe, k):.6g} vs {m(bi[2], k):.6g}: {pct(v)} "
              f"(tolerance {100 * tol[k]:g} %): {'ok' if good else 'FAIL'}")
        if not good:
            failures.append(f"FE vs BI at n_d = 40: {k} differs by {pct(v)}")
    out["fe_vs_bi_40"] = d
    out["failures"] = failures
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default="build/slipfront")
    ap.add_argument("--work", default="/tmp/slipfront-bi-bench")
    ap.add_argument("--json", default=None, help="default: WORK/spectral_bi.json")
    ap.add_argument("--only", nargs="+", default=["a", "b", "c", "d", "e"],
                    help="sections; t (re-timing, not in the default) repeats the quoted runs fresh")
    ap.add_argument("--repeats", type=int, default=3, help="repeats per run in section t")
    ap.add_argument("--max-nd", type=float, default=160)
    ap.add_argument("--with-320", action="store_true", help="n_d = 320 in the ladders and the cost table")
    ap.add_argument("--fine-beta", action="store_true", help="add beta = 0.0625 to the dt ladder of a")
    ap.add_argument("--fresh", action="store_true", help="repeat runs already in --work")
    ap.add_argument("--quick", action="store_true", help="the short CTest check (see above)")
    args = ap.parse_args()
    runner = Runner(args.binary, args.work, args.fresh)
    out = {"started_utc": time.strftime("%Y-%m-%d %H:%M:%S", time.gmtime()), "loadavg_start": loadavg(),
           "binary": args.binary, "argv": sys.argv}
    started = time.time()
    if args.quick:
        out["quick"] = quick(runner)
    else:
        for section, fn in (("a", section_a), ("b", section_b), ("c", section_c), ("d", section_d),
                            ("e", section_e), ("t", section_t)):
            if section in args.only:
                fn(runner, args, out)
    out["runs"] = runner.records
    out["loadavg_end"] = loadavg()
    out["elapsed_s"] = time.time() - started
    path = args.json or os.path.join(args.work, "spectral_bi.json")
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    with open(path, "w") as fh:
        json.dump(out, fh, indent=1, default=str)
    print(f"\nall measurements: {path} ({len(runner.records)} runs, {out['elapsed_s']:.0f} s)", file=sys.stderr)
    if args.quick and out["quick"]["failures"]:
        print("FAILED: " + "; ".join(out["quick"]["failures"]), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Stations of real runs, FE and spectral BI, read back with h5py (docs/hdf5-layout.md
"/stations"): every step recorded; on a node the station's series are that node's /interface
columns bit for bit (the interface sampled every step); between two nodes, and across the
periodic seam, their weighted sum; the rupture time is the first crossing of the recorded
|slip_rate|, the same in the file, the metrics and the CSV of `slipfront stations`. The same
run without stations has no /stations group and every other number the same, bit for bit.

usage: check_stations.py SLIPFRONT WORK_DIR
"""
import json
import math
import os
import subprocess
import sys

import h5py
import numpy as np

# The paper's domain [-10, 30) at n_d = 10 (dx = 0.1 m): stations on nodes (0, 6, 11), halfway
# between two (6.05), and between the last node (29.9) and x_min + width = node 0 (29.95).
STATIONS = [0.0, 6.0, 6.05, 11.0, 29.95]
SEAM = 4
JOBS = {
    "fe": {"geometry": {"nodes_per_meter": 10}, "time": {"duration": 6}},
    "spectral_bi": {"method": "spectral_bi", "geometry": {"nodes_per_meter": 10},
                    "time": {"duration": 6}},
}
SERIES = {"slip_rate": "m/s", "slip": "m", "shear_traction": "Pa", "normal_traction": "Pa"}


def fail(message):
    sys.exit(f"check_stations: {message}")


def expect(condition, message):
    if not condition:
        fail(message)


def run(slipfront, job, work_dir, name):
    job_path = os.path.join(work_dir, f"{name}.json")
    result = os.path.join(work_dir, f"{name}.h5")
    with open(job_path, "w") as f:
        json.dump(job, f)
    done = subprocess.run([slipfront, "run", job_path, "--output", result, "--quiet",
                           "--threads", "1"], capture_output=True, text=True, timeout=600)
    expect(done.returncode == 0, f"{name}: exit {done.returncode}: {done.stderr}")
    return result, json.loads(done.stdout)


def first_crossing(time, speed, threshold):
    """The rupture time rule of docs/hdf5-layout.md, from a recorded series."""
    above = np.nonzero(np.abs(speed) > threshold)[0]
    if above.size == 0:
        return math.nan
    k = above[0]
    if k == 0:
        return time[0]
    before, now = abs(speed[k - 1]), abs(speed[k])
    return time[k - 1] + (threshold - before) / (now - before) * (time[k] - time[k - 1])


def check_file(name, path, metrics):
    with h5py.File(path, "r") as f:
        s, i = f["stations"], f["interface"]
        threshold = s.attrs["rupture_threshold"]
        # One threshold: the front's (the paper's 1e-6 m/s), the job giving none of its own.
        expect(threshold == metrics["front_threshold"] == 1e-6,
               f"{name}: rupture_threshold {threshold}")
        expect(s["x1"][()].tolist() == STATIONS, f"{name}: /stations/x1 {s['x1'][()]}")
        time = s["time"][()]
        m, n = time.size, len(STATIONS)
        expect(m == metrics["steps"], f"{name}: {m} rows for {metrics['steps']} steps")
        expect(np.allclose(time, np.arange(m) * metrics["dt"], rtol=0, atol=1e-12 * time[-1]),
               f"{name}: /stations/time is not every step")
        expect(np.array_equal(i["time"][()], time), f"{name}: /interface is not every step")
        for field, units in SERIES.items():
            d = s[field]
            expect(d.shape == (m, n), f"{name}: {field} shape {d.shape}")
            expect(d.attrs["units"] == units, f"{name}: {field} units {d.attrs['units']!r}")
            scales = [[scale.name for scale in dim.values()] for dim in d.dims]
            expect(scales == [["/stations/time"], ["/stations/x1"]],
                   f"{name}: {field} scales {scales}")
        node_x1, weight = s["node_x1"][()], s["node_weight"][()]
        x1 = i["x1"][()]
        interface = {"slip_rate": i["slip_velocity"][()], "slip": i["slip"][()],
                     "shear_traction": i["shear_traction"][()],
                     "normal_traction": -i["contact_pressure"][()]}
        for k, station in enumerate(STATIONS):
            columns = [int(np.argmin(np.abs(x1 - node_x1[k, j]))) for j in range(2)]
            expect(all(abs(x1[c] - node_x1[k, j]) < 1e-9 for j, c in enumerate(columns)),
                   f"{name}: the nodes of {station} are not interface nodes")
            on_node = weight[k, 1] == 0.0
            expect(on_node == (station in (0.0, 6.0, 11.0)), f"{name}: station {station} weights")
            for field in SERIES:
                got = s[field][:, k]
                if on_node:
                    expect(np.array_equal(got, interface[field][:, columns[0]]),
                           f"{name}: {field} at {station} is not its node's, bit for bit")
                else:
                    want = (weight[k, 0] * interface[field][:, columns[0]]
                            + weight[k, 1] * interface[field][:, columns[1]])
                    scale = np.max(np.abs(interface[field])) or 1.0
                    expect(np.allclose(got, want, rtol=0, atol=1e-13 * scale),
                           f"{name}: {field} at {station} is not the nodes' weighted sum")
            if not on_node:
                expect(abs(weight[k, 0] - 0.5) < 1e-9, f"{name}: weights at {station}")
        expect(np.allclose(node_x1[SEAM], [29.9, -10.0], rtol=0, atol=1e-12),
               f"{name}: the seam station reads {node_x1[SEAM]}")
        expect(np.all(s["normal_traction"][0, :] < 0), f"{name}: normal traction not compressive")
        rupture = s["rupture_time"][()]
        for k in range(n):
            want = first_crossing(time, s["slip_rate"][:, k], threshold)
            got = rupture[k]
            expect((math.isnan(want) and math.isnan(got)) or abs(got - want) <= 1e-12 * time[-1],
                   f"{name}: rupture time at {STATIONS[k]}: {got}, recomputed {want}")
            listed = metrics["stations"][k]
            expect(listed["x1"] == STATIONS[k], f"{name}: metrics station {k} x1")
            expect((listed["rupture_time"] is None and math.isnan(got)) or
                   listed["rupture_time"] == got, f"{name}: metrics rupture time at {STATIONS[k]}")
        expect(not math.isnan(rupture[1]) and rupture[2] > rupture[1],
               f"{name}: the rupture must reach 6 m and then 6.05 m: {rupture}")
        return s["slip"][()], s["slip_rate"][()], time, rupture


def check_csv(slipfront, name, path, stored):
    slip, slip_rate, time, rupture = stored
    done = subprocess.run([slipfront, "stations", path, "--csv", "-"], capture_output=True,
                          text=True, timeout=60)
    expect(done.returncode == 0, f"{name}: stations --csv exit {done.returncode}: {done.stderr}")
    lines = done.stdout.splitlines()
    comments = [line for line in lines if line.startswith("#")]
    expect(any("slip_rate [m/s]" in c for c in comments), f"{name}: no units in the CSV header")
    rows = [line for line in lines if not line.startswith("#")]
    expect(rows[0] == "station_x1,time,slip,slip_rate,shear_traction,normal_traction",
           f"{name}: CSV header {rows[0]!r}")
    values = np.array([[float(v) for v in row.split(",")] for row in rows[1:]])
    m = time.size
    expect(values.shape == (m * len(STATIONS), 6), f"{name}: CSV shape {values.shape}")
    for k, station in enumerate(STATIONS):
        block = values[k * m:(k + 1) * m]
        expect(np.all(block[:, 0] == station), f"{name}: CSV station column")
        expect(np.array_equal(block[:, 1], time), f"{name}: CSV time at {station}")
        expect(np.array_equal(block[:, 2], slip[:, k]), f"{name}: CSV slip at {station}")
        expect(np.array_equal(block[:, 3], slip_rate[:, k]), f"{name}: CSV slip_rate at {station}")
        listed = [c for c in comments if c.startswith(f"# station_x1 = {station:g}:")]
        expect(len(listed) == 1, f"{name}: no rupture time comment for {station}")
        text = listed[0].rsplit("= ", 1)[1]
        expect(text == "nan" if math.isnan(rupture[k]) else float(text) == rupture[k],
               f"{name}: CSV rupture time {text} at {station}")
    table = subprocess.run([slipfront, "stations", path], capture_output=True, text=True,
                           timeout=60)
    expect(table.returncode == 0 and "rupture_time [s]" in table.stdout and
           "(on the node)" in table.stdout, f"{name}: stations table:\n{table.stdout}")


def datasets(path, skip):
    """Every dataset of a result file outside the group `skip`, by name."""
    found = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda name, obj: found.__setitem__(name, obj[()])
                     if isinstance(obj, h5py.Dataset) and not name.startswith(skip) else None)
    return found


def check_same_run_without(slipfront, work_dir, method, job, path, metrics):
    """The same job without stations: no /stations group, no metrics entry, the command says
    so, and every other number is the same, bit for bit (stations only watch the interface,
    which is why they stay out of the scene hash: docs/api-job-spec.md)."""
    plain = {k: v for k, v in job.items() if k != "stations"}
    plain_path, plain_metrics = run(slipfront, plain, work_dir, f"no_stations_{method}")
    with h5py.File(plain_path, "r") as f:
        expect("stations" not in f, f"{method}: a run without stations has a /stations group")
    expect("stations" not in plain_metrics, f"{method}: metrics list stations without any")
    # spec_sha256: the stations are part of the job (not of its scene); provenance: the job's
    # values, with the stations' threshold among them
    varying = {"stations", "spec_sha256", "wall_time_s", "result_file", "provenance"}
    for key in set(metrics) | set(plain_metrics):
        if key not in varying:
            expect(metrics.get(key) == plain_metrics.get(key),
                   f"{method}: metric {key} changes with stations: {metrics.get(key)} vs "
                   f"{plain_metrics.get(key)}")
    with_stations, without = datasets(path, "stations"), datasets(plain_path, "stations")
    expect(sorted(with_stations) == sorted(without), f"{method}: other datasets differ")
    for name, values in without.items():
        expect(np.array_equal(with_stations[name], values, equal_nan=values.dtype.kind == "f"),
               f"{method}: /{name} changes with stations")
    done = subprocess.run([slipfront, "stations", plain_path], capture_output=True, text=True,
                          timeout=60)
    expect(done.returncode == 1 and "has no stations" in done.stderr,
           f"stations of a file without: exit {done.returncode}: {done.stderr}")


def main():
    if len(sys.argv) != 3:
        fail(__doc__)
    slipfront, work_dir = sys.argv[1:3]
    os.makedirs(work_dir, exist_ok=True)
    for method, base in JOBS.items():
        job = dict(base, stations={"x1": STATIONS},
                   output={"interval": 1e-9, "space_stride": 1})
        path, metrics = run(slipfront, job, work_dir, f"stations_{method}")
        stored = check_file(method, path, metrics)
        check_csv(slipfront, method, path, stored)
        check_same_run_without(slipfront, work_dir, method, job, path, metrics)
        print(f"ok {method}: {stored[2].size} steps, rupture times {stored[3].tolist()}; "
              "the same run without stations: no /stations, every other number the same")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Checks a slipfront HDF5 result file against docs/hdf5-layout.md with h5py.

usage: check_result_file.py RESULT.h5 [--synthetic]

--synthetic also checks the values written by write_synthetic_result (tests/api).
Exits non-zero with a message on the first violation.
"""
import json
import sys

import h5py
import numpy as np

INTERFACE_FIELDS = {
    "slip_velocity": "m/s",
    "slip": "m",
    "shear_traction": "Pa",
    "contact_pressure": "Pa",
    "strength": "Pa",
}
PROBES = {
    "time": "s",
    "slip_velocity_arrival": "m/s",
    "slip_velocity_spectrum": "m/s",
    "strength_spectrum": "Pa",
}
ENERGY = {"time": "s", "kinetic": "J/m", "strain": "J/m", "external_work": "J/m", "dissipated": "J/m"}
FRONT = {"x1": "m", "arrival_time": "s", "rupture_speed": "m/s"}
METRICS = [
    "front_threshold", "arrest_position", "propagation_distance", "arrival_time_at_probe",
    "rupture_speed", "max_slip_velocity", "outcome", "energy_error", "wall_time_s", "steps", "dt",
    "stable_dt", "simulated_time", "spectral_critical_length", "mesh", "code_version", "method",
    "method_description",
]
OUTCOMES = {"arrested", "running_at_end", "no_rupture"}  # a diverged run leaves no file


def fail(message):
    sys.exit(f"check_result_file: {message}")


def expect(condition, message):
    if not condition:
        fail(message)


def dataset(f, path, units, dtype=np.float64, ndim=1):
    expect(path in f, f"missing dataset {path}")
    d = f[path]
    expect(isinstance(d, h5py.Dataset), f"{path} is not a dataset")
    expect(d.dtype == dtype, f"{path} has dtype {d.dtype}, expected {dtype}")
    expect(d.ndim == ndim, f"{path} has shape {d.shape}, expected {ndim} dimension(s)")
    expect(d.attrs.get("units") == units, f"{path} units {d.attrs.get('units')!r}, expected {units!r}")
    return d


def check_interface(f):
    x1 = dataset(f, "/interface/x1", "m")
    time = dataset(f, "/interface/time", "s")
    n_nodes, n_samples = x1.shape[0], time.shape[0]
    expect(n_nodes > 0 and n_samples > 0, f"empty interface records: {n_samples} x {n_nodes}")
    expect(np.all(np.diff(x1[:]) > 0), "/interface/x1 is not increasing")
    expect(np.all(np.diff(time[:]) > 0), "/interface/time is not increasing")
    for name, units in INTERFACE_FIELDS.items():
        d = dataset(f, f"/interface/{name}", units, ndim=2)
        expect(d.shape == (n_samples, n_nodes), f"{name} shape {d.shape} != {(n_samples, n_nodes)}")
        expect(d.chunks is not None and d.compression == "gzip" and d.shuffle,
               f"{name} is not chunked with shuffle + gzip")
        expect(d.maxshape[0] is None, f"{name} is not extendible along time")
    state = dataset(f, "/interface/state", "1", dtype=np.int8, ndim=2)
    expect(state.shape == (n_samples, n_nodes), f"state shape {state.shape}")
    expect(set(np.unique(state[:])) <= {0, 1, 2}, "state holds values other than 0, 1, 2")
    expect("stick" in state.attrs.get("meaning", ""), "state has no 'meaning' attribute")
    return n_samples, n_nodes


def check_records(f):
    front_x1 = dataset(f, "/front/x1", "m")
    for name, units in FRONT.items():
        d = dataset(f, f"/front/{name}", units)
        expect(d.shape == front_x1.shape, f"/front/{name} shape {d.shape} != {front_x1.shape}")
    n = f["/probes/time"].shape
    for name, units in PROBES.items():
        expect(dataset(f, f"/probes/{name}", units).shape == n, f"/probes/{name} shape")
    for key in ("arrival_x1", "spectrum_x1"):
        expect(key in f["/probes"].attrs, f"/probes has no attribute {key}")
    n = f["/energy/time"].shape
    for name, units in ENERGY.items():
        expect(dataset(f, f"/energy/{name}", units).shape == n, f"/energy/{name} shape")


def check_root(f):
    for key in ("spec", "metrics", "code_version", "spec_sha256", "method", "method_description", "created"):
        expect(isinstance(f.attrs.get(key), str), f"root attribute {key} missing or not a string")
    spec = json.loads(f.attrs["spec"])
    for key in ("material", "geometry", "loading", "friction", "nucleation", "time", "output",
                "probe", "threads", "name", "tags"):
        expect(key in spec, f"spec has no {key}")
    metrics = json.loads(f.attrs["metrics"])
    for key in METRICS:
        expect(key in metrics, f"metrics have no {key}")
    expect(metrics["outcome"] in OUTCOMES, f"outcome {metrics['outcome']!r}")
    expect(metrics["method"] == f.attrs["method"], "method attribute differs from metrics")
    sha = f.attrs["spec_sha256"]
    expect(len(sha) == 64 and all(c in "0123456789abcdef" for c in sha), f"spec_sha256 {sha!r}")
    return spec, metrics


def check_synthetic_values(f):
    v = f["/interface/slip_velocity"][:]
    k, i = np.meshgrid(np.arange(v.shape[0]), np.arange(v.shape[1]), indexing="ij")
    expect(np.allclose(v, k + i / 1000.0), "synthetic slip_velocity values differ")
    expect(np.allclose(f["/interface/strength"][:], 5.0 * v), "synthetic strength values differ")
    arrival = f["/front/arrival_time"][:]
    expect(np.isnan(arrival[0]) and np.isnan(arrival[-1]), "undefined arrivals are not NaN")


def main():
    if len(sys.argv) not in (2, 3):
        fail(__doc__)
    with h5py.File(sys.argv[1], "r") as f:
        n_samples, n_nodes = check_interface(f)
        check_records(f)
        spec, metrics = check_root(f)
        if "--synthetic" in sys.argv[2:]:
            check_synthetic_values(f)
    print(f"ok: {n_samples} samples x {n_nodes} nodes, outcome {metrics['outcome']}, "
          f"spec {spec['name']!r}")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""The result file opens in other tools with its coordinates (docs/hdf5-layout.md, "Opening
results in ParaView and xarray"): `slipfront run` writes RESULT.h5 and its XDMF sidecar
RESULT.xdmf; this checks, with the HDF5 API (h5py), that /interface/time and /interface/x1
are dimension scales attached to every interface field (and the front, probe and energy
coordinates to theirs); that the XDMF is well-formed XML whose every data item names an
existing dataset of the right shape and type; and that xarray (h5netcdf engine) reads the
fields with x1 and time as coordinates.

usage: check_result_coordinates.py SLIPFRONT WORK_DIR
"""

import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

INTERFACE_2D = ["slip_velocity", "slip", "shear_traction", "contact_pressure", "strength", "state"]
OTHER_SCALES = {
    "/front/x1": ["/front/arrival_time", "/front/rupture_speed"],
    "/probes/time": ["/probes/slip_velocity_arrival", "/probes/slip_velocity_spectrum",
                     "/probes/strength_spectrum"],
    "/energy/time": ["/energy/kinetic", "/energy/strain", "/energy/external_work",
                     "/energy/dissipated"],
}


def fail(message):
    sys.exit(f"FAIL: {message}")


def check_scales(path):
    with h5py.File(path, "r") as f:
        interface = f["interface"]
        for name, coordinate in (("x1", "x1"), ("time", "time")):
            ds = interface[name]
            if not h5py.h5ds.is_scale(ds.id):
                fail(f"/interface/{name} is not a dimension scale")
            if h5py.h5ds.get_scale_name(ds.id) != coordinate.encode():
                fail(f"/interface/{name} has scale name {h5py.h5ds.get_scale_name(ds.id)!r}")
        for name in INTERFACE_2D:
            ds = interface[name]
            time_scales = [s.name for s in ds.dims[0].values()]
            x1_scales = [s.name for s in ds.dims[1].values()]
            if time_scales != ["/interface/time"]:
                fail(f"/interface/{name} dim 0 has scales {time_scales}, not /interface/time")
            if x1_scales != ["/interface/x1"]:
                fail(f"/interface/{name} dim 1 has scales {x1_scales}, not /interface/x1")
            if ds.dims[0].label not in ("", "time") or ds.shape != (
                    interface["time"].shape[0], interface["x1"].shape[0]):
                fail(f"/interface/{name} shape {ds.shape} does not match its scales")
        for scale, datasets in OTHER_SCALES.items():
            if not h5py.h5ds.is_scale(f[scale].id):
                fail(f"{scale} is not a dimension scale")
            for d in datasets:
                attached = [s.name for s in f[d].dims[0].values()]
                if attached != [scale]:
                    fail(f"{d} dim 0 has scales {attached}, not {scale}")
        return {name: interface[name].shape for name in ["x1", "time"] + INTERFACE_2D}


def check_item(item, xdmf_path, h5_path, f):
    """A DataItem in HDF format names the HDF5 file beside the XDMF file, an existing dataset
    of its Dimensions, and the dataset's type."""
    file_name, dataset = item.text.split(":", 1)
    if os.path.join(os.path.dirname(xdmf_path), file_name) != h5_path:
        fail(f"data item {item.text} does not point at {h5_path}")
    if dataset not in f:
        fail(f"data item {item.text}: no such dataset")
    dims = tuple(int(d) for d in item.get("Dimensions").split())
    if dims != f[dataset].shape:
        fail(f"data item {item.text}: Dimensions {dims}, dataset {f[dataset].shape}")
    kind = f[dataset].dtype
    want = ("Char", "1") if kind == np.int8 else ("Float", "8")
    if (item.get("NumberType"), item.get("Precision")) != want:
        fail(f"data item {item.text}: {item.get('NumberType')}/{item.get('Precision')} for {kind}")
    return dataset


def check_temporal(collection, xdmf_path, h5_path, f, n_samples, n_nodes):
    """The grid ParaView animates: a temporal collection of one line of nodes per recorded
    time, its Time the file's /interface/time, each field a hyperslab of that time's row."""
    if (collection.get("GridType"), collection.get("CollectionType")) != ("Collection", "Temporal"):
        fail(f"first grid {collection.attrib}: not a temporal collection")
    steps = collection.findall("Grid")
    if len(steps) != n_samples:
        fail(f"{len(steps)} grids in the temporal collection, {n_samples} recorded times")
    times = [float(step.find("Time").get("Value")) for step in steps]
    if not np.array_equal(np.array(times), f["interface/time"][()]):
        fail("the collection's Time values differ from /interface/time")
    for k in sorted({0, n_samples // 2, n_samples - 1}):
        step = steps[k]
        if step.find("Topology").get("Dimensions") != f"1 {n_nodes}":
            fail(f"step {k}: topology {step.find('Topology').attrib}")
        x1 = step.find("Geometry/DataItem")
        if check_item(x1, xdmf_path, h5_path, f) != "/interface/x1":
            fail(f"step {k}: geometry X is {x1.text}")
        names = [a.get("Name") for a in step.findall("Attribute")]
        if names != INTERFACE_2D:
            fail(f"step {k}: attributes {names}, expected {INTERFACE_2D}")
        for attribute in step.findall("Attribute"):
            slab = attribute.find("DataItem")
            selection, whole = slab.findall("DataItem")
            start, stride, count = [tuple(int(v) for v in row) for row in
                                    np.array(selection.text.split()).reshape(3, 2)]
            dataset = check_item(whole, xdmf_path, h5_path, f)
            if (slab.get("ItemType"), slab.get("Dimensions")) != ("HyperSlab", f"1 {n_nodes}") or \
                    start != (k, 0) or stride != (1, 1) or count != (1, n_nodes):
                fail(f"step {k}, {dataset}: hyperslab {slab.attrib} {start} {stride} {count}")
            if dataset != f"/interface/{attribute.get('Name')}":
                fail(f"step {k}: attribute {attribute.get('Name')} reads {dataset}")


def check_xdmf(xdmf_path, h5_path, shapes):
    root = ET.parse(xdmf_path).getroot()  # raises on malformed XML
    if root.tag != "Xdmf" or root.get("Version") != "3.0":
        fail(f"{xdmf_path}: root is {root.tag} version {root.get('Version')}")
    n_samples, n_nodes = shapes["time"][0], shapes["x1"][0]
    grids = root.findall("Domain/Grid")
    if [g.get("Name") for g in grids] != ["interface", "x1-t plane"]:
        fail(f"top-level grids {[g.get('Name') for g in grids]}")
    with h5py.File(h5_path, "r") as f:
        check_temporal(grids[0], xdmf_path, h5_path, f, n_samples, n_nodes)
        grid = grids[1]
        topology = grid.find("Topology")
        if topology.get("TopologyType") != "2DRectMesh" or \
                topology.get("Dimensions") != f"{n_samples} {n_nodes}":
            fail(f"topology {topology.attrib}, expected 2DRectMesh {n_samples} {n_nodes}")
        geometry = [item.text for item in grid.findall("Geometry/DataItem")]
        h5_name = os.path.basename(h5_path)
        if geometry != [f"{h5_name}:/interface/x1", f"{h5_name}:/interface/time"]:
            fail(f"geometry items {geometry}")
        names = [a.get("Name") for a in grid.findall("Attribute")]
        if names != INTERFACE_2D:
            fail(f"attributes {names}, expected {INTERFACE_2D}")
        for item in grid.findall(".//DataItem"):
            check_item(item, xdmf_path, h5_path, f)


def check_xarray(h5_path):
    try:
        import xarray
    except ImportError:
        fail("xarray is not installed (scripts/setup.sh installs python3-xarray, "
             "python3-h5netcdf)")
    with xarray.open_dataset(h5_path, group="interface", engine="h5netcdf") as ds:
        v = ds["slip_velocity"]
        if v.dims != ("time", "x1"):
            fail(f"xarray: slip_velocity dims {v.dims}, expected ('time', 'x1')")
        for c in ("time", "x1"):
            if c not in v.coords:
                fail(f"xarray: {c} is not a coordinate of slip_velocity: {list(v.coords)}")
        with h5py.File(h5_path, "r") as f:
            if not np.array_equal(v["x1"].values, f["interface/x1"][()]):
                fail("xarray: x1 coordinate differs from /interface/x1")
        # A selection by coordinate, as a user would write it.
        at = v.sel(x1=float(v["x1"][len(v["x1"]) // 2]), method="nearest")
        if at.dims != ("time",):
            fail(f"xarray: a node's history has dims {at.dims}")


def main(slipfront, work):
    os.makedirs(work, exist_ok=True)
    job = os.path.join(work, "coordinates.json")
    with open(job, "w") as f:
        json.dump({"method": "spectral_bi", "geometry": {"width": 12, "x_min": -1},
                   "probe": {"arrival_x1": 3, "spectrum_x1": 2}, "time": {"duration": 2}}, f)
    h5 = os.path.join(work, "coordinates.h5")
    xdmf = os.path.join(work, "coordinates.xdmf")
    for stale in (h5, xdmf):
        if os.path.exists(stale):
            os.remove(stale)
    run = subprocess.run([slipfront, "run", job, "--output", h5, "--quiet"],
                         capture_output=True, text=True, timeout=300)
    if run.returncode != 0:
        fail(f"slipfront run exited {run.returncode}: {run.stderr}")
    printed = json.loads(run.stdout)
    if printed["result_file"].get("xdmf") != xdmf or not os.path.exists(xdmf):
        fail(f"no XDMF sidecar at {xdmf}: {printed['result_file']}")
    shapes = check_scales(h5)
    check_xdmf(xdmf, h5, shapes)
    check_xarray(h5)
    print(f"ok: scales attached, XDMF valid ({shapes['time'][0]} samples x {shapes['x1'][0]} "
          f"nodes, a temporal collection of {shapes['time'][0]} steps, "
          f"{os.path.getsize(xdmf)} bytes), xarray reads time and x1 as coordinates")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])

"""Reading result files (docs/hdf5-layout.md / api/result_file.cpp) and run summaries.

A `Result` holds what the plots need from one HDF5 file: the interface fields sampled in
time (time-major [n_samples, n_nodes]), the front, the probes, the spec and the metrics.
Sources may be local paths or job ids (downloaded once into a cache directory).
"""

import json
import os
import re
from dataclasses import dataclass, field

import h5py
import numpy as np

from . import methods
from .errors import UsageError
from .friction_labels import friction_label

JOB_ID = re.compile(r"^[0-9a-f]{32}$")


@dataclass
class Result:
    path: str
    x1: np.ndarray            # interface node positions [m]
    time: np.ndarray          # sample times [s]
    slip_velocity: np.ndarray  # [n_samples, n_nodes], m/s
    strength: np.ndarray       # [n_samples, n_nodes], Pa
    front_x1: np.ndarray
    arrival_time: np.ndarray   # NaN where the front never arrived
    rupture_speed: np.ndarray  # NaN where undefined
    spec: dict = field(default_factory=dict)
    metrics: dict = field(default_factory=dict)
    note: str = ""            # shown after the label on figures, e.g. "not converged"

    @property
    def L(self):
        return (self.spec.get("friction") or {}).get("L")

    @property
    def n_d(self):
        return (self.spec.get("geometry") or {}).get("nodes_per_meter")

    @property
    def law(self):
        return (self.spec.get("friction") or {}).get("law", "prakash_clifton")

    def label(self):
        """What tells this run from others on one figure (run_label): 'FE, L = 5e-05 m,
        n_d = 40'."""
        label = run_label(self.spec, self.metrics)
        return f"{label} ({self.note})" if self.note else label

    def positions(self, most=4):
        """The run's own places to watch (job_positions of its spec)."""
        return job_positions(self.spec, most)

    def thresholds(self):
        """(front, stations): the slip speeds [m/s] that define the front and the stations'
        rupture times (the same unless the job gives two); stations None without stations."""
        front = self.metrics.get("front_threshold",
                                 (self.spec.get("probe") or {}).get("front_threshold"))
        stations = self.spec.get("stations") or {}
        return front, (stations.get("rupture_threshold") if stations.get("x1") else None)

    def event_window(self, fraction=0.01):
        """((x0, x1), (t0, t1)): the nodes where |V| ever exceeded `fraction` of its peak and
        those the front reached, padded by 10 % (at least two nodes), and the times from the
        first sample to the last such |V|, padded by 15 %; None if nothing slipped."""
        v = np.abs(self.slip_velocity)
        finite = v[np.isfinite(v)]
        peak = float(finite.max()) if finite.size else 0.0
        if not peak > 0:
            return None
        above = np.nan_to_num(v) > fraction * peak
        xs = list(self.x1[above.any(axis=0)])
        xs += list(self.front_x1[np.isfinite(self.arrival_time)])
        last = float(self.time[above.any(axis=1)].max())
        dx = float(self.x1[1] - self.x1[0]) if self.x1.size > 1 else 1.0
        pad = max(0.1 * (max(xs) - min(xs)), 2 * dx)
        x_box = (float(self.x1.min()) - dx / 2, float(self.x1.max()) + dx / 2)
        t_box = (float(self.time[0]), float(self.time[-1]))
        return ((max(x_box[0], min(xs) - pad), min(x_box[1], max(xs) + pad)),
                (t_box[0], min(t_box[1], last + 0.15 * max(last - t_box[0], 1e-12))))

    def wave_speeds(self):
        """(c_s, c_p) of the run's material (plane strain), in either form of the job's
        `material` (moduli, or wave speeds as given: docs/api-job-spec.md)."""
        return solid_wave_speeds(self.spec.get("material") or {})


def job_positions(spec, most=4):
    """A job's own places to watch: its stations (at most `most`, spread along them), else its
    probes (spectrum_x1, arrival_x1), each once: [(x1, what)] (the web view's jobPositions)."""
    stations = sorted((spec.get("stations") or {}).get("x1") or [])
    if stations:
        if len(stations) > most:
            stations = [stations[round(i * (len(stations) - 1) / (most - 1))]
                        for i in range(most)]
        return [(float(x), "station") for x in stations]
    probe = spec.get("probe") or {}
    found = []
    for key in ("spectrum_x1", "arrival_x1"):
        x = probe.get(key)
        if x is not None and all(abs(x - y) > 1e-12 for y, _ in found):
            found.append((float(x), f"probe.{key}"))
    return sorted(found)



def _number(value, unit=""):
    return "?" if value is None else f"{value:g}{unit}"


def below_label(spec):
    """'bimaterial' for an interface between two different elastic solids, 'full space' for
    two identical ones (the homogeneous mode II problem), '' on the rigid plane (the paper's
    scene)."""
    lower = spec.get("lower") or {}
    if lower.get("solid") != "elastic":
        return ""
    upper = spec.get("material") or {}
    same = np.allclose([upper.get("density", 1.0), *solid_wave_speeds(upper)],
                       [lower.get("density", 1.0), *solid_wave_speeds(lower)], rtol=1e-12, atol=0)
    return "full space" if same else "bimaterial"


def run_label(spec, metrics=None):
    """What identifies a run among others of a figure: the method, what is below the interface
    (when not the rigid plane), the friction law by its scale parameter (friction_label) and
    n_d: 'FE, L = 5e-05 m, n_d = 40', 'BI, Coulomb, n_d = 20', 'BI, bimaterial, slip weakening
    D_c = 0.000744 m, t* = 0.00035 s, n_d = 5'."""
    spec = spec or {}
    method = spec.get("method") or (metrics or {}).get("method") or methods.default()
    n_d = (spec.get("geometry") or {}).get("nodes_per_meter")
    damping = (spec.get("fe") or {}).get("mesh_damping")
    parts = [methods.label(method), below_label(spec), friction_label(spec.get("friction")),
             f"mesh damping {_number(damping)}" if damping else "", f"n_d = {_number(n_d)}"]
    return ", ".join(p for p in parts if p)


def solid_wave_speeds(material):
    """(c_s, c_p) of a solid of a job (its `material` or `lower`), plane strain, in either form:
    moduli, or wave speeds as given (docs/api-job-spec.md)."""
    m = material or {}
    if "s_wave_speed" in m and "p_wave_speed" in m:
        return float(m["s_wave_speed"]), float(m["p_wave_speed"])
    return wave_speeds(m.get("density", 1.0), m.get("young_modulus", 2.5), m.get("poisson_ratio", 0.25))


def wave_speeds(density=1.0, young_modulus=2.5, poisson_ratio=0.25):
    """(c_s, c_p) of an isotropic elastic solid in plane strain."""
    mu = young_modulus / (2 * (1 + poisson_ratio))
    lam = young_modulus * poisson_ratio / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio))
    return float(np.sqrt(mu / density)), float(np.sqrt((lam + 2 * mu) / density))


def _json_attr(f, name):
    raw = f.attrs.get(name)
    if raw is None:
        return {}
    if isinstance(raw, bytes):
        raw = raw.decode()
    try:
        return json.loads(raw)
    except (TypeError, ValueError):
        return {}


def load_result(path):
    """Read one result file; UsageError if it is not a slipfront result."""
    try:
        with h5py.File(path, "r") as f:
            i, fr = f["interface"], f["front"]
            return Result(
                path=path,
                x1=i["x1"][()],
                time=i["time"][()],
                slip_velocity=i["slip_velocity"][()],
                strength=i["strength"][()],
                front_x1=fr["x1"][()],
                arrival_time=fr["arrival_time"][()],
                rupture_speed=fr["rupture_speed"][()],
                spec=_json_attr(f, "spec"),
                metrics=_json_attr(f, "metrics"),
            )
    except (OSError, KeyError) as e:
        raise UsageError(f"{path}: not a readable slipfront result file ({e})") from e


def cache_dir():
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(base, "slipfront")


def resolve_source(source, api_factory, cache=None, log=None):
    """A local path for `source`: an existing file, or a job id downloaded into the cache."""
    if os.path.exists(source):
        return source
    if not JOB_ID.match(source):
        raise UsageError(f"{source}: no such file, and not a job id (32 hex characters)")
    from .result_download import download_result  # here: plotting local files needs no HTTP

    cache = cache or cache_dir()
    os.makedirs(cache, exist_ok=True)
    path, _, fetched = download_result(api_factory(), source, os.path.join(cache, source + ".h5"),
                                       log=log)
    if log and fetched:
        log(f"downloaded job {source} ({fetched} bytes) to {path}")
    return path


def load_results(sources, api_factory, cache=None, log=None):
    return [load_result(resolve_source(s, api_factory, cache, log)) for s in sources]


def run_row(spec, metrics, wall_time_s=None, job_id=None, status=None):
    """The summary of one run used by the convergence and cost figures."""
    metrics = metrics or {}
    return {
        "id": job_id,
        "L": (spec.get("friction") or {}).get("L"),
        "n_d": (spec.get("geometry") or {}).get("nodes_per_meter"),
        "status": status,
        "outcome": metrics.get("outcome"),
        "propagation_distance": metrics.get("propagation_distance"),
        "arrival_time_at_probe": metrics.get("arrival_time_at_probe"),
        "steps": metrics.get("steps"),
        "simulated_time": metrics.get("simulated_time"),
        "stable_dt": metrics.get("stable_dt"),
        "wall_time_s": metrics.get("wall_time_s", wall_time_s),
    }


def row_from_job(job):
    return run_row(job.get("spec") or {}, job.get("metrics"), job.get("wall_time_s"),
                   job.get("id"), job.get("status"))


def row_from_result(result):
    return run_row(result.spec, result.metrics, job_id=os.path.basename(result.path))


def _floats(values):
    return np.array([np.nan if v is None else float(v) for v in values or ()], dtype=float)


def result_from_front(api, job_id):
    """A `Result` with only the front, from the server's JSON (GET /jobs/{id}/front and
    the job's spec and metrics): enough for the rupture-speed figure, no download."""
    return result_from_json(api, api.job(job_id, fields=["id", "spec", "metrics"]))


def result_from_json(api, job, positions=()):
    """A `Result` of `job` (its JSON, with `id`, `spec` and `metrics`) from the server's JSON,
    no download: the front (GET /jobs/{id}/front) and, for each of `positions` [m] inside the
    interface, the |V| history of the node nearest it (/fields/slip_velocity with x1_min =
    x1_max; the run's sample times): `x1` then holds those nodes only, enough for the velocity
    figure at those positions."""
    front = api.front(job["id"])
    front_x1 = _floats(front.get("x1"))
    nodes, columns, time = [], [], np.empty(0)
    inside = [x for x in positions if front_x1.size and front_x1.min() <= x <= front_x1.max()]
    for x in inside:
        field = api.get_json(f"/api/v1/jobs/{job['id']}/fields/slip_velocity",
                             params={"x1_min": x, "x1_max": x, "max_points": 4000})
        nodes.append(field["x1"][0])
        columns.append(_floats(row[0] for row in field["values"]))
        time = _floats(field["time"])
    velocity = np.column_stack(columns) if columns else np.empty((0, 0))
    return Result(path=job["id"], x1=np.array(nodes, dtype=float), time=time,
                  slip_velocity=velocity, strength=np.empty((0, 0)), front_x1=front_x1,
                  arrival_time=_floats(front.get("arrival_time")),
                  rupture_speed=_floats(front.get("rupture_speed")),
                  spec=job.get("spec") or {}, metrics=job.get("metrics") or {})

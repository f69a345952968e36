"""The paper's question at a bimaterial interface: the requests and the
measurements behind clients/bimaterial_study.py.

The scene is the `bimaterial_prakash_clifton` preset (two different solids, constant
mu = 0.7, the paper's Prakash-Clifton law) by the spectral BI method. Two sets of runs:

- a convergence study over L (POST /api/v1/studies: L x an n_d ladder, refined by the
  server until two successive meshes agree, docs/studies.md), whose map and L_c verdict are
  the server's;
- plain Coulomb friction on the same scene (`"law": "coulomb"`, no L, no V*) under mesh
  refinement, submitted as single jobs (a study varies L, which Coulomb does not have); the
  convergence rule is applied to them by the client (analysis.py, the server's rules one
  for one).
"""

import copy

from . import analysis
from .reproduction_plan import FE_ONLY

PRESET = "bimaterial_prakash_clifton"
FULL_L = [1e-2, 3e-3, 1e-3, 3e-4, 1e-4]
FULL_LADDER = [5, 10, 20, 40]
# Coulomb runs as (n_d, spectral_bi.time_step_factor β): the BI default β = 0.5, and β = 0.25,
# which removes the scheme's own mesh-scale mode of steady sliding under plain Coulomb
# (docs/verification.md), so that what is left is the continuum's ill-posedness.
FULL_COULOMB = [(2.5, 0.5), (5, 0.5), (10, 0.5), (20, 0.5), (2.5, 0.25), (5, 0.25), (10, 0.25)]
QUICK_L = [1e-2, 1e-4]
QUICK_LADDER = [2, 4, 8]
QUICK_COULOMB = [(2, 0.5), (4, 0.5), (8, 0.5), (2, 0.25), (4, 0.25)]
# The quick scene: the preset on a 200 m periodic interface for 30 ms (the rupture is still
# growing then); stations and probes of the preset that lie inside it are kept.
QUICK_PATCH = {"geometry": {"width": 200, "x_min": -100}, "time": {"duration": 0.03}}
COULOMB_FRICTION = {"law": "coulomb", "mu": 0.7, "L": None, "v_star": None}
FINAL_JOB = ("succeeded", "failed", "cancelled")


def merge(target, patch):
    """JSON merge patch (RFC 7396) of `patch` over a copy of `target`."""
    if not isinstance(patch, dict):
        return copy.deepcopy(patch)
    out = copy.deepcopy(target) if isinstance(target, dict) else {}
    for key, value in patch.items():
        if value is None:
            out.pop(key, None)
        else:
            out[key] = merge(out.get(key), value)
    return out


def bi_scene(api, quick=False):
    """The preset's job by the spectral BI method as the server expands it (GET /presets,
    `specs.spectral_bi`), with the quick patch when asked, one solver thread, and without
    the study's variables (friction.L, geometry.nodes_per_meter) and name."""
    preset = next((p for p in api.presets() if p.get("name") == PRESET), None)
    if preset is None:
        raise SystemExit(f"bimaterial study: the server has no preset {PRESET!r}")
    spec = copy.deepcopy((preset.get("specs") or {}).get("spectral_bi") or preset["spec"])
    for section, keys in FE_ONLY.items():
        for key in keys:
            (spec.get(section) or {}).pop(key, None)
    spec["method"] = "spectral_bi"
    spec["threads"] = 1
    if quick:
        spec = merge(spec, QUICK_PATCH)
    spec.pop("name", None)
    spec["friction"].pop("L", None)
    spec["geometry"].pop("nodes_per_meter", None)
    return spec


def study_body(base, lengths, ladder, quick=False, fresh=False):
    body = {"name": "bimaterial PC" + (" (quick)" if quick else ""),
            "tags": ["bimaterial-study"] + (["quick"] if quick else []),
            "base": base,
            "convergence": {"L": lengths, "n_d": ladder, "n_d_max": max(ladder)}}
    if fresh:
        body["fresh"] = True
    return body


def coulomb_job(base, n_d, beta, quick=False):
    job = merge(base, {"friction": COULOMB_FRICTION, "geometry": {"nodes_per_meter": n_d},
                       "spectral_bi": {"time_step_factor": beta},
                       "name": f"bimaterial Coulomb n_d={n_d:g} beta={beta:g}",
                       "tags": ["bimaterial-study", "coulomb"] + (["quick"] if quick else [])})
    job["friction"] = {k: v for k, v in job["friction"].items() if k in ("law", "mu")}
    return job


def submit_coulomb(api, base, ladder, quick=False, fresh=False):
    """Submit the Coulomb runs, `ladder` = [(n_d, β)]; returns their job ids in that order."""
    return [api.submit(coulomb_job(base, n, beta, quick), fresh=fresh or None)["id"]
            for n, beta in ladder]


def wait_jobs(api, ids, log, poll=2.0, timeout=None):
    import time
    t0 = time.monotonic()
    while True:
        jobs = [api.job(i) for i in ids]
        if all(j.get("status") in FINAL_JOB for j in jobs):
            return jobs
        if timeout is not None and time.monotonic() - t0 > timeout:
            raise SystemExit(f"bimaterial study: Coulomb runs not finished after {timeout} s")
        time.sleep(poll)


def coulomb_rows(jobs):
    """Rows of analysis.py (L = 0 stands for "no L") with the client-side convergence status
    (among the runs of the same β) and the quantities that show ill-posedness: peak slip
    rate, slipped length. Sorted by β (largest first), then n_d."""
    rows = []
    for j in jobs:
        m = j.get("metrics") or {}
        spec = j.get("spec") or {}
        rows.append({"id": j["id"], "L": 0.0,
                     "n_d": float(spec["geometry"]["nodes_per_meter"]),
                     "status": j.get("status"), "outcome": m.get("outcome"),
                     "propagation_distance": m.get("propagation_distance"),
                     "arrival_time_at_probe": m.get("arrival_time_at_probe"),
                     "steps": m.get("steps"), "simulated_time": m.get("simulated_time"),
                     "max_slip_velocity": m.get("max_slip_velocity"),
                     "beta": float((spec.get("spectral_bi") or {}).get("time_step_factor", 0.5)),
                     "wall_time_s": m.get("wall_time_s"), "dx": 1.0 / float(
                         spec["geometry"]["nodes_per_meter"]),
                     "warnings": m.get("warnings") or [], "stations": m.get("stations") or []})
    out = []
    for beta in sorted({r["beta"] for r in rows}, reverse=True):
        out += analysis.convergence_statuses([r for r in rows if r["beta"] == beta])
    return sorted(out, key=lambda r: (-r["beta"], r["n_d"]))


def peak_ratios(rows, key="max_slip_velocity"):
    """Per β: [(coarse n_d, fine n_d, fine/coarse of `key`)] for successive meshes."""
    out = {}
    for beta in sorted({r["beta"] for r in rows}, reverse=True):
        group = [r for r in rows if r["beta"] == beta and (r.get(key) or 0) > 0]
        out[beta] = [(a["n_d"], b["n_d"], b[key] / a[key]) for a, b in zip(group, group[1:])]
    return out


def study_metrics(api, study):
    """{job_id: metrics} of the study's runs (also kept as run["_metrics"])."""
    out = {}
    for r in study.get("runs") or []:
        out[r["job_id"]] = api.job(r["job_id"]).get("metrics") or {}
        r["_metrics"] = out[r["job_id"]]
    return out


def _time(text):
    import datetime
    return datetime.datetime.fromisoformat(str(text).replace("Z", "+00:00"))


def computation_span(api, job_ids):
    """Seconds from the first submission to the last end among the jobs that computed these
    runs (a reused run counts by the job it was reused from); None if unknown."""
    starts, ends = [], []
    for job_id in job_ids:
        job = api.job(job_id)
        if job.get("cached_from"):
            job = api.job(job["cached_from"])
        try:
            starts.append(_time(job["created_at"]))
            ends.append(_time(job["finished_at"]))
        except (KeyError, TypeError, ValueError):
            return None
    return (max(ends) - min(starts)).total_seconds() if starts else None

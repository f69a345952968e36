"""Studies (SPEC §4: POST /studies, GET /studies/{id}): a grid of runs over L × n_d of one
base job, from which the server derives convergence statuses and the critical length L_c.

The request the client sends: {"name", "tags", "base": job spec, "L": [...], "n_d": [...]}.
Responses are read tolerantly (runs under `jobs` or `runs`; L_c under `critical_length`
or `L_c`). A server without the API is reported as "server has no studies API (404)".
"""

import time

from .errors import ServerError
from .waiting import Backoff

FINAL_STUDY = ("succeeded", "failed", "cancelled", "complete", "completed", "done", "finished")
FINAL_JOB = ("succeeded", "failed", "cancelled")


def _no_api(error):
    return (isinstance(error, ServerError) and error.status == 404 and
            "no such resource" in str(error.problem.get("detail", "")))


def _guard(call):
    try:
        return call()
    except ServerError as e:
        if e.status in (404, 405) and (e.status == 405 or _no_api(e)):
            raise ServerError(f"server has no studies API ({e.status})", status=e.status) from e
        raise


def study_request(base, lengths, densities, name=None, tags=None):
    body = {"base": base, "L": list(lengths), "n_d": list(densities)}
    if name:
        body["name"] = name
    if tags:
        body["tags"] = list(tags)
    return body


def create(api, body):
    return _guard(lambda: api.create_study(body))


def get(api, study_id):
    return _guard(lambda: api.study(study_id))


def runs_of(study):
    runs = study.get("jobs") or study.get("runs") or []
    return [r for r in runs if isinstance(r, dict)]


def is_final(study):
    if study.get("status") in FINAL_STUDY:
        return True
    runs = runs_of(study)
    return bool(runs) and all(r.get("status") in FINAL_JOB for r in runs)


def wait(api, study_id, timeout=None, log=None, sleep=time.sleep):
    backoff = Backoff(first=0.5, cap=10.0)
    deadline = None if timeout is None else time.monotonic() + timeout
    while True:
        study = get(api, study_id)
        if is_final(study):
            return study
        if log:
            runs = runs_of(study)
            done = sum(r.get("status") in FINAL_JOB for r in runs)
            log(f"study {study_id}: {done}/{len(runs)} runs finished")
        delay = backoff.next()
        if deadline is not None and time.monotonic() + delay > deadline:
            raise ServerError(f"study {study_id} not finished after {timeout} s")
        sleep(delay)


def _value(run, key, spec_path):
    if key in run:
        return run[key]
    node = run.get("spec") or {}
    for part in spec_path:
        node = node.get(part) if isinstance(node, dict) else None
    return node


def summary_lines(study):
    """A readable table of the study's runs and its critical length."""
    lines = [f"study {study.get('id', '?')}  {study.get('name') or ''}  status "
             f"{study.get('status', '?')}"]
    lines.append(f"{'L [m]':>10} {'n_d':>6} {'status':>10} {'outcome':>15} {'distance':>10} "
                 f"{'t_probe':>10} {'convergence':>14}  id")
    for r in runs_of(study):
        m = r.get("metrics") or {}
        L = _value(r, "L", ("friction", "L"))
        n_d = _value(r, "n_d", ("geometry", "nodes_per_meter"))
        conv = r.get("convergence")
        if isinstance(conv, dict):
            conv = conv.get("status")
        lines.append(f"{_fmt(L):>10} {_fmt(n_d):>6} {r.get('status', '?'):>10} "
                     f"{str(m.get('outcome', r.get('outcome', '-'))):>15} "
                     f"{_fmt(m.get('propagation_distance', r.get('propagation_distance'))):>10} "
                     f"{_fmt(m.get('arrival_time_at_probe', r.get('arrival_time_at_probe'))):>10} "
                     f"{str(conv or '-'):>14}  {r.get('id', '')}")
    for key in ("critical_length", "L_c", "spectral_critical_length"):
        if key in study:
            lines.append(f"{key}: {_fmt(study[key])}")
    return lines


def _fmt(value):
    if value is None:
        return "-"
    if isinstance(value, float):
        return f"{value:.4g}"
    return str(value)

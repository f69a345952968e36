"""The functions a notebook needs (docs/python-api.md): connect, submit, wait, download and
load a result as numpy arrays, run a study, and the run table as a pandas DataFrame.

    import slipfront_client as sf
    api = sf.connect()                         # --server / SLIPFRONT_SERVER / config file
    job = sf.submit(api, {"method": "spectral_bi"}, wait=True)
    result = sf.load_job_result(api, job["id"])  # Result: x1, time, slip_velocity, ...
    df = sf.runs_dataframe(api, where="method=spectral_bi", sort="friction.L")
"""

import json
import os

from . import config, methods, studies
from .api import Api
from .result_download import download_result, write_xdmf
from .results import cache_dir, load_result
from .waiting import check_outcome, wait_for_job


def connect(server=None, token=None, timeout=30.0):
    """An `Api` for the server at `server` (else SLIPFRONT_SERVER, the config file, or
    http://127.0.0.1:8080); see slipfront_client.config."""
    url, source = config.server_url(server)
    api = Api(url, token=config.token(token), timeout=timeout, url_source=source)
    methods.use(api)  # the server's methods and their labels, read when first needed
    return api


def submit(api, spec, wait=False, timeout=None, fresh=False):
    """POST a job (a dict, every field optional); with `wait`, return the finished job and
    raise JobFailed/JobCancelled if it did not succeed."""
    job = api.submit(spec, fresh=True if fresh else None)
    if wait:
        job = wait_job(api, job["id"], timeout=timeout)
    return job


def wait_job(api, job_id, timeout=None):
    """Poll until the job is final; raise JobFailed/JobCancelled unless it succeeded."""
    return check_outcome(wait_for_job(api, job_id, timeout=timeout))


def download(api, job_id, path=None, xdmf=False):
    """Download (verified by SHA-256, resumable) a job's HDF5 result; returns the path.
    Default path: the cache directory (~/.cache/slipfront/ID.h5). With `xdmf`, also writes
    its XDMF sidecar (ParaView) beside it, naming the file by the name it was saved under."""
    if path is None:
        os.makedirs(cache_dir(), exist_ok=True)
        path = os.path.join(cache_dir(), f"{job_id}.h5")
    path = download_result(api, job_id, path)[0]
    if xdmf:
        write_xdmf(api, job_id, path)
    return path


def load_job_result(api, job_id, path=None):
    """The job's result file as a `Result` of numpy arrays (x1, time, slip_velocity
    [n_samples, n_nodes], strength, the front; spec and metrics as dicts)."""
    return load_result(download(api, job_id, path))


def run_study(api, base=None, L=(), n_d=(), convergence=False, n_d_max=None, name=None,
              tags=None, wait=True, timeout=None):
    """Create a study over L x n_d (or, with `convergence`, refine each L along the n_d
    ladder); with `wait`, return it finished (runs, convergence statuses, L_c)."""
    body = studies.study_request(base or {}, L, n_d, name, tags, convergence=convergence,
                                 n_d_max=n_d_max)
    study = studies.create(api, body)
    if wait:
        study = studies.wait(api, study["id"], timeout)
    return study


def list_runs(api, where=None, sort=None, limit=None, **filters):
    """The run table (one flat dict per job: job columns, spec.*, metrics.*, the
    convergence status) of the jobs matching `where` (docs/server.md, "Searching and
    exporting runs")."""
    params = {"where": where, "sort": sort, **filters}
    text = api.export_runs("ndjson", params, limit=limit)
    return [json.loads(line) for line in text.splitlines() if line.strip()]


def runs_dataframe(api, where=None, sort=None, limit=None, **filters):
    """`list_runs` as a pandas DataFrame (index: job id) when pandas is importable, else the
    plain list of records."""
    records = list_runs(api, where=where, sort=sort, limit=limit, **filters)
    try:
        import pandas
    except ImportError:
        return records
    frame = pandas.DataFrame.from_records(records)
    if "id" in frame.columns:
        frame = frame.set_index("id")
    for column in ("created_at", "finished_at"):
        if column in frame.columns:
            frame[column] = pandas.to_datetime(frame[column], utc=True, errors="coerce")
    return frame

"""Downloading result files: verified (size and sha256 = the strong ETag) and resumable
(a partial `FILE.part` is continued with a Range request guarded by If-Range)."""

import hashlib
import os
from xml.sax.saxutils import escape as xml_escape

from .api import API
from .errors import ServerError

CHUNK = 1 << 16


def sha256_file(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def _expected(api, job_id):
    """(size, sha256) the server announces for the job's result file."""
    job = api.job(job_id, fields=["status", "result", "error"])
    result = job.get("result")
    if not result:
        raise ServerError(f"job {job_id} has no result file (status {job.get('status')}"
                          + (f": {job['error']}" if job.get("error") else "") + ")")
    return int(result["size"]), result["sha256"]


def _fetch(api, job_id, part, size, sha):
    """Append the missing bytes of the result to `part`; return how many were fetched."""
    have = os.path.getsize(part) if os.path.exists(part) else 0
    headers = {}
    if 0 < have < size:
        headers = {"Range": f"bytes={have}-", "If-Range": f'"{sha}"'}
    elif have >= size:
        have = 0  # complete or too long: start again
    response = api.request("GET", f"{API}/jobs/{job_id}/result.h5", headers=headers,
                           stream=True, ok=(200, 206))
    etag = response.headers.get("ETag", "").strip('"')
    if etag and etag != sha:
        response.close()
        raise ServerError(f"job {job_id}: ETag {etag} differs from the announced sha256 {sha}")
    mode = "ab" if response.status_code == 206 else "wb"
    fetched = 0
    with response, open(part, mode) as f:
        for block in response.iter_content(CHUNK):
            f.write(block)
            fetched += len(block)
    return fetched


def download_result(api, job_id, output, log=None):
    """Download the result of `job_id` to `output`; return (path, sha256, bytes fetched).

    An `output` that already holds the right bytes is kept (0 bytes fetched). A partial
    download in `output.part` (or a short `output`) is resumed. Size and sha256 are checked;
    a mismatch after a resume starts once more from scratch, then fails.
    """
    size, sha = _expected(api, job_id)
    os.makedirs(os.path.dirname(os.path.abspath(output)), exist_ok=True)
    if os.path.exists(output) and os.path.getsize(output) == size and sha256_file(output) == sha:
        return output, sha, 0
    part = output + ".part"
    if os.path.exists(output) and not os.path.exists(part) and os.path.getsize(output) < size:
        os.replace(output, part)  # a short file left by an interrupted download
    total = 0
    for attempt in range(2):
        total += _fetch(api, job_id, part, size, sha)
        got_size = os.path.getsize(part)
        got_sha = sha256_file(part) if got_size == size else None
        if got_sha == sha:
            os.replace(part, output)
            return output, sha, total
        if log:
            log(f"download of job {job_id}: got {got_size} bytes (sha256 {got_sha}), expected "
                f"{size} bytes (sha256 {sha}); " + ("retrying from scratch" if attempt == 0 else "giving up"))
        os.remove(part)
    raise ServerError(f"download of job {job_id} does not match its sha256 {sha}")


def write_xdmf(api, job_id, h5_path):
    """Writes the XDMF sidecar of job `job_id` beside its downloaded result `h5_path`, as
    H5_STEM.xdmf, pointing at the file by the name it was saved under. Returns its path."""
    xdmf = os.path.splitext(h5_path)[0] + ".xdmf"
    text = api.result_xdmf(job_id)
    # The server names the file ID.h5 (its download name); the sidecar must name this one.
    text = text.replace(f">{job_id}.h5:", f">{xml_escape(os.path.basename(h5_path))}:")
    with open(xdmf, "w", encoding="utf-8") as f:
        f.write(text)
    return xdmf

"""A thin HTTP client of the slipfront API (docs/server.md, under /api/v1).

Every request goes through `Api.request`, which
- sends the bearer token when one is configured,
- retries 503 and 429 answers after the server's `Retry-After` (bounded), and idempotent
  requests after a connection failure (bounded exponential back-off),
- turns error answers (`application/problem+json`) into `UsageError` (400, 413, 422: the
  request was wrong) or `ServerError` (everything else), listing each bad field as
  "pointer: reason".
"""

import email.utils
import re
import time
import uuid

from .errors import MissingDependency, ServerError, UsageError

try:
    import requests
except ModuleNotFoundError:  # the package imports without it; Api() names what is missing
    requests = None

API = "/api/v1"
# A result_url cell of the run table: a CSV cell, or the value of an NDJSON row's key.
RESULT_PATH = re.compile(r'(^|,|"result_url":")(/api/v1/jobs/[0-9a-f]{32}/result\.h5)(?=,|"|\r?$)',
                         re.MULTILINE)
USER_AGENT = "slipfront-client/1"


def parse_retry_after(value, default):
    """Seconds to wait from a Retry-After header (delta-seconds or HTTP date)."""
    if not value:
        return default
    value = value.strip()
    try:
        return max(0.0, float(value))
    except ValueError:
        pass
    try:
        when = email.utils.parsedate_to_datetime(value)
        return max(0.0, when.timestamp() - time.time())
    except (TypeError, ValueError):
        return default


def problem_details(response):
    """(detail, ["pointer: reason", ...]) of an error response, whatever its body."""
    try:
        body = response.json()
    except ValueError:
        text = response.text.strip()
        return (text[:300] or response.reason or "no detail"), [], {}
    if not isinstance(body, dict):
        return str(body)[:300], [], {}
    detail = body.get("detail") or body.get("title") or response.reason or "no detail"
    lines = []
    for error in body.get("errors") or []:
        if isinstance(error, dict):
            pointer = error.get("pointer", "")
            lines.append(f"{pointer or '(document)'}: {error.get('reason', '')}")
        else:
            lines.append(str(error))
    return detail, lines, body


class Api:
    """The server at `base_url`, with an optional bearer `token`."""

    def __init__(self, base_url, token=None, timeout=30.0, max_retries=6, max_retry_wait=60.0,
                 connect_retries=3, sleep=time.sleep, url_source=None):
        self.base_url = base_url.rstrip("/")
        self.url_source = url_source  # where the URL came from, for the "nothing listens" hint
        self.token = token
        self.timeout = timeout
        self.max_retries = max_retries
        self.max_retry_wait = max_retry_wait
        self.connect_retries = connect_retries
        self.sleep = sleep
        if requests is None:
            raise MissingDependency("requests", "talk to the server")
        self.session = requests.Session()
        self.session.headers["User-Agent"] = USER_AGENT
        if token:
            self.session.headers["Authorization"] = f"Bearer {token}"

    def close(self):
        self.session.close()

    def url(self, path):
        """Absolute URL of an API path ("/api/v1/jobs") or of an absolute URL."""
        if path.startswith("http://") or path.startswith("https://"):
            return path
        return self.base_url + path

    # -- the one place that talks HTTP --------------------------------------------------

    def request(self, method, path, *, params=None, json_body=None, headers=None,
                stream=False, ok=(200,), idempotent=None, data=None):
        """Send a request; return the response when its status is in `ok`.

        `idempotent` (default: GET/HEAD) says whether a connection failure may be retried
        (at most `connect_retries` times, after 0.5, 1, 2, ... s).
        503 and 429 are retried after Retry-After whatever the method: the server did not
        act on the request.
        """
        if idempotent is None:
            idempotent = method in ("GET", "HEAD")
        backoff = 0.5
        connect_failures = 0
        for attempt in range(self.max_retries + 1):
            last = attempt == self.max_retries
            try:
                response = self.session.request(
                    method, self.url(path), params=params, json=json_body, headers=headers,
                    stream=stream, timeout=self.timeout, data=data)
            except requests.RequestException as e:
                connect_failures += 1
                if idempotent and not last and connect_failures <= self.connect_retries:
                    self.sleep(backoff)
                    backoff = min(backoff * 2, 8.0)
                    continue
                raise ServerError(self.unreachable_message(e)) from e
            if response.status_code in ok:
                return response
            if response.status_code in (429, 503) and not last:
                wait = parse_retry_after(response.headers.get("Retry-After"), backoff)
                response.close()
                self.sleep(min(wait, self.max_retry_wait))
                backoff = min(backoff * 2, 8.0)
                continue
            raise self.error_for(method, path, response)
        raise AssertionError("unreachable")

    def unreachable_message(self, error):
        """A friendly sentence for a server that does not answer."""
        source = f" (from {self.url_source})" if self.url_source else ""
        if isinstance(error, requests.ConnectionError) and not isinstance(
                error, requests.exceptions.SSLError):
            return (f"nothing answers at {self.base_url}{source}. Is `slipfront serve` running "
                    f"there? Set the URL with --server, the SLIPFRONT_SERVER environment "
                    f"variable or `server = \"...\"` in ~/.config/slipfront/client.toml.")
        return f"cannot reach the server at {self.base_url}{source}: {error}"

    def error_for(self, method, path, response):
        """The exception an error response becomes."""
        detail, lines, body = problem_details(response)
        status = response.status_code
        message = f"{method} {path}: {status} {response.reason}: {detail}"
        if status in (400, 413, 422):
            return UsageError(message, lines)
        if status == 401:
            message += " (pass --token or set SLIPFRONT_TOKEN)"
        return ServerError(message, lines, status=status, problem=body)

    def get_json(self, path, params=None):
        return self.request("GET", path, params=params).json()

    # -- endpoints -----------------------------------------------------------------------

    def healthz(self):
        return self.get_json("/healthz")

    def submit(self, spec, fresh=None, priority=None, idempotency_key=None):
        """POST /jobs. The Idempotency-Key (a fresh UUID by default) makes retries safe."""
        params = {}
        if fresh is not None:
            params["fresh"] = "true" if fresh else "false"
        if priority is not None:
            params["priority"] = str(priority)
        headers = {"Idempotency-Key": idempotency_key or uuid.uuid4().hex}
        response = self.request("POST", f"{API}/jobs", params=params, json_body=spec,
                                headers=headers, ok=(200, 201), idempotent=True)
        return response.json()

    def job_schema(self):
        """GET /schema/job.json: the job's JSON Schema (with the methods and their labels in
        `properties.method`: slipfront_client.methods)."""
        return self.get_json(f"{API}/schema/job.json")

    def validate(self, spec):
        """POST /jobs/validate: the job checked as submit() would check it, nothing stored:
        {valid, spec, spec_sha256, warnings, provenance, estimate, memory_estimate_bytes}, or
        {valid: false, errors: [{pointer, reason}]} for an invalid job."""
        return self.request("POST", f"{API}/jobs/validate", json_body=spec,
                            idempotent=True).json()

    def presets(self):
        """GET /presets: [{name, origin, title, description, reference, spec}]."""
        return self.get_json(f"{API}/presets")["presets"]

    def preset(self, name):
        return self.get_json(f"{API}/presets/{name}")

    def job(self, job_id, fields=None):
        params = {"fields": ",".join(fields)} if fields else None
        return self.get_json(f"{API}/jobs/{job_id}", params=params)

    def cancel(self, job_id):
        response = self.request("POST", f"{API}/jobs/{job_id}/cancel", ok=(200, 202),
                                idempotent=True)
        return response.json()

    # Keep, annotate, share (docs/server.md): the owner's changes after submission.

    def annotate(self, job_id, tags=None, note=None, add=None, remove=None):
        """PATCH /jobs/{id}: `tags` replaces every tag (a list), `add` and `remove` change
        some (not with `tags`), and/or a new note; the job as it is now."""
        body = {k: v for k, v in (("tags", tags), ("tags_add", add), ("tags_remove", remove),
                                  ("note", note)) if v is not None}
        return self.patch_job(job_id, body)

    def patch_job(self, job_id, body):
        """PATCH /jobs/{id} with `body` ({"tags"} or {"tags_add", "tags_remove"}, "note")."""
        return self.request("PATCH", f"{API}/jobs/{job_id}", json_body=body,
                            idempotent=True).json()

    def archive(self, job_id, archived=True):
        action = "archive" if archived else "restore"
        return self.request("POST", f"{API}/jobs/{job_id}/{action}", idempotent=True).json()

    def delete(self, job_id):
        """DELETE /jobs/{id}: {id, deleted, result_deleted}."""
        return self.request("DELETE", f"{API}/jobs/{job_id}").json()

    def export_archive(self, path, ids=None, filters=None):
        """The runs `ids` (POST /exports: up to 1000, more than a URL holds), or those of the
        filters of GET /jobs (GET /exports), as a tar archive streamed into the file `path`."""
        if ids:
            response = self.request("POST", f"{API}/exports", json_body={"ids": list(ids)},
                                    stream=True, idempotent=True)
        else:
            response = self.request("GET", f"{API}/exports", params=dict(filters or {}),
                                    stream=True)
        size = 0
        with open(path, "wb") as f:
            for chunk in response.iter_content(1 << 20):
                f.write(chunk)
                size += len(chunk)
        return size

    def import_archive(self, path, again=False):
        """POST /imports with the tar file at `path`: {imported: [{id, original_id, url}],
        skipped: [{original_id, id, url, reason, detail}], count}. A run already on the
        server is skipped (listed with the run it is), unless `again`."""
        with open(path, "rb") as f:
            data = f.read()
        return self.request("POST", f"{API}/imports", data=data, ok=(200, 201),
                            params={"again": "true"} if again else None,
                            headers={"Content-Type": "application/x-tar"}).json()

    def list_jobs(self, filters=None, limit=None, page_size=100):
        """Yield jobs newest first, following the pagination cursor until `limit` jobs
        (None: all of them) have been yielded."""
        params = {k: v for k, v in (filters or {}).items() if v is not None}
        count = 0
        while True:
            want = page_size if limit is None else min(page_size, limit - count)
            if want <= 0:
                return
            page = self.get_json(f"{API}/jobs", params={**params, "limit": str(want)})
            for job in page.get("jobs", []):
                yield job
                count += 1
            cursor = page.get("next_cursor")
            if not cursor or not page.get("jobs"):
                return
            params["cursor"] = cursor

    def export_runs(self, fmt="ndjson", filters=None, limit=None):
        """The run table (GET /jobs?format=csv|ndjson) as text pages joined: every page
        the server links (`Link: rel="next"`) until `limit` rows (None: all).
        For csv, the header of each page after the first is dropped."""
        params = {k: v for k, v in (filters or {}).items() if v is not None}
        params["format"] = fmt
        url, texts, rows = f"{API}/jobs", [], 0
        while url:
            want = 100000 if limit is None else min(100000, limit - rows)
            if want <= 0:
                break
            params["limit"] = str(want)
            response = self.request("GET", url, params=params)
            lines = response.text.splitlines(keepends=True)
            if fmt == "csv":
                if texts:
                    lines = lines[1:]
                rows += max(0, len(lines) - (0 if texts else 1))
            else:
                rows += len(lines)
            texts.append("".join(lines))
            url = response.links.get("next", {}).get("url")
            params = {}  # the next URL carries every parameter but the page size
        return self._absolute_result_urls("".join(texts))

    def _absolute_result_urls(self, text):
        """The run table's result_url cells (the server writes them as paths, /api/v1/jobs/
        ID/result.h5) as full URLs on the server asked, for a table read elsewhere."""
        return RESULT_PATH.sub(lambda m: m.group(1) + self.base_url + m.group(2), text)

    def list_studies(self, status=None, limit=None, page_size=100, archived=None):
        """Yield study summaries newest first (all of them, or `limit`); archived ones only
        with `archived` "include" or "only"."""
        params = {"status": status} if status else {}
        if archived:
            params["archived"] = archived
        count = 0
        while True:
            want = page_size if limit is None else min(page_size, limit - count)
            if want <= 0:
                return
            page = self.get_json(f"{API}/studies", params={**params, "limit": str(want)})
            for study in page.get("studies", []):
                yield study
                count += 1
            cursor = page.get("next_cursor")
            if not cursor or not page.get("studies"):
                return
            params["cursor"] = cursor

    def result_xdmf(self, job_id):
        """The XDMF sidecar of a job's result file (it names the file ID.h5)."""
        return self.request("GET", f"{API}/jobs/{job_id}/result.xdmf").text

    def metrics(self, job_id):
        return self.get_json(f"{API}/jobs/{job_id}/metrics")

    def front(self, job_id):
        return self.get_json(f"{API}/jobs/{job_id}/front")

    def stations_csv(self, job_id):
        """The job's stations, every step, as CSV text (docs/hdf5-layout.md "Stations as CSV")."""
        return self.request("GET", f"{API}/jobs/{job_id}/stations.csv").text

    def fit_length(self, body):
        """POST /length-fits (docs/length-fit.md): `body` is {"record": CSV text or
        {"time": [...], ...}, and the options}; slipfront_client.length_fit.request_body
        builds it. Nothing is stored, so a retry is safe."""
        return self.request("POST", f"{API}/length-fits", json_body=body,
                            idempotent=True).json()

    def create_study(self, study):
        response = self.request("POST", f"{API}/studies", json_body=study, ok=(200, 201, 202),
                                idempotent=False)
        return response.json()

    def study(self, study_id):
        return self.get_json(f"{API}/studies/{study_id}")

    def patch_study(self, study_id, body):
        """PATCH /studies/{id}: {"tags"} or {"tags_add", "tags_remove"}, and/or "note"; the
        study as it is now."""
        return self.request("PATCH", f"{API}/studies/{study_id}", json_body=body,
                            idempotent=True).json()

    def archive_study(self, study_id, archived=True):
        action = "archive" if archived else "restore"
        return self.request("POST", f"{API}/studies/{study_id}/{action}", idempotent=True).json()

    def export_study(self, study_id, path):
        """GET /studies/{id}/export: the study with its runs as one tar archive, streamed into
        the file `path` (import it with import_archive)."""
        response = self.request("GET", f"{API}/studies/{study_id}/export", stream=True)
        size = 0
        with open(path, "wb") as f:
            for chunk in response.iter_content(1 << 20):
                f.write(chunk)
                size += len(chunk)
        return size

    def delete_study(self, study_id):
        """DELETE /studies/{id}: {id, deleted, deleted_jobs, results_deleted}."""
        return self.request("DELETE", f"{API}/studies/{study_id}").json()

    def cancel_study(self, study_id):
        response = self.request("POST", f"{API}/studies/{study_id}/cancel", ok=(200, 202),
                                idempotent=True)
        return response.json()

    def convergence_map(self, params=None):
        return self.get_json(f"{API}/convergence-map", params=params)

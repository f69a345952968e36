"""Start `slipfront serve` on an ephemeral loopback port with a temporary data dir, and
talk to it. Shared by the server tests and the load benchmark. Every wait is bounded."""

import json
import os
import sys
import time

import requests

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))), "clients"))
from slipfront_client import local_server  # noqa: E402

TERMINAL = {"succeeded", "failed", "cancelled"}

# A tiny, coarse job: n_d = 5, 2 s simulated; runs in a fraction of a second.
TINY = {"geometry": {"nodes_per_meter": 5}, "time": {"duration": 2.0}}


def long_job(name="long"):
    """A job that runs for about 20 s on one core (for cancel/progress/drain tests); the
    tests cancel it or stop the server long before it ends. (n_d = 30 ran for 10 s until
    the FE step became 2.5x faster; then it sometimes ended before its cancel.)"""
    return {
        "name": name,
        "geometry": {"nodes_per_meter": 50},
        "time": {"duration": 16.0, "stop_on_arrest": False},
    }


class Server(local_server.Server):
    """The shared launcher (clients/slipfront_client/local_server.py) with a requests
    session for the tests: get/post/submit and waiting for a job's status."""

    def __init__(self, binary, data_dir=None, args=(), startup_timeout=20.0, preexec_fn=None):
        super().__init__(binary, data_dir, args, startup_timeout, preexec_fn)
        self.session = requests.Session()

    def url(self, path):
        return self.base + path

    def get(self, path, **kw):
        kw.setdefault("timeout", 10)
        return self.session.get(self.url(path), **kw)

    def post(self, path, **kw):
        kw.setdefault("timeout", 10)
        return self.session.post(self.url(path), **kw)

    def submit(self, spec, **kw):
        return self.post("/api/v1/jobs", data=json.dumps(spec),
                         headers={"Content-Type": "application/json", **kw.pop("headers", {})},
                         **kw)

    def wait_status(self, job_id, statuses, timeout=60.0, interval=0.05):
        deadline = time.monotonic() + timeout
        job = None
        while time.monotonic() < deadline:
            job = self.get(f"/api/v1/jobs/{job_id}").json()
            if job["status"] in statuses:
                return job
            time.sleep(interval)
        raise AssertionError(f"job {job_id} not in {statuses} after {timeout} s: {job}")

    def terminate(self, timeout=30.0):
        """SIGTERM (drain) and wait; returns the exit code."""
        self.session.close()
        try:
            return super().terminate(timeout)
        except RuntimeError as e:
            raise AssertionError(str(e)) from None

    def kill(self):
        super().kill()
        self.session.close()


def wait_study(server, study_id, timeout=240.0):
    """GET /api/v1/studies/{id} until it is finished (bounded by `timeout`: FE runs under the
    sanitizers on a loaded 2-core machine took more than 90 s)."""
    deadline = time.monotonic() + timeout
    study = None
    while time.monotonic() < deadline:
        study = server.get(f"/api/v1/studies/{study_id}").json()
        if study["status"] == "finished":
            return study
        time.sleep(0.1)
    raise AssertionError(f"study {study_id} not finished after {timeout} s: "
                         f"{json.dumps(study)[:2000]}")

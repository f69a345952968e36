"""Start `slipfront serve` on an ephemeral loopback port with a temporary data dir, and
talk to it. Shared by the server tests and the load benchmark. Every wait is bounded."""

import json
import os
import select
import shutil
import signal
import subprocess
import tempfile
import time

import requests

TERMINAL = {"succeeded", "failed", "cancelled"}

# A tiny, coarse job: n_d = 5, 2 s simulated; runs in a fraction of a second.
TINY = {"geometry": {"nodes_per_meter": 5}, "time": {"duration": 2.0}}


def long_job(name="long"):
    """A job that runs for about 10 s on one core (for cancel/progress/drain tests); the
    tests cancel it or stop the server long before it ends."""
    return {
        "name": name,
        "geometry": {"nodes_per_meter": 30},
        "time": {"duration": 16.0, "stop_on_arrest": False},
    }


class Server:
    def __init__(self, binary, data_dir=None, args=(), startup_timeout=20.0, preexec_fn=None):
        self.binary = binary
        self.own_dir = data_dir is None
        self.data_dir = data_dir or tempfile.mkdtemp(prefix="slipfront-test-")
        self.args = list(args)
        self.startup_timeout = startup_timeout
        self.preexec_fn = preexec_fn  # e.g. lower resource limits in the server's process
        self.proc = None
        self.base = None
        self.log_path = os.path.join(self.data_dir, "server.log")
        self.session = requests.Session()

    def start(self):
        cmd = [self.binary, "serve", "--host", "127.0.0.1", "--port", "0",
               "--data-dir", self.data_dir] + self.args
        self.log = open(self.log_path, "ab")
        self.proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=self.log,
                                     preexec_fn=self.preexec_fn)
        deadline = time.monotonic() + self.startup_timeout
        line = b""
        while time.monotonic() < deadline:
            ready, _, _ = select.select([self.proc.stdout], [], [], 0.2)
            if ready:
                line = self.proc.stdout.readline()
                break
            if self.proc.poll() is not None:
                break
        text = line.decode().strip()
        if not text.startswith("listening on http://"):
            self.kill()
            raise RuntimeError(f"server did not start (got {text!r}); log:\n{self.read_log()}")
        self.base = text[len("listening on "):]
        return self

    def read_log(self):
        try:
            with open(self.log_path, "rb") as f:
                return f.read().decode(errors="replace")[-4000:]
        except OSError:
            return ""

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
        if self.proc and self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
            try:
                self.proc.wait(timeout=timeout)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(timeout=10)
                raise AssertionError("server did not stop within %s s of SIGTERM" % timeout)
        self.session.close()
        return self.proc.returncode if self.proc else None

    def kill(self):
        if self.proc and self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait(timeout=10)
        self.session.close()

    def cleanup(self):
        self.kill()
        if self.proc and self.proc.stdout:
            self.proc.stdout.close()
        if getattr(self, "log", None):
            self.log.close()
        if self.own_dir:
            shutil.rmtree(self.data_dir, ignore_errors=True)


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

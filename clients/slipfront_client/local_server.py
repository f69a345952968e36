"""A local `slipfront serve` for scripts (clients/reproduce_paper.py, benchmarks): started
on an ephemeral loopback port in a data dir, its URL read from its stdout, stopped with
SIGTERM (the server drains) and killed after 30 s."""

import os
import re
import subprocess
import sys
import time


def log(text):
    print(f"[reproduce {time.strftime('%H:%M:%S')}] {text}", file=sys.stderr, flush=True)

class Server:
    """`slipfront serve --port 0` in a data dir; the URL is read from its stdout."""

    def __init__(self, binary, data_dir, workers, extra=()):
        self.binary, self.data_dir, self.workers, self.extra = binary, data_dir, workers, extra
        self.proc = None
        self.url = None

    def start(self, timeout=30):
        cmd = [self.binary, "serve", "--host", "127.0.0.1", "--port", "0",
               "--data-dir", self.data_dir, "--workers", str(self.workers), *self.extra]
        self.log_path = os.path.join(self.data_dir, "server.log")
        os.makedirs(self.data_dir, exist_ok=True)
        self.stderr = open(self.log_path, "w")
        self.proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=self.stderr, text=True)
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            line = self.proc.stdout.readline()
            if not line:
                if self.proc.poll() is not None:
                    break
                continue
            m = re.search(r"listening on (http://\S+)", line)
            if m:
                self.url = m.group(1)
                log(f"server {self.url} (pid {self.proc.pid}, data {self.data_dir})")
                return self
        self.stop()
        raise SystemExit(f"reproduce: the server did not start; see {self.log_path}")

    def stop(self):
        if self.proc and self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(timeout=30)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        if getattr(self, "stderr", None):
            self.stderr.close()


REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def default_binary():
    """build/slipfront of this checkout (or build-repro/slipfront)."""
    for cand in ("build/slipfront", "build-repro/slipfront"):
        path = os.path.join(REPO, cand)
        if os.access(path, os.X_OK):
            return path
    return os.path.join(REPO, "build/slipfront")

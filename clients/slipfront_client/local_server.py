"""A local `slipfront serve` on an ephemeral loopback port: the one launcher that
clients/reproduce_paper.py, the benchmarks and the server and client tests share
(tests/server/server_harness.py and tests/clients/harness.py build on it).

The server prints "listening on http://HOST:PORT" on stdout once it accepts connections;
start() reads that line (bounded wait) and keeps the URL in `base` (also `url`). Its log
goes to DATA_DIR/server.log. terminate() sends SIGTERM (the server drains) and waits."""

import os
import select
import shutil
import signal
import subprocess
import sys
import tempfile
import time


def log(text):
    print(f"[reproduce {time.strftime('%H:%M:%S')}] {text}", file=sys.stderr, flush=True)


class Server:
    """`slipfront serve --host 127.0.0.1 --port 0 --data-dir DATA_DIR ARGS...`.

    data_dir: None = a temporary directory, removed by cleanup(). preexec_fn: run in the
    server's process before exec (e.g. lower resource limits)."""

    def __init__(self, binary, data_dir=None, args=(), startup_timeout=20.0, preexec_fn=None):
        self.binary = binary
        self.own_dir = data_dir is None
        self.data_dir = data_dir or tempfile.mkdtemp(prefix="slipfront-test-")
        self.args = list(args)
        self.startup_timeout = startup_timeout
        self.preexec_fn = preexec_fn
        self.proc = None
        self.base = None
        self.log = None
        self.log_path = os.path.join(self.data_dir, "server.log")

    @property
    def url(self):
        return self.base

    def start(self, timeout=None):
        """Starts the server and waits (at most `timeout`, default startup_timeout, seconds)
        for its "listening on" line; raises RuntimeError with the log's end otherwise."""
        if not os.access(self.binary, os.X_OK):
            raise RuntimeError(f"no slipfront binary at {self.binary} (pass --binary)")
        cmd = [self.binary, "serve", "--host", "127.0.0.1", "--port", "0",
               "--data-dir", self.data_dir] + self.args
        self.log = open(self.log_path, "ab")
        self.proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=self.log,
                                     preexec_fn=self.preexec_fn)
        deadline = time.monotonic() + (self.startup_timeout if timeout is None else timeout)
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
            raise RuntimeError(f"server did not start (got {text!r}); log "
                               f"{self.log_path}:\n{self.read_log()}")
        self.base = text[len("listening on "):]
        return self

    def read_log(self):
        """The last 4000 characters of the server's log."""
        try:
            with open(self.log_path, "rb") as f:
                return f.read().decode(errors="replace")[-4000:]
        except OSError:
            return ""

    def terminate(self, timeout=30.0):
        """SIGTERM (drain) and wait; returns the exit code. A server still running after
        `timeout` s is killed and RuntimeError raised."""
        if self.proc and self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
            try:
                self.proc.wait(timeout=timeout)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(timeout=10)
                raise RuntimeError(f"server did not stop within {timeout} s of SIGTERM")
        return self.proc.returncode if self.proc else None

    def kill(self):
        if self.proc and self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait(timeout=10)

    def cleanup(self):
        """Kills the server if it still runs, closes its pipes and removes a temporary data
        dir."""
        self.kill()
        if self.proc and self.proc.stdout:
            self.proc.stdout.close()
        if self.log:
            self.log.close()
            self.log = None
        if self.own_dir:
            shutil.rmtree(self.data_dir, ignore_errors=True)

    def stop(self, timeout=30.0):
        """terminate() (a server that does not drain in time is killed, quietly), then
        cleanup()."""
        try:
            self.terminate(timeout)
        except RuntimeError:
            pass
        self.cleanup()


REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def default_binary():
    """build/slipfront of this checkout (or build-repro/slipfront)."""
    for cand in ("build/slipfront", "build-repro/slipfront"):
        path = os.path.join(REPO, cand)
        if os.access(path, os.X_OK):
            return path
    return os.path.join(REPO, "build/slipfront")

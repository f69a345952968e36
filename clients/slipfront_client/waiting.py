"""Waiting for jobs: bounded exponential back-off polling, a progress bar on stderr, and
the mapping of a finished job to success or to an exception with its exit code."""

import sys
import time

from .errors import JobCancelled, JobFailed, ServerError

FINAL = ("succeeded", "failed", "cancelled")


class Backoff:
    """Delays that grow geometrically from `first` to at most `cap` seconds."""

    def __init__(self, first=0.2, factor=1.5, cap=5.0):
        self.first, self.factor, self.cap = first, factor, cap
        self.current = first

    def next(self):
        delay = self.current
        self.current = min(self.current * self.factor, self.cap)
        return delay

    def reset(self):
        self.current = self.first


def format_duration(seconds):
    """'42 s', '3 min 05 s', '1 h 02 min'; '?' when unknown."""
    if seconds is None or seconds != seconds or seconds < 0:
        return "?"
    seconds = int(round(seconds))
    if seconds < 60:
        return f"{seconds} s"
    if seconds < 3600:
        return f"{seconds // 60} min {seconds % 60:02d} s"
    return f"{seconds // 3600} h {(seconds % 3600) // 60:02d} min"


class ProgressBar:
    """One line on stderr: bar, fraction, simulated time, ETA and status.

    On a terminal the line is redrawn in place; otherwise a line is printed when the status
    changes or the fraction passes another 25 %, so logs stay short.
    """

    def __init__(self, stream=None, width=30, enabled=True):
        self.stream = stream or sys.stderr
        self.width = width
        self.enabled = enabled
        self.tty = hasattr(self.stream, "isatty") and self.stream.isatty()
        self.last_status = None
        self.last_quarter = -1
        self.drawn = False

    def render(self, job):
        p = job.get("progress") or {}
        fraction = float(p.get("fraction") or 0.0)
        if job.get("status") == "succeeded":
            fraction = 1.0
        filled = int(round(fraction * self.width))
        bar = "#" * filled + "-" * (self.width - filled)
        t, duration = p.get("time") or 0.0, p.get("duration") or 0.0
        eta = p.get("eta_s") if job.get("status") == "running" else None
        return (f"[{bar}] {100 * fraction:5.1f}%  t = {t:.3g}/{duration:.3g} s  "
                f"ETA {format_duration(eta)}  {job.get('status', '?')}")

    def update(self, job):
        if not self.enabled:
            return
        line = self.render(job)
        if self.tty:
            self.stream.write("\r" + line + "\033[K")
            self.stream.flush()
            self.drawn = True
            return
        quarter = int(4 * float((job.get("progress") or {}).get("fraction") or 0.0))
        if job.get("status") != self.last_status or quarter > self.last_quarter:
            self.stream.write(line + "\n")
            self.stream.flush()
        self.last_status, self.last_quarter = job.get("status"), quarter

    def close(self):
        if self.enabled and self.tty and self.drawn:
            self.stream.write("\n")
            self.stream.flush()


def wait_for_job(api, job_id, progress=None, timeout=None, backoff=None, clock=time.monotonic,
                 sleep=time.sleep):
    """Poll GET /jobs/{id} until the job is final; return it.

    The delay between polls grows while nothing changes and falls back to the first delay
    when the job moves. `timeout` (seconds, None = no limit) raises ServerError.
    """
    backoff = backoff or Backoff()
    deadline = None if timeout is None else clock() + timeout
    seen = None
    while True:
        job = api.job(job_id)
        if progress:
            progress.update(job)
        if job.get("status") in FINAL:
            return job
        state = (job.get("status"), (job.get("progress") or {}).get("steps"))
        if state != seen:
            backoff.reset()
            seen = state
        delay = backoff.next()
        if deadline is not None and clock() + delay > deadline:
            raise ServerError(f"job {job_id} is still {job.get('status')} after {timeout} s")
        sleep(delay)


def check_outcome(job):
    """Raise JobFailed / JobCancelled for a final job that did not succeed (or diverged)."""
    status = job.get("status")
    job_id = job.get("id", "?")
    if status == "cancelled":
        raise JobCancelled(f"job {job_id} was cancelled")
    if status == "failed":
        raise JobFailed(f"job {job_id} failed: {job.get('error') or 'no error message'}")
    metrics = job.get("metrics") or {}
    if metrics.get("outcome") == "diverged":
        raise JobFailed(f"job {job_id} diverged: {metrics.get('message') or ''}".rstrip(": "))
    return job

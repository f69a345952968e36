"""Submissions and status reads while anonymous clients loop CSV exports:
before, with 4 clients exporting 3,000 jobs in a loop, `POST /jobs` took about 1 s (p50).

A real data dir is filled with 3,000 succeeded jobs (copies of one real run's rows, written
with sqlite3 while the server is stopped: seconds instead of 3,000 fsynced submissions), the
server is started on it, EXPORTERS processes loop `GET /jobs?format=csv`, and one client
submits jobs (cache hits of the seeded run) and reads a job's status in turn, bounded in
count and time. Prints p50/p99/max of both and the exports done meanwhile.

    /usr/bin/python3 tests/server/test_export_contention.py --binary build/slipfront
    # the figures alone, longer (docs/reliability.md):
    /usr/bin/python3 tests/server/test_export_contention.py --binary build/slipfront \\
        --measure --seconds 30 --submissions 200
"""

import argparse
import json
import multiprocessing
import os
import sqlite3
import sys
import time
import unittest
import uuid

import requests

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import TINY, Server  # noqa: E402

BINARY = None
JOBS = "/api/v1/jobs"
FITS = "/api/v1/length-fits"
SEEDED_JOBS = 3000
EXPORTERS = 4
FITTERS = 32
# A run of the paper's scene at n_d = 10 with 24 on-fault stations: its stations CSV (every
# step) is a length-fit record of about 0.9 MB, each fit about 50 ms of one core.
STATION_JOB = {"name": "fit-record", "geometry": {"nodes_per_meter": 10},
               "friction": {"L": 3e-4}, "stations": {"x1": list(range(1, 25))}}


def seed_copies(data_dir, job_id, count):
    """`count` more succeeded jobs in the stopped server's database: copies of job `job_id`'s
    rows (jobs and metrics) with new ids and names, marked as cache hits of it."""
    with sqlite3.connect(os.path.join(data_dir, "slipfront.db")) as db:
        db.row_factory = sqlite3.Row
        job = dict(db.execute("SELECT * FROM jobs WHERE id = ?", (job_id,)).fetchone())
        metrics = dict(db.execute("SELECT * FROM metrics WHERE job_id = ?",
                                  (job_id,)).fetchone())
        del job["seq"]
        job_cols, metric_cols = list(job), list(metrics)
        insert_job = (f"INSERT INTO jobs ({', '.join(job_cols)}) "
                      f"VALUES ({', '.join('?' * len(job_cols))})")
        insert_metrics = (f"INSERT INTO metrics ({', '.join(metric_cols)}) "
                          f"VALUES ({', '.join('?' * len(metric_cols))})")
        for i in range(count):
            new_id = uuid.uuid4().hex
            job.update(id=new_id, name=f"copy-{i}", cached_from=job_id, idempotency_key=None)
            metrics["job_id"] = new_id
            db.execute(insert_job, [job[c] for c in job_cols])
            db.execute(insert_metrics, [metrics[c] for c in metric_cols])


def seeded_server(jobs, args=()):
    """A running server whose database holds `jobs` succeeded jobs; returns (server, the id
    of the one that ran)."""
    server = Server(BINARY, args=list(args)).start()
    try:
        r = server.submit(dict(TINY, name="export-seed"))
        assert r.status_code == 201, r.text
        seed = r.json()["id"]
        server.wait_status(seed, {"succeeded"}, timeout=60)
        assert server.terminate() == 0
    except BaseException:
        server.kill()
        server.cleanup()
        raise
    seed_copies(server.data_dir, seed, jobs - 1)
    server.proc.stdout.close()  # the first process's pipe and log; start() opens new ones
    server.log.close()
    server.start()
    return server, seed


def export_loop(url, stop, done, failures, body=None):
    """One anonymous exporter: GET the CSV of every job, again and again, until `stop` (with a
    `body`: POST it instead, as a client looping length fits, at nice 10: such clients run
    elsewhere, not on the server's two cores, whose time the test measures)."""
    if body is not None:
        os.nice(10)
    with requests.Session() as s:
        while not stop.is_set():
            try:
                r = (s.get(url, timeout=120) if body is None else
                     s.post(url, data=body, headers={"Content-Type": "application/json"},
                            timeout=120))
            except requests.RequestException:
                with failures.get_lock():
                    failures.value += 1
                continue
            with (done if r.status_code == 200 else failures).get_lock():
                (done if r.status_code == 200 else failures).value += 1
            if r.status_code == 503:  # turned away: come back as Retry-After says
                stop.wait(float(r.headers.get("Retry-After", "1")))


def percentile(values, q):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(q * len(ordered)))]


def summary(name, latencies):
    return (f"{name}: {len(latencies)} requests, p50 {percentile(latencies, 0.5) * 1000:.0f} ms, "
            f"p99 {percentile(latencies, 0.99) * 1000:.0f} ms, "
            f"max {max(latencies) * 1000:.0f} ms")


def measure(server, seed, exporters, submissions, seconds, fit_body=None):
    """With `exporters` processes looping the CSV export (with `fit_body`: POSTing that length
    fit), submit up to `submissions` jobs and read the seed's status after each, for at most
    `seconds`. Returns a dict of figures."""
    ctx = multiprocessing.get_context("fork")
    stop, done, failures = ctx.Event(), ctx.Value("i", 0), ctx.Value("i", 0)
    url = server.url(f"{JOBS}?format=csv&limit=100000" if fit_body is None else FITS)
    procs = [ctx.Process(target=export_loop, args=(url, stop, done, failures, fit_body))
             for _ in range(exporters)]
    for p in procs:
        p.start()
    post, status = [], []
    try:
        time.sleep(1.0 if exporters else 0)  # every exporter has an export in flight
        with requests.Session() as s:
            started = time.monotonic()
            for i in range(submissions):
                if time.monotonic() - started > seconds:
                    break
                t0 = time.monotonic()
                r = s.post(server.url(JOBS), data=json.dumps(dict(TINY, name=f"during-{i}")),
                           headers={"Content-Type": "application/json"}, timeout=60)
                post.append(time.monotonic() - t0)
                assert r.status_code == 201, r.text
                t0 = time.monotonic()
                r = s.get(server.url(f"{JOBS}/{seed}"), timeout=60)
                status.append(time.monotonic() - t0)
                assert r.status_code == 200, r.text
            elapsed = time.monotonic() - started
    finally:
        stop.set()
        for p in procs:
            p.join(timeout=130)
            if p.is_alive():
                p.kill()
    return {"post": post, "status": status, "exports": done.value,
            "refused_exports": failures.value, "seconds": elapsed}


def report(figures, exporters, what=f"exporters of {SEEDED_JOBS} jobs"):
    return (f"{exporters} {what}, {figures['seconds']:.1f} s, "
            f"load average {os.getloadavg()[0]:.1f}: "
            f"{summary('POST /jobs', figures['post'])}; "
            f"{summary('GET /jobs/{id}', figures['status'])}; "
            f"answered 200: {figures['exports']}, "
            f"otherwise: {figures['refused_exports']}")


class ExportsDoNotHoldUpSubmissions(unittest.TestCase):
    def test_submissions_and_status_stay_quick_while_exports_loop(self):
        server, seed = seeded_server(SEEDED_JOBS)
        try:
            figures = measure(server, seed, EXPORTERS, submissions=100, seconds=15)
            print(report(figures, EXPORTERS), file=sys.stderr)
            # Before the fix: p50 about 1 s (the issue), and every submission measured.
            self.assertLess(percentile(figures["post"], 0.5), 0.1, figures["post"])
            self.assertLess(percentile(figures["status"], 0.5), 0.1, figures["status"])
            self.assertLess(max(figures["status"]), 1.0, figures["status"])
            # The exports are served all the while, not only refused.
            self.assertGreater(figures["exports"], 0)
            self.assertEqual(server.get("/healthz").status_code, 200)
            self.assertEqual(server.terminate(), 0)
        finally:
            server.kill()
            server.cleanup()


def fit_record_server():
    """A running server with the seed job and a length-fit body of about 0.9 MB (the stations
    CSV of STATION_JOB); returns (server, seed id, body)."""
    server = Server(BINARY, args=["--workers", "1"]).start()
    try:
        seed = server.submit(dict(TINY, name="fit-seed")).json()["id"]
        record = server.submit(STATION_JOB).json()["id"]
        server.wait_status(seed, {"succeeded"}, timeout=60)
        server.wait_status(record, {"succeeded"}, timeout=120)
        csv = server.get(f"{JOBS}/{record}/stations.csv", timeout=60).text
        return server, seed, json.dumps({"record": csv, "station_x1": 6})
    except BaseException:
        server.kill()
        server.cleanup()
        raise


class FitsDoNotHoldUpSubmissions(unittest.TestCase):
    """Anonymous length fits ran on the write pool: 32 clients looping 0.9 MB fits pushed
    POST /jobs to a p50 of 1.85-3.6 s. They run on a bounded pool of their own now."""

    def test_submissions_stay_quick_while_fits_loop(self):
        server, seed, body = fit_record_server()
        try:
            # 200 submissions: the p99 is then the second largest, not the largest (one stall of
            # the shared machine's scheduler is not a submission held up by the fits).
            figures = measure(server, seed, FITTERS, submissions=200, seconds=15, fit_body=body)
            print(report(figures, FITTERS, f"clients looping {len(body) / 1e6:.2f} MB fits"),
                  file=sys.stderr)
            self.assertLess(percentile(figures["post"], 0.99), 0.1, figures["post"])
            self.assertLess(percentile(figures["status"], 0.99), 0.1, figures["status"])
            # Fits are served all the while; the ones past --max-fits are told to come back.
            self.assertGreater(figures["exports"], 0)
            self.assertGreater(figures["refused_exports"], 0)
            busy = server.post(FITS, data=body, headers={"Content-Type": "application/json"})
            self.assertIn(busy.status_code, (200, 503))
            self.assertEqual(server.terminate(), 0)
        finally:
            server.kill()
            server.cleanup()


def peak_rss_mib(pid):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmHWM:"):
                return int(line.split()[1]) / 1024
    raise AssertionError("no VmHWM")


class ExportMemory(unittest.TestCase):
    """An export was built as JSON objects, about 22 kB a row (2.2 GB for the 100000 rows
    one export may ask for); its rows are now kept as the text of their cells."""

    def test_an_export_holds_kilobytes_per_row(self):
        server, _ = seeded_server(SEEDED_JOBS)
        try:
            before = peak_rss_mib(server.proc.pid)
            r = server.get(f"{JOBS}?format=csv&limit=100000", timeout=60)
            self.assertEqual(r.status_code, 200)
            self.assertEqual(r.text.count("\r\n"), SEEDED_JOBS + 1)
            peak = peak_rss_mib(server.proc.pid)
            print(f"CSV export of {SEEDED_JOBS} jobs ({len(r.content) / 1e6:.1f} MB): server "
                  f"peak RSS {before:.0f} -> {peak:.0f} MiB", file=sys.stderr)
            # Before: +64 MiB; now about +18 (the answer, the rows' cells, SQLite's cache).
            self.assertLess(peak - before, 40)
            self.assertEqual(server.terminate(), 0)
        finally:
            server.kill()
            server.cleanup()


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    parser.add_argument("--measure", action="store_true",
                        help="print the figures (with and without exporters) instead of testing")
    parser.add_argument("--seconds", type=float, default=20)
    parser.add_argument("--submissions", type=int, default=100)
    parser.add_argument("--exporters", type=int, default=EXPORTERS)
    parser.add_argument("--fits", action="store_true",
                        help="with --measure: clients looping length fits instead of exports")
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    if not args.measure:
        unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)
    elif args.fits:
        server, seed, body = fit_record_server()
        try:
            for n in (0, FITTERS):
                print(report(measure(server, seed, n, args.submissions, args.seconds, body), n,
                             f"clients looping {len(body) / 1e6:.2f} MB fits"))
        finally:
            server.kill()
            server.cleanup()
    else:
        server, seed = seeded_server(SEEDED_JOBS)
        try:
            for n in (0, args.exporters):
                print(report(measure(server, seed, n, args.submissions, args.seconds), n))
        finally:
            server.kill()
            server.cleanup()

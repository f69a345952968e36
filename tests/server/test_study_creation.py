"""Creating a study under faults: SIGKILL while a 400-run study is
being created never leaves part of a study, a client's retry with the same Idempotency-Key
never makes a second study, and `--queue-limit` holds when several studies are created at
once.

    /usr/bin/python3 tests/server/test_study_creation.py --binary build/slipfront
"""

import argparse
import json
import os
import random
import shutil
import sqlite3
import sys
import tempfile
import threading
import time
import unittest

import requests

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import Server  # noqa: E402

BINARY = None
STUDIES = "/api/v1/studies"

# A tiny scene (runs well under a second each); a grid of 20 x 20 = 400 runs, the most a study
# may have.
BASE = {"geometry": {"width": 12, "x_min": -1, "height": 4},
        "probe": {"arrival_x1": 3, "spectrum_x1": 2}, "time": {"duration": 3}}


def grid_study(name, first_L=5e-5):
    return {"name": name, "base": BASE,
            "grid": {"L": [first_L * (1 + 0.01 * i) for i in range(20)],
                     "n_d": [5 + 0.25 * k for k in range(20)]}}


def post(server, body, key=None, timeout=60):
    headers = {"Content-Type": "application/json"}
    if key is not None:
        headers["Idempotency-Key"] = key
    return requests.post(server.url(STUDIES), data=json.dumps(body), headers=headers,
                         timeout=timeout)


def studies_in(data_dir):
    """Every study of the database: id -> (runs recorded in study_runs, jobs of those runs
    that exist, runs_total, idempotency key)."""
    with sqlite3.connect(os.path.join(data_dir, "slipfront.db")) as db:
        columns = [c[1] for c in db.execute("PRAGMA table_info(studies)")]
        key = "s.idempotency_key" if "idempotency_key" in columns else "NULL"  # before m7
        rows = db.execute(
            f"SELECT s.id, s.runs_total, {key}, "
            "(SELECT COUNT(*) FROM study_runs r WHERE r.study_id = s.id), "
            "(SELECT COUNT(*) FROM study_runs r JOIN jobs j ON j.id = r.job_id "
            " WHERE r.study_id = s.id), "
            "(SELECT COUNT(*) FROM jobs j WHERE j.study_id = s.id) FROM studies s").fetchall()
        orphans = db.execute("SELECT COUNT(*) FROM jobs j WHERE j.study_id IS NOT NULL AND "
                             "NOT EXISTS (SELECT 1 FROM studies s WHERE s.id = j.study_id)"
                             ).fetchone()[0]
        integrity = db.execute("PRAGMA integrity_check").fetchone()[0]
    return {r[0]: {"runs_total": r[1], "key": r[2], "runs": r[3], "runs_with_job": r[4],
                   "jobs": r[5]} for r in rows}, orphans, integrity


class StudyKilledMidCreation(unittest.TestCase):
    """Before: SIGKILL during a 400-run study's creation left a `running` study with 18-92 of
    its runs and a runs_total that disagreed; the client's retry made a second study."""

    def test_kill_loop_never_leaves_part_of_a_study(self):
        seed = int(os.environ.get("SLIPFRONT_FAULT_SEED", "10"))
        iterations = int(os.environ.get("SLIPFRONT_STUDY_KILLS", "6"))
        rng = random.Random(seed)
        data = tempfile.mkdtemp(prefix="slipfront-study-kill-")
        self.addCleanup(shutil.rmtree, data, True)
        outcomes = []
        started = time.monotonic()
        for i in range(iterations):
            server = Server(BINARY, data_dir=data,
                            args=["--workers", "1", "--queue-limit", "100000"]).start()
            try:
                key = f"study-kill-{i}"
                answers = []

                def create():
                    try:
                        answers.append(post(server, grid_study(f"killed-{i}"), key).status_code)
                    except requests.RequestException:
                        answers.append(None)
                thread = threading.Thread(target=create)
                thread.start()
                # From the request's arrival to a little after a creation usually ends.
                time.sleep(rng.uniform(0.0, 0.6))
                server.proc.kill()
                server.proc.wait(timeout=10)
                thread.join(timeout=30)
            finally:
                server.cleanup()
            studies, orphans, integrity = studies_in(data)
            self.assertEqual(integrity, "ok")
            self.assertEqual(orphans, 0, f"iteration {i}: jobs of a study that is not there")
            for study_id, s in studies.items():
                self.assertEqual(s["runs"], 400, f"iteration {i}: partial study {study_id}: {s}")
                self.assertEqual(s["runs_with_job"], 400, f"iteration {i}: {study_id}: {s}")
                self.assertEqual(s["jobs"], 400, f"iteration {i}: {study_id}: {s}")
            committed = any(s["key"] == key for s in studies.values())
            outcomes.append("committed" if committed else "nothing")

            # The client retries with the same key: the study it may have made, or a new one;
            # never two.
            server = Server(BINARY, data_dir=data,
                            args=["--workers", "1", "--queue-limit", "100000"]).start()
            try:
                r = post(server, grid_study(f"killed-{i}"), key)
                self.assertEqual(r.status_code, 200 if committed else 201, r.text)
                if committed:
                    self.assertEqual(r.headers.get("Idempotent-Replayed"), "true")
                study = r.json()
                self.assertEqual(study["progress"]["total"], 400, study)
                self.assertEqual(len(study["runs"]), 400)
                self.assertEqual(server.terminate(), 0)
            finally:
                server.cleanup()
            studies, _, _ = studies_in(data)
            self.assertEqual(sum(1 for s in studies.values() if s["key"] == key), 1,
                             f"iteration {i}: the retry made a second study")
        print(f"study kill loop (seed {seed}): {iterations} SIGKILLs during creation: "
              f"{outcomes}; {time.monotonic() - started:.1f} s", file=sys.stderr)


class StudyIdempotency(unittest.TestCase):
    """The same key: the same study (200, Idempotent-Replayed); another body: 422."""

    def test_same_key_same_study_other_body_refused(self):
        server = Server(BINARY, args=["--workers", "1"]).start()
        try:
            body = {"name": "idem", "base": BASE, "grid": {"L": [5e-5], "n_d": [5]}}
            first = post(server, body, "k-1")
            self.assertEqual(first.status_code, 201, first.text)
            again = post(server, body, "k-1")
            self.assertEqual(again.status_code, 200, again.text)
            self.assertEqual(again.headers.get("Idempotent-Replayed"), "true")
            self.assertEqual(again.json()["id"], first.json()["id"])
            other = post(server, dict(body, name="another"), "k-1")
            self.assertEqual(other.status_code, 422, other.text)
            self.assertIn("Idempotency-Key k-1 was used for a different study", other.text)
            bad = post(server, body, "")
            self.assertEqual(bad.status_code, 400, bad.text)
            self.assertIn("/headers/Idempotency-Key", bad.text)
            listed = server.get(STUDIES).json()["studies"]
            self.assertEqual(len(listed), 1)
            self.assertEqual(server.terminate(), 0)
        finally:
            server.cleanup()


class QueueLimitWithConcurrentStudies(unittest.TestCase):
    """Before: three 400-run studies created at once with --queue-limit 500 got 201, 201, 503
    and the queue held 780 (the limit was read outside the submission lock)."""

    def test_queue_never_exceeds_the_limit(self):
        server = Server(BINARY, args=["--workers", "1", "--queue-limit", "500"]).start()
        try:
            codes = []
            barrier = threading.Barrier(3)

            def create(k):
                barrier.wait()
                codes.append(post(server, grid_study(f"concurrent-{k}", 5e-5 * (1 + k))
                                  ).status_code)
            threads = [threading.Thread(target=create, args=(k,)) for k in range(3)]
            for t in threads:
                t.start()
            for t in threads:
                t.join(timeout=120)
            waiting = server.get("/api/v1/jobs", params={"status": "queued,running",
                                                         "limit": 1000, "fields": "id"})
            count = waiting.json()["count"]
            print(f"three 400-run studies at once, --queue-limit 500: {sorted(codes)}, "
                  f"{count} jobs queued or running", file=sys.stderr)
            self.assertEqual(sorted(codes), [201, 503, 503])
            # The limit is on the queue; one more job may be running.
            self.assertLessEqual(count, 501)
            self.assertEqual(server.terminate(), 0)
        finally:
            server.cleanup()


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

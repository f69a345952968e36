"""Crash and drain: nothing accepted is lost.

- SIGKILL while jobs run; restart on the same data dir: every accepted job reaches a final
  state (the interrupted ones are run again) and PRAGMA integrity_check is ok.
- SIGTERM drains: running jobs stop at a safe point, go back to queued, the process exits 0
  and the database is closed cleanly; the next start runs them.

    /usr/bin/python3 tests/server/test_crash.py --binary build/slipfront
"""

import argparse
import os
import shutil
import sqlite3
import sys
import tempfile
import time
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import TERMINAL, TINY, Server, long_job  # noqa: E402

BINARY = None
JOBS = "/api/v1/jobs"


def medium(i):
    # About a second each on one core: some are running when the process dies.
    return {"name": f"crash-{i}", "tags": ["crash"], "geometry": {"nodes_per_meter": 20},
            "time": {"duration": 6.0, "stop_on_arrest": False},
            "friction": {"L": 5e-5 * (1 + 0.01 * i)}}


def integrity(db_path):
    con = sqlite3.connect(db_path)
    try:
        return con.execute("PRAGMA integrity_check").fetchone()[0]
    finally:
        con.close()


def statuses(db_path):
    con = sqlite3.connect(db_path)
    try:
        return dict(con.execute("SELECT id, status FROM jobs").fetchall())
    finally:
        con.close()


class CrashRecovery(unittest.TestCase):
    def setUp(self):
        self.data_dir = tempfile.mkdtemp(prefix="slipfront-crash-")
        self.db = os.path.join(self.data_dir, "slipfront.db")

    def tearDown(self):
        shutil.rmtree(self.data_dir, ignore_errors=True)

    def test_sigkill_while_running_then_restart(self):
        s = Server(BINARY, data_dir=self.data_dir, args=["--workers", "2"]).start()
        try:
            ids = []
            for i in range(6):
                r = s.submit(medium(i))
                self.assertEqual(r.status_code, 201, r.text)
                ids.append(r.json()["id"])
            s.wait_status(ids[0], {"running"}, timeout=10, interval=0.02)
            s.wait_status(ids[1], {"running"}, timeout=10, interval=0.02)
            s.kill()  # SIGKILL: no chance to clean up
        finally:
            s.cleanup()
        self.assertEqual(integrity(self.db), "ok")
        before = statuses(self.db)
        self.assertEqual(set(before), set(ids), "every 201 was committed")
        self.assertIn("running", before.values())

        s = Server(BINARY, data_dir=self.data_dir, args=["--workers", "2"]).start()
        try:
            for job_id in ids:
                job = s.wait_status(job_id, TERMINAL, timeout=60)
                self.assertEqual(job["status"], "succeeded", job)
                if before[job_id] == "running":
                    self.assertGreaterEqual(job["attempts"], 2)
                r = s.get(job["result"]["url"])
                self.assertEqual(r.status_code, 200)
            self.assertIn("queued again", s.read_log())  # the recovery is logged
            self.assertEqual(s.terminate(), 0)
        finally:
            s.cleanup()
        self.assertEqual(integrity(self.db), "ok")
        leftovers = [f for f in os.listdir(os.path.join(self.data_dir, "results")) if ".tmp" in f]
        self.assertEqual(leftovers, [])

    def test_sigterm_drains_and_requeues(self):
        s = Server(BINARY, data_dir=self.data_dir, args=["--workers", "1"]).start()
        try:
            r = s.submit(long_job("drain"))
            self.assertEqual(r.status_code, 201, r.text)
            running_id = r.json()["id"]
            r = s.submit(dict(TINY, name="waiting"))
            queued_id = r.json()["id"]
            s.wait_status(running_id, {"running"}, timeout=10, interval=0.02)
            time.sleep(0.3)
            t0 = time.monotonic()
            self.assertEqual(s.terminate(timeout=20), 0)
            self.assertLess(time.monotonic() - t0, 5, "drain took too long")
        finally:
            s.cleanup()
        self.assertEqual(integrity(self.db), "ok")
        self.assertFalse(os.path.exists(self.db + "-wal") and os.path.getsize(self.db + "-wal") > 0,
                         "the WAL was checkpointed at shutdown")
        after = statuses(self.db)
        self.assertEqual(after[running_id], "queued", "drained job goes back to queued")
        self.assertEqual(after[queued_id], "queued")

        s = Server(BINARY, data_dir=self.data_dir, args=["--workers", "1"]).start()
        try:
            job = s.wait_status(running_id, {"running"} | TERMINAL, timeout=10)
            self.assertIn(job["status"], {"running", "succeeded"})
            r = s.post(f"{JOBS}/{running_id}/cancel")
            self.assertIn(r.status_code, (200, 202, 409))
            self.assertEqual(s.wait_status(queued_id, TERMINAL, timeout=30)["status"], "succeeded")
            self.assertEqual(s.terminate(), 0)
        finally:
            s.cleanup()
        self.assertEqual(integrity(self.db), "ok")


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

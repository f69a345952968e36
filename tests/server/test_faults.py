"""Faults around a live server (issue 10): a second server on the same data dir. Each
asserts what must hold: no accepted job lost or stuck, no 500, the database intact.

    /usr/bin/python3 tests/server/test_faults.py --binary build/slipfront
"""

import argparse
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import TERMINAL, Server, long_job  # noqa: E402

BINARY = None
JOBS = "/api/v1/jobs"


class SecondServerOnTheSameDir(unittest.TestCase):
    """Defect 2: the second server's start-up recovery re-queued the first one's running
    job and deleted its temporary file."""

    def test_second_server_refuses_the_locked_dir(self):
        first = Server(BINARY, args=["--workers", "1"]).start()
        try:
            job = first.submit(long_job("owned")).json()
            first.wait_status(job["id"], {"running"}, timeout=30)
            second = Server(BINARY, data_dir=first.data_dir, args=["--workers", "1"])
            with self.assertRaises(RuntimeError) as caught:
                second.start()
            self.assertIn("in use by another slipfront server", str(caught.exception))
            self.assertIn(str(first.proc.pid), str(caught.exception))
            self.assertEqual(second.proc.returncode, 1)
            second.cleanup()
            # The first server's job was not touched.
            now = first.get(f"{JOBS}/{job['id']}").json()
            self.assertEqual(now["status"], "running")
            self.assertEqual(now["attempts"], 1)
            self.assertEqual(first.post(f"{JOBS}/{job['id']}/cancel").status_code, 202)
            first.wait_status(job["id"], TERMINAL, timeout=10)
            self.assertEqual(first.terminate(), 0)
            # Released with the process: the next server takes the dir.
            third = Server(BINARY, data_dir=first.data_dir).start()
            self.assertEqual(third.get("/healthz").status_code, 200)
            self.assertEqual(third.terminate(), 0)
            third.cleanup()
        finally:
            first.own_dir = True
            first.cleanup()


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

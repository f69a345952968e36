"""A database row whose stored JSON does not parse: before, one job with a
spec that is not JSON made `GET /jobs?limit=1000` and the CSV export answer 500 for everyone,
and the start-up check did not notice. Now listings leave the row out and say so, the start-up
log names it, and `slipfront check DATA_DIR` lists it.

    /usr/bin/python3 tests/server/test_malformed_rows.py --binary build/slipfront
"""

import argparse
import os
import sqlite3
import subprocess
import sys
import unittest

import requests

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import TINY, Server  # noqa: E402

BINARY = None
JOBS = "/api/v1/jobs"


class MalformedRow(unittest.TestCase):
    def test_a_row_that_is_not_json_is_skipped_and_reported(self):
        server = Server(BINARY, args=["--workers", "1"]).start()
        try:
            ids = []
            for i in range(3):
                r = server.submit(dict(TINY, name=f"row-{i}"), params={"fresh": "true"})
                self.assertEqual(r.status_code, 201, r.text)
                ids.append(server.wait_status(r.json()["id"], {"succeeded"})["id"])
            self.assertEqual(server.terminate(), 0)
            check = subprocess.run([BINARY, "check", server.data_dir], capture_output=True,
                                   text=True, timeout=60)
            self.assertEqual((check.returncode, check.stdout.strip()), (0, "ok"), check.stderr)

            with sqlite3.connect(os.path.join(server.data_dir, "slipfront.db")) as db:
                db.execute("UPDATE jobs SET spec = '{not json' WHERE id = ?", (ids[1],))
            check = subprocess.run([BINARY, "check", server.data_dir], capture_output=True,
                                   text=True, timeout=60)
            self.assertEqual(check.returncode, 1, check.stdout + check.stderr)
            self.assertIn(f"jobs {ids[1]}: spec is not JSON", check.stdout)

            server.log.close()
            server.proc.stdout.close()
            server.start()
            server.session = requests.Session()  # terminate() closed the first one
            self.assertIn("start-up check: 1 row(s)", server.read_log())
            listing = server.get(JOBS, params={"limit": 1000})
            self.assertEqual(listing.status_code, 200, listing.text[:300])
            listed = [j["id"] for j in listing.json()["jobs"]]
            self.assertEqual(sorted(listed), sorted([ids[0], ids[2]]))
            self.assertEqual(len(listing.json()["skipped"]), 1)
            self.assertTrue(listing.json()["skipped"][0].startswith(ids[1]))
            # Pages of one: the bad row is skipped, the cursor moves past it.
            seen, url, params = [], JOBS, {"limit": 1}
            while url:
                page = server.get(url, params=params).json()
                seen += [j["id"] for j in page["jobs"]]
                url, params = page["next"], None
            self.assertEqual(sorted(seen), sorted([ids[0], ids[2]]))
            csv = server.get(JOBS, params={"limit": 1000, "format": "csv"})
            self.assertEqual(csv.status_code, 200, csv.text[:300])
            self.assertIn("1 unreadable row(s) left out", csv.headers.get("Skipped-Rows", ""))
            self.assertIn(ids[0], csv.text)
            self.assertNotIn(ids[1], csv.text)
            # The other jobs are served as before; the damaged one alone answers 500.
            self.assertEqual(server.get(f"{JOBS}/{ids[0]}").status_code, 200)
            self.assertEqual(server.terminate(), 0)
        finally:
            server.cleanup()


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

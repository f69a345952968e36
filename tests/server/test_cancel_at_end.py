"""A cancel that arrives after a run's last step: before, it was answered
202 and the job still ended `succeeded`. Now a 202 is always kept (the job ends `cancelled`,
without a result file) and a cancel the run can no longer honour is a 409 "finishing".

    /usr/bin/python3 tests/server/test_cancel_at_end.py --binary build/slipfront
"""

import argparse
import os
import sys
import time
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import TERMINAL, Server  # noqa: E402

BINARY = None
JOBS = "/api/v1/jobs"

# About a second of steps, then a result file of a few MB to write (the window after the
# last step), no arrest: the live progress reaches fraction 1 at the last step.
JOB = {"geometry": {"nodes_per_meter": 20}, "output": {"interval": 2e-5},
       "time": {"duration": 6.0, "stop_on_arrest": False}}


class CancelAfterTheLastStep(unittest.TestCase):
    def test_a_202_is_always_kept(self):
        server = Server(BINARY, args=["--workers", "1"]).start()
        try:
            answers = []
            for i in range(int(os.environ.get("SLIPFRONT_CANCEL_TRIES", "6"))):
                r = server.submit(dict(JOB, name=f"cancel-at-end-{i}"),
                                  params={"fresh": "true"})
                self.assertEqual(r.status_code, 201, r.text)
                job_id = r.json()["id"]
                deadline = time.monotonic() + 60
                # Wait for the final progress report (fraction 1: the last step is done).
                while time.monotonic() < deadline:
                    job = server.get(f"{JOBS}/{job_id}").json()
                    progress = job.get("progress") or {}
                    if job["status"] in TERMINAL or (progress.get("fraction") or 0) >= 1.0:
                        break
                    time.sleep(0.002)
                cancel = server.post(f"{JOBS}/{job_id}/cancel")
                done = server.wait_status(job_id, TERMINAL, timeout=60)
                answers.append((cancel.status_code, done["status"]))
                if cancel.status_code == 202:
                    self.assertEqual(done["status"], "cancelled",
                                     f"a 202 was not kept: {done['status']}")
                    self.assertIsNone(done.get("result"), done)
                else:
                    self.assertEqual(cancel.status_code, 409, cancel.text)
                    self.assertEqual(done["status"], "succeeded")
                    if "finishing" in cancel.json()["detail"]:
                        self.assertIn("will not be cancelled", cancel.json()["detail"])
            print(f"cancels after the last step: {answers}", file=sys.stderr)
            self.assertEqual(server.terminate(), 0)
        finally:
            server.cleanup()


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

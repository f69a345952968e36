"""Every curl example in clients/examples/ against a real `slipfront serve` on loopback.

Each script is run as a user would run it (sh, SLIPFRONT_SERVER set) and its output read
back: the JSON it prints must be the answer the endpoint promises (not a problem+json), the
download must pass its sha256 check, Range must give the HDF5 signature. The study body
`study.json` is created as is and cancelled at once (its paper-scene runs are not waited
for). A test also checks that every script in the directory is exercised here.

    /usr/bin/python3 tests/clients/test_curl_examples.py --binary build/slipfront
"""

import json
import os
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from harness import REPO, TINY, Server, binary_from_argv, wait_until  # noqa: E402

EXAMPLES = os.path.join(REPO, "clients", "examples")
BINARY = None
# workflow.sh drives slipfront-client (tested by test_end_to_end.py), not curl.
NOT_CURL = {"workflow.sh"}


class CurlExamples(unittest.TestCase):
    exercised = set()

    @classmethod
    def setUpClass(cls):
        cls.server = Server(BINARY, args=["--workers", "2"]).start()
        cls.tmp = tempfile.mkdtemp(prefix="slipfront-curl-")
        cls.job_file = os.path.join(cls.tmp, "tiny.json")
        with open(cls.job_file, "w") as f:
            json.dump(dict(TINY, tags=["curl-example"]), f)

    @classmethod
    def tearDownClass(cls):
        cls.server.stop()

    def sh(self, script, *args):
        """Runs one example; returns its stdout. A failing script fails the test."""
        self.exercised.add(script)
        env = dict(os.environ, SLIPFRONT_SERVER=self.server.base)
        env.pop("SLIPFRONT_TOKEN", None)
        done = subprocess.run(["sh", os.path.join(EXAMPLES, script), *args], capture_output=True,
                              text=True, timeout=60, env=env, cwd=self.tmp)
        self.assertEqual(done.returncode, 0, f"{script}: {done.stderr}")
        return done.stdout

    def json_of(self, script, *args):
        text = self.sh(script, *args)
        body = json.loads(text)
        if isinstance(body, dict):
            self.assertNotIn("title", body, f"{script} answered a problem: {text[:500]}")
        return body

    def finished_job(self):
        job = self.json_of("submit.sh", self.job_file)
        wait_until(lambda: self.json_of("status.sh", job["id"], "status")["status"] == "succeeded",
                   timeout=60)
        return job["id"]

    def test_jobs_endpoints(self):
        # The paper's scene at n_d = 20 (seconds), printed with its headers (-i); cancelled
        # at once, so it is still queued or running.
        head, _, body = self.sh("submit-inline.sh").replace("\r\n", "\n").partition("\n\n")
        self.assertTrue(head.startswith("HTTP/1.1 201"), head)
        self.assertIn("\nlocation: /api/v1/jobs/", head.lower())
        inline = json.loads(body)
        self.assertIn(inline["status"], {"queued", "running"})
        cancelled = self.json_of("cancel.sh", inline["id"])
        self.assertTrue(cancelled["cancel_requested"])

        job_id = self.finished_job()
        status = self.json_of("status.sh", job_id)
        self.assertEqual(status["status"], "succeeded")
        self.assertIn("metrics", status)
        listed = self.json_of("list.sh", "tag=curl-example&limit=5")
        self.assertIn(job_id, [j["id"] for j in listed["jobs"]])
        self.assertIn("outcome", self.json_of("metrics.sh", job_id)["metrics"])
        self.assertIn("arrival_time", self.json_of("front.sh", job_id))

        out = os.path.join(self.tmp, "result.h5")
        self.assertIn(": OK", self.sh("download.sh", job_id, out))
        self.assertEqual(self.sh("download-if-changed.sh", job_id, out).strip(), "304")
        self.assertIn("H   D   F", self.sh("range.sh", job_id))

        table = self.sh("export.sh", "tag=curl-example; status=succeeded", "csv")
        header, first = table.splitlines()[:2]
        self.assertIn("spec.friction.L", header.split(","))
        self.assertIn(job_id, first)
        ndjson = self.sh("export.sh", "tag=curl-example", "ndjson", "-created_at")
        self.assertIn(job_id, [json.loads(line)["id"] for line in ndjson.splitlines()])
        self.assertEqual(self.sh("xdmf.sh", job_id).strip(), f"{job_id}.xdmf")
        with open(os.path.join(self.tmp, f"{job_id}.xdmf")) as f:
            self.assertIn(f"{job_id}.h5:/interface/slip_velocity", f.read())

        # A finished job cannot be cancelled: the script prints the 409 problem.
        self.assertIn("already finished", json.loads(self.sh("cancel.sh", job_id))["detail"])

    def test_operations_endpoints(self):
        self.assertEqual(self.json_of("healthz.sh")["status"], "ok")
        self.assertIn("/api/v1/studies/{id}/cancel", self.json_of("openapi.sh")["paths"])
        self.assertIn("slipfront_", self.sh("prometheus.sh"))

    def test_study_endpoints(self):
        tiny_study = os.path.join(self.tmp, "study.json")
        with open(tiny_study, "w") as f:
            base = json.loads(json.dumps(TINY))
            del base["geometry"]["nodes_per_meter"]  # the study sets it
            json.dump({"name": "curl tiny", "base": base, "grid": {"L": [1e-4], "n_d": [5, 10]}}, f)
        study = self.json_of("study-create.sh", tiny_study)
        wait_until(lambda: self.json_of("study-get.sh", study["id"])["status"] == "finished",
                   timeout=60)
        self.assertIn(study["id"], [s["id"] for s in self.json_of("study-list.sh")["studies"]])
        self.assertEqual(len(self.json_of("speed-accuracy.sh", study["id"])["runs"]), 2)
        cmap = self.json_of("convergence-map.sh", f"study={study['id']}")
        self.assertEqual(cmap["convergence_map"]["n_d"], [5, 10])

        # The shipped study.json (paper scene, 3 x 3 grid) is accepted, then cancelled.
        shipped = self.json_of("study-create.sh")
        self.assertEqual(len(shipped["runs"]), 9)
        cancelled = self.json_of("study-cancel.sh", shipped["id"])
        self.assertEqual(cancelled["status"], "cancelled")
        self.assertGreater(len(cancelled["cancelled_jobs"]), 0)  # 9 runs on 2 workers
        wait_until(lambda: all(r["job_status"] in ("succeeded", "failed", "cancelled")
                               for r in self.json_of("study-get.sh", shipped["id"])["runs"]),
                   timeout=60)
        running = self.json_of("study-list.sh", "status=running")
        self.assertNotIn(shipped["id"], [s["id"] for s in running["studies"]])

    def test_zz_every_example_is_exercised(self):
        scripts = {f for f in os.listdir(EXAMPLES) if f.endswith(".sh")} - NOT_CURL
        self.assertEqual(scripts - self.exercised, set(), "examples no test ran")


if __name__ == "__main__":
    BINARY, rest = binary_from_argv(sys.argv[1:])
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

"""A scene of one's own over real HTTP on loopback (a `slipfront serve` on an ephemeral port,
temporary data dir; docs/api-job-spec.md "Defaults and the scene's scale" and "Warnings",
docs/performance.md "Cost estimate"):

- POST /jobs/validate answers a valid job with its canonical spec, warnings, the source of each
  number with a unit and the cost estimate, and an invalid one with {valid: false, errors}
  naming the field (POST /jobs refuses it with 422);
- the rock-scale example validates without a warning, its watching values derived; rock wave
  speeds with the paper's stresses are warned about, field by field;
- POST /jobs keeps the warnings, the provenance and the estimate in its 201 and in the job
  record (GET /jobs/{id}), and the metrics and the result file carry them too;
- --max-run-seconds refuses a job whose estimate is above it, the estimate in the message;
  --cost-model F is the model of the estimates.

    /usr/bin/python3 tests/server/test_scene_checks.py --binary build/slipfront
"""

import argparse
import json
import os
import sys
import tempfile
import unittest

import h5py

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import TINY, Server  # noqa: E402

BINARY = None
VALIDATE = "/api/v1/jobs/validate"
ROCK = {"density": 2670, "p_wave_speed": 6000, "s_wave_speed": 3464}


def by_pointer(items):
    return {item["pointer"]: item for item in items}


class SceneChecks(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.server = Server(BINARY, args=["--workers", "1"]).start()

    @classmethod
    def tearDownClass(cls):
        code = cls.server.terminate()
        cls.server.cleanup()
        assert code == 0, f"server exit code {code}"

    def count(self):
        return self.server.get("/api/v1/jobs", params={"fields": "id"}).json()["count"]

    def test_validate_the_rock_example_derives_what_watches_the_run(self):
        before = self.count()
        r = self.server.post(VALIDATE, json={"preset": "rock_patch_nd2"})
        self.assertEqual(r.status_code, 200, r.text)
        answer = r.json()
        self.assertTrue(answer["valid"])
        self.assertEqual(answer["warnings"], [])
        values = by_pointer(answer["provenance"])
        self.assertEqual(values["/time/arrest_window"]["value"], 0.005)
        self.assertEqual(values["/time/arrest_window"]["source"],
                         "derived: a tenth of the duration 0.05 s")
        self.assertEqual(values["/material/density"]["source"], "preset rock_patch_nd2")
        self.assertEqual(answer["spec"]["time"]["arrest_window"], 0.005)
        estimate = answer["estimate"]
        self.assertEqual(estimate["threads"], 1)  # the server's one thread per job
        self.assertGreater(estimate["steps"], 100)
        self.assertGreater(estimate["wall_time_s"], 0)
        self.assertTrue(estimate["stops_on_arrest"])
        self.assertEqual(len(answer["spec_sha256"]), 64)
        self.assertEqual(self.count(), before)  # nothing was stored

    def test_validate_warns_of_the_papers_units_at_another_scale(self):
        r = self.server.post(VALIDATE, json={"material": ROCK})
        self.assertEqual(r.status_code, 200, r.text)
        warned = by_pointer(r.json()["warnings"])
        for pointer in ("/loading/normal_stress", "/loading/shear_stress", "/time/duration",
                        "/geometry/width"):
            self.assertIn(pointer, warned)
            self.assertIn("paper's scaled units", warned[pointer]["message"])
        r = self.server.post(VALIDATE, json={"material": {"density": -1}})
        self.assertEqual(r.status_code, 200, r.text)  # the validation answered: not valid
        self.assertFalse(r.json()["valid"])
        self.assertEqual(r.json()["errors"][0]["pointer"], "/material/density")
        self.assertEqual(self.server.submit({"material": {"density": -1}}).status_code, 422)

    def test_submit_keeps_the_warnings_provenance_and_estimate(self):
        job = dict(TINY, probe={"arrival_x1": 2.0})  # inside the nucleation patch [0, 3.65] m
        r = self.server.submit(job)
        self.assertEqual(r.status_code, 201, r.text)
        created = r.json()
        self.assertIn("/probe/arrival_x1", by_pointer(created["warnings"]))
        done = self.server.wait_status(created["id"], {"succeeded", "failed"}, 120)
        self.assertEqual(done["status"], "succeeded", done)
        self.assertEqual(done["warnings"], created["warnings"])
        self.assertEqual(by_pointer(done["provenance"])["/probe/arrival_x1"]["source"], "given")
        self.assertGreater(done["estimate"]["wall_time_s"], 0)
        self.assertEqual(done["metrics"]["job_warnings"], created["warnings"])
        result = os.path.join(self.server.data_dir, "results", created["id"] + ".h5")
        with h5py.File(result, "r") as f:
            self.assertEqual(json.loads(f.attrs["job_warnings"]), created["warnings"])
            self.assertEqual(by_pointer(json.loads(f.attrs["provenance"]))["/time/duration"]["value"], 2.0)

    def test_a_run_above_max_run_seconds_is_refused_with_its_estimate(self):
        with tempfile.TemporaryDirectory() as tmp:
            model = os.path.join(tmp, "model.json")
            with open(model, "w") as f:  # every run costs an hour
                json.dump({"machine": "test", "calibrated_at": "now", "coefficients": {
                    "fe": {"1": {"setup_s": 3600, "node_step_s": 0, "row_step_s": 0,
                                 "interface_step_s": 0, "rate_solve_s": 0}},
                    "spectral_bi": {"1": {"setup_s": 3600, "lag_step_s": 0, "transform_step_s": 0,
                                          "interface_step_s": 0, "rate_solve_s": 0}}}},
                    f)
            server = Server(BINARY, args=["--workers", "1", "--max-run-seconds", "600",
                                          "--cost-model", model]).start()
            try:
                r = server.post(VALIDATE, json=TINY)
                self.assertEqual(r.status_code, 200, r.text)
                self.assertFalse(r.json()["valid"])
                error = by_pointer(r.json()["errors"])["/geometry/nodes_per_meter"]["reason"]
                self.assertIn("the run would take about 60 min on this server", error)
                self.assertIn("--max-run-seconds 600 s", error)
                r = server.submit(TINY)
                self.assertEqual(r.status_code, 422, r.text)
                self.assertIn("--max-run-seconds 600 s", r.text)
                self.assertEqual(server.get("/api/v1/jobs").json()["count"], 0)
            finally:
                self.assertEqual(server.terminate(), 0)
                server.cleanup()
            server = Server(BINARY, args=["--workers", "1", "--cost-model", model]).start()
            try:
                estimate = server.post(VALIDATE, json=TINY).json()["estimate"]
                self.assertEqual(estimate["wall_time_s"], 3600)
                self.assertIn(model, estimate["model"])
            finally:
                self.assertEqual(server.terminate(), 0)
                server.cleanup()


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0]] + rest)

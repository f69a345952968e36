"""GET /api/v1/jobs/{id}/stations.csv and /stations over real HTTP on loopback (docs/server.md,
docs/hdf5-layout.md "Stations as CSV"): a `slipfront serve` on an ephemeral port runs small
FE and spectral BI jobs with stations; the CSV holds every step of /stations of the job's own
result file, value for value, with its units and rupture times in the header comments, and the
rupture times of the metrics; the JSON holds the same values (every step within its budget,
else every k-th step from the first, k = ceil(steps / max_samples), still the file's values);
a bad max_samples or an unknown parameter is a 400 naming it; a job without stations is a 404
that says so, an unfinished job a 409; the OpenAPI document lists both routes.

    /usr/bin/python3 tests/server/test_stations_http.py --binary build/slipfront
"""

import argparse
import io
import math
import os
import sys
import unittest

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import TERMINAL, Server, long_job  # noqa: E402

BINARY = None
JOBS = "/api/v1/jobs"
HEADER = "station_x1,time,slip,slip_rate,shear_traction,normal_traction"
# The paper's scene on [-1, 11) at n_d = 5 (dx = 0.2 m), 3 s: the slip grows out of the
# nucleation patch past a station on a node (1.0), then one between two (2.1), and never
# reaches the third (10.5); the slip rate there stays below 1e-3 m/s, so the threshold is
# 1e-4 m/s.
STATIONS = [1.0, 2.1, 10.5]


def scene(method):
    job = {"geometry": {"nodes_per_meter": 5, "width": 12, "height": 5, "x_min": -1},
           "probe": {"arrival_x1": 3, "spectrum_x1": 3}, "time": {"duration": 3},
           "stations": {"x1": STATIONS, "rupture_threshold": 1e-4}}
    if method == "spectral_bi":
        job["method"] = "spectral_bi"
        del job["geometry"]["height"]
    return job


def parse_csv(text):
    """(comment lines, header, [rows, 6] float array) of a stations CSV."""
    lines = text.splitlines()
    comments = [line for line in lines if line.startswith("#")]
    rows = [line for line in lines if not line.startswith("#")]
    values = np.array([[float(v) for v in row.split(",")] for row in rows[1:]])
    return comments, rows[0], values


class StationsCsv(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.server = Server(BINARY, args=["--workers", "2"]).start()

    @classmethod
    def tearDownClass(cls):
        code = cls.server.terminate()
        cls.server.cleanup()
        assert code == 0, f"server exit code {code}"

    def finished(self, spec):
        r = self.server.submit(spec)
        self.assertEqual(r.status_code, 201, r.text)
        job = self.server.wait_status(r.json()["id"], TERMINAL, timeout=120)
        self.assertEqual(job["status"], "succeeded", job)
        return job

    def check_method(self, method):
        job = self.finished(scene(method))
        r = self.server.get(f"{JOBS}/{job['id']}/stations.csv")
        self.assertEqual(r.status_code, 200, r.text)
        self.assertTrue(r.headers["Content-Type"].startswith("text/csv"), r.headers)
        self.assertIn(f'filename="{job["id"]}-stations.csv"', r.headers["Content-Disposition"])
        comments, header, values = parse_csv(r.text)
        self.assertEqual(header, HEADER)
        self.assertTrue(any("slip_rate [m/s]" in c and "normal_traction [Pa]" in c
                            for c in comments), comments)

        h5 = self.server.get(f"{JOBS}/{job['id']}/result.h5").content
        with h5py.File(io.BytesIO(h5), "r") as f:
            s = f["stations"]
            time = s["time"][()]
            series = {name: s[name][()] for name in ("slip", "slip_rate", "shear_traction",
                                                     "normal_traction")}
            rupture = s["rupture_time"][()]
        m = time.size
        self.assertEqual(m, job["metrics"]["steps"])
        self.assertEqual(values.shape, (m * len(STATIONS), 6))
        for k, x1 in enumerate(STATIONS):
            block = values[k * m:(k + 1) * m]
            self.assertTrue(np.all(block[:, 0] == x1))
            self.assertTrue(np.array_equal(block[:, 1], time))
            for column, name in enumerate(("slip", "slip_rate", "shear_traction",
                                           "normal_traction"), start=2):
                self.assertTrue(np.array_equal(block[:, column], series[name][:, k]),
                                f"{method}: {name} at {x1}")
            self.assertTrue(np.all(block[:, 5] < 0), "normal traction: compression is < 0")
            listed = job["metrics"]["stations"][k]
            self.assertEqual(listed["x1"], x1)
            if math.isnan(rupture[k]):
                self.assertIsNone(listed["rupture_time"])
                self.assertIn(f"# station_x1 = {x1:g}: rupture_time = nan", comments)
            else:
                self.assertEqual(listed["rupture_time"], rupture[k])
                self.assertIn(f"# station_x1 = {x1:g}: rupture_time = {rupture[k]!r}", comments)
        # The rupture passes the first two stations, in order, and not the far one.
        self.assertLess(rupture[0], rupture[1])
        self.assertTrue(math.isnan(rupture[2]), rupture)
        self.check_json(job["id"], time, series, rupture)

    def check_json(self, job_id, time, series, rupture):
        """GET /stations: the file's values, every step; then every k-th within a budget."""
        m = time.size
        for budget, stride in ((None, 1), (m, 1), (7, -(-m // 7)), (1, m)):
            params = {} if budget is None else {"max_samples": budget}
            r = self.server.get(f"{JOBS}/{job_id}/stations", params=params)
            self.assertEqual(r.status_code, 200, r.text)
            body = r.json()
            self.assertEqual(body["x1"], STATIONS)
            self.assertEqual(body["rupture_threshold"], 1e-4)
            self.assertEqual(body["units"]["slip_rate"], "m/s")
            self.assertEqual(body["units"]["normal_traction"], "Pa")
            self.assertEqual([None if math.isnan(t) else t for t in rupture],
                             body["rupture_time"])
            self.assertEqual((body["steps"], body["stride"]), (m, stride), budget)
            self.assertTrue(np.array_equal(body["time"], time[::stride]))
            self.assertLessEqual(len(body["time"]), budget or m)
            for name, values in series.items():
                self.assertTrue(np.array_equal(np.array(body[name]), values[::stride]),
                                f"{name}, max_samples {budget}")

    def test_fe_job_csv_is_its_result_files_stations(self):
        self.check_method("fe")

    def test_spectral_bi_job_csv_is_its_result_files_stations(self):
        self.check_method("spectral_bi")

    def test_job_without_stations_is_404_saying_so(self):
        spec = scene("fe")
        del spec["stations"]
        job = self.finished(spec)
        self.assertNotIn("stations", job["metrics"])
        for route in ("stations.csv", "stations"):
            r = self.server.get(f"{JOBS}/{job['id']}/{route}")
            self.assertEqual(r.status_code, 404, r.text)
            self.assertIn("has no stations", r.json()["detail"])

    def test_unfinished_job_is_409(self):
        spec = long_job("stations-unfinished")
        spec["stations"] = {"x1": [1.0]}
        r = self.server.submit(spec)
        self.assertEqual(r.status_code, 201, r.text)
        job_id = r.json()["id"]
        self.assertEqual(self.server.get(f"{JOBS}/{job_id}/stations.csv").status_code, 409)
        self.assertEqual(self.server.get(f"{JOBS}/{job_id}/stations").status_code, 409)
        self.server.post(f"{JOBS}/{job_id}/cancel")
        self.server.wait_status(job_id, TERMINAL, timeout=30)

    def test_invalid_stations_are_422_naming_the_field(self):
        for stations, pointer in (({"x1": [0.0, 11.0]}, "/stations/x1/1"),
                                  ({"x1": [0.0], "rupture_threshold": 0}, "/stations/rupture_threshold"),
                                  ({"x1": [0.0] * 65}, "/stations/x1")):
            spec = scene("fe")
            spec["stations"] = stations
            r = self.server.submit(spec)
            self.assertEqual(r.status_code, 422, r.text)
            pointers = [e["pointer"] for e in r.json()["errors"]]
            self.assertIn(pointer, pointers)

    def test_bad_query_is_400_naming_the_parameter(self):
        job = self.finished(scene("spectral_bi"))
        for params, pointer in (({"max_samples": 0}, "/query/max_samples"),
                                ({"max_samples": "ten"}, "/query/max_samples"),
                                ({"max_samples": 1000001}, "/query/max_samples"),
                                ({"max_samples": "99999999999999999999"}, "/query/max_samples"),
                                ({"stride": 2}, "/query/stride")):
            r = self.server.get(f"{JOBS}/{job['id']}/stations", params=params)
            self.assertEqual(r.status_code, 400, r.text)
            self.assertEqual([e["pointer"] for e in r.json()["errors"]], [pointer], params)

    def test_openapi_lists_the_routes(self):
        doc = self.server.get("/api/v1/openapi.json").json()
        operation = doc["paths"]["/api/v1/jobs/{id}/stations.csv"]["get"]
        self.assertIn("text/csv", operation["responses"]["200"]["content"])
        self.assertIn("404", operation["responses"])
        operation = doc["paths"]["/api/v1/jobs/{id}/stations"]["get"]
        self.assertIn("application/json", operation["responses"]["200"]["content"])
        self.assertEqual([p.get("name") for p in operation["parameters"]][1:], ["max_samples"])
        self.assertIn("400", operation["responses"])


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

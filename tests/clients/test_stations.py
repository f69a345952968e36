"""The stations in slipfront-client against a real `slipfront serve` (ephemeral loopback port,
temporary data dir): `slipfront-client stations ID` (the rupture times, as a table and as
JSON), `--csv FILE` / `--csv -` (the server's CSV, byte for byte), and the library's
job_stations / load_stations / parse_stations_csv, which read the same numbers from the CSV
and from the HDF5 file; a job without stations exits 1 saying so.

    /usr/bin/python3 tests/clients/test_stations.py --binary build/slipfront
"""

import json
import math
import os
import shutil
import sys
import tempfile
import unittest

import numpy as np

from harness import TINY, Server, binary_from_argv, run_client
from slipfront_client.api import Api
from slipfront_client.errors import UsageError
from slipfront_client.stations import job_stations, load_stations, parse_stations_csv

BINARY = None
# The tiny job's domain is [-1, 11) at dx = 0.2 m: a station on a node, one between two, and
# one the slip does not reach in 3 s (at most about 1e-2 m/s there: threshold 1e-4 m/s).
STATIONS = [1.0, 2.1, 10.5]


class ClientStations(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.server = Server(BINARY, args=["--workers", "2"]).start()
        cls.tmp = tempfile.mkdtemp(prefix="slipfront-client-stations-")
        cls.api = Api(cls.server.base)
        job = dict(json.loads(json.dumps(TINY)), stations={"x1": STATIONS, "rupture_threshold": 1e-4})
        cls.job_id = cls.submit(job)
        cls.plain_id = cls.submit(TINY)

    @classmethod
    def submit(cls, job):
        path = os.path.join(cls.tmp, "job.json")
        with open(path, "w") as f:
            json.dump(job, f)
        r = cls.client("submit", path, "--wait")
        assert r.returncode == 0, r.stderr
        return r.stdout.strip().splitlines()[-1]

    @classmethod
    def tearDownClass(cls):
        cls.api.close()
        cls.server.stop()
        shutil.rmtree(cls.tmp, ignore_errors=True)

    @classmethod
    def client(cls, *args):
        return run_client(*args, server=cls.server.base)

    def test_rupture_times_as_json_match_the_metrics(self):
        r = self.client("stations", self.job_id, "--json")
        self.assertEqual(r.returncode, 0, r.stderr)
        listed = json.loads(r.stdout)
        self.assertEqual(listed["rupture_threshold"], 1e-4)
        metrics = self.api.get_json(f"/api/v1/jobs/{self.job_id}/metrics")["metrics"]
        self.assertEqual(listed["stations"], metrics["stations"])
        times = [s["rupture_time"] for s in listed["stations"]]
        self.assertLess(times[0], times[1])
        self.assertIsNone(times[2])

    def test_rupture_times_as_a_table(self):
        r = self.client("stations", self.job_id)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("rupture_time [s]", r.stdout)
        self.assertIn("2.1", r.stdout)

    def test_csv_to_a_file_and_to_stdout_is_the_servers(self):
        served = self.api.stations_csv(self.job_id)
        path = os.path.join(self.tmp, "stations.csv")
        r = self.client("stations", self.job_id, "--csv", path)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(path, encoding="utf-8") as f:
            self.assertEqual(f.read(), served)
        r = self.client("stations", self.job_id, "--csv", "-")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stdout, served)

    def test_csv_and_hdf5_give_the_same_arrays(self):
        from_csv = job_stations(self.api, self.job_id)
        h5 = os.path.join(self.tmp, "result.h5")
        r = self.client("download", self.job_id, "-o", h5)
        self.assertEqual(r.returncode, 0, r.stderr)
        from_file = load_stations(h5)
        self.assertEqual(from_csv.x1.tolist(), STATIONS)
        self.assertEqual(from_csv.rupture_threshold, from_file.rupture_threshold)
        for name in ("x1", "time", "slip", "slip_rate", "shear_traction", "normal_traction"):
            a, b = getattr(from_csv, name), getattr(from_file, name)
            self.assertEqual(a.shape, b.shape, name)
            self.assertTrue(np.array_equal(a, b), name)
        self.assertTrue(np.array_equal(from_csv.rupture_time, from_file.rupture_time,
                                       equal_nan=True))
        self.assertTrue(math.isnan(from_csv.rupture_time[2]))
        self.assertEqual(from_csv.at(2.1), 1)
        with self.assertRaises(UsageError):
            from_csv.at(5.0)
        columns = from_csv.long_rows()
        self.assertEqual(len(columns["time"]), 3 * from_csv.time.size)
        self.assertTrue(np.array_equal(columns["slip"][from_csv.time.size:2 * from_csv.time.size],
                                       from_csv.slip[:, 1]))

    def test_not_a_stations_csv_is_a_usage_error(self):
        with self.assertRaises(UsageError):
            parse_stations_csv("a,b\n1,2\n")

    def test_job_without_stations_exits_1_saying_so(self):
        r = self.client("stations", self.plain_id)
        self.assertEqual(r.returncode, 1, r.stdout)
        self.assertIn("has no stations", r.stderr)
        h5 = os.path.join(self.tmp, "plain.h5")
        self.assertEqual(self.client("download", self.plain_id, "-o", h5).returncode, 0)
        with self.assertRaises(UsageError):
            load_stations(h5)


if __name__ == "__main__":
    BINARY, rest = binary_from_argv(sys.argv[1:])
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

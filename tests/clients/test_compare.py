"""`slipfront-client compare` against a real `slipfront serve` (ephemeral loopback port,
temporary data dir), with an FE and a BI run of the paper's scene (L = 1e-4 m, n_d = 10:
about a second each) and a two-mesh BI study:

- the table names each run by its legend text (the method first), marks `method` and the
  fields only one method has with '*', leaves L and n_d unmarked, gives the spread of the
  numbers that differ, hides identical fields unless --all; --json gives every field with its
  values and whether it differs;
- four PNGs (velocity at the first run's probes, x1 = 6 and 11 m, rupture speed, fronts, scatter) that are real
  pictures, not blank; a second run refuses to replace them, naming them, unless --force;
- the |V| histories drawn are the server's /fields values at the nodes (result_from_json);
- --study compares the study's runs, told apart by n_d; a bad --x is a usage error naming it.

    /usr/bin/python3 tests/clients/test_compare.py --binary build/slipfront
"""

import json
import os
import shutil
import sys
import tempfile
import unittest

import numpy as np

from harness import Server, binary_from_argv, run_client
from slipfront_client.api import Api
from slipfront_client.results import result_from_json

BINARY = None
SCENE = {"friction": {"L": 1e-4}, "geometry": {"nodes_per_meter": 10}}
FIGURES = ("velocity", "speed", "front", "scatter")


class ClientCompare(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.server = Server(BINARY, args=["--workers", "2"]).start()
        cls.tmp = tempfile.mkdtemp(prefix="slipfront-client-compare-")
        cls.api = Api(cls.server.base)
        cls.ids = {}
        for method in ("fe", "spectral_bi"):
            path = os.path.join(cls.tmp, f"{method}.json")
            with open(path, "w") as f:
                json.dump({**SCENE, "method": method}, f)
            r = cls.client("submit", path, "--wait")
            assert r.returncode == 0, r.stderr
            cls.ids[method] = r.stdout.strip().splitlines()[-1]
        study = cls.api.create_study({"name": "two meshes", "base": {"method": "spectral_bi"},
                                      "grid": {"L": [1e-4], "n_d": [5, 10]}})
        cls.study_id = study["id"]
        r = cls.client("study", "wait", cls.study_id)
        assert r.returncode == 0, r.stderr

    @classmethod
    def tearDownClass(cls):
        cls.api.close()
        cls.server.stop()
        shutil.rmtree(cls.tmp, ignore_errors=True)

    @classmethod
    def client(cls, *args):
        return run_client(*args, server=cls.server.base, timeout=120)

    def compare(self, *args):
        return self.client("compare", self.ids["fe"], self.ids["spectral_bi"], *args)

    def test_table_marks_the_method_and_names_the_runs(self):
        r = self.compare("--no-figures")
        self.assertEqual(r.returncode, 0, r.stderr)
        lines = r.stdout.splitlines()
        self.assertEqual(lines[0], f"run 1: {self.ids['fe']}  FE, L = 0.0001 m, n_d = 10")
        self.assertEqual(lines[1], f"run 2: {self.ids['spectral_bi']}  BI, L = 0.0001 m, n_d = 10")
        self.assertIn(["*", "method", "fe", "spectral_bi"], [line.split() for line in lines])
        self.assertIn(["*", "spectral_bi.memory_periods", "-", "8"], [line.split() for line in lines])
        self.assertIn(["friction.L", "0.0001", "0.0001"], [line.split() for line in lines])
        self.assertIn(["geometry.nodes_per_meter", "10", "10"], [line.split() for line in lines])
        self.assertNotIn("material.density", r.stdout)  # identical: shown with --all
        r = self.compare("--no-figures", "--all")
        self.assertIn(["material.density", "1", "1"], [line.split() for line in r.stdout.splitlines()])

    def test_json_has_every_field(self):
        r = self.compare("--no-figures", "--json")
        self.assertEqual(r.returncode, 0, r.stderr)
        doc = json.loads(r.stdout)
        self.assertEqual([run["label"][:3] for run in doc["runs"]], ["FE,", "BI,"])
        fields = {(f["group"], f["field"]): f for f in doc["fields"]}
        self.assertEqual(fields["spec", "method"]["values"], ["fe", "spectral_bi"])
        self.assertTrue(fields["spec", "method"]["differs"])
        self.assertFalse(fields["spec", "friction.L"]["differs"])
        served = [self.api.job(i)["metrics"]["steps"] for i in self.ids.values()]
        self.assertEqual(fields["metrics", "steps"]["values"], served)

    def test_figures_are_written_and_never_replaced_silently(self):
        from matplotlib.image import imread
        out = os.path.join(self.tmp, "figs")
        r = self.compare("--out", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        paths = [os.path.join(out, f"compare_{name}.png") for name in FIGURES]
        for path in paths:
            self.assertIn(f"wrote {path}", r.stdout)
            self.assertGreater(os.path.getsize(path), 20000, path)
            image = imread(path)
            self.assertGreater(image.shape[0], 400, path)
            self.assertGreater(float(np.std(image[..., :3])), 0.05, f"{path} looks blank")
        before = {p: os.path.getmtime(p) for p in paths}
        r = self.compare("--out", out)
        self.assertEqual(r.returncode, 2, r.stdout)
        self.assertIn("4 figure file(s) exist", r.stderr)
        self.assertIn(paths[0], r.stderr)
        self.assertEqual(before, {p: os.path.getmtime(p) for p in paths})
        r = self.compare("--out", out, "--force", "--x", "method", "--y", "metrics.steps")
        self.assertEqual(r.returncode, 0, r.stderr)

    def test_velocity_is_the_servers_history_at_the_nodes(self):
        job = self.api.job(self.ids["spectral_bi"])
        result = result_from_json(self.api, job, [6.0, 10.0, 99.0])  # 99 m: outside
        np.testing.assert_allclose(result.x1, [6.0, 10.0], rtol=1e-12)  # the nodes there
        for k, x in enumerate((6.0, 10.0)):
            field = self.api.get_json(f"/api/v1/jobs/{job['id']}/fields/slip_velocity",
                                      params={"x1_min": x, "x1_max": x, "max_points": 4000})
            np.testing.assert_array_equal(result.slip_velocity[:, k], [row[0] for row in field["values"]])
            np.testing.assert_array_equal(result.time, field["time"])
        front = self.api.front(job["id"])
        self.assertEqual(result.front_x1.tolist(), front["x1"])

    def test_study_runs_told_apart_by_n_d(self):
        r = self.client("compare", "--study", self.study_id, "--no-figures")
        self.assertEqual(r.returncode, 0, r.stderr)
        lines = r.stdout.splitlines()
        self.assertTrue(lines[0].endswith("BI, L = 0.0001 m, n_d = 5"), lines[0])
        self.assertTrue(lines[1].endswith("BI, L = 0.0001 m, n_d = 10"), lines[1])
        self.assertIn(["*", "geometry.nodes_per_meter", "5", "10", "50", "%"],  # (10 - 5) / 10
                      [line.split() for line in lines])

    def test_usage_errors_name_what_is_wrong(self):
        bad = os.path.join(self.tmp, "bad")
        r = self.compare("--out", bad, "--x", "friction.nonsense")
        self.assertEqual(r.returncode, 2, r.stdout)
        self.assertIn("--x 'friction.nonsense': no parameter of that name", r.stderr)
        self.assertFalse(os.path.exists(bad))  # nothing written
        r = self.compare("--no-figures", "--y", "outcome")  # text: not on a scatter's y axis
        self.assertEqual(r.returncode, 2, r.stdout)
        self.assertIn("--y 'outcome': no numeric metric", r.stderr)
        r = self.client("compare", self.ids["fe"])
        self.assertEqual(r.returncode, 2)
        self.assertIn("at least two", r.stderr)


if __name__ == "__main__":
    BINARY, rest = binary_from_argv(sys.argv[1:])
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

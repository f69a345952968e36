"""Two methods behind one job API, over real HTTP on loopback (docs/spectral-bi.md,
docs/studies.md): a spectral boundary-integral job and its HDF5 result; a field the method
does not use is a 422 naming it; one convergence study per method, each with its own map and
verdict, the cross-method table and speed-accuracy across methods.

    /usr/bin/python3 tests/server/test_methods.py --binary build/slipfront
"""

import argparse
import io
import json
import os
import sys
import unittest

import h5py

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import Server, wait_study  # noqa: E402

BINARY = None
JOBS, STUDIES = "/api/v1/jobs", "/api/v1/studies"

# A small scene (12 m wide, probes inside, 3 s). The FE block keeps its default height: the
# counterpart of a BI scene is FE with FE's own fields at their defaults (docs/studies.md).
SCENE = {"geometry": {"width": 12, "x_min": -1},
         "probe": {"arrival_x1": 3, "spectrum_x1": 2}, "time": {"duration": 3}}


def scene(method):
    s = json.loads(json.dumps(SCENE))
    if method == "spectral_bi":
        s["method"] = "spectral_bi"
    return s


def post(server, path, body):
    return server.post(path, data=json.dumps(body), headers={"Content-Type": "application/json"})


class Methods(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.server = Server(BINARY, args=["--workers", "2"]).start()

    @classmethod
    def tearDownClass(cls):
        code = cls.server.terminate()
        cls.server.cleanup()
        assert code == 0, f"server exit code {code}"

    def test_spectral_bi_job_reports_its_method_everywhere(self):
        r = post(self.server, JOBS, {"method": "spectral_bi", "friction": {"L": 5e-6},
                                     "geometry": {"nodes_per_meter": 20}})
        self.assertEqual(r.status_code, 201, r.text)
        job_id = r.json()["id"]
        job = self.server.wait_status(job_id, {"succeeded", "failed"}, timeout=60)
        self.assertEqual(job["status"], "succeeded", json.dumps(job)[:1500])
        self.assertEqual(job["method"], "spectral_bi")
        self.assertEqual(job["spec"]["method"], "spectral_bi")
        self.assertIn("spectral_bi", job["spec"])
        self.assertNotIn("height", job["spec"]["geometry"])
        m = job["metrics"]
        self.assertEqual(m["method"], "spectral_bi")
        self.assertIn("spectral boundary integral", m["method_description"])
        self.assertEqual(m["outcome"], "arrested")
        self.assertGreater(m["arrest_position"], 10.5)  # the paper's scene arrests near 11 m
        self.assertLess(m["arrest_position"], 12.0)
        listed = self.server.get(JOBS, params={"limit": 100}).json()["jobs"]
        self.assertEqual([j["method"] for j in listed if j["id"] == job_id], ["spectral_bi"])
        data = self.server.get(f"{JOBS}/{job_id}/result.h5").content
        with h5py.File(io.BytesIO(data), "r") as f:
            self.assertEqual(f.attrs["method"], "spectral_bi")
            for name in ("x1", "time", "slip_velocity", "slip", "shear_traction",
                         "contact_pressure", "strength", "state"):
                self.assertIn(name, f["interface"])
            self.assertEqual(f["interface/x1"].shape[0], 800)  # 40 m at 20 nodes/m
            self.assertEqual(f["energy/kinetic"][-1], 0.0)      # no bulk
            self.assertGreater(f["energy/strain"][-1], 0.0)     # energy into the half-space

    def test_fields_the_method_does_not_use_are_422_naming_the_field(self):
        for body, pointer in (
                ({"method": "spectral_bi", "geometry": {"height": 20}}, "/geometry/height"),
                ({"method": "spectral_bi", "time": {"safety_factor": 0.5}}, "/time/safety_factor"),
                ({"spectral_bi": {"memory_periods": 8}}, "/spectral_bi"),
                ({"method": "boundary_elements"}, "/method")):
            r = post(self.server, JOBS, body)
            self.assertEqual(r.status_code, 422, r.text)
            pointers = [e["pointer"] for e in r.json()["errors"]]
            self.assertEqual(pointers, [pointer], r.text)

    def test_one_study_per_method_with_both_maps_and_the_cross_method_table(self):
        ids = {}
        for method in ("fe", "spectral_bi"):
            r = post(self.server, STUDIES, {"name": method, "base": scene(method),
                                            "convergence": {"L": [5e-5, 1e-3], "n_d": [5, 10, 20],
                                                            "n_d_max": 20}})
            self.assertEqual(r.status_code, 201, r.text)
            ids[method] = r.json()["id"]
        studies = {m: wait_study(self.server, i) for m, i in ids.items()}
        fe, bi = studies["fe"], studies["spectral_bi"]
        self.assertEqual(fe["method"], "fe")
        self.assertEqual(bi["method"], "spectral_bi")
        # Two scenes, two maps, each the other's counterpart.
        self.assertNotEqual(fe["scene_hash"], bi["scene_hash"])
        self.assertEqual(fe["counterpart_scene_hash"], bi["scene_hash"])
        self.assertEqual(bi["counterpart_scene_hash"], fe["scene_hash"])
        for s in (fe, bi):
            self.assertEqual(s["convergence_map"]["L"], [5e-5, 1e-3])
            self.assertIn("reason", s["critical_length"])
            self.assertIn("steps_in_L", s["critical_length"])
        # The cross-method table is the same from either study.
        self.assertEqual(fe["cross_method"], bi["cross_method"])
        rows = {row["L"]: row for row in bi["cross_method"]}
        self.assertEqual(sorted(rows), [5e-5, 1e-3])
        both = [row for row in rows.values() if row["fe"] and row["spectral_bi"]]
        self.assertTrue(both, json.dumps(bi["cross_method"])[:2000])
        for row in both:
            self.assertIn("arrival_time_at_probe", row["differences"])
            self.assertIn(row["agree"], (True, False))
        # L = 1e-3 m: no rupture by either method (paper §3.1).
        big = rows[1e-3]
        for side in ("fe", "spectral_bi"):
            if big[side]:
                self.assertEqual(big[side]["outcome"], "no_rupture")
        listed = {st["id"]: st["method"] for st in self.server.get(STUDIES).json()["studies"]}
        self.assertEqual(listed[ids["fe"]], "fe")
        self.assertEqual(listed[ids["spectral_bi"]], "spectral_bi")
        sa = self.server.get(f"{STUDIES}/{ids['fe']}/speed-accuracy").json()
        methods = {e["method"] for e in sa["across_methods"]["runs"]}
        self.assertEqual(methods, {"fe", "spectral_bi"})
        for e in sa["across_methods"]["runs"]:
            self.assertIn(e["reference_method"], ("fe", "spectral_bi", None))


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

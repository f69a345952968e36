"""The web view's server side, over real HTTP on loopback (docs/web.md, docs/server.md):
GET /api/v1/jobs/{id}/fields/{name} read back against the HDF5 file itself (whole field,
windows, the nearest node, decimation to a point budget), its 400/404/409 answers naming the
parameter, the static files at / with their Content-Security-Policy, the weak ETags of JSON
answers (304 on If-None-Match) and GET /api/v1/job-defaults.

    /usr/bin/python3 tests/server/test_web_api.py --binary build/slipfront [--web-dir build/web]
"""

import argparse
import http.client
import io
import os
import sys
import unittest

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import TINY, Server, long_job  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BINARY = None
WEB_DIR = None
JOBS = "/api/v1/jobs"


def as_array(rows):
    return np.array([[np.nan if v is None else v for v in row] for row in rows], dtype=float)


class FieldSlices(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        args = ["--workers", "1"] + (["--web-dir", WEB_DIR] if WEB_DIR else [])
        cls.server = Server(BINARY, args=args).start()
        jobs = {}
        for key, spec in (("fe", dict(TINY, name="fe tiny")),
                          ("bi", {"method": "spectral_bi", "name": "bi", "time": {"duration": 2.0},
                                  "geometry": {"nodes_per_meter": 10}})):
            r = cls.server.submit(spec)
            assert r.status_code == 201, r.text
            jobs[key] = cls.server.wait_status(r.json()["id"], {"succeeded", "failed"}, 120)
            assert jobs[key]["status"] == "succeeded", jobs[key]
        cls.jobs = jobs
        cls.files = {}
        for key, job in jobs.items():
            data = cls.server.get(f"{JOBS}/{job['id']}/result.h5").content
            with h5py.File(io.BytesIO(data), "r") as f:
                cls.files[key] = {name: f["interface"][name][:] for name in
                                  ("x1", "time", "slip_velocity", "slip", "state",
                                   "shear_traction")}

    @classmethod
    def tearDownClass(cls):
        cls.server.cleanup()

    def fields(self, key, name, **query):
        return self.server.get(f"{JOBS}/{self.jobs[key]['id']}/fields/{name}", params=query)

    def test_whole_field_equals_the_file(self):
        for key in ("fe", "bi"):
            f = self.files[key]
            for name in ("slip_velocity", "slip", "state"):
                r = self.fields(key, name, max_points=4000000)
                self.assertEqual(r.status_code, 200, r.text)
                body = r.json()
                self.assertEqual(body["field"], name)
                self.assertEqual(body["source_shape"], list(f[name].shape))
                self.assertEqual(body["shape"], list(f[name].shape))
                self.assertEqual(body["stride"], {"time": 1, "x1": 1})
                np.testing.assert_array_equal(np.array(body["x1"]), f["x1"])
                np.testing.assert_array_equal(np.array(body["time"]), f["time"])
                np.testing.assert_array_equal(as_array(body["values"]), f[name].astype(float))
                self.assertEqual(body["units"]["values"], {"slip_velocity": "m/s", "slip": "m",
                                                           "state": "1"}[name])

    def test_window_and_decimation(self):
        f = self.files["fe"]
        x1, t, v = f["x1"], f["time"], f["shear_traction"]
        lo, hi = float(x1[len(x1) // 4]), float(x1[len(x1) // 2])
        tlo, thi = float(t[len(t) // 5]), float(t[(4 * len(t)) // 5])
        r = self.fields("fe", "shear_traction", x1_min=lo, x1_max=hi, t_min=tlo, t_max=thi,
                        max_points=4000000)
        self.assertEqual(r.status_code, 200, r.text)
        body = r.json()
        cols = np.where((x1 >= lo) & (x1 <= hi))[0]
        rows = np.where((t >= tlo) & (t <= thi))[0]
        np.testing.assert_array_equal(np.array(body["x1"]), x1[cols])
        np.testing.assert_array_equal(np.array(body["time"]), t[rows])
        np.testing.assert_array_equal(as_array(body["values"]), v[np.ix_(rows, cols)])
        # A budget of a tenth of the window: every k-th row and column of the file's values.
        budget = len(rows) * len(cols) // 10
        body = self.fields("fe", "shear_traction", x1_min=lo, x1_max=hi, t_min=tlo, t_max=thi,
                           max_points=budget).json()
        n_t, n_x = body["shape"]
        self.assertLessEqual(n_t * n_x, budget)
        self.assertGreater(n_t * n_x, budget // 4)  # not decimated more than it must be
        st, sx = body["stride"]["time"], body["stride"]["x1"]
        self.assertGreater(st * sx, 1)
        np.testing.assert_array_equal(as_array(body["values"]),
                                      v[np.ix_(rows[::st], cols[::sx])])

    def test_one_node_history_is_the_nearest_node(self):
        f = self.files["bi"]
        x1 = f["x1"]
        target = float(x1[7]) + 0.3 * float(x1[8] - x1[7])  # nearer node 7
        body = self.fields("bi", "slip_velocity", x1_min=target, x1_max=target).json()
        self.assertEqual(body["x1"], [float(x1[7])])
        self.assertEqual(body["shape"], [len(f["time"]), 1])
        np.testing.assert_array_equal(as_array(body["values"])[:, 0], f["slip_velocity"][:, 7])
        # A one-column window spends the whole budget on time.
        body = self.fields("bi", "slip_velocity", x1_min=target, x1_max=target,
                           max_points=10).json()
        self.assertLessEqual(body["shape"][0], 10)
        self.assertEqual(body["shape"][1], 1)

    def test_bad_parameters_are_400_naming_them(self):
        cases = [({"x1_min": "abc"}, "/query/x1_min"), ({"t_max": "nan"}, "/query/t_max"),
                 ({"max_points": "0"}, "/query/max_points"),
                 ({"max_points": "1.5"}, "/query/max_points"),
                 ({"max_points": "99999999"}, "/query/max_points"),
                 ({"x1_min": "5", "x1_max": "1"}, "/query/x1_max"),
                 ({"t_min": "2", "t_max": "1"}, "/query/t_max"),
                 ({"bogus": "1"}, "/query/bogus")]
        for query, pointer in cases:
            r = self.fields("fe", "slip_velocity", **query)
            self.assertEqual(r.status_code, 400, (query, r.text))
            self.assertEqual(r.headers["Content-Type"], "application/problem+json")
            self.assertIn(pointer, [e["pointer"] for e in r.json()["errors"]], query)

    def test_unknown_field_job_and_unfinished_job(self):
        r = self.fields("fe", "temperature")
        self.assertEqual(r.status_code, 404)
        self.assertIn("slip_velocity", r.json()["detail"])
        self.assertEqual(self.server.get(f"{JOBS}/{'0' * 32}/fields/slip").status_code, 404)
        self.assertEqual(self.server.get(f"{JOBS}/nothex/fields/slip").status_code, 404)
        job = self.server.submit(long_job("web-409")).json()
        try:
            r = self.server.get(f"{JOBS}/{job['id']}/fields/slip_velocity")
            self.assertEqual(r.status_code, 409, r.text)
        finally:
            self.server.post(f"{JOBS}/{job['id']}/cancel")
        done = self.server.wait_status(job["id"], {"cancelled", "succeeded", "failed"}, 60)
        if done["status"] == "cancelled":
            self.assertEqual(self.server.get(f"{JOBS}/{job['id']}/fields/slip").status_code, 404)

    def test_json_etag_gives_304(self):
        url = f"{JOBS}/{self.jobs['fe']['id']}"
        r = self.server.get(url)
        etag = r.headers["ETag"]
        self.assertTrue(etag.startswith('W/"'), etag)
        r2 = self.server.get(url, headers={"If-None-Match": etag})
        self.assertEqual(r2.status_code, 304)
        self.assertEqual(r2.content, b"")
        r3 = self.server.get(JOBS, headers={"If-None-Match": etag})
        self.assertEqual(r3.status_code, 200)

    def test_job_defaults(self):
        for method in ("fe", "spectral_bi"):
            body = self.server.get("/api/v1/job-defaults", params={"method": method}).json()
            self.assertEqual(body["method"], method)
            self.assertIn("friction", body["spec"])
            # The defaults are a valid job as they are.
            self.assertEqual(self.server.get("/api/v1/job-defaults",
                                             params={"method": method}).status_code, 200)
        r = self.server.get("/api/v1/job-defaults", params={"method": "abc"})
        self.assertEqual(r.status_code, 400)
        self.assertEqual(r.json()["errors"][0]["pointer"], "/query/method")

    def test_presets_are_served_and_a_job_may_name_one(self):
        listing = self.server.get("/api/v1/presets")
        self.assertEqual(listing.status_code, 200)
        presets = listing.json()["presets"]
        names = [p["name"] for p in presets]
        examples = sorted(f[:-5] for f in os.listdir(os.path.join(ROOT, "examples"))
                          if f.endswith(".json"))
        self.assertTrue(set(examples) <= set(names), names)
        for p in presets:
            self.assertTrue({"name", "origin", "title", "description", "reference", "spec"} <= set(p))
        one = self.server.get("/api/v1/presets/quick_nd10")
        self.assertEqual(one.status_code, 200)
        self.assertEqual(one.json()["spec"]["geometry"]["nodes_per_meter"], 10)
        missing = self.server.get("/api/v1/presets/none_such")
        self.assertEqual(missing.status_code, 404)
        self.assertIn("none_such", missing.json()["detail"])
        # A job naming a preset is stored expanded, the job's members merged over the preset's.
        r = self.server.post(JOBS, json={"preset": "quick_nd10", "method": "spectral_bi",
                                         "time": {"duration": 0.5}, "name": "from a preset"})
        self.assertEqual(r.status_code, 201, r.text)
        job = r.json()
        self.assertNotIn("preset", job["spec"])
        self.assertEqual(job["spec"]["geometry"]["nodes_per_meter"], 10)
        self.assertEqual(job["spec"]["time"]["duration"], 0.5)
        self.assertEqual(job["spec"]["friction"]["L"], 5e-5)
        self.assertEqual(job["name"], "from a preset")
        bad = self.server.post(JOBS, json={"preset": "none_such"})
        self.assertEqual(bad.status_code, 422)
        self.assertEqual(bad.json()["errors"][0]["pointer"], "/preset")

    def test_openapi_documents_the_new_endpoints(self):
        doc = self.server.get("/api/v1/openapi.json").json()
        op = doc["paths"]["/api/v1/jobs/{id}/fields/{name}"]["get"]
        names = {p.get("name") for p in op["parameters"]}
        self.assertTrue({"x1_min", "x1_max", "t_min", "t_max", "max_points"} <= names)
        self.assertIn("/api/v1/job-defaults", doc["paths"])
        self.assertIn("/api/v1/presets/{name}", doc["paths"])

    def test_static_files(self):
        r = self.server.get("/")
        self.assertEqual(r.status_code, 200, r.text[:300])
        self.assertTrue(r.headers["Content-Type"].startswith("text/html"))
        csp = r.headers["Content-Security-Policy"]
        self.assertIn("default-src 'self'", csp)
        self.assertIn("script-src 'self'", csp)
        self.assertNotIn("unsafe-inline", csp)
        self.assertNotIn("unsafe-eval", csp)
        self.assertEqual(r.headers["X-Content-Type-Options"], "nosniff")
        self.assertNotIn("<script>", r.text)  # no inline script
        js = self.server.get("/app/main.js")
        self.assertEqual(js.status_code, 200)
        self.assertTrue(js.headers["Content-Type"].startswith("text/javascript"))
        self.assertEqual(self.server.get("/app/main.js",
                                         headers={"If-None-Match": js.headers["ETag"]}).status_code,
                         304)
        self.assertEqual(self.server.get("/api-docs").status_code, 200)
        # Sent as they are (requests would normalise the dots away).
        host, port = self.server.base[len("http://"):].split(":")
        for bad in ("/app/nothing.js", "/app/../index.html", "/app/%2e%2e/index.html",
                    "/vendor/x/../../../etc/passwd", "/app/..%2f..%2fslipfront.db",
                    "/vendor/swagger-ui/../../../../etc/passwd"):
            conn = http.client.HTTPConnection(host, int(port), timeout=10)
            conn.putrequest("GET", bad, skip_accept_encoding=True)
            conn.endheaders()
            status = conn.getresponse().status
            conn.close()
            self.assertIn(status, (400, 404), bad)
        self.assertEqual(self.server.session.head(self.server.url("/")).status_code, 200)


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    parser.add_argument("--web-dir")
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    WEB_DIR = args.web_dir
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

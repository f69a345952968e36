"""Searching and exporting runs over real HTTP on loopback (docs/server.md, "Searching and
exporting runs"): `where` conditions on spec fields, metrics and job columns, `sort` with
paging, `format=csv|ndjson` run tables, and 400s naming the parameter for bad filters
(including attempts at SQL injection, which must match nothing and change nothing).

    /usr/bin/python3 tests/server/test_search.py --binary build/slipfront
"""

import argparse
import csv
import io
import json
import os
import sys
import unittest
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import Server, wait_study  # noqa: E402

BINARY = None
JOBS = "/api/v1/jobs"

# Spectral BI runs of a small scene: each well under a second.
SCENE = {"method": "spectral_bi", "geometry": {"width": 12, "x_min": -1},
         "probe": {"arrival_x1": 3, "spectrum_x1": 2}, "time": {"duration": 3}}


def job(L, tags, name):
    spec = json.loads(json.dumps(SCENE))
    spec["friction"] = {"L": L}
    spec["tags"] = tags
    spec["name"] = name
    return spec


class SearchTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.server = Server(BINARY).start()
        cls.ids = {}
        for L, tags, name in [(1e-3, ["big"], "big L"), (1e-4, ["mid", "paper"], "mid L"),
                              (5e-5, ["small", "paper"], "small, \"quoted\" L")]:
            r = cls.server.submit(job(L, tags, name))
            assert r.status_code in (200, 201), r.text
            cls.ids[L] = r.json()["id"]
        fe = cls.server.submit({"geometry": {"nodes_per_meter": 5}, "time": {"duration": 2.0},
                                "name": "fe tiny"})
        assert fe.status_code in (200, 201), fe.text
        cls.fe_id = fe.json()["id"]
        cls.jobs = {}
        for i in list(cls.ids.values()) + [cls.fe_id]:
            cls.jobs[i] = cls.server.wait_status(i, {"succeeded", "failed"}, timeout=120)
        base = json.loads(json.dumps(SCENE))
        r = cls.server.post("/api/v1/studies", data=json.dumps(
            {"base": base, "grid": {"L": [5e-5], "n_d": [10, 20]}}),
            headers={"Content-Type": "application/json"})
        assert r.status_code == 201, r.text
        cls.study = wait_study(cls.server, r.json()["id"], timeout=180)

    @classmethod
    def tearDownClass(cls):
        cls.server.terminate()
        cls.server.cleanup()

    def listing(self, **params):
        r = self.server.get(JOBS, params=params)
        self.assertEqual(r.status_code, 200, r.text)
        return r.json()

    def ids_of(self, **params):
        return {j["id"] for j in self.listing(limit=1000, **params)["jobs"]}

    def test_filters_on_spec_fields_metrics_and_columns(self):
        self.assertEqual(self.ids_of(where="friction.L<1e-4", name="small, \"quoted\" L"),
                         {self.ids[5e-5]})
        bi_big = self.ids_of(where="method=spectral_bi and friction.L>=1e-4")
        self.assertEqual(bi_big, {self.ids[1e-3], self.ids[1e-4]})
        self.assertEqual(self.ids_of(where="spec.friction.L = 1e-3; method = spectral_bi"),
                         {self.ids[1e-3]})
        self.assertIn(self.fe_id, self.ids_of(where="method=fe"))
        self.assertNotIn(self.fe_id, self.ids_of(where="method!=fe"))
        self.assertEqual(self.ids_of(where="tag=paper"), {self.ids[1e-4], self.ids[5e-5]})
        self.assertNotIn(self.ids[1e-4], self.ids_of(where="tag!=mid"))
        # `tags`, the run table's column name, filters as `tag` does
        self.assertEqual(self.ids_of(where="tags=paper"), self.ids_of(where="tag=paper"))
        self.assertEqual(self.ids_of(where="tags!=mid"), self.ids_of(where="tag!=mid"))
        # Metrics: compare with what each job reports.
        arrests = {i: j["metrics"]["arrest_position"] for i, j in self.jobs.items()
                   if j["metrics"] and j["metrics"]["arrest_position"] is not None}
        self.assertGreaterEqual(len(arrests), 2, arrests)
        cut = sorted(arrests.values())[len(arrests) // 2]
        want = {i for i, a in arrests.items() if a > cut}
        self.assertEqual(self.ids_of(where=f"metrics.arrest_position>{cut!r}") & set(self.jobs),
                         want)
        outcomes = {i: j["metrics"]["outcome"] for i, j in self.jobs.items()}
        for outcome in set(outcomes.values()):
            want = {i for i, o in outcomes.items() if o == outcome}
            self.assertEqual(self.ids_of(where=f"outcome={outcome}") & set(self.jobs), want)
            self.assertEqual(self.ids_of(where=f"metrics.outcome='{outcome}'") & set(self.jobs),
                             want)
        self.assertEqual(self.ids_of(where="metrics.rupture_speed.max>0") & set(self.jobs),
                         {i for i, j in self.jobs.items()
                          if (j["metrics"]["rupture_speed"]["max"] or 0) > 0})
        # Dates and cost.
        self.assertEqual(self.ids_of(where="created_at>2999-01-01"), set())
        self.assertTrue(set(self.jobs) <= self.ids_of(where="created_at>=2000-01-01T00:00:00Z"))
        self.assertTrue(set(self.jobs) <= self.ids_of(where="wall_time_s>=0"))
        # Convergence status of study runs.
        study_ids = {r["job_id"] for r in self.study["runs"]}
        statuses = self.ids_of(where=f"study_id={self.study['id']};convergence_status!=pending")
        self.assertEqual(statuses, study_ids)

    def test_sort_and_pages(self):
        listing = self.listing(where="method=spectral_bi;tag!=nosuchtag", sort="-friction.L",
                               limit=2)
        Ls = [j["spec"]["friction"]["L"] for j in listing["jobs"]]
        self.assertEqual(Ls, [1e-3, 1e-4])
        self.assertTrue(listing["next_cursor"].startswith("o"))
        rest = self.server.get(listing["next"]).json()
        self.assertEqual(rest["jobs"][0]["spec"]["friction"]["L"], 5e-5)
        ascending = self.listing(where="method=spectral_bi", sort="friction.L,-created_at")
        Ls = [j["spec"]["friction"]["L"] for j in ascending["jobs"]]
        self.assertEqual(Ls, sorted(Ls))
        # Metrics sort with nulls last.
        by_arrest = self.listing(sort="-metrics.arrest_position", limit=1000)["jobs"]
        values = [j["metrics"]["arrest_position"] if j["metrics"] else None for j in by_arrest]
        present = [v for v in values if v is not None]
        self.assertEqual(present, sorted(present, reverse=True))
        self.assertEqual(values[:len(present)], present)

    def test_bad_filters_are_400_naming_the_parameter(self):
        cases = [
            ({"where": "friction.L<abc"}, "/query/where", "not a finite number"),
            ({"where": "no_such.field=1"}, "/query/where", "unknown field"),
            ({"where": "metrics.nope>1"}, "/query/where", "unknown metric"),
            ({"where": "friction.L<1e-4; DROP TABLE jobs"}, "/query/where", "unknown field 'DROP'"),
            ({"where": "friction.L<1e-4 or 1=1"}, "/query/where", "expected ';' or 'and'"),
            ({"where": "name='unterminated"}, "/query/where", "unterminated"),
            ({"where": ""}, "/query/where", "empty"),
            ({"where": "tag<x"}, "/query/where", "tag takes"),
            ({"where": "time.stop_on_arrest=maybe"}, "/query/where", "true or false"),
            ({"sort": "friction.L;DROP"}, "/query/sort", "not a field name"),
            ({"sort": "bogus"}, "/query/sort", "unknown field"),
            ({"sort": "friction.L", "cursor": "12"}, "/query/cursor", "same sort"),
            ({"format": "xml"}, "/query/format", "csv"),
            ({"format": "csv", "limit": "100001"}, "/query/limit", "100000"),
        ]
        for params, pointer, reason in cases:
            with self.subTest(params=params):
                r = self.server.get(JOBS, params=params)
                self.assertEqual(r.status_code, 400, r.text)
                self.assertTrue(r.headers["Content-Type"].startswith("application/problem+json"))
                errors = r.json()["errors"]
                self.assertIn(pointer, [e["pointer"] for e in errors], errors)
                reasons = " ".join(e["reason"] for e in errors)
                self.assertIn(reason, reasons)

    def test_injection_attempts_are_values_not_sql(self):
        before = self.listing(limit=1000)["count"]
        for where in ["name=\"x' OR 1=1 --\"", "name=\"a' OR '1'='1\"",
                      "id='; DROP TABLE jobs; --'"]:
            with self.subTest(where=where):
                self.assertEqual(self.ids_of(where=where), set())
        self.assertEqual(self.listing(limit=1000)["count"], before)

    def test_csv_cells_never_start_a_formula(self):
        """Text cells starting with =, +, -, @ are neutralised with a leading
        ' (a spreadsheet would run them); numbers, negative ones too, stay numbers."""
        names = ["=HYPERLINK(\"http://x\")", "+1+2", "-2+3", "@SUM(A1)"]
        for name in names:
            r = self.server.submit({"geometry": {"nodes_per_meter": 5}, "time": {"duration": 2.0},
                                    "name": name, "tags": ["=tag", "formula"]})
            self.assertIn(r.status_code, (200, 201), r.text)
        r = self.server.get(JOBS, params={"format": "csv", "tag": "formula", "limit": 100})
        self.assertEqual(r.status_code, 200, r.text)
        rows = list(csv.DictReader(io.StringIO(r.text)))
        self.assertEqual(sorted(row["name"] for row in rows), sorted("'" + n for n in names))
        for row in rows:
            self.assertEqual(row["tags"], "'=tag;formula")
            self.assertFalse(row["spec.geometry.nodes_per_meter"].startswith("'"))
        # NDJSON is JSON: unchanged.
        r = self.server.get(JOBS, params={"format": "ndjson", "tag": "formula", "limit": 100})
        self.assertEqual(sorted(json.loads(line)["name"] for line in r.text.splitlines()),
                         sorted(names))

    def test_csv_and_ndjson_export(self):
        r = self.server.get(JOBS, params={"format": "csv", "where": "method=spectral_bi",
                                          "sort": "friction.L"})
        self.assertEqual(r.status_code, 200, r.text)
        self.assertTrue(r.headers["Content-Type"].startswith("text/csv"))
        rows = list(csv.DictReader(io.StringIO(r.text)))
        header = next(csv.reader(io.StringIO(r.text)))
        for column in ["id", "status", "method", "outcome", "convergence_status", "wall_time_s",
                       "spec.friction.L", "spec.geometry.nodes_per_meter",
                       "metrics.arrest_position", "metrics.rupture_speed.max",
                       "metrics.wall_time_s", "metrics.steps"]:
            self.assertIn(column, header)
        self.assertLess(header.index("wall_time_s"), header.index("spec.friction.L"))
        self.assertLess(header.index("spec.time.duration"), header.index("metrics.dt"))
        Ls = [float(row["spec.friction.L"]) for row in rows]
        self.assertEqual(Ls, sorted(Ls))
        by_id = {row["id"]: row for row in rows}
        quoted = by_id[self.ids[5e-5]]
        self.assertEqual(quoted["name"], "small, \"quoted\" L")
        self.assertEqual(quoted["tags"], "small;paper")
        for i in self.ids.values():
            m = self.jobs[i]["metrics"]
            self.assertEqual(by_id[i]["metrics.outcome"], m["outcome"])
            a = m["arrest_position"]
            cell = by_id[i]["metrics.arrest_position"]
            self.assertEqual(cell == "", a is None)
            if a is not None:
                self.assertEqual(float(cell), a)
        study_rows = [row for row in rows if row["study_id"] == self.study["id"]]
        self.assertEqual(len(study_rows), 2)
        self.assertEqual({row["convergence_status"] for row in study_rows},
                         {r["convergence"]["status"] for r in self.study["runs"]})
        # NDJSON: the same rows as JSON objects.
        r = self.server.get(JOBS, params={"format": "ndjson", "where": "method=spectral_bi",
                                          "sort": "friction.L"})
        self.assertEqual(r.status_code, 200, r.text)
        self.assertTrue(r.headers["Content-Type"].startswith("application/x-ndjson"))
        lines = [json.loads(line) for line in r.text.splitlines()]
        self.assertEqual([line["id"] for line in lines], [row["id"] for row in rows])
        self.assertEqual(lines[0]["spec.friction.L"], Ls[0])
        # Paging of exports through the Link header.
        r = self.server.get(JOBS, params={"format": "ndjson", "limit": 1, "sort": "friction.L"})
        self.assertIn('rel="next"', r.headers.get("Link", ""))
        self.assertEqual(len(r.text.splitlines()), 1)


class XdmfRouteTest(unittest.TestCase):
    """GET /jobs/{id}/result.xdmf: the sidecar of the result file, naming it ID.h5."""

    def test_sidecar(self):
        server = Server(BINARY).start()
        try:
            job_id = server.submit(job(5e-5, [], "xdmf")).json()["id"]
            server.wait_status(job_id, {"succeeded"}, timeout=120)
            r = server.get(f"{JOBS}/{job_id}/result.xdmf")
            self.assertEqual(r.status_code, 200, r.text)
            self.assertTrue(r.headers["Content-Type"].startswith("application/xml"))
            self.assertIn(f'filename="{job_id}.xdmf"', r.headers["Content-Disposition"])
            root = ET.fromstring(r.text)
            items = [i.text for i in root.iter("DataItem") if i.get("Format") == "HDF"]
            self.assertIn(f"{job_id}.h5:/interface/slip_velocity", items)
            self.assertTrue(all(i.startswith(f"{job_id}.h5:/interface/") for i in items), items)
            self.assertEqual(server.get(f"{JOBS}/{'0' * 32}/result.xdmf").status_code, 404)
            spec = server.get("/api/v1/openapi.json").json()
            self.assertIn("/api/v1/jobs/{id}/result.xdmf", spec["paths"])
            params = {p["name"] for p in spec["paths"]["/api/v1/jobs"]["get"]["parameters"]}
            self.assertTrue({"where", "sort", "format"} <= params)
        finally:
            server.terminate()
            server.cleanup()


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

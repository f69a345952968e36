"""The API's details over real HTTP on loopback (a `slipfront serve` on an ephemeral
port, temporary data dir):
- the answers: a body of another Content-Type than JSON gets 415 naming application/json; a 405
  lists every method of the path in Allow; the OpenAPI document carries the code's version, a
  description naming both methods, its operations under the tags jobs, results, studies,
  presets and ops, and no HEAD rows;
- `slipfront serve`'s command line: a port in use is said first and alone (no
  "shutting down" lines before it, nothing created), --config is read before the flags that
  override it, and the old name --max-memory-bytes still sets the memory limit.

    /usr/bin/python3 tests/server/test_api_details.py --binary build/slipfront
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import TINY, Server  # noqa: E402

BINARY = None
JOBS, STUDIES, FITS = "/api/v1/jobs", "/api/v1/studies", "/api/v1/length-fits"
STUDY = {"name": "415", "base": TINY, "grid": {"L": [5e-5], "n_d": [5]}}
TAGS = ["jobs", "results", "studies", "presets", "ops"]


class ApiDetails(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.server = Server(BINARY, args=["--workers", "1"]).start()

    @classmethod
    def tearDownClass(cls):
        code = cls.server.terminate()
        cls.server.cleanup()
        assert code == 0, f"server exit code {code}"

    def counts(self):
        jobs = self.server.get(JOBS, params={"limit": 1000, "fields": "id"}).json()["count"]
        return jobs, len(self.server.get(STUDIES).json()["studies"])

    def test_a_body_of_another_type_is_415_naming_json(self):
        before = self.counts()
        for path, body in ((JOBS, TINY), (STUDIES, STUDY), (FITS, {"record": "time,slip_rate"})):
            for content_type in ("text/plain", "application/x-www-form-urlencoded",
                                 "application/xml; charset=utf-8", "multipart/form-data; boundary=b",
                                 "application/jsonx"):
                with self.subTest(path=path, content_type=content_type):
                    r = self.server.post(path, data=json.dumps(body).encode(),
                                         headers={"Content-Type": content_type})
                    self.assertEqual(r.status_code, 415, r.text)
                    self.assertTrue(r.headers["Content-Type"].startswith("application/problem+json"))
                    self.assertEqual(r.headers["Accept"], "application/json")
                    problem = r.json()
                    self.assertEqual(problem["status"], 415)
                    self.assertIn("application/json", problem["detail"])
                    self.assertIn(content_type, problem["detail"])
        self.assertEqual(self.counts(), before, "a refused body created something")
        # The OpenAPI document lists the 415 of both operations.
        doc = self.server.get("/api/v1/openapi.json").json()
        for path in (JOBS, STUDIES, FITS):
            self.assertIn("415", doc["paths"][path]["post"]["responses"])

    def test_json_is_taken_with_parameters_any_case_or_without_a_type(self):
        for headers in ({"Content-Type": "Application/JSON; charset=utf-8"}, {}):
            with self.subTest(headers=headers):
                r = self.server.post(JOBS, params={"fresh": "true"},
                                     data=json.dumps(TINY).encode(), headers=headers)
                self.assertEqual(r.status_code, 201, r.text)

    def test_405_allows_every_method_of_the_path(self):
        unknown = "0" * 32
        cases = {
            JOBS: {"GET", "HEAD", "POST"},
            f"{JOBS}/{unknown}": {"DELETE", "GET", "HEAD", "PATCH"},
            f"{JOBS}/{unknown}/cancel": {"POST"},
            STUDIES: {"GET", "HEAD", "POST"},
            f"{STUDIES}/{unknown}/cancel": {"POST"},
            "/api/v1/openapi.json": {"GET", "HEAD"},
            "/healthz": {"GET", "HEAD"},
        }
        for path, allowed in cases.items():
            for method in sorted({"DELETE", "PUT", "PATCH", "GET", "POST"} - allowed):
                with self.subTest(path=path, method=method):
                    r = self.server.session.request(method, self.server.url(path), timeout=10)
                    self.assertEqual(r.status_code, 405, r.text)
                    listed = {m.strip() for m in r.headers["Allow"].split(",")}
                    self.assertEqual(listed, allowed)
                    self.assertTrue(r.headers["Content-Type"].startswith("application/problem+json"))
            # Every method Allow names is answered by a route, not 405.
            for method in allowed:
                with self.subTest(path=path, allowed=method):
                    r = self.server.session.request(method, self.server.url(path), timeout=10,
                                                    json={"unknown_field": 1} if method == "POST" else None)
                    self.assertNotEqual(r.status_code, 405, f"{method} {path}")

    def test_openapi_version_description_and_tags(self):
        doc = self.server.get("/api/v1/openapi.json").json()
        version = subprocess.run([BINARY, "--version"], capture_output=True, text=True).stdout
        self.assertEqual("slipfront " + doc["info"]["version"], version.strip())
        description = doc["info"]["description"]
        self.assertIn("explicit finite-element method", description)
        self.assertIn("spectral boundary-integral method", description)
        self.assertIn("HEAD", description)  # said once, not as a row beside every GET
        self.assertEqual([t["name"] for t in doc["tags"]], TAGS)
        used = set()
        for path, operations in doc["paths"].items():
            self.assertNotIn("head", operations, path)
            for method, operation in operations.items():
                self.assertEqual(len(operation["tags"]), 1, f"{method} {path}")
                self.assertIn(operation["tags"][0], TAGS, f"{method} {path}")
                used.add(operation["tags"][0])
        self.assertEqual(used, set(TAGS), "a tag without operations")
        tag = {path: ops[next(iter(ops))]["tags"][0] for path, ops in doc["paths"].items()}
        self.assertEqual(tag[JOBS], "jobs")
        self.assertEqual(tag[f"{JOBS}/{{id}}/result.h5"], "results")
        self.assertEqual(tag[f"{STUDIES}/{{id}}"], "studies")
        self.assertEqual(tag["/api/v1/presets"], "presets")
        self.assertEqual(tag["/healthz"], "ops")
        # HEAD is still answered (the description's promise).
        r = self.server.session.head(self.server.url("/api/v1/openapi.json"), timeout=10)
        self.assertEqual((r.status_code, r.content), (200, b""))


class ServeCommandLine(unittest.TestCase):
    def test_a_port_in_use_is_said_first_and_alone(self):
        first = Server(BINARY, args=["--workers", "1"]).start()
        try:
            port = first.base.rsplit(":", 1)[1]
            data = os.path.join(tempfile.mkdtemp(prefix="slipfront-busy-"), "data")
            second = subprocess.run([BINARY, "serve", "--port", port, "--data-dir", data],
                                    capture_output=True, text=True, timeout=30)
            self.assertEqual(second.returncode, 1, second.stderr)
            self.assertEqual(second.stdout, "")
            lines = second.stderr.splitlines()
            self.assertEqual(len(lines), 1, second.stderr)
            self.assertIn(f"cannot listen on 127.0.0.1:{port}: Address already in use", lines[0])
            self.assertIn("--port", lines[0])
            self.assertNotIn("shutting down", second.stderr)
            self.assertFalse(os.path.exists(data), "the refused server created its data dir")
            os.rmdir(os.path.dirname(data))
        finally:
            first.terminate()
            first.cleanup()

    def test_the_flags_override_the_config_file(self):
        with tempfile.TemporaryDirectory(prefix="slipfront-config-") as tmp:
            config = os.path.join(tmp, "config.json")
            with open(config, "w") as f:
                json.dump({"workers": 3, "max_memory": "2G"}, f)
            for flags, workers in (([], 3), (["--workers", "1"], 1), (["--workers=2"], 2)):
                with self.subTest(flags=flags):
                    server = Server(BINARY, args=["--config", config] + flags).start()
                    try:
                        self.assertEqual(server.get("/healthz").json()["workers"], workers)
                    finally:
                        server.terminate()
                        server.cleanup()

    def test_the_old_memory_flag_sets_the_same_limit(self):
        server = Server(BINARY, args=["--workers", "1", "--max-memory-bytes", "1G"]).start()
        try:
            r = server.submit({"geometry": {"nodes_per_meter": 200}})
            self.assertEqual(r.status_code, 422, r.text)
            error = r.json()["errors"][0]
            self.assertEqual(error["pointer"], "/geometry/nodes_per_meter")
            self.assertIn("above the limit of 1 GB", error["reason"])
        finally:
            server.terminate()
            server.cleanup()


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

"""The job server over real HTTP on loopback: a `slipfront serve` started by the test on an
ephemeral port with a temporary data dir, running the real solver on tiny coarse jobs.
Over 400 lines on purpose: one short test per HTTP contract of docs/server.md.

    /usr/bin/python3 tests/server/test_http.py --binary build/slipfront
"""

import argparse
import hashlib
import json
import os
import socket
import sys
import tempfile
import time
import unittest

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import TERMINAL, TINY, Server, long_job  # noqa: E402

BINARY = None
JOBS = "/api/v1/jobs"


def tiny(**extra):
    spec = json.loads(json.dumps(TINY))
    spec.update(extra)
    return spec


def raw_http(server, payload, timeout=10.0):
    """Send raw bytes on a fresh connection; return everything the server sends back."""
    host, port = server.base[len("http://"):].split(":")
    with socket.create_connection((host, int(port)), timeout=timeout) as s:
        s.sendall(payload)
        chunks = []
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            try:
                data = s.recv(65536)
            except socket.timeout:
                break
            if not data:
                break
            chunks.append(data)
        return b"".join(chunks)


class MainServer(unittest.TestCase):
    """Two workers, no auth; most endpoints and error paths."""

    @classmethod
    def setUpClass(cls):
        cls.server = Server(BINARY, args=["--workers", "2", "--queue-limit", "50",
                                          "--max-body-bytes", "65536",
                                          "--request-timeout-s", "2",
                                          "--max-memory", "2G"]).start()

    @classmethod
    def tearDownClass(cls):
        code = cls.server.terminate()
        cls.server.cleanup()
        assert code == 0, f"server exit code {code}"

    def run_tiny(self, **extra):
        r = self.server.submit(tiny(**extra))
        self.assertEqual(r.status_code, 201, r.text)
        return self.server.wait_status(r.json()["id"], TERMINAL, timeout=60)

    def assertProblem(self, r, status):
        self.assertEqual(r.status_code, status, r.text)
        self.assertTrue(r.headers["Content-Type"].startswith("application/problem+json"),
                        r.headers)
        body = r.json()
        self.assertEqual(body["status"], status)
        self.assertIn("detail", body)
        return body

    # --- operations -------------------------------------------------------------------
    def test_healthz(self):
        r = self.server.get("/healthz")
        self.assertEqual(r.status_code, 200)
        body = r.json()
        self.assertEqual(body["status"], "ok")
        self.assertEqual(body["workers"], 2)
        self.assertEqual(body["database"], "ok")

    def test_openapi_describes_every_endpoint(self):
        doc = self.server.get("/api/v1/openapi.json").json()
        self.assertEqual(doc["openapi"][:2], "3.")
        for path in ["/api/v1/jobs", "/api/v1/jobs/{id}", "/api/v1/jobs/{id}/cancel",
                     "/api/v1/jobs/{id}/result.h5", "/api/v1/jobs/{id}/metrics",
                     "/api/v1/jobs/{id}/front", "/healthz", "/metrics", "/api/v1/schema/job.json"]:
            self.assertIn(path, doc["paths"])
        # What holds on every path: a 503 with Retry-After on every operation
        # (storage errors, the connection cap); HEAD beside every GET is said once in the
        # description, not as a row of its own (test_api_details.py).
        # test_hostile.py checks every status its requests were answered against the document.
        self.assertIn("Every GET also answers HEAD", doc["info"]["description"])
        for path, operations in doc["paths"].items():
            self.assertNotIn("head", operations, path)
            for method, operation in operations.items():
                unavailable = operation["responses"].get("503")
                self.assertIsNotNone(unavailable, f"{method} {path}")
                if "$ref" in unavailable:
                    unavailable = doc["components"]["responses"][unavailable["$ref"].split("/")[-1]]
                self.assertIn("Retry-After", unavailable["headers"], f"{method} {path}")
        self.assertIn("410", doc["paths"]["/api/v1/jobs/{id}/result.h5"]["get"]["responses"])
        # The job body is the job schema, section by section (api/job_schema.hpp).
        job = doc["components"]["schemas"]["JobSpec"]
        L = job["properties"]["friction"]["properties"]["L"]
        self.assertEqual((L["type"], L["exclusiveMinimum"], L["x-unit"]), ("number", 0, "m"))
        self.assertIn("priority", job["properties"])

    def test_job_schema_is_served_and_matches_validation(self):
        r = self.server.get("/api/v1/schema/job.json")
        self.assertEqual(r.status_code, 200)
        schema = r.json()
        self.assertTrue(schema["$schema"].startswith("https://json-schema.org/"))
        nu = schema["properties"]["material"]["properties"]["poisson_ratio"]
        self.assertEqual((nu["exclusiveMinimum"], nu["exclusiveMaximum"], nu["default"]), (0, 0.5, 0.25))
        # The bound the schema states is the one the server enforces.
        bad = self.server.post("/api/v1/jobs", json={"material": {"poisson_ratio": 0.5}})
        self.assertEqual(bad.status_code, 422)
        self.assertIn("/material/poisson_ratio", bad.text)

    def test_prometheus_metrics(self):
        self.run_tiny(name="for-metrics")
        r = self.server.get("/metrics")
        self.assertEqual(r.status_code, 200)
        self.assertTrue(r.headers["Content-Type"].startswith("text/plain"))
        text = r.text
        for name in ["slipfront_queue_depth ", "slipfront_jobs_running ",
                     'slipfront_jobs{status="succeeded"}', "slipfront_run_duration_seconds_bucket",
                     "slipfront_run_duration_seconds_count", "slipfront_http_requests_total"]:
            self.assertIn(name, text)

    # --- a job from submission to its HDF5 file ---------------------------------------
    def test_submit_poll_download(self):
        r = self.server.submit(tiny(name="roundtrip", tags=["t-roundtrip"]), params={"fresh": "true"})
        self.assertEqual(r.status_code, 201, r.text)
        job = r.json()
        self.assertEqual(r.headers["Location"], f"{JOBS}/{job['id']}")
        self.assertEqual(len(job["id"]), 32)
        self.assertIn(job["status"], ("queued", "running"))
        self.assertEqual(job["spec"]["geometry"]["nodes_per_meter"], 5)
        self.assertEqual(job["spec"]["threads"], 1)  # one core per job by default
        self.assertEqual(len(job["spec_sha256"]), 64)
        self.assertFalse(job["reused"])
        self.assertEqual(job["cache"], "bypassed")

        done = self.server.wait_status(job["id"], TERMINAL)
        self.assertEqual(done["status"], "succeeded", done)
        for key in ["id", "status", "name", "tags", "spec", "spec_sha256", "submitted_by",
                    "created_at", "started_at", "finished_at", "progress", "metrics", "error",
                    "wall_time_s", "code_version", "host", "result", "cached_from"]:
            self.assertIn(key, done)
        self.assertEqual(done["progress"]["fraction"], 1.0)
        self.assertGreater(done["progress"]["steps"], 0)
        self.assertGreater(done["wall_time_s"], 0)
        self.assertIn(done["metrics"]["outcome"],
                      ["arrested", "running_at_end", "no_rupture", "diverged"])
        self.assertTrue(done["code_version"])
        self.assertTrue(done["host"])
        result = done["result"]
        self.assertEqual(result["url"], f"{JOBS}/{job['id']}/result.h5")

        r = self.server.get(result["url"])
        self.assertEqual(r.status_code, 200)
        self.assertEqual(r.headers["Content-Type"], "application/x-hdf5")
        self.assertEqual(int(r.headers["Content-Length"]), result["size"])
        self.assertIn("attachment", r.headers["Content-Disposition"])
        self.assertEqual(r.headers["ETag"], '"%s"' % result["sha256"])
        self.assertEqual(hashlib.sha256(r.content).hexdigest(), result["sha256"])
        data = r.content
        with tempfile.NamedTemporaryFile(suffix=".h5") as f:
            f.write(data)
            f.flush()
            with h5py.File(f.name, "r") as h5:
                x1 = np.asarray(h5["/interface/x1"])
                v = np.asarray(h5["/interface/slip_velocity"])
                self.assertEqual(v.shape[1], x1.shape[0])
                self.assertIn("/front/arrival_time", h5)

        # Range requests, conditional requests.
        r = self.server.get(result["url"], headers={"Range": "bytes=10-99"})
        self.assertEqual(r.status_code, 206)
        self.assertEqual(r.content, data[10:100])
        self.assertEqual(r.headers["Content-Range"], f"bytes 10-99/{len(data)}")
        r = self.server.get(result["url"], headers={"Range": "bytes=-16"})
        self.assertEqual(r.status_code, 206)
        self.assertEqual(r.content, data[-16:])
        r = self.server.get(result["url"], headers={"Range": f"bytes={len(data)}-"})
        self.assertProblem(r, 416)
        self.assertEqual(r.headers["Content-Range"], f"bytes */{len(data)}")
        r = self.server.get(result["url"], headers={"If-None-Match": r.headers.get("ETag", '"%s"' % result["sha256"])})
        self.assertEqual(r.status_code, 304)
        self.assertEqual(r.content, b"")
        r = self.server.get(result["url"], headers={"If-None-Match": '"other"'})
        self.assertEqual(r.status_code, 200)

        # Metrics and front as JSON.
        m = self.server.get(f"{JOBS}/{job['id']}/metrics").json()
        self.assertEqual(m["metrics"], done["metrics"])
        front = self.server.get(f"{JOBS}/{job['id']}/front").json()
        self.assertEqual(len(front["x1"]), len(front["arrival_time"]))
        self.assertEqual(len(front["x1"]), len(front["rupture_speed"]))

        # Projection.
        small = self.server.get(f"{JOBS}/{job['id']}", params={"fields": "status,progress"}).json()
        self.assertEqual(set(small), {"id", "status", "progress"})

    def test_results_of_unfinished_jobs_are_409(self):
        r = self.server.submit(long_job("unfinished"))
        self.assertEqual(r.status_code, 201)
        job_id = r.json()["id"]
        for tail in ("/result.h5", "/metrics", "/front"):
            self.assertProblem(self.server.get(f"{JOBS}/{job_id}{tail}"), 409)
        self.server.post(f"{JOBS}/{job_id}/cancel")
        self.server.wait_status(job_id, TERMINAL, timeout=10)

    # --- cache reuse and idempotency --------------------------------------------------
    def test_identical_spec_reuses_result_unless_fresh(self):
        spec = tiny(name="cache", loading={"shear_stress": 0.0104})
        first = self.run_tiny(**{k: v for k, v in spec.items() if k not in TINY})
        self.assertEqual(first["status"], "succeeded")
        r = self.server.submit(dict(spec, name="cache-again", tags=["other"]))
        self.assertEqual(r.status_code, 201, r.text)
        again = r.json()
        self.assertTrue(again["reused"])
        self.assertEqual(again["cache"], "hit")
        self.assertEqual(again["cached_from"], first["id"])
        self.assertEqual(again["status"], "succeeded")
        self.assertEqual(again["name"], "cache-again")
        self.assertEqual(again["metrics"], first["metrics"])
        self.assertEqual(again["result"]["sha256"], first["result"]["sha256"])
        self.assertEqual(self.server.get(again["result"]["url"]).status_code, 200)
        # Fresh runs: by query or by body.
        r = self.server.submit(spec, params={"fresh": "true"})
        self.assertEqual(r.status_code, 201)
        self.assertFalse(r.json()["reused"])
        self.assertIsNone(r.json()["cached_from"])
        r2 = self.server.submit(dict(spec, fresh=True))
        self.assertEqual(r2.status_code, 201)
        self.assertFalse(r2.json()["reused"])
        for j in (r.json(), r2.json()):
            self.assertEqual(self.server.wait_status(j["id"], TERMINAL)["status"], "succeeded")

    def assertFileSampling(self, job, interval, stride=1):
        """The job's HDF5 file (downloaded over HTTP) says and has this output sampling."""
        r = self.server.get(job["result"]["url"])
        self.assertEqual(r.status_code, 200, r.content[:300])
        with tempfile.NamedTemporaryFile(suffix=".h5") as f:
            f.write(r.content)
            f.flush()
            with h5py.File(f.name, "r") as h5:
                spec = json.loads(h5.attrs["spec"])
                self.assertEqual(spec["output"]["interval"], interval)
                self.assertEqual(spec["output"]["space_stride"], stride)
                group = h5["interface"]
                self.assertAlmostEqual(float(group.attrs["sample_interval"]), interval,
                                       delta=0.5 * interval)
                t = np.asarray(group["time"])
                self.assertAlmostEqual(float(np.median(np.diff(t))),
                                       float(group.attrs["sample_interval"]), places=9)

    def test_cache_hit_only_with_the_same_output_settings(self):
        # Output settings are not physics (same spec_sha256), but the
        # file holds them; a job asking for another sampling must not get another job's file.
        physics = {"loading": {"shear_stress": 0.01015}}
        fine = self.run_tiny(name="out-fine", output={"interval": 0.05}, **physics)
        self.assertEqual(fine["status"], "succeeded", fine)
        self.assertFileSampling(fine, 0.05)

        r = self.server.submit(tiny(name="out-coarse", output={"interval": 0.2}, **physics))
        self.assertEqual(r.status_code, 201, r.text)
        coarse = r.json()
        self.assertEqual(coarse["spec_sha256"], fine["spec_sha256"])  # same physics
        self.assertEqual(coarse["cache"], "miss")
        self.assertFalse(coarse["reused"])
        self.assertIsNone(coarse["cached_from"])
        coarse = self.server.wait_status(coarse["id"], TERMINAL)
        self.assertEqual(coarse["status"], "succeeded", coarse)
        self.assertIsNone(coarse["cached_from"])
        self.assertEqual(coarse["spec"]["output"]["interval"], 0.2)
        self.assertNotEqual(coarse["result"]["sha256"], fine["result"]["sha256"])
        self.assertFileSampling(coarse, 0.2)
        # The listing says the same as the job.
        listed = self.server.get(JOBS, params={"spec_sha256": fine["spec_sha256"],
                                               "fields": "id,spec,cached_from,result"}).json()
        by_id = {j["id"]: j for j in listed["jobs"]}
        self.assertEqual(by_id[coarse["id"]]["spec"]["output"]["interval"], 0.2)
        self.assertIsNone(by_id[coarse["id"]]["cached_from"])
        self.assertEqual(by_id[coarse["id"]]["result"]["sha256"], coarse["result"]["sha256"])

        # Same physics and same output (key order, explicit defaults): a hit of that job.
        for output, source in (({"space_stride": 1, "interval": 0.2}, coarse),
                               ({"interval": 0.05}, fine)):
            r = self.server.submit(tiny(name="out-again", output=output, **physics))
            self.assertEqual(r.status_code, 201, r.text)
            hit = r.json()
            self.assertEqual(hit["cache"], "hit")
            self.assertEqual(hit["cached_from"], source["id"])
            self.assertEqual(hit["result"]["sha256"], source["result"]["sha256"])
            self.assertFileSampling(hit, source["spec"]["output"]["interval"])
        # Another stride is another file too.
        r = self.server.submit(tiny(name="out-stride", output={"interval": 0.2, "space_stride": 2},
                                    **physics))
        self.assertEqual(r.status_code, 201, r.text)
        self.assertEqual(r.json()["cache"], "miss")
        strided = self.server.wait_status(r.json()["id"], TERMINAL)
        self.assertEqual(strided["status"], "succeeded", strided)
        self.assertFileSampling(strided, 0.2, stride=2)

    def test_idempotency_key(self):
        spec = tiny(name="idem", loading={"shear_stress": 0.0103})
        h = {"Idempotency-Key": "retry-me-1"}
        r1 = self.server.submit(spec, headers=h, params={"fresh": "true"})
        self.assertEqual(r1.status_code, 201, r1.text)
        r2 = self.server.submit(spec, headers=h, params={"fresh": "true"})
        self.assertEqual(r2.status_code, 200, r2.text)
        self.assertEqual(r2.json()["id"], r1.json()["id"])
        self.assertEqual(r2.headers["Location"], r1.headers["Location"])
        other = tiny(name="idem", loading={"shear_stress": 0.0102})
        self.assertProblem(self.server.submit(other, headers=h), 422)
        self.server.wait_status(r1.json()["id"], TERMINAL)

    def test_idempotency_key_compares_the_whole_request(self):
        """Before: another output.interval or other tags with the same key replayed the first
        job (200), though the docs say the same key with another spec is 422."""
        spec = tiny(name="idem-whole", tags=["a"], output={"interval": 0.05})
        h = {"Idempotency-Key": "retry-me-whole"}
        r1 = self.server.submit(spec, headers=h)
        self.assertEqual(r1.status_code, 201, r1.text)
        for changed in (dict(spec, output={"interval": 0.1}), dict(spec, tags=["b"]),
                        dict(spec, name="idem-other")):
            r = self.server.submit(changed, headers=h)
            self.assertProblem(r, 422)
            self.assertIn(r1.json()["id"], r.json()["detail"])
        for params in ({"priority": "5"}, {"fresh": "true"}):
            self.assertProblem(self.server.submit(spec, headers=h, params=params), 422)
        # The same request again, its keys in another order: a replay.
        r2 = self.server.submit(dict(reversed(list(spec.items()))), headers=h)
        self.assertEqual(r2.status_code, 200, r2.text)
        self.assertEqual(r2.json()["id"], r1.json()["id"])
        self.server.wait_status(r1.json()["id"], TERMINAL)

    # --- listing ----------------------------------------------------------------------
    def test_list_filters_and_pagination(self):
        ids = []
        for i, (L, nd) in enumerate([(1e-5, 5), (5e-5, 5), (1e-4, 6), (5e-4, 6), (1e-3, 7)]):
            spec = tiny(name=f"sweep-{i % 2}", tags=["list-test", f"L{L}"],
                        friction={"L": L}, geometry={"nodes_per_meter": nd})
            r = self.server.submit(spec, params={"fresh": "true"})
            self.assertEqual(r.status_code, 201, r.text)
            ids.append(r.json()["id"])
        for job_id in ids:
            self.server.wait_status(job_id, TERMINAL)

        def listing(**params):
            r = self.server.get(JOBS, params=params)
            self.assertEqual(r.status_code, 200, r.text)
            return r.json()

        got = listing(tag="list-test")
        self.assertEqual([j["id"] for j in got["jobs"]], ids[::-1])  # newest first
        self.assertEqual(len(listing(tag="list-test", name="sweep-0")["jobs"]), 3)
        self.assertEqual({j["id"] for j in listing(tag="list-test", L_min=5e-5, L_max=5e-4)["jobs"]},
                         set(ids[1:4]))
        self.assertEqual({j["id"] for j in listing(tag="list-test", n_d_min=6, n_d_max=6)["jobs"]},
                         set(ids[2:4]))
        self.assertEqual(len(listing(tag="list-test", status="succeeded")["jobs"]), 5)
        self.assertEqual(len(listing(tag="list-test", status="queued,running")["jobs"]), 0)
        outcomes = {j["metrics"]["outcome"] for j in got["jobs"]}
        for outcome in outcomes:
            n = sum(j["metrics"]["outcome"] == outcome for j in got["jobs"])
            self.assertEqual(len(listing(tag="list-test", outcome=outcome)["jobs"]), n)
        # Projection keeps listings small.
        small = listing(tag="list-test", fields="id,status")
        for j in small["jobs"]:
            self.assertEqual(set(j), {"id", "status"})
        # Cursor pagination walks every job once.
        seen, cursor, pages = [], None, 0
        while pages < 10:
            params = {"tag": "list-test", "limit": 2, "fields": "id"}
            if cursor:
                params["cursor"] = cursor
            page = listing(**params)
            seen += [j["id"] for j in page["jobs"]]
            if page["next"]:
                self.assertIn("tag=list-test", page["next"])
            pages += 1
            cursor = page["next_cursor"]
            if not cursor:
                break
        self.assertEqual(seen, ids[::-1])
        self.assertEqual(pages, 3)
        # Bad query parameters are 400 naming each one.
        r = self.server.get(JOBS, params={"limit": "0", "status": "done", "L_min": "x", "bogus": 1})
        body = self.assertProblem(r, 400)
        pointers = {e["pointer"] for e in body["errors"]}
        self.assertEqual(pointers, {"/query/limit", "/query/status", "/query/L_min", "/query/bogus"})

    # --- error paths ------------------------------------------------------------------
    def test_unparseable_json_is_400(self):
        r = self.server.post(JOBS, data=b'{"geometry": ', headers={"Content-Type": "application/json"})
        body = self.assertProblem(r, 400)
        self.assertEqual(body["errors"][0]["pointer"], "")

    def test_invalid_spec_is_422_with_pointers(self):
        spec = {"material": {"poisson_ratio": 0.7}, "geometry": {"nodes_per_meter": -3},
                "bogus": 1, "priority": "high"}
        body = self.assertProblem(self.server.submit(spec), 422)
        pointers = {e["pointer"] for e in body["errors"]}
        for p in ["/material/poisson_ratio", "/geometry/nodes_per_meter", "/bogus", "/priority"]:
            self.assertIn(p, pointers)
        for e in body["errors"]:
            self.assertTrue(e["reason"])
        self.assertProblem(self.server.submit([1, 2]), 422)
        # A priority past 64 bits is refused, not wrapped into the range (2^64 - 1 was -1).
        for huge in (18446744073709551615, 9223372036854775808):
            body = self.assertProblem(self.server.submit({"priority": huge}), 422)
            self.assertIn("/priority", {e["pointer"] for e in body["errors"]})

    def test_memory_estimate_above_limit_is_422(self):
        body = self.assertProblem(self.server.submit({"geometry": {"nodes_per_meter": 400}}), 422)
        self.assertTrue(any("memory" in e["reason"].lower() for e in body["errors"]), body)

    def test_unknown_and_malformed_ids_are_404(self):
        self.assertProblem(self.server.get(f"{JOBS}/{'0' * 32}"), 404)
        self.assertProblem(self.server.post(f"{JOBS}/{'0' * 32}/cancel"), 404)
        for bad in ["..%2F..%2Fetc%2Fpasswd", "ABCDEF0123456789ABCDEF0123456789",
                    "0" * 31, "0" * 33, "%00" + "0" * 29, "results", "..", "~root"]:
            for tail in ("", "/result.h5", "/metrics", "/front"):
                r = self.server.get(f"{JOBS}/{bad}{tail}")
                self.assertIn(r.status_code, (404,), (bad, tail, r.text))
        # A real traversal attempt on the raw wire (no client-side normalisation).
        reply = raw_http(self.server, b"GET /api/v1/jobs/../../../../etc/passwd/result.h5 HTTP/1.1\r\n"
                                      b"Host: x\r\nConnection: close\r\n\r\n")
        self.assertTrue(reply.startswith(b"HTTP/1.1 404"), reply[:200])
        self.assertNotIn(b"root:", reply)

    def test_body_over_limit_is_413(self):
        big = json.dumps({"name": "x" * 200000})
        r = self.server.post(JOBS, data=big, headers={"Content-Type": "application/json"})
        self.assertProblem(r, 413)
        self.assertEqual(self.server.get("/healthz").status_code, 200)

    def test_method_not_allowed_is_405(self):
        r = self.server.session.delete(self.server.url(JOBS), timeout=10)
        self.assertProblem(r, 405)
        self.assertIn("GET", r.headers["Allow"])

    def test_malformed_requests_get_4xx_and_server_goes_on(self):
        for payload in [b"GARBAGE\r\n\r\n", b"GET / HTTP/9.9\r\n\r\n",
                        b"GET /healthz HTTP/1.1\r\nContent-Length: nope\r\n\r\n",
                        b"GET /healthz HTTP/1.1\r\n" + b"X-Big: " + b"a" * 40000 + b"\r\n\r\n",
                        b"POST /api/v1/jobs HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\n\r\nzz\r\n"]:
            reply = raw_http(self.server, payload)
            self.assertRegex(reply[:12], rb"^HTTP/1\.1 4\d\d", payload[:40])
        self.assertEqual(self.server.get("/healthz").status_code, 200)

    def test_slow_and_idle_connections_time_out(self):
        # Half a request, then nothing: 408 after the 2 s request timeout, then closed.
        t0 = time.monotonic()
        reply = raw_http(self.server, b"GET /healthz HTTP/1.1\r\nHost: x\r\n", timeout=8)
        self.assertTrue(reply.startswith(b"HTTP/1.1 408"), reply[:100])
        self.assertLess(time.monotonic() - t0, 6)
        # An idle connection is closed.
        t0 = time.monotonic()
        reply = raw_http(self.server, b"", timeout=8)
        self.assertEqual(reply, b"")
        self.assertLess(time.monotonic() - t0, 6)
        self.assertEqual(self.server.get("/healthz").status_code, 200)

    def test_keep_alive(self):
        reply = raw_http(self.server, b"GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n"
                                      b"GET /healthz HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
        self.assertEqual(reply.count(b"HTTP/1.1 200"), 2)


class OneWorkerServer(unittest.TestCase):
    """One worker and a queue of two: cancel (queued and running), progress, queue full,
    responsiveness while the worker is busy."""

    @classmethod
    def setUpClass(cls):
        cls.server = Server(BINARY, args=["--workers", "1", "--queue-limit", "2",
                                          "--retry-after-s", "7"]).start()

    @classmethod
    def tearDownClass(cls):
        code = cls.server.terminate()
        cls.server.cleanup()
        assert code == 0, f"server exit code {code}"

    def test_cancel_progress_queue_full(self):
        s = self.server
        running = s.submit(long_job("busy"))
        self.assertEqual(running.status_code, 201, running.text)
        running_id = running.json()["id"]
        job = s.wait_status(running_id, {"running"}, timeout=10)

        # Progress moves and is refreshed at least every second while running.
        stamps, fractions = set(), []
        t_end = time.monotonic() + 2.5
        while time.monotonic() < t_end:
            t0 = time.monotonic()
            job = s.get(f"{JOBS}/{running_id}").json()
            self.assertLess(time.monotonic() - t0, 0.5, "status poll blocked by a running job")
            if job["status"] != "running":
                break
            stamps.add(job["progress"]["updated_at"])
            fractions.append(job["progress"]["fraction"])
            time.sleep(0.2)
        self.assertEqual(job["status"], "running", "the long job finished too early for this test")
        self.assertGreaterEqual(len(stamps), 2)
        self.assertGreater(fractions[-1], fractions[0])
        self.assertGreater(job["progress"]["steps"], 0)
        self.assertIsNotNone(job["progress"]["eta_s"])
        self.assertGreater(job["progress"]["duration"], 0)

        # Two queued jobs fill the queue; the third is 503 with Retry-After.
        q1 = s.submit(long_job("queued-1"))
        q2 = s.submit(long_job("queued-2"), params={"priority": "5"})
        self.assertEqual((q1.status_code, q2.status_code), (201, 201))
        full = s.submit(long_job("one-too-many"))
        self.assertEqual(full.status_code, 503, full.text)
        self.assertEqual(full.headers["Retry-After"], "7")
        self.assertTrue(full.headers["Content-Type"].startswith("application/problem+json"))

        # Cancel a queued job: at once.
        r = s.post(f"{JOBS}/{q1.json()['id']}/cancel")
        self.assertEqual(r.status_code, 200, r.text)
        self.assertEqual(r.json()["status"], "cancelled")
        self.assertProblem409(s.post(f"{JOBS}/{q1.json()['id']}/cancel"))
        # Room again.
        q3 = s.submit(long_job("queued-3"))
        self.assertEqual(q3.status_code, 201, q3.text)

        # Cancel the running job: it stops within about a second.
        t0 = time.monotonic()
        r = s.post(f"{JOBS}/{running_id}/cancel")
        self.assertEqual(r.status_code, 202, r.text)
        self.assertTrue(r.json()["cancel_requested"])
        done = s.wait_status(running_id, TERMINAL, timeout=5, interval=0.02)
        self.assertLess(time.monotonic() - t0, 1.5)
        self.assertEqual(done["status"], "cancelled")
        self.assertIsNone(done["result"])
        self.assertIn("cancelled", done["error"])

        # The worker moves on to the higher-priority queued job first.
        nxt = s.wait_status(q2.json()["id"], {"running"} | TERMINAL, timeout=10)
        self.assertEqual(nxt["status"], "running")
        self.assertEqual(s.get(f"{JOBS}/{q3.json()['id']}").json()["status"], "queued")
        for job_id in (q2.json()["id"], q3.json()["id"]):
            r = s.post(f"{JOBS}/{job_id}/cancel")
            self.assertIn(r.status_code, (200, 202), r.text)
        for job_id in (q2.json()["id"], q3.json()["id"]):
            self.assertEqual(s.wait_status(job_id, TERMINAL, timeout=5)["status"], "cancelled")

    def assertProblem409(self, r):
        self.assertEqual(r.status_code, 409, r.text)
        self.assertTrue(r.headers["Content-Type"].startswith("application/problem+json"))


class AuthServer(unittest.TestCase):
    """--token-file: submitting and cancelling need a bearer token; users cancel their own."""

    @classmethod
    def setUpClass(cls):
        cls.tokens = tempfile.NamedTemporaryFile("w", suffix=".tokens", delete=False)
        cls.tokens.write("# user:token\nalice:alice-secret-token\nbob:bob-secret-token\n")
        cls.tokens.close()
        cls.server = Server(BINARY, args=["--workers", "1", "--token-file", cls.tokens.name]).start()

    @classmethod
    def tearDownClass(cls):
        code = cls.server.terminate()
        cls.server.cleanup()
        os.unlink(cls.tokens.name)
        assert code == 0, f"server exit code {code}"

    def test_tokens(self):
        s = self.server
        alice = {"Authorization": "Bearer alice-secret-token"}
        bob = {"Authorization": "Bearer bob-secret-token"}
        r = s.submit(tiny())
        self.assertEqual(r.status_code, 401)
        self.assertIn("Bearer", r.headers["WWW-Authenticate"])
        self.assertEqual(s.submit(tiny(), headers={"Authorization": "Bearer wrong-token"}).status_code, 401)
        r = s.submit(long_job("alice's"), headers=alice)
        self.assertEqual(r.status_code, 201, r.text)
        job = r.json()
        self.assertEqual(job["submitted_by"], "alice")
        # Reading is open.
        self.assertEqual(s.get(f"{JOBS}/{job['id']}").status_code, 200)
        self.assertEqual(s.get(JOBS).status_code, 200)
        # Cancelling: 401 without a token, 403 for another user, OK for the owner.
        self.assertEqual(s.post(f"{JOBS}/{job['id']}/cancel").status_code, 401)
        r = s.post(f"{JOBS}/{job['id']}/cancel", headers=bob)
        self.assertEqual(r.status_code, 403, r.text)
        self.assertTrue(r.headers["Content-Type"].startswith("application/problem+json"))
        r = s.post(f"{JOBS}/{job['id']}/cancel", headers=alice)
        self.assertIn(r.status_code, (200, 202), r.text)
        self.assertEqual(s.wait_status(job["id"], TERMINAL, timeout=5)["status"], "cancelled")
        # The listing filters by submitter.
        mine = s.get(JOBS, params={"submitted_by": "alice"}).json()["jobs"]
        self.assertEqual([j["id"] for j in mine], [job["id"]])


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

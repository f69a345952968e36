"""Hostile input against a live server over loopback: every bad request gets its
4xx naming the field, never a 5xx or the JSON library's own messages, changes nothing, and
the server still answers /healthz afterwards.

    /usr/bin/python3 tests/server/test_hostile.py --binary build/slipfront
"""

import argparse
import json
import os
import re
import sys
import unittest
from urllib.parse import urlparse

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import TINY, Server  # noqa: E402

BINARY = None
JOBS = "/api/v1/jobs"
STUDIES = "/api/v1/studies"
LIBRARY_WORDS = ("json.exception", "parse_error", "out_of_range", "type_error", "[json")


# Paths of the API with their OpenAPI template: /api/v1/jobs/<anything>/front -> .../{id}/front.
TEMPLATES = [
    (re.compile(r"^/api/v1/(jobs|studies)/[^/]+$"), r"/api/v1/\1/{id}"),
    (re.compile(r"^/api/v1/(jobs|studies)/[^/]+/([^/]+)$"), r"/api/v1/\1/{id}/\2"),
]


def path_template(path):
    for pattern, template in TEMPLATES:
        if pattern.match(path):
            return pattern.sub(template, path)
    return path


def undocumented_answers(document, answers):
    """The (method, template, status) answered that the OpenAPI document does not list for
    that operation (an answer of a method that is no operation must be 405). HEAD answers as
    GET does (the document's description says so)."""
    missing = set()
    for method, path, status in answers:
        operations = document["paths"].get(path)
        if operations is None:
            continue  # not a path of the API (e.g. /api/v1/nothing): its 404 is generic
        operation = operations.get("get" if method == "HEAD" else method.lower())
        if operation is None:
            if status != 405:
                missing.add((method, path, status))
            continue
        if str(status) not in operation["responses"]:
            missing.add((method, path, status))
    return sorted(missing)


def nested(levels, inner="1"):
    return "[" * levels + inner + "]" * levels


def nested_objects(levels):
    return '{"a":' * levels + "1" + "}" * levels


class HostileInput(unittest.TestCase):
    """One open server (no auth); each case checks the answer, then that nothing changed
    and the server is alive."""

    @classmethod
    def setUpClass(cls):
        cls.server = Server(BINARY, args=["--workers", "1", "--queue-limit", "20",
                                          "--request-timeout-s", "5"]).start()
        # Every answer of the suite, to hold against the OpenAPI document at the end.
        cls.answers = set()

        def record(response, *args, **kwargs):
            path = path_template(urlparse(response.request.url).path)
            cls.answers.add((response.request.method, path, response.status_code))
        cls.server.session.hooks["response"].append(record)
        # One real job so that listings and result paths have something to walk.
        r = cls.server.submit(dict(TINY, name="hostile-seed"))
        assert r.status_code == 201, r.text
        cls.seed = cls.server.wait_status(r.json()["id"], {"succeeded"}, timeout=60)

    @classmethod
    def tearDownClass(cls):
        # Over the whole suite: how many answers were 4xx, and not one 5xx.
        codes = {}
        for line in cls.server.get("/metrics").text.splitlines():
            m = re.match(r'slipfront_http_requests_total\{code="(\d+)"\} (\d+)', line)
            if m:
                codes[int(m.group(1))] = int(m.group(2))
        client = sum(n for c, n in codes.items() if 400 <= c < 500)
        server = sum(n for c, n in codes.items() if c >= 500)
        print(f"hostile suite: {client} answers 4xx, {server} answers 5xx", file=sys.stderr)
        # Every status answered on a path of the API is in the OpenAPI document.
        document = cls.server.get("/api/v1/openapi.json").json()
        missing = undocumented_answers(document, cls.answers)
        print(f"hostile suite: {len(cls.answers)} distinct (method, path, status) answers, "
              f"{len(missing)} not in the OpenAPI document", file=sys.stderr)
        code = cls.server.terminate()
        cls.server.cleanup()
        assert code == 0, f"server exit code {code}"
        assert server == 0, f"{server} answers were 5xx: {codes}"
        assert not missing, f"answers missing from the OpenAPI document: {missing}"

    def counts(self):
        jobs = self.server.get(JOBS, params={"limit": 1000, "fields": "id"}).json()["count"]
        studies = len(self.server.get(STUDIES).json()["studies"])
        return jobs, studies

    def setUp(self):
        self.before = self.counts()

    def tearDown(self):
        r = self.server.get("/healthz")
        self.assertEqual(r.status_code, 200, r.text)
        if self.before is not None:  # None: a test that creates jobs on purpose
            self.assertEqual(self.counts(), self.before, "a rejected request changed the state")

    def assertRejected(self, r, status, pointer=None):
        self.assertEqual(r.status_code, status, r.text)
        self.assertTrue(r.headers["Content-Type"].startswith("application/problem+json"))
        for word in LIBRARY_WORDS:
            self.assertNotIn(word, r.text)
        body = r.json()
        if pointer is not None:
            pointers = [e["pointer"] for e in body.get("errors", [])]
            self.assertIn(pointer, pointers, body)
        return body

    def post_raw(self, path, text):
        return self.server.post(path, data=text.encode(),
                                headers={"Content-Type": "application/json"}, timeout=30)

    # --- nesting depth, shared by every endpoint that parses a body --------------------
    def test_deep_array_to_studies_is_422_not_a_crash(self):
        self.assertRejected(self.post_raw(STUDIES, nested(60000)), 422)
        self.assertRejected(self.post_raw(STUDIES, '{"tags": ' + nested(60000) + "}"), 422)

    def test_deep_array_to_jobs_is_422(self):
        self.assertRejected(self.post_raw(JOBS, nested(60000)), 422)

    def test_deep_objects_to_studies_and_jobs(self):
        for path in (STUDIES, JOBS):
            self.assertRejected(self.post_raw(path, nested_objects(60000)), 422)

    def test_deep_value_inside_a_field_is_named(self):
        body = '{"name": "x", "base": {"name": ' + nested(100) + "}}"
        b = self.assertRejected(self.post_raw(STUDIES, body), 422)
        self.assertTrue(b["errors"][0]["pointer"].startswith("/base/name/0/0"), b)
        body = '{"tags": ' + nested(100) + "}"
        b = self.assertRejected(self.post_raw(JOBS, body), 422)
        self.assertTrue(b["errors"][0]["pointer"].startswith("/tags/0/0"), b)

    def test_deep_but_allowed_nesting_gets_the_ordinary_answer(self):
        # 20 levels is within the bound: the validator answers for the field.
        b = self.assertRejected(self.post_raw(JOBS, '{"tags": ' + nested(20) + "}"), 422)
        self.assertIn("/tags/0", [e["pointer"] for e in b["errors"]])

    # --- numbers beyond a double, non-finite filters, library messages -----------------
    def test_number_overflow_in_job_names_the_field(self):
        cases = [
            ('{"time": {"duration": 1e999}}', "/time/duration"),
            ('{"material": {"density": -1e999}}', "/material/density"),
            ('{"geometry": {"nodes_per_meter": 5, "height": 1E+400}}', "/geometry/height"),
            ('{"tags": ["a", 1e999]}', "/tags/1"),
            ('{"unknown": {"x/y": [0, 1e999]}}', "/unknown/x~1y/1"),
            ("1e999", ""),
            ('{"priority": 1e999}', "/priority"),
        ]
        for text, pointer in cases:
            with self.subTest(text=text):
                self.assertRejected(self.post_raw(JOBS, text), 422, pointer)

    def test_number_overflow_in_study_names_the_field(self):
        cases = [
            ('{"grid": {"L": [1e-5, 1e999], "n_d": [10]}}', "/grid/L/1"),
            ('{"grid": {"L": [1e-5], "n_d": [10]}, "base": {"time": {"duration": 1e999}}}',
             "/base/time/duration"),
            ('{"convergence": {"L": [1e-5], "n_d_max": 1e999}}', "/convergence/n_d_max"),
        ]
        for text, pointer in cases:
            with self.subTest(text=text):
                self.assertRejected(self.post_raw(STUDIES, text), 422, pointer)

    def test_long_non_ascii_values_in_error_messages(self):
        # Found by the fuzzer: the value quoted in an error is cut to 40 bytes; a cut inside
        # a UTF-8 character made the message itself fail (500).
        value = "a" * 39 + "\u00e9" * 5
        for body, pointer in (({"friction": {"law": value}}, "/friction/law"),
                              ({"method": value}, "/method")):
            b = self.assertRejected(self.post_raw(JOBS, json.dumps(body)), 422, pointer)
            self.assertIn("a" * 39 + '"...', b["errors"][0]["reason"])
        self.assertRejected(self.post_raw(STUDIES, json.dumps({"base": {"friction": {"law": value}}})),
                            422)

    def test_a_long_preset_name_is_cut_in_its_error(self):
        # Before: a 100 kB "preset" came back whole in a 100 kB 422.
        r = self.post_raw(JOBS, json.dumps({"preset": "p" * 100_000}))
        b = self.assertRejected(r, 422, "/preset")
        self.assertIn('no preset is called "' + "p" * 40 + '"...', b["errors"][0]["reason"])
        self.assertLess(len(r.content), 2000)

    def test_syntax_errors_are_400_in_our_words(self):
        for path in (JOBS, STUDIES):
            for text in ("{", "[1,]", '{"a" 1}', "nul", '"\\uZZZZ"', "\xff", ""):
                with self.subTest(path=path, text=text):
                    b = self.assertRejected(self.post_raw(path, text), 400)
                    self.assertIn("not valid JSON", json.dumps(b))

    def test_non_finite_query_filters_are_rejected(self):
        for key in ("L_min", "L_max", "n_d_min", "n_d_max"):
            for value in ("nan", "NaN", "inf", "-inf", "infinity", "1e999"):
                with self.subTest(key=key, value=value):
                    self.assertRejected(self.server.get(JOBS, params={key: value}), 400,
                                        "/query/" + key)

    # --- a result file of hundreds of GB is refused at validation -----------------------
    def test_result_size_limit_names_the_interval(self):
        body = {"output": {"interval": 1e-6}, "time": {"duration": 3000.0}}  # ~55 GB
        b = self.assertRejected(self.server.submit(body), 422, "/output/interval")
        self.assertIn("result file would hold about", json.dumps(b))
        study = {"grid": {"L": [5e-5], "n_d": [40]}, "base": body}
        self.assertRejected(self.server.post(STUDIES, json=study), 422, "/base/output/interval")

    # --- a result file deleted behind the server's back -----------------------------------
    def test_deleted_result_file_is_410_and_never_reused(self):
        self.before = None
        spec = dict(TINY, name="to-delete", loading={"shear_stress": 0.01041})
        r = self.server.submit(spec)
        self.assertEqual(r.status_code, 201, r.text)
        first = self.server.wait_status(r.json()["id"], {"succeeded"}, timeout=60)
        os.remove(os.path.join(self.server.data_dir, "results", first["id"] + ".h5"))
        b = self.assertRejected(self.server.get(first["result"]["url"]), 410)
        self.assertIn("no longer on the server", b["detail"])
        # An identical job is not pointed at the missing file: it runs again.
        r = self.server.submit(dict(spec, name="to-delete-again"))
        self.assertEqual(r.status_code, 201, r.text)
        self.assertNotEqual(r.json()["cache"], "hit", r.json())
        again = self.server.wait_status(r.json()["id"], {"succeeded"}, timeout=60)
        self.assertEqual(self.server.get(again["result"]["url"]).status_code, 200)

    # --- HEAD, log lines ------------------------------------------------------------------
    def test_head_answers_like_get_without_the_body(self):
        seed = self.seed["id"]
        for path in ["/healthz", "/metrics", "/api/v1/openapi.json", JOBS, f"{JOBS}/{seed}",
                     f"{JOBS}/{seed}/result.h5", f"{JOBS}/{seed}/metrics", f"{JOBS}/{seed}/front",
                     STUDIES, f"{JOBS}/{'0' * 32}", "/nowhere"]:
            with self.subTest(path=path):
                get = self.server.get(path)
                head = self.server.session.head(self.server.url(path), timeout=10)
                self.assertEqual(head.status_code, get.status_code)
                self.assertEqual(head.content, b"")
                self.assertEqual(head.headers.get("Content-Type"), get.headers.get("Content-Type"))
                if path.endswith("result.h5"):
                    self.assertEqual(int(head.headers["Content-Length"]), len(get.content))
                    self.assertEqual(head.headers["ETag"], get.headers["ETag"])
        # The connection is still in step after HEAD answers (keep-alive).
        self.assertEqual(self.server.get("/healthz").status_code, 200)

    def test_control_characters_in_names_and_tags_are_refused(self):
        # Such a name once went into a SLURM batch script (and a log line).
        # Free text anywhere a client sends it: no C0, DEL, C1, U+2028/U+2029.
        forged = "x\n2026-01-01T00:00:00Z error FORGED\r\x1b[2J"
        grid = {"grid": {"L": [1e-4], "n_d": [5]}, "base": {"time": {"duration": 2.0}}}
        cases = [
            (JOBS, dict(TINY, name=forged), "/name"),
            (JOBS, dict(TINY, name="x)\nid > FILE\n# ("), "/name"),
            (JOBS, dict(TINY, name="a\u2028b"), "/name"),
            (JOBS, dict(TINY, name="a\u0085b"), "/name"),
            (JOBS, dict(TINY, tags=["ok", "bad\ttag"]), "/tags/1"),
            (STUDIES, dict(grid, name=forged), "/name"),
            (STUDIES, dict(grid, tags=["\x7f"]), "/tags/0"),
            (STUDIES, dict(grid, base={"name": "x\n#SBATCH --wrap=id"}), "/base/name"),
        ]
        for path, body, pointer in cases:
            with self.subTest(path=path, body=body):
                b = self.assertRejected(self.server.post(path, json=body), 422, pointer)
                self.assertIn("must not contain control characters", json.dumps(b))
        for line in self.server.read_log().splitlines():
            self.assertNotIn("FORGED", line)
            self.assertNotIn("\x1b", line)

    # --- jobs whose fields imply an impossible run ------------------------------------
    def test_impossible_runs_are_422_naming_the_field(self):
        bi = {"method": "spectral_bi"}
        cases = [
            (dict(bi, spectral_bi={"time_step_factor": 1e-300}), "/spectral_bi/time_step_factor"),
            ({"time": {"duration": 1e19}}, "/time/duration"),
            (dict(bi, time={"duration": 1e19}), "/time/duration"),
            ({"material": {"young_modulus": 1e300}}, "/material/young_modulus"),
            ({"material": {"density": 5e-324}}, "/material/density"),
            (dict(bi, material={"density": 5e-324}), "/material/density"),
            ({"material": {"density": 1.7e308}}, "/material/density"),
        ]
        for body, pointer in cases:
            with self.subTest(body=body):
                self.assertRejected(self.server.submit(body), 422, pointer)
        # The convergence study of the issue, which reported L_c = 1e-4 from runs of 0 steps.
        study = {"convergence": {"L": [5e-5, 1e-4], "n_d": [5, 10]},
                 "base": dict(bi, spectral_bi={"time_step_factor": 1e-300})}
        self.assertRejected(self.server.post(STUDIES, json=study), 422,
                            "/base/spectral_bi/time_step_factor")

    # --- search expressions too long for SQLite -------------------------------------------
    def test_long_search_expressions_are_400_naming_the_limit(self):
        where = ";".join(f"L>{i}" for i in range(1100))  # 1,100 terms in 12 kB
        b = self.assertRejected(self.server.get(JOBS, params={"where": where}), 400,
                                "/query/where")
        self.assertIn("at most 64 conditions", json.dumps(b))
        sort = ",".join(["n_d", "-L"] * 1050)  # 2,100 keys in 12 kB (the header limit: 16)
        b = self.assertRejected(self.server.get(JOBS, params={"sort": sort}), 400, "/query/sort")
        self.assertIn("at most 16 keys", json.dumps(b))
        # At the limits the search still answers.
        ok = self.server.get(JOBS, params={"where": ";".join(["friction.L>0"] * 64),
                                           "sort": ",".join(["friction.L"] * 16)})
        self.assertEqual(ok.status_code, 200, ok.text[:300])
        # No statement of tens of kB in the log (before: 30-100 KB of SQL per request).
        longest = max(len(line) for line in self.server.read_log().splitlines())
        self.assertLess(longest, 4000)

    # --- an error body never amplifies its request -------------------------------------
    def test_error_bodies_list_at_most_100_errors(self):
        body = {f"u{i}": 0 for i in range(90000)}
        text = json.dumps(body, separators=(",", ":"))
        self.assertLess(len(text), 1 << 20)
        r = self.post_raw(JOBS, text)
        b = self.assertRejected(r, 422)
        self.assertEqual(len(b["errors"]), 100)
        self.assertIn("and 89900 more", b["detail"])
        self.assertLess(len(r.content), 64 * 1024)
        study = {"grid": {"L": [1e-5], "n_d": [10]}, **{f"x{i}": 0 for i in range(5000)}}
        b = self.assertRejected(self.server.post(STUDIES, json=study), 422)
        self.assertEqual(len(b["errors"]), 100)
        self.assertIn("and 4900 more", b["detail"])

    # --- study tags and absolute-form request targets ----------------------------------
    def test_study_tags_errors_point_at_what_the_client_sent(self):
        grid = {"grid": {"L": [1e-4], "n_d": [5]}, "base": {"time": {"duration": 2.0}}}
        # 31 of the study's own tags fit (its runs carry one more: study:<id>); 32 do not.
        b = self.assertRejected(self.server.post(STUDIES, json=dict(
            grid, tags=[f"t{i}" for i in range(32)])), 422, "/tags")
        self.assertIn("at most 31 tags", json.dumps(b))
        b = self.assertRejected(self.server.post(STUDIES, json=dict(
            grid, tags=["a", "b"], base=dict(grid["base"], tags=[f"b{i}" for i in range(30)]))),
            422, "/tags")
        self.assertIn("30 in /base/tags", json.dumps(b))
        pointers = lambda body: [e["pointer"] for e in body["errors"]]  # noqa: E731
        b = self.assertRejected(self.server.post(STUDIES, json=dict(grid, tags=["ok", ""])),
                                422, "/tags/1")
        self.assertNotIn("/base/tags", pointers(b))
        b = self.assertRejected(self.server.post(STUDIES, json=dict(
            grid, base=dict(grid["base"], tags=["x" * 1000]))), 422, "/base/tags/0")
        self.assertNotIn("/tags/0", pointers(b))

    def test_absolute_form_request_target_is_accepted(self):
        import socket
        host, port = self.server.base[len("http://"):].split(":")
        for target in (f"http://{host}:{port}/healthz", f"HTTP://{host}:{port}/healthz?x=1",
                       f"http://{host}:{port}/api/v1/jobs/{self.seed['id']}"):
            with self.subTest(target=target):
                with socket.create_connection((host, int(port)), timeout=5) as s:
                    s.sendall(f"GET {target} HTTP/1.1\r\nHost: {host}:{port}\r\n"
                              "Connection: close\r\n\r\n".encode())
                    answer = b""
                    while chunk := s.recv(65536):
                        answer += chunk
                self.assertTrue(answer.startswith(b"HTTP/1.1 200"), answer[:300])
        with socket.create_connection((host, int(port)), timeout=5) as s:
            s.sendall(b"GET ftp://elsewhere/healthz HTTP/1.1\r\nHost: x\r\n"
                      b"Connection: close\r\n\r\n")
            answer = b""
            while chunk := s.recv(65536):
                answer += chunk
        self.assertTrue(answer.startswith(b"HTTP/1.1 400"), answer[:300])
        self.assertIn(b"http://", answer)

    # --- breadth: every endpoint, bad fields, ids, queries, headers, methods -------------
    def assertClientError(self, r, pointer=None):
        """Any 4xx in problem+json form (naming `pointer` if given), never a 5xx."""
        self.assertGreaterEqual(r.status_code, 400, r.text)
        self.assertLess(r.status_code, 500, r.text)
        return self.assertRejected(r, r.status_code, pointer)

    def test_bad_job_fields_are_422_by_pointer(self):
        cases = [
            ({"name": 5}, "/name"), ({"name": "x" * 1000}, "/name"), ({"tags": "a"}, "/tags"),
            ({"tags": [1]}, "/tags/0"), ({"tags": ["a"] * 100}, "/tags"),
            ({"priority": 101}, "/priority"), ({"priority": "high"}, "/priority"),
            ({"priority": 1.5}, "/priority"), ({"fresh": "yes"}, "/fresh"),
            ({"threads": 100000}, "/threads"), ({"threads": -1}, "/threads"),
            ({"frobnicate": 1}, "/frobnicate"), ({"material": 5}, "/material"),
            ({"material": {"density": -1}}, "/material/density"),
            ({"material": {"density": "1"}}, "/material/density"),
            ({"material": {"poisson_ratio": 0.5}}, "/material/poisson_ratio"),
            ({"geometry": {"nodes_per_meter": 0}}, "/geometry/nodes_per_meter"),
            # The absurd factor is blamed, not the width it multiplies.
            ({"geometry": {"nodes_per_meter": 1e12}}, "/geometry/nodes_per_meter"),
            ({"geometry": {"height": "tall"}}, "/geometry/height"),
            ({"geometry": {"width": 1e300}}, "/geometry/width"),
            ({"geometry": {"top_boundary": "open"}}, "/geometry/top_boundary"),
            ({"friction": {"law": "magic"}}, "/friction/law"),
            ({"friction": {"L": 0}}, "/friction/L"), ({"friction": {"mu": -0.1}}, "/friction/mu"),
            ({"time": {"duration": 0}}, "/time/duration"),
            ({"time": {"duration": 1e300}}, "/time/duration"),
            ({"time": {"safety_factor": 3}}, "/time/safety_factor"),
            ({"output": {"interval": -1}}, "/output/interval"),
            ({"output": {"space_stride": 0}}, "/output/space_stride"),
            ({"probe": {"arrival_x1": 1e6}}, "/probe/arrival_x1"),
            ({"loading": {"shear_stress": 1.0}}, "/loading/shear_stress"),
            ({"nucleation": {"alpha": 2}}, "/nucleation/alpha"),
        ]
        for body, pointer in cases:
            with self.subTest(body=body):
                self.assertRejected(self.server.submit(body), 422, pointer)
        for text in ("[]", '"job"', "null", "3", "true"):
            with self.subTest(text=text):
                self.assertRejected(self.post_raw(JOBS, text), 422, "")

    def test_bad_study_fields_are_422_by_pointer(self):
        cases = [
            ({}, ""), ({"grid": {"L": [1e-5], "n_d": [10]}, "preset": "failure_regimes"}, ""),
            ({"grid": 5}, "/grid"), ({"grid": {"L": [], "n_d": [10]}}, "/grid/L"),
            ({"grid": {"L": [-1], "n_d": [10]}}, "/grid/L/0"),
            ({"grid": {"L": [1e-5, 1e-5], "n_d": [10]}}, "/grid/L/1"),
            ({"grid": {"L": ["a"], "n_d": [10]}}, "/grid/L/0"),
            ({"grid": {"L": [1e-5], "n_d": [10], "x": 1}}, "/grid/x"),
            ({"grid": {"L": [1e-5] * 1000, "n_d": [10]}}, "/grid/L"),
            ({"convergence": {"L": [1e-5], "n_d": [20, 10]}}, "/convergence/n_d"),
            ({"convergence": {"L": [1e-5], "n_d_max": -1}}, "/convergence/n_d_max"),
            ({"preset": "chaos"}, "/preset"), ({"preset": 5}, "/preset"),
            ({"grid": {"L": [1e-5], "n_d": [10]}, "base": 5}, "/base"),
            ({"grid": {"L": [1e-5], "n_d": [10]}, "base": {"friction": {"L": 1}}},
             "/base/friction/L"),
            ({"grid": {"L": [1e-5], "n_d": [10]}, "base": {"material": {"density": -1}}},
             "/base/material/density"),
            ({"grid": {"L": [1e-5], "n_d": [10]}, "name": 5}, "/name"),
            ({"grid": {"L": [1e-5], "n_d": [10]}, "tags": [1]}, "/tags/0"),
            ({"grid": {"L": [1e-5], "n_d": [10]}, "priority": 1000}, "/priority"),
            ({"grid": {"L": [1e-5], "n_d": [10]}, "fresh": 1}, "/fresh"),
            ({"grid": {"L": [1e-5], "n_d": [10]}, "unknown": 1}, "/unknown"),
        ]
        for body, pointer in cases:
            with self.subTest(body=body):
                self.assertRejected(self.server.post(STUDIES, json=body), 422, pointer)

    def test_bad_ids_are_404_everywhere(self):
        bad = ["0" * 31, "0" * 33, "G" * 32, "A" * 32, "..%2F..%2Fetc%2Fpasswd", "%00" * 8,
               "0" * 32]  # the last is well-formed but unknown
        for ident in bad:
            for path in [f"{JOBS}/{ident}", f"{JOBS}/{ident}/result.h5", f"{JOBS}/{ident}/metrics",
                         f"{JOBS}/{ident}/front", f"{STUDIES}/{ident}",
                         f"{STUDIES}/{ident}/speed-accuracy"]:
                with self.subTest(path=path):
                    self.assertRejected(self.server.get(path), 404)
            for path in [f"{JOBS}/{ident}/cancel", f"{STUDIES}/{ident}/cancel"]:
                with self.subTest(path=path):
                    self.assertRejected(self.server.post(path), 404)

    def test_bad_queries_are_400_by_parameter(self):
        cases = [
            (JOBS, {"limit": "0"}, "/query/limit"), (JOBS, {"limit": "1001"}, "/query/limit"),
            (JOBS, {"limit": "abc"}, "/query/limit"), (JOBS, {"limit": "1e3"}, "/query/limit"),
            (JOBS, {"cursor": "-5"}, "/query/cursor"), (JOBS, {"cursor": "x"}, "/query/cursor"),
            (JOBS, {"status": "bogus"}, "/query/status"), (JOBS, {"order_by": "id"}, "/query/order_by"),
            (JOBS, {"L_min": "1,2"}, "/query/L_min"), (JOBS, {"n_d_max": ""}, "/query/n_d_max"),
            (STUDIES, {"limit": "0"}, "/query/limit"), (STUDIES, {"cursor": "-1"}, "/query/cursor"),
            (STUDIES, {"x": "1"}, "/query/x"),
            (f"{JOBS}/{'0' * 32}", {"fields": "id"}, None),  # unknown job: 404
        ]
        for path, params, pointer in cases:
            with self.subTest(path=path, params=params):
                self.assertClientError(self.server.get(path, params=params), pointer)
        for params in ({}, {"scene": "xyz"}, {"study": "nothex"},
                       {"scene": "0" * 64, "study": "0" * 32}):
            with self.subTest(convergence_map=params):
                self.assertClientError(self.server.get("/api/v1/convergence-map", params=params))

    def test_bad_submission_options_and_headers(self):
        cases = [
            ({"params": {"fresh": "maybe"}}, "/query/fresh"),
            ({"params": {"priority": "999"}}, "/query/priority"),
            ({"params": {"priority": "-1e9"}}, "/query/priority"),
            ({"headers": {"Idempotency-Key": "k" * 201}}, "/headers/Idempotency-Key"),
        ]
        for kw, pointer in cases:
            with self.subTest(kw=kw):
                self.assertRejected(self.server.submit(dict(TINY), **kw), 400, pointer)

    def test_methods_bodies_and_encodings(self):
        for method, path in [("DELETE", JOBS), ("PUT", f"{JOBS}/{'0' * 32}"), ("PATCH", STUDIES),
                             ("DELETE", "/healthz"), ("POST", "/metrics")]:
            with self.subTest(method=method, path=path):
                r = self.server.session.request(method, self.server.url(path), timeout=10)
                self.assertRejected(r, 405)
                self.assertIn("Allow", r.headers)
        for data in (b'{"name": "\xff"}', b'{"name": "a\nb"}', b'{"name": "\\ud800"}'):
            with self.subTest(data=data):
                # raw invalid UTF-8, a raw newline inside a string, a lone surrogate escape
                r = self.server.post(JOBS, data=data, timeout=10)
                self.assertRejected(r, 400)
        r = self.server.post(JOBS, data=b"{" + b" " * (2 << 20) + b"}", timeout=30)
        self.assertRejected(r, 413)


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

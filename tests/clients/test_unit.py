"""Client pieces that need no server: job overrides, retries, back-off, convergence
statuses, the filter law, the figures' inputs.

    /usr/bin/python3 -m unittest discover -s tests/clients -p 'test_unit*.py'
"""

import io
import json
import math
import os
import tempfile
import unittest

import harness  # noqa: F401  (puts clients/ on sys.path)
from slipfront_client import analysis, jobspec
from slipfront_client.api import Api, parse_retry_after
from slipfront_client.errors import EXIT_USAGE, JobCancelled, JobFailed, ServerError, UsageError
from slipfront_client.plots import convergence, filter_response
from slipfront_client.plots.common import parse_formats
from slipfront_client.waiting import Backoff, ProgressBar, check_outcome


class FakeResponse:
    def __init__(self, status, body=None, headers=None, reason=""):
        self.status_code = status
        self.headers = headers or {}
        self.reason = reason
        self._body = body

    def json(self):
        if self._body is None:
            raise ValueError("no body")
        return self._body

    @property
    def text(self):
        return json.dumps(self._body) if self._body is not None else ""

    def close(self):
        pass


class FakeSession:
    def __init__(self, responses):
        self.responses = list(responses)
        self.calls = []
        self.headers = {}

    def request(self, method, url, **kw):
        self.calls.append((method, url, kw))
        return self.responses.pop(0)

    def close(self):
        pass


class JobSpecTest(unittest.TestCase):
    def test_overrides_create_nested_objects_and_parse_json(self):
        doc = jobspec.build_job(None, ["friction.L=1e-5", "geometry.nodes_per_meter=20",
                                       "friction.law=coulomb", "tags=[\"a\"]",
                                       "time.stop_on_arrest=false"])
        self.assertEqual(doc, {"friction": {"L": 1e-5, "law": "coulomb"},
                               "geometry": {"nodes_per_meter": 20}, "tags": ["a"],
                               "time": {"stop_on_arrest": False}})

    def test_file_stdin_and_errors(self):
        doc = jobspec.build_job("-", ["time.duration=3"], stdin=io.StringIO('{"name": "x"}'))
        self.assertEqual(doc, {"name": "x", "time": {"duration": 3}})
        for bad in ("friction.L", "=3", "a..b=1"):
            with self.assertRaises(UsageError):
                jobspec.apply_override({}, bad)
        with self.assertRaises(UsageError):
            jobspec.apply_override({"friction": 3}, "friction.L=1")
        with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
            f.write("[1, 2]")
        try:
            with self.assertRaises(UsageError) as cm:
                jobspec.load_job(f.name)
            self.assertEqual(cm.exception.exit_code, EXIT_USAGE)
        finally:
            os.remove(f.name)
        with self.assertRaises(UsageError):
            jobspec.load_job("/no/such/job.json")


class ApiTest(unittest.TestCase):
    def api(self, responses):
        sleeps = []
        api = Api("http://server", sleep=sleeps.append, max_retries=3)
        api.session = FakeSession(responses)
        return api, sleeps

    def test_retry_after_is_honoured_on_503_and_429(self):
        api, sleeps = self.api([FakeResponse(503, {"detail": "full"}, {"Retry-After": "2"}),
                                FakeResponse(429, {}, {"Retry-After": "1"}),
                                FakeResponse(201, {"id": "x", "status": "queued"})])
        self.assertEqual(api.submit({})["id"], "x")
        self.assertEqual(sleeps, [2.0, 1.0])
        keys = {c[2]["headers"]["Idempotency-Key"] for c in api.session.calls}
        self.assertEqual(len(keys), 1, "retries must reuse the idempotency key")

    def test_retries_are_bounded(self):
        api, sleeps = self.api([FakeResponse(503, {"detail": "full"}, {"Retry-After": "999"})] * 4)
        with self.assertRaises(ServerError) as cm:
            api.job("abc")
        self.assertEqual(cm.exception.status, 503)
        self.assertEqual(sleeps, [60.0] * 3)  # capped by max_retry_wait

    def test_validation_problem_becomes_usage_error_with_pointers(self):
        problem = {"detail": "the job spec is invalid (1 error)",
                   "errors": [{"pointer": "/friction/L", "reason": "must be > 0"}]}
        api, _ = self.api([FakeResponse(422, problem, reason="Unprocessable Entity")])
        with self.assertRaises(UsageError) as cm:
            api.submit({"friction": {"L": -1}})
        self.assertIn("/friction/L: must be > 0", cm.exception.lines()[1])

    def test_parse_retry_after(self):
        self.assertEqual(parse_retry_after("5", 1.0), 5.0)
        self.assertEqual(parse_retry_after(None, 1.5), 1.5)
        self.assertEqual(parse_retry_after("Wed, 21 Oct 2015 07:28:00 GMT", 1.0), 0.0)
        self.assertEqual(parse_retry_after("soon", 3.0), 3.0)


class WaitingTest(unittest.TestCase):
    def test_backoff_grows_to_a_bound(self):
        b = Backoff(first=0.2, factor=2, cap=1.0)
        self.assertEqual([b.next() for _ in range(5)], [0.2, 0.4, 0.8, 1.0, 1.0])
        b.reset()
        self.assertEqual(b.next(), 0.2)

    def test_outcomes_map_to_exit_codes(self):
        check_outcome({"status": "succeeded", "metrics": {"outcome": "arrested"}})
        with self.assertRaises(JobFailed):
            check_outcome({"status": "failed", "error": "boom"})
        with self.assertRaises(JobFailed):
            check_outcome({"status": "succeeded", "metrics": {"outcome": "diverged"}})
        with self.assertRaises(JobCancelled):
            check_outcome({"status": "cancelled"})

    def test_progress_bar_text(self):
        out = io.StringIO()
        bar = ProgressBar(stream=out)
        bar.update({"status": "running", "progress": {"fraction": 0.5, "time": 1.5,
                                                      "duration": 3, "eta_s": 65}})
        line = out.getvalue()
        self.assertIn("50.0%", line)
        self.assertIn("t = 1.5/3 s", line)
        self.assertIn("ETA 1 min 05 s", line)


class AnalysisTest(unittest.TestCase):
    def rows(self):
        def row(L, n_d, d, t, status="succeeded", outcome="arrested"):
            return {"L": L, "n_d": n_d, "propagation_distance": d, "arrival_time_at_probe": t,
                    "status": status, "outcome": outcome, "wall_time_s": n_d ** 2 / 100}
        return [row(1e-4, 10, 11.9, 8.0), row(1e-4, 20, 12.03, 8.004), row(1e-4, 40, 12.031, 8.0041),
                row(1e-5, 10, 13.0, 7.0), row(1e-5, 20, 12.5, 7.5),
                row(1e-5, 40, None, None, status="running", outcome=None),
                row(1e-6, 10, None, None, status="failed", outcome="diverged")]

    def test_convergence_statuses(self):
        got = {(r["L"], r["n_d"]): r["convergence"]
               for r in analysis.convergence_statuses(self.rows())}
        self.assertEqual(got, {(1e-4, 10): "not_converged", (1e-4, 20): "converged",
                               (1e-4, 40): "unknown", (1e-5, 10): "not_converged",
                               (1e-5, 20): "unknown", (1e-5, 40): "pending",
                               (1e-6, 10): "diverged"})

    def test_errors_against_finest(self):
        rows = analysis.errors_against_finest(self.rows())
        e = {(r["L"], r["n_d"]): r["error"] for r in rows}
        self.assertAlmostEqual(e[(1e-4, 10)], max(0.131 / 12.031, 0.0041 / 8.0041))
        self.assertNotIn((1e-4, 40), e)  # the reference itself


class PlotInputTest(unittest.TestCase):
    def test_points_from_json_shapes(self):
        flat = [{"L": 1e-4, "n_d": 20, "status": "converged"}]
        self.assertEqual(convergence.points_from_json(flat)[0]["status"], "converged")
        nested = {"points": [{"spec": {"friction": {"L": 1e-5},
                                       "geometry": {"nodes_per_meter": 40}},
                              "convergence": "not_converged"}]}
        self.assertEqual(convergence.points_from_json(nested),
                         [{"L": 1e-5, "n_d": 40.0, "status": "not_converged"}])
        self.assertEqual(convergence.points_from_json([{"L": 1, "n_d": 2, "status": "odd"}])[0]
                         ["status"], "unknown")
        with self.assertRaises(UsageError):
            convergence.points_from_json({"nothing": 1})
        with self.assertRaises(UsageError):
            convergence.points_from_json([{"L": 1}])

    def test_filter_law(self):
        self.assertAlmostEqual(float(filter_response.amplitude_ratio(0.0, 5e-5)), 1.0)
        f = 1e-4 / (2 * math.pi * 5e-5)  # 2 pi f L / V* = 1
        self.assertAlmostEqual(float(filter_response.amplitude_ratio(f, 5e-5)), 1 / math.sqrt(2))
        # dx / c_p for n_d = 5: the solver's stable_dt of the tiny job is 0.11547006...
        self.assertAlmostEqual(filter_response.stable_dt_estimate(5), 0.1154700649, places=6)

    def test_formats(self):
        self.assertEqual(parse_formats("png, pdf"), ["png", "pdf"])
        with self.assertRaises(UsageError):
            parse_formats("gif")


if __name__ == "__main__":
    unittest.main()

"""Client pieces that need no server: job overrides, retries, back-off, convergence
statuses, the filter law, the figures' inputs.
Over 400 lines on purpose: one short test per client rule, no server needed.

    /usr/bin/python3 -m unittest discover -s tests/clients -p 'test_unit*.py'
"""

import io
import json
import math
import os
import tempfile
import unittest

import harness
from slipfront_client import analysis, jobspec, report, reproduction
from slipfront_client.api import Api, parse_retry_after

assert harness.CLIENTS  # importing harness put clients/ on sys.path
from slipfront_client.errors import EXIT_USAGE, JobCancelled, JobFailed, ServerError, UsageError
from slipfront_client.plots import convergence, cost, filter_response
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


class ResultSpecTest(unittest.TestCase):
    def test_wave_speeds_of_either_material_form(self):
        from slipfront_client.results import Result
        empty = [None] * 7
        moduli = Result("a.h5", *empty, spec={"material": {"density": 1.0, "young_modulus": 2.5,
                                                            "poisson_ratio": 0.25}})
        c_s, c_p = moduli.wave_speeds()
        self.assertAlmostEqual(c_s, 1.0, places=12)
        self.assertAlmostEqual(c_p, math.sqrt(3.0), places=12)
        speeds = Result("b.h5", *empty, spec={"material": {"density": 2670.0, "p_wave_speed": 6000.0,
                                                            "s_wave_speed": 3464.0}})
        self.assertEqual(speeds.wave_speeds(), (3464.0, 6000.0))


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

    def test_shared_convergence_cases_as_the_server(self):
        # The cases api/study/convergence.cpp is tested against (study.ConvergenceCases.*).
        path = os.path.join(os.path.dirname(__file__), "..", "study", "convergence_cases.json")
        with open(path) as f:
            cases = json.load(f)["cases"]
        self.assertGreater(len(cases), 10)
        for case in cases:
            rows = [{"id": r["id"], "L": r["L"], "n_d": r["n_d"], "status": r["status"],
                     **{k: (r["metrics"] or {}).get(k) for k in
                        ("outcome", "propagation_distance", "arrival_time_at_probe", "steps",
                         "simulated_time", "stations")}}
                    for r in case["runs"]]
            got = {r["id"]: r["convergence"] for r in analysis.convergence_statuses(rows)}
            self.assertEqual(got, case["expected"], case["name"])

    def test_a_local_result_without_status_counts_as_succeeded(self):
        rows = [{"L": 1e-4, "n_d": n_d, "status": None, "outcome": "arrested",
                 "propagation_distance": 12.0, "arrival_time_at_probe": 8.0}
                for n_d in (10, 20)]
        self.assertEqual([r["convergence"] for r in analysis.convergence_statuses(rows)],
                         ["converged", "unknown"])

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


def _study(method, L_c, steps, reason, converged=None, refinement=None, spectral=1.7e-5):
    runs = [{"job_id": f"{method}{L}{n}", "L": L, "n_d": n}
            for L in (1e-4, 1e-5) for n in (10, 20, 40)]
    return {"id": f"study-{method}", "status": "finished", "method": method, "L_c": L_c,
            "spectral_critical_length": spectral, "runs": runs,
            "convergence_map": {"converged_n_d": converged or {"0.0001": 10, "1e-05": None}},
            "refinement": refinement or {"0.0001": {"state": "converged"},
                                         "1e-05": {"state": "not_converged_at_cap"}},
            "critical_length": {"L_c": L_c, "steps_in_L": steps, "reason": reason,
                                "spectral_critical_length": spectral, "spectral_from_L": 5e-6}}


STEPS = [{"from_L": 5e-6, "to_L": 1e-5, "agree": False,
          "changes": {"propagation_distance": 0.0213, "arrival_time": 0.00312}},
         {"from_L": 1e-5, "to_L": 5e-5, "agree": False,
          "changes": {"propagation_distance": 0.0187, "arrival_time": None}}]


class ReportTest(unittest.TestCase):
    """The report's pieces (slipfront_client.report) on small fixtures."""

    def test_verdict_text(self):
        none = _study("spectral_bi", None, STEPS, "no L meets the rule: the two smallest ...")
        self.assertEqual(report.verdict_text(none), "no L meets the rule")
        # no reason prefix (an older server), but every step disagrees: the same verdict
        self.assertEqual(report.verdict_text(_study("fe", None, STEPS, "")), "no L meets the rule")
        self.assertEqual(report.verdict_text(_study("fe", 1e-5, STEPS[:1], "L = 5e-05 ...")),
                         "L_c = 1e-05 m")
        self.assertEqual(report.verdict_text(_study("fe", None, [], "needs at least two")),
                         "L_c undetermined")

    def test_verdict_lines_lead_with_the_verdict_steps_and_n_d(self):
        study = _study("spectral_bi", None, STEPS, "no L meets the rule: steps ...")
        lines = report.verdict_lines(study)
        self.assertEqual(lines[0], "### spectral boundary integral (`spectral_bi`): "
                                   "no L meets the rule\n")
        text = "\n".join(lines)
        self.assertIn("Spectral estimate beside it: **1.7e-05 m** (from the reference run of "
                      "L = 5e-06 m", text)
        self.assertIn("| 5e-06 → 1e-05 | 2.13 % | 0.312 % | no |", lines)
        self.assertIn("| 1e-05 → 5e-05 | 1.87 % | — | no |", lines)
        self.assertIn("| 0.0001 | 10 | 40 | converged |", lines)
        self.assertIn("| 1e-05 | none up to the cap | 40 | not_converged_at_cap |", lines)
        lc = report.verdict_lines(_study("fe", 1e-5, STEPS[:1], "L = 5e-05 ..."))
        self.assertTrue(lc[0].endswith(": L_c = 1e-05 m\n"), lc[0])

    def test_cross_method_table(self):
        side = {"run_id": "a", "n_d": 40, "outcome": "arrested", "wall_time_s": 12.0,
                "arrest_position": 12.5, "propagation_distance": 12.43,
                "arrival_time_at_probe": 4.512, "max_slip_velocity": 0.0081,
                "spectral_velocity": 0.0031}
        bi = dict(side, n_d=80, wall_time_s=0.4, propagation_distance=12.4)
        rows = [{"L": 5e-6, "fe": None, "spectral_bi": bi, "differences": None, "agree": None,
                 "reason": "no mesh-converged run of this L by fe"},
                {"L": 5e-5, "fe": side, "spectral_bi": bi, "agree": True, "reason": "",
                 "differences": {"propagation_distance": 0.0024194, "arrival_time_at_probe": 0.0,
                                 "arrest_position": 0.0, "max_slip_velocity": 0.0,
                                 "spectral_velocity": None}}]
        lines = report.cross_method_lines(rows)
        self.assertTrue(lines[0].startswith("| L [m] | n_d FE / BI | propagation distance [m] |"))
        self.assertEqual(lines[2], "| 5e-05 | 40 / 80 | 12.43 / 12.4 (0.242 %) | 4.512 / 4.512 (0 %) | "
                                   "12.5 / 12.5 (0 %) | 0.0081 / 0.0081 (0 %) | "
                                   "0.0031 / 0.0031 (—) | 12 / 0.4 | yes |")
        self.assertEqual(lines[3], "| 5e-06 | — / 80 | — / 12.4 | — / 4.512 | — / 12.5 | "
                                   "— / 0.0081 | — / 0.0031 | — / 0.4 | "
                                   "— no mesh-converged run of this L by fe |")
        self.assertIn("No cross-method rows", report.cross_method_lines([])[0])

    def test_bi_base_drops_fe_only_fields(self):
        base = {"geometry": {"width": 20, "height": 8}, "time": {"duration": 10, "safety_factor": 0.5}}
        self.assertEqual(reproduction.bi_base(base),
                         {"geometry": {"width": 20}, "time": {"duration": 10},
                          "method": "spectral_bi"})
        self.assertEqual(base["geometry"]["height"], 8)  # the FE base is left alone
        self.assertEqual(reproduction.bi_base(None), {"method": "spectral_bi"})


class SpeedAccuracyTest(unittest.TestCase):
    def run_(self, method, L, n_d, wall, mem, err):
        return {"id": f"{method}-{n_d}", "job_id": f"{method}-{n_d}", "method": method, "L": L,
                "n_d": n_d, "wall_time_s": wall, "memory_bytes": mem,
                "errors": {"propagation_distance": err, "arrival_time": err / 10}}

    def test_across_methods_preferred_and_runs_fallback(self):
        fe = self.run_("fe", 5e-5, 20, 3.0, 9e7, 0.01)
        bi = self.run_("spectral_bi", 5e-5, 40, 0.2, 2.8e7, 0.001)
        doc = {"runs": [dict(fe, errors={"propagation_distance": 0.5})],
               "across_methods": {"runs": [fe, bi], "reference": "finest converged"}}
        rows = analysis.rows_from_speed_accuracy(doc)
        self.assertEqual([(r["method"], r["error"], r["memory_bytes"]) for r in rows],
                         [("fe", 0.01, 9e7), ("spectral_bi", 0.001, 2.8e7)])
        self.assertTrue(analysis.has_across_methods(doc))
        old = {"runs": [{k: v for k, v in bi.items() if k != "method"}]}
        self.assertEqual(analysis.rows_from_speed_accuracy(old, "spectral_bi")[0]["method"],
                         "spectral_bi")
        self.assertEqual(analysis.rows_from_speed_accuracy(old)[0]["method"], "fe")
        rows, source = reproduction.cost_rows(old, doc)
        self.assertEqual(source, "across_methods")
        rows, source = reproduction.cost_rows({"runs": [fe]}, old)
        self.assertEqual((source, [r["method"] for r in rows]), ("runs", ["fe", "spectral_bi"]))
        self.assertEqual(len(analysis.merge_rows(rows, rows)), 2)

    def test_plot_cost_study_rows(self):
        from slipfront_client.commands_plot import study_cost_rows
        fe = self.run_("fe", 5e-5, 20, 3.0, 9e7, 0.01)
        bi = self.run_("spectral_bi", 5e-5, 40, 0.2, 2.8e7, 0.001)
        strip = lambda r: {k: v for k, v in r.items() if k != "method"}  # noqa: E731

        class FakeApi:
            def __init__(self, docs):
                self.docs = docs

            def get_json(self, path):
                return self.docs[path.split("/")[4]]

            def study(self, sid):
                return {"id": sid, "method": "spectral_bi" if sid == "B" else "fe"}

        old = FakeApi({"F": {"runs": [strip(fe)]}, "B": {"runs": [strip(bi)]}})
        rows, reference = study_cost_rows(old, ["F", "B"])
        self.assertEqual([r["method"] for r in rows], ["fe", "spectral_bi"])
        self.assertEqual(reference, "converged")
        new = FakeApi({"F": {"runs": [fe], "across_methods": {"runs": [fe, bi]}}})
        rows, reference = study_cost_rows(new, ["F"])
        self.assertEqual([r["method"] for r in rows], ["fe", "spectral_bi"])

    def test_cost_chart_of_a_study_with_no_converged_L(self):
        """The server has no reference (errors null): the chart still draws, with errors
        against the finest run of each L, and says so on the figure."""
        from slipfront_client.commands_plot import study_cost_rows
        unconverged = self.run_("fe", 5e-5, 10, 0.5, 2e7, 0.0)
        unconverged["errors"] = {"propagation_distance": None, "arrival_time": None}

        def job(n_d, distance, arrival, wall):
            return {"id": f"j{n_d}", "status": "succeeded", "wall_time_s": wall,
                    "spec": {"friction": {"L": 5e-5}, "geometry": {"nodes_per_meter": n_d}},
                    "metrics": {"outcome": "arrested", "propagation_distance": distance,
                                "arrival_time_at_probe": arrival, "wall_time_s": wall}}

        class FakeApi:
            def get_json(self, path):
                return {"runs": [unconverged]}

            def study(self, sid):
                return {"id": sid, "method": "fe"}

            def list_jobs(self, filters, limit=None):
                assert filters == {"study_id": "S"}
                return iter([job(10, 10.0, 8.0, 0.5), job(20, 10.5, 8.4, 2.0),
                             job(40, 11.0, 8.8, 8.0)])

        rows, reference = study_cost_rows(FakeApi(), ["S"])
        self.assertEqual(reference, "unconverged")
        self.assertEqual(sorted(r["n_d"] for r in rows), [10, 20])
        self.assertAlmostEqual(min(r["error"] for r in rows), 0.5 / 11.0)
        fig, data = cost.plot_cost(rows, reference=reference)
        self.assertEqual(data[("fe", 5e-5)]["n_d"], [10, 20])
        footer = fig._supxlabel.get_text()
        self.assertIn("error = max(|d - d_ref| / d_ref, |t - t_ref| / t_ref)", footer)
        self.assertIn("No L of the study converged", footer)

    def test_cost_chart_has_both_methods_and_a_memory_panel(self):
        rows = analysis.rows_from_speed_accuracy({"across_methods": {"runs": [
            self.run_("fe", 5e-5, 10, 0.8, 2.5e7, 0.03), self.run_("fe", 5e-5, 20, 3.0, 9e7, 0.01),
            self.run_("spectral_bi", 5e-5, 20, 0.1, 1.4e7, 0.002),
            self.run_("spectral_bi", 5e-5, 40, 0.2, 2.8e7, 0.0)]}})  # a reference: left out
        fig, data = cost.plot_cost(rows)
        self.assertEqual(set(data), {("fe", 5e-5), ("spectral_bi", 5e-5)})
        self.assertEqual(data[("spectral_bi", 5e-5)]["memory_bytes"], [1.4e7])
        self.assertEqual(len(fig.axes), 2)
        labels = [t.get_text() for t in fig.axes[-1].get_legend().get_texts()]
        self.assertEqual(labels, ["L = 5e-5 m", "FE (finite elements)",
                                  "BI (spectral boundary integral)"])
        self.assertEqual(fig.axes[1].get_xlabel(), "memory estimate [MB]")
        fig, _ = cost.plot_cost([{"L": 1e-4, "n_d": 10, "wall_time_s": 1, "error": 0.1}])
        self.assertEqual(len(fig.axes), 1)  # no memory: wall time only


if __name__ == "__main__":
    unittest.main()

"""Compare runs in a real browser (headless Chromium, Selenium) against `slipfront serve` on
loopback (docs/web.md "Compare runs"), as a researcher meets it:

- an FE and a BI run of the paper's scene (L = 1e-4 m, n_d = 10: about a second each), ticked
  in the jobs list, "Compare selected" opens #/compare?ids=FE,BI;
- the table marks the `method` row (and, lighter, the fields one method has) as differing,
  first, and leaves L and n_d unmarked; the spread of the numbers that differ; a check box
  shows the identical fields too;
- the legends of the overlaid curves say the method ("FE, …", "BI, …"), FE solid lines and
  circles, BI dashed lines and squares; |V|(t) at the first run's own probes (x1 = 6 and 11 m) holds each run's
  /fields values in mm/s, V_r and the front each run's /front;
- the scatter puts the parameter that differs (the method) against a metric chosen in a menu,
  one point per run at the server's values;
- a study's "Compare these runs" link opens its runs, told apart by n_d.

Saves the compare view as <screenshots>/web-compare.png (docs/figures/web-compare.png).

    /usr/bin/python3 tests/web/test_web_compare.py --binary build/slipfront --web-dir build/share/slipfront/web
"""

import os
import sys

import numpy as np
from browser_harness import BrowserCase, run
from selenium.webdriver.support.ui import Select

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "server"))
from server_harness import wait_study  # noqa: E402

SCENE = {"friction": {"L": 1e-4}, "geometry": {"nodes_per_meter": 10}}


class WebCompare(BrowserCase):
    @classmethod
    def setUpClass(cls):
        cls.start(workers=2)
        s = cls.server
        ids = {}
        for method in ("fe", "spectral_bi"):
            r = s.submit({**SCENE, "method": method, "name": f"paper scene, {method}"})
            assert r.status_code == 201, r.text
            ids[method] = r.json()["id"]
        cls.runs = {m: s.wait_status(i, {"succeeded", "failed"}, 180) for m, i in ids.items()}
        for job in cls.runs.values():
            assert job["status"] == "succeeded", job
        r = s.post("/api/v1/studies", json={"name": "two meshes", "base": {"method": "spectral_bi"},
                                            "grid": {"L": [1e-4], "n_d": [5, 10]}})
        assert r.status_code in (201, 202), r.text
        cls.study = wait_study(s, r.json()["id"])

    def open_compare_from_the_jobs_list(self):
        fe, bi = self.runs["fe"]["id"], self.runs["spectral_bi"]["id"]
        self.open("/#/jobs")
        self.wait(lambda d: len(self.css(f"#jobs-table tr[data-id='{fe}'] input.pick")) == 1,
                  message="the FE run in the list")
        button = self.css("#compare-selected")[0]
        self.assertFalse(button.is_enabled())  # nothing picked yet
        for job_id in (fe, bi):
            self.css(f"#jobs-table tr[data-id='{job_id}'] input.pick")[0].click()
        self.wait(lambda d: self.css("#compare-selected")[0].text == "Compare selected (2)")
        self.css("#compare-selected")[0].click()
        self.wait(lambda d: all(self.chart_ready(f"#cmp-{c}") for c in ("vt", "vr", "front", "scatter")),
                  timeout=60, message="the four compare charts")
        return fe, bi

    def legend(self, selector):
        """(name, dash, symbol) of each trace shown in the legend of a chart."""
        return [tuple(x) for x in self.js(
            "return document.querySelector(arguments[0]).data.filter(t => t.showlegend !== false)"
            ".map(t => [t.name, (t.line || {}).dash || null, (t.marker || {}).symbol || null])", selector)]

    def test_jobs_list_to_the_compare_view(self):
        fe, bi = self.open_compare_from_the_jobs_list()
        self.assertIn("#/compare?ids=", self.driver.current_url)
        self.assertEqual(set(self.driver.current_url.split("ids=")[1].split(",")), {fe, bi})
        # The table: the method differs (highlighted), L and n_d do not.
        method = self.css("#compare-table tr[data-field='spec.method']")[0]
        self.assertIn("differs", method.get_attribute("class"))
        self.assertEqual(self.texts("#compare-table tr[data-field='spec.method'] td:not(.spread)"), ["fe", "spectral_bi"])
        for field in ("spec.friction.L", "spec.geometry.nodes_per_meter"):
            row = self.css(f"#compare-table tr[data-field='{field}']")[0]
            self.assertNotIn("differs", row.get_attribute("class") or "", field)
        self.assertRegex(self.css("#compare-count")[0].text, r"^\d+ fields differ \(highlighted, ≠\), \d+ only some runs have")
        only_bi = self.css("#compare-table tr[data-field='spec.spectral_bi.memory_periods']")[0]
        self.assertEqual(only_bi.get_attribute("class"), "differs partial")  # "—" for the FE run
        # The real differences first, then the fields one method has, then the identical ones.
        order = self.js("return [...document.querySelectorAll('#compare-table tr[data-field^=\"spec.\"]')]"
                        ".map(r => r.dataset.field)")
        self.assertEqual(order[0], "spec.method")
        self.assertLess(order.index("spec.spectral_bi.memory_periods"), order.index("spec.friction.L"))
        # The spread of the numbers that differ: (max - min) / max |v|, in percent.
        d = [self.runs[m]["metrics"]["propagation_distance"] for m in ("fe", "spectral_bi")]
        spread = self.texts("#compare-table tr[data-field='metrics.propagation_distance'] td.spread")[0]
        self.assertAlmostEqual(float(spread.rstrip(" %")), 100 * (max(d) - min(d)) / max(d), delta=0.01)
        self.assertEqual(self.texts("#compare-table tr[data-field='spec.friction.L'] td.spread"), [""])
        # Identical fields are hidden until asked for.
        self.assertEqual(self.css("#compare-table tr[data-field='spec.material.density']"), [])
        self.css("#compare-all")[0].click()
        self.wait(lambda d: len(self.css("#compare-table tr[data-field='spec.material.density']")) == 1)
        self.assertEqual(self.texts("#compare-table tr[data-field='spec.material.density'] td"), ["1", "1", ""])
        self.assert_no_console_errors("compare view")

    def test_legends_tell_the_methods_apart(self):
        fe, bi = self.open_compare_from_the_jobs_list()
        fe_label, bi_label = "FE, L = 1.00e-4 m, n_d = 10", "BI, L = 1.00e-4 m, n_d = 10"
        self.assertEqual(self.legend("#cmp-vt"), [(fe_label, "solid", None), (bi_label, "dash", None)])
        self.assertEqual(self.legend("#cmp-vr"), [(fe_label, "solid", "circle"), (bi_label, "dash", "square")])
        self.assertEqual(self.legend("#cmp-front"), [(fe_label, "solid", None), (bi_label, "dash", None)])
        # |V|(t) at the first run's own probes (the paper's spectrum and arrival probes), each
        # run's history at the node in mm/s.
        self.assertEqual(self.css("#cmp-x1")[0].get_attribute("value"), "6, 11")
        traces = self.js("return document.getElementById('cmp-vt').data.map(t => ({name: t.name, y: t.y, yaxis: t.yaxis}))")
        self.assertEqual(len(traces), 4)
        for k, x in enumerate((6, 11)):
            panel = [t for t in traces if t["yaxis"] == ("y" if k == 0 else "y2")]
            self.assertEqual([t["name"] for t in panel], [fe_label, bi_label])
            for t, job_id in zip(panel, (fe, bi)):
                field = self.server.get(f"/api/v1/jobs/{job_id}/fields/slip_velocity",
                                        params={"x1_min": x, "x1_max": x, "max_points": 4000}).json()
                np.testing.assert_allclose(t["y"], [abs(r[0]) * 1e3 for r in field["values"]], rtol=1e-12)
        # V_r(x1) and the front: each run's /front.
        vr = self.js("return document.getElementById('cmp-vr').data.map(t => t.y)")
        front = self.js("return document.getElementById('cmp-front').data.map(t => t.y)")
        for i, job_id in enumerate((fe, bi)):
            served = self.server.get(f"/api/v1/jobs/{job_id}/front").json()
            self.assertEqual(vr[i], served["rupture_speed"])
            order = np.argsort(served["x1"])
            expected = np.array([np.nan if t is None else t for t in served["arrival_time"]])[order]
            shown = np.array([np.nan if t is None else t for t in front[i]])
            np.testing.assert_allclose(shown, expected, rtol=1e-12)
        self.shot("web-compare")
        self.assert_no_console_errors("compare view, figures")

    def test_scatter_of_a_parameter_against_a_metric(self):
        fe, bi = self.open_compare_from_the_jobs_list()
        # The parameter that differs (the method: L and n_d are the same) against the
        # propagation distance, then against the steps chosen in the menu.
        self.assertEqual(Select(self.css("#cmp-scatter-x")[0]).first_selected_option.get_attribute("value"), "method")
        points = self.js("return document.getElementById('cmp-scatter').data.map(t => [t.x[0], t.y[0], t.marker.symbol])")
        self.assertEqual(points, [["fe", self.runs["fe"]["metrics"]["propagation_distance"], "circle"],
                                  ["spectral_bi", self.runs["spectral_bi"]["metrics"]["propagation_distance"], "square"]])
        Select(self.css("#cmp-scatter-y")[0]).select_by_value("steps")
        self.wait(lambda d: self.js("return document.getElementById('cmp-scatter').data[0].y[0]")
                  == self.runs["fe"]["metrics"]["steps"], message="the scatter redrawn with the steps")
        self.assertEqual(self.js("return document.getElementById('cmp-scatter').layout.yaxis.title.text"), "metrics.steps")

    def test_study_link_compares_its_runs(self):
        self.open(f"/#/studies/{self.study['id']}")
        self.wait(lambda d: len(self.css("#compare-study")) == 1, message="the compare link")
        self.css("#compare-study")[0].click()
        self.wait(lambda d: self.chart_ready("#cmp-vr"), timeout=60, message="the study's runs compared")
        self.assertEqual([n for n, _, _ in self.legend("#cmp-vr")],
                         ["BI, L = 1.00e-4 m, n_d = 5", "BI, L = 1.00e-4 m, n_d = 10"])
        row = self.css("#compare-table tr[data-field='spec.geometry.nodes_per_meter']")[0]
        self.assertIn("differs", row.get_attribute("class"))
        self.assertIn("the runs of study", self.css("#compare-source")[0].text)
        self.assert_no_console_errors("compare view of a study")

    def test_a_running_run_appears_when_it_finishes(self):
        # A run that takes some seconds (FE, n_d = 60, one thread: ~10 s idle) beside a
        # finished one: the page says it is still running (or queued), then draws it without a
        # reload once it has finished.
        r = self.server.submit({"friction": {"L": 1e-4}, "geometry": {"nodes_per_meter": 60},
                                "threads": 1, "name": "a slower run"})
        self.assertEqual(r.status_code, 201, r.text)
        slow, fe = r.json()["id"], self.runs["fe"]["id"]
        self.open(f"/#/compare?ids={fe},{slow}")
        self.wait(lambda d: len(self.css("#compare-running")) == 1, message="the running note")
        self.assertIn("a slower run", self.css("#compare-running")[0].text)
        job = self.server.wait_status(slow, {"succeeded", "failed"}, 180)
        self.assertEqual(job["status"], "succeeded", job)
        self.wait(lambda d: not self.css("#compare-running") and self.chart_ready("#cmp-vr")
                  and len(self.legend("#cmp-vr")) == 2, timeout=30,
                  message="the finished run drawn without a reload")
        outcome = self.css("#compare-table tr[data-field='metrics.outcome'] td")
        self.assertEqual([c.text for c in outcome[:2]], ["arrested", "arrested"])
        self.assert_no_console_errors("compare view while a run finishes")

    def test_nothing_picked_says_how_to_pick(self):
        self.open("/#/compare")
        self.wait(lambda d: len(self.css("#compare-empty")) == 1)
        self.assertIn("tick them in the jobs list", self.css("#compare-empty")[0].text)
        self.open("/#/compare?ids=0123456789abcdef0123456789abcdef,nonsense")
        self.wait(lambda d: len(self.css("#compare-empty")) == 1)
        errors = self.texts("#view p.error")
        self.assertTrue(any("nonsense" in e for e in errors), errors)
        self.assertTrue(any("no such job" in e for e in errors), errors)
        self.assert_no_console_errors("compare view of unknown runs", expected=["0123456789abcdef"])  # the 404 asked for


if __name__ == "__main__":
    run()

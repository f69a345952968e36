"""The web view's figures, study page and error pages in a real browser (headless
Chromium, Selenium) against `slipfront serve` on loopback (docs/web.md, "Tests"):

- the run page: V(t) at the paper's x1 = 6 and 10 m by default, in mm/s (the field endpoint's
  values × 1000); V_r(x1) on the same pixels and range as the map's x1 axis, also after a zoom
  by mouse; the map's colour scale equal to the CLI's (its colour_norm, imported), log and
  linear, grey or viridis; hover read-out; PNG and SVG export buttons that download a PNG and
  an SVG; a spectral BI run without "null", "height" or "stable —";
- the 404 pages of a job and a study: one message, no empty boxes;
- the study page: each convergence cell shows d and t against their tolerances, the failing
  one marked, as the server's numbers say; "finest mesh", never "no finer mesh yet", once the
  study has finished; the speed-accuracy chart joins runs only along a refinement (a repeated
  run of one mesh is a separate cross), checked on the server's data and on a made-up one;
(The submit form: test_web_form.py.)

    /usr/bin/python3 tests/web/test_web_views.py --binary build/slipfront --web-dir build/share/slipfront/web
"""

import math
import os
import re
import sys

import numpy as np
from browser_harness import BrowserCase, run
from selenium import webdriver
from selenium.webdriver.support.ui import Select

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, os.path.join(ROOT, "clients"))
sys.path.insert(0, os.path.join(HERE, "..", "server"))
from server_harness import wait_study  # noqa: E402
from slipfront_client.plots.slip_map import colour_norm  # noqa: E402

NOT_FOUND = " 404 "


def percent_in(text, symbol):
    """The percentage after `symbol` in a cell line such as "d 0.33 % < 0.5 %"."""
    m = re.match(rf"{symbol} ([0-9.e+-]+) %", text)
    return float(m.group(1)) if m else None


class WebViews(BrowserCase):
    @classmethod
    def setUpClass(cls):
        cls.start(workers=2)
        s = cls.server
        r = s.submit({"method": "spectral_bi", "name": "paper scene, BI"})
        assert r.status_code == 201, r.text
        cls.bi_run = s.wait_status(r.json()["id"], {"succeeded", "failed"}, 120)
        assert cls.bi_run["status"] == "succeeded", cls.bi_run
        r = s.post("/api/v1/studies", json={"name": "refinement", "base": {"method": "spectral_bi"},
                                            "convergence": {"L": [1e-4, 5e-5], "n_d": [10, 20, 40],
                                                            "n_d_max": 40}})
        assert r.status_code in (201, 202), r.text
        cls.study_id = r.json()["id"]
        wait_study(s, cls.study_id)
        # A second run of one mesh of the study's scene (fresh: not a cache hit) and an FE run
        # of the same scene (so that the chart shows both methods, from every run of the scene).
        extra = {}
        for key, spec in (("repeat", {"method": "spectral_bi", "friction": {"L": 1e-4},
                                      "geometry": {"nodes_per_meter": 10}, "fresh": True}),
                          ("fe", {"friction": {"L": 1e-4}, "geometry": {"nodes_per_meter": 10}})):
            r = s.submit(spec)
            assert r.status_code == 201, r.text
            extra[key] = s.wait_status(r.json()["id"], {"succeeded", "failed"}, 180)
            assert extra[key]["status"] == "succeeded", extra[key]
        cls.repeat_run, cls.fe_run = extra["repeat"], extra["fe"]

    def open_run(self, job_id):
        self.open(f"/#/jobs/{job_id}")
        self.wait(lambda d: self.chart_ready("#fig-map") and self.chart_ready("#fig-vr")
                  and self.chart_ready("#fig-vt"), timeout=60, message="the three figures")

    # -- the run page --------------------------------------------------------------------
    def test_run_positions_default_to_the_jobs_probes_in_mm_per_s(self):
        job_id = self.bi_run["id"]
        self.open_run(job_id)
        # The job's own probes: probe.spectrum_x1 = 6 m and probe.arrival_x1 = 11 m.
        self.assertEqual(self.css("#vt-x1")[0].get_attribute("value"), "6, 11")
        traces = self.chart_data("#fig-vt")
        self.assertEqual([t["name"] for t in traces],
                         ["x1 = 6 m (probe.spectrum_x1)", "x1 = 11 m (probe.arrival_x1)"])
        # The map marks them, in the curves' colours.
        marks = [t for t in self.chart_data("#fig-map") if t.get("name", "").startswith("x1 =")]
        np.testing.assert_allclose([t["x"][0] for t in marks], [6, 11], rtol=1e-9)  # the nodes
        # |V| in mm/s: the field endpoint's history at the node, times 1000.
        for trace, x in zip(traces, (6, 11)):
            field = self.server.get(f"/api/v1/jobs/{job_id}/fields/slip_velocity",
                                    params={"x1_min": x, "x1_max": x, "max_points": 4000}).json()
            expected = [abs(row[0]) * 1e3 for row in field["values"]]
            np.testing.assert_allclose(trace["y"], expected, rtol=1e-12)
        self.assertEqual(self.js("return document.getElementById('fig-vt').layout.yaxis.title.text"),
                         "|V| [mm/s]")
        self.assert_no_console_errors("run page")

    def test_the_map_opens_on_the_event_the_whole_box_one_click_away(self):
        """The map zooms to the event (where |V| exceeded 1 % of its peak, and the front) and a
        button shows the whole domain and run; the front is named with its threshold. For the
        paper's run, a bimaterial preset and the rock-scale example (screenshots)."""
        runs = {"paper": self.bi_run}
        for name, spec in (("bimaterial", {"preset": "bimaterial_prakash_clifton",
                                           "method": "spectral_bi", "geometry": {"nodes_per_meter": 2}}),
                           ("rock", {"preset": "rock_patch_nd2"})):
            r = self.server.submit(spec)
            self.assertEqual(r.status_code, 201, r.text)
            runs[name] = self.server.wait_status(r.json()["id"], {"succeeded", "failed"}, 300)
            self.assertEqual(runs[name]["status"], "succeeded", runs[name])
        for name, job in runs.items():
            with self.subTest(run=name):
                self.open_run(job["id"])
                spec = job["spec"]
                domain = [spec["geometry"]["x_min"], spec["geometry"]["x_min"] + spec["geometry"]["width"]]
                shown = self.plot_area("#fig-map")["range"]
                self.assertLess(shown[1] - shown[0], 0.8 * (domain[1] - domain[0]), shown)
                front = [t["name"] for t in self.chart_data("#fig-map") if t.get("name", "").startswith("slip front")]
                self.assertEqual(len(front), 1)
                self.assertRegex(front[0], r"^slip front \(\|V\| > [0-9.e+-]+ m/s\)$")
                self.assertIn("Zoomed to the event", " ".join(self.texts("#fig-map + .caption")))
                self.shot(f"run-{name}")
                button = self.css("#map-view")[0]
                self.assertEqual(button.text, "show the whole domain and run")
                self.js("arguments[0].scrollIntoView({block: 'center'})", button)
                button.click()
                self.wait(lambda d: self.plot_area("#fig-map")["range"][1] - self.plot_area("#fig-map")["range"][0]
                          > 0.95 * (domain[1] - domain[0]), message="the whole domain")
                self.wait(lambda d: self.plot_area("#fig-vr")["range"] == self.plot_area("#fig-map")["range"],
                          message="V_r follows")
                self.shot(f"run-{name}-whole")
                self.assertEqual(self.css("#map-view")[0].text, "zoom to the event")
        # The rock run's page lists the values it did not give, with where they came from.
        self.open_run(runs["rock"]["id"])
        checks = " ".join(self.texts("#job-checks"))
        self.assertIn("derived: a tenth of the duration 0.05 s", self.js(
            "return document.getElementById('job-checks').textContent"))
        self.assertIn("No warning", checks)
        self.assert_no_console_errors("run pages zoomed to the event")

    def test_rupture_speed_axis_is_the_maps_x1_axis(self):
        self.open_run(self.bi_run["id"])
        map_area, vr_area = self.plot_area("#fig-map"), self.plot_area("#fig-vr")
        self.assertAlmostEqual(map_area["left"], vr_area["left"], delta=0.5)
        self.assertAlmostEqual(map_area["width"], vr_area["width"], delta=0.5)
        self.assertEqual(map_area["range"], vr_area["range"])
        # Zoom the map by dragging across its plot area: V_r follows, still on the same pixels.
        area = self.css("#fig-map .nsewdrag[data-subplot=xy]")[0]
        self.js("arguments[0].scrollIntoView({block: 'center'})", area)
        width = area.rect["width"]
        (webdriver.ActionChains(self.driver).move_to_element_with_offset(area, -0.3 * width, 0)
         .click_and_hold().move_by_offset(0.2 * width, 10).move_by_offset(0.2 * width, 10)
         .release().perform())
        self.wait(lambda d: self.plot_area("#fig-map")["range"] != map_area["range"],
                  message="the map zoomed")
        self.wait(lambda d: self.plot_area("#fig-vr")["range"] == self.plot_area("#fig-map")["range"],
                  message="V_r follows the map's zoom")
        zoomed = self.plot_area("#fig-map")["range"]
        self.assertLess(zoomed[1] - zoomed[0], 0.6 * (map_area["range"][1] - map_area["range"][0]))
        self.assertAlmostEqual(self.plot_area("#fig-vr")["left"], map_area["left"], delta=0.5)

    def test_map_colour_scale_is_the_clis(self):
        self.open_run(self.bi_run["id"])

        def heat():
            return self.js("const t = document.getElementById('fig-map').data[0];"
                           "return {zmin: t.zmin, zmax: t.zmax, colorscale: t.colorscale, v: t.customdata.flat(),"
                           " title: document.getElementById('fig-map').layout.yaxis2.title.text}")
        shown = heat()
        v = np.array([np.nan if x is None else x for x in shown["v"]])
        norm, _ = colour_norm(v, "log")  # the CLI's, on the same |V| [mm/s]
        self.assertAlmostEqual(shown["zmin"], math.log10(norm.vmin), places=9)
        self.assertAlmostEqual(shown["zmax"], math.log10(norm.vmax), places=9)
        self.assertEqual(shown["colorscale"], [[0, "#ffffff"], [1, "#000000"]])  # darker = faster
        self.assertIn("|V| [mm/s] (log scale)", shown["title"])
        Select(self.css("#map-scale")[0]).select_by_value("linear")
        self.wait(lambda d: heat()["zmin"] == 0)
        shown = heat()
        norm, clipped = colour_norm(v, "linear")
        self.assertAlmostEqual(shown["zmax"], norm.vmax, delta=1e-9 * norm.vmax)
        self.assertEqual("clipped at top" in shown["title"], clipped)
        Select(self.css("#map-colours")[0]).select_by_value("viridis")
        self.wait(lambda d: heat()["colorscale"] == "Viridis")
        # Hover read-out: position, time and |V| with its unit.
        area = self.css("#fig-map .nsewdrag[data-subplot=xy]")[0]
        self.js("arguments[0].scrollIntoView({block: 'center'})", area)
        webdriver.ActionChains(self.driver).move_to_element_with_offset(area, 20, 0).pause(0.2) \
            .move_by_offset(2, 0).perform()
        self.wait(lambda d: "mm/s" in " ".join(self.texts("#fig-map .hovertext")),
                  message="a hover label with |V| in mm/s")
        self.assertIn("x1 =", " ".join(self.texts("#fig-map .hovertext")))

    def test_charts_export_png_and_svg(self):
        job_id = self.bi_run["id"]
        self.open_run(job_id)
        for chart in ("#fig-map", "#fig-vr", "#fig-vt"):
            titles = [b.get_attribute("data-title") for b in self.css(f"{chart} .modebar-btn")]
            self.assertIn("Download plot as PNG", titles, chart)
            self.assertIn("Download plot as SVG", titles, chart)
        for fmt in ("png", "svg"):
            button = self.css(f'#fig-map .modebar-btn[data-title="Download plot as {fmt.upper()}"]')[0]
            self.js("arguments[0].scrollIntoView({block: 'center'})", button)
            button.click()
        png = self.downloaded(f"slipfront-{job_id[:8]}-map.png")
        self.assertEqual(png[:8], b"\x89PNG\r\n\x1a\n")
        svg = self.downloaded(f"slipfront-{job_id[:8]}-map.svg").decode()
        self.assertTrue(svg.startswith("<svg"), svg[:80])
        self.assertIn("<image", svg)  # the heat map's raster
        self.assertIn("x1 [m]", svg)
        self.assert_no_console_errors("run page (exports)")

    def test_bi_run_page_has_no_null_and_no_empty_stable_step(self):
        self.open_run(self.bi_run["id"])
        cost = " ".join(self.texts("#job-live ~ .cols .card:nth-child(2) table.kv"))
        self.assertIn("mesh", cost)
        text = self.js("return document.getElementById('view').innerText")
        for bad in ("null", "stable —", "height", "undefined", "NaN"):
            self.assertNotIn(bad, text)
        self.assertRegex(cost, r"dx = [0-9.e-]+ m, nx = ")  # lengths with their unit
        # The result file and its XDMF sidecar, which names the HDF5 file's download name.
        job_id = self.bi_run["id"]
        self.assertEqual(self.css("#download")[0].get_attribute("download"), f"{job_id}.h5")
        xdmf = self.css("#download-xdmf")[0]
        self.assertEqual(xdmf.get_attribute("download"), f"{job_id}.xdmf")
        sidecar = self.server.get(xdmf.get_attribute("href").replace(self.server.base, ""))
        self.assertEqual(sidecar.status_code, 200)
        self.assertIn(f">{job_id}.h5:/interface/slip_velocity<", sidecar.text)
        # The FE run of the same scene does have a stable step and a height.
        self.open(f"/#/jobs/{self.fe_run['id']}")
        self.wait(lambda d: "stable" in " ".join(self.texts(".cols table.kv")))
        self.assertRegex(" ".join(self.texts(".cols table.kv")), r"height = [0-9.]+ m")

    def test_404_pages_have_no_empty_boxes(self):
        for path, what in (("/#/jobs/0123456789abcdef0123456789abcdef", "No job"),
                           ("/#/studies/0123456789abcdef0123456789abcdef", "No study")):
            self.open(path)
            self.wait(lambda d: self.css("#not-found"), message=f"{path}: the not-found card")
            self.assertIn(what, self.css("#not-found h1")[0].text)
            self.assertEqual(len(self.css("#view .card")), 1, "only the message, no empty boxes")
            self.assertEqual(self.css("#view .pagehead"), [])
            self.assertEqual(len(self.css("#not-found a[href]")), 1)  # the way back
            self.assert_no_console_errors(path, expected=(NOT_FOUND,))
            self.shot("job-404" if "jobs" in path else "study-404")

    # -- the study page ------------------------------------------------------------------
    def test_convergence_cells_show_the_deciding_criterion(self):
        study = self.server.get(f"/api/v1/studies/{self.study_id}").json()
        self.assertEqual(study["status"], "finished")
        tol = study["critical_length"]["tolerances"]
        cells = {c["run_id"]: c for c in study["convergence_map"]["cells"]}
        self.open(f"/#/studies/{self.study_id}")
        self.wait(lambda d: self.css("#study-cmap td.cell"))
        rendered = self.js(
            "return [...document.querySelectorAll('#study-cmap td.cell')].map(td => ({"
            " run: (td.querySelector('a') || {}).getAttribute?.call(td.querySelector('a'), 'href') || '',"
            " cls: td.className, label: td.querySelector('a')?.textContent,"
            " against: td.querySelector('.against')?.textContent,"
            " crit: [...td.querySelectorAll('.crit')].map(c => [c.textContent, c.className])}))")
        judged = 0
        for cell in rendered:
            if not cell["run"]:
                continue
            api = cells[cell["run"].rsplit("/", 1)[1]]
            self.assertNotEqual(cell["label"], "no finer mesh yet", "the study has finished")
            if api["status"] == "unknown":
                self.assertEqual(cell["label"], "finest mesh")
            if api["status"] not in ("converged", "not_converged"):
                continue
            judged += 1
            self.assertEqual(cell["against"], f"vs n_d = {api['partner_n_d']:g}")
            bad = []
            for symbol, key, tol_key in (("d", "propagation_distance", "propagation_distance"),
                                         ("t", "arrival_time", "arrival_time")):
                line = next(c for c in cell["crit"] if c[0].startswith(symbol))
                change = api["changes"][key]
                self.assertAlmostEqual(percent_in(line[0], symbol), 100 * change,
                                       delta=0.05 * 100 * change + 1e-9)  # two digits shown
                fails = not change < tol[tol_key]
                self.assertEqual("crit-bad" in line[1], fails, line)
                self.assertIn(("≥ " if fails else "< ") + f"{100 * tol[tol_key]:g} %", line[0])
                bad.append(fails)
            self.assertEqual(any(bad), api["status"] == "not_converged", cell)
        self.assertGreaterEqual(judged, 4, "each L has two judged meshes")
        self.assertNotIn("unknown", " ".join(self.texts("#study-runs .badge")))
        self.assert_no_console_errors("study")

    def test_l_search_panel_shows_the_verdict_and_each_step(self):
        # An L search on the paper's scene by BI (docs/studies-api.md "L search"), started
        # near its L_c so that it ends in three L: 1.6e-6 differs from 8e-7, which agrees with 4e-7.
        r = self.server.post("/api/v1/studies", json={
            "name": "L search", "base": {"method": "spectral_bi"},
            "convergence": {"search": {"from": 1.6e-6, "factor": 2}}})
        self.assertEqual(r.status_code, 201, r.text)
        study = wait_study(self.server, r.json()["id"], timeout=300)
        search = study["search"]
        self.assertEqual(search["state"], "found", search)
        self.open(f"/#/studies/{study['id']}")
        self.wait(lambda d: self.css("#search-steps tbody tr"), message="the search's steps")
        self.assertEqual(self.texts("#search-state"), ["L_c found"])
        self.assertEqual(self.texts("#search-reason"), [search["reason"]])
        rows = self.js("return [...document.querySelectorAll('#search-steps tbody tr')]"
                       ".map(tr => [tr.className, tr.cells[0].textContent, tr.cells[3].textContent])")
        self.assertEqual(len(rows), len(search["steps"]))
        for row, step in zip(rows, search["steps"]):
            self.assertEqual(row[2], "agree" if step["agree"] else "differ")
            self.assertEqual(row[0], "agree" if step["agree"] else "differ")
        lc = self.texts("#lc-value")[0]
        self.assertTrue(lc.endswith(" m") and "not determined" not in lc, lc)
        # The headline answer first: the search's verdict with its bracket, then labelled numbers.
        self.assertEqual(self.texts("#answer-verdict"), [study["answer"]["verdict"]])
        self.assertTrue(study["answer"]["verdict"].startswith(f"L_c = {search['L_c']:g} m, in ["),
                        study["answer"])
        order = self.js("return [...document.querySelectorAll('#view section.card')].map(s => s.id)")
        self.assertEqual(order[0], "study-answer")
        self.assertIn("not the rule's answer", " ".join(self.texts("#study-answer")))
        # Plain Coulomb beside the L (the paper scene is well-posed under it): one row per L.
        coulomb = search["coulomb"]
        self.assertIn(coulomb["status"], self.texts("#search-coulomb p")[0])
        self.assertEqual(len(self.css("#search-coulomb tbody tr")), len(coulomb["steps"]))
        self.shot("study-l-search")
        self.assert_no_console_errors("study with an L search")

    def test_accuracy_study_shows_the_answer_and_its_meshes(self):
        # The paper scene's arrest position within 0.5 % (docs/studies-api.md "Accuracy target").
        r = self.server.post("/api/v1/studies", json={
            "name": "arrest 0.5 %", "accuracy": {"metric": "arrest_position", "tolerance": 0.005}})
        self.assertEqual(r.status_code, 201, r.text)
        study = wait_study(self.server, r.json()["id"], timeout=300)
        answer = study["accuracy"]
        self.assertEqual(answer["state"], "met", answer)
        self.open(f"/#/studies/{study['id']}")
        self.wait(lambda d: self.chart_ready("#fig-accuracy"), message="the accuracy chart")
        self.assertEqual(self.texts("#accuracy-state"), ["target met"])
        self.assertIn(f"± {answer['error']:g}", self.texts("#accuracy-answer")[0])
        self.assertEqual(len(self.css("#accuracy-steps tbody tr")), len(answer["steps"]))
        trace = self.chart_data("#fig-accuracy")[0]
        self.assertEqual(trace["x"], [s["n_d"] for s in answer["steps"]])
        self.assertEqual(trace["y"], [s["value"] for s in answer["steps"]])
        self.assertEqual(self.texts("#lc-value"), [])  # one L: no critical length on this page
        self.shot("study-accuracy")
        self.assert_no_console_errors("accuracy study")

    def test_speed_accuracy_joins_runs_only_along_refinements(self):
        sa = self.server.get(f"/api/v1/studies/{self.study_id}/speed-accuracy").json()
        entries = {e["id"]: e for e in sa["across_methods"]["runs"]}
        self.assertIn(self.repeat_run["id"], entries)
        self.open(f"/#/studies/{self.study_id}")
        self.wait(lambda d: self.chart_ready("#fig-speed"), message="the speed-accuracy chart")
        traces = self.chart_data("#fig-speed")
        lines = [t for t in traces if "lines" in t["mode"]]
        self.assertGreaterEqual(len(lines), 3)  # BI at two L, FE at one
        shown = []
        for t in lines:
            runs = [entries[c[0]] for c in t["customdata"]]
            self.assertEqual(len({(e.get("method"), e["L"]) for e in runs}), 1, t["name"])
            n_d = [e["n_d"] for e in runs]
            self.assertEqual(n_d, sorted(set(n_d)), f"{t['name']}: one run per mesh, coarse to fine")
            shown += [e["id"] for e in runs]
        repeats = [c[0] for t in traces if t["mode"] == "markers" for c in t["customdata"]]
        # The two runs of the repeated mesh: one on its curve, the other a cross beside it.
        twins = {self.repeat_run["id"], self._twin_of_repeat(entries)}
        self.assertEqual(len(twins & set(shown)), 1)
        self.assertEqual(len(twins & set(repeats)), 1)
        # Every run with a positive error is shown once.
        def error(e):
            both = [v for v in (e["errors"]["propagation_distance"], e["errors"]["arrival_time"])
                    if v is not None and v > 0]
            return max(both) if both else None
        expected = sorted(i for i, e in entries.items() if error(e) and e["wall_time_s"] > 0)
        self.assertEqual(sorted(shown + repeats), expected)
        # The same rule on made-up entries: wall times out of mesh order and a repeated mesh.
        curves = self.driver.execute_async_script(
            "const done = arguments[arguments.length - 1];"
            "import('/app/speed_chart.js').then(m => done(m.refinementCurves(arguments[0], 'max', 'fe')"
            ".map(c => ({method: c.method, L: c.L, runs: c.runs.map(e => e.id), repeats: c.repeats.map(e => e.id)}))));",
            [{"id": "c", "L": 1e-4, "n_d": 40, "wall_time_s": 1.0, "errors": {"propagation_distance": 0.01}},
             {"id": "a", "L": 1e-4, "n_d": 10, "wall_time_s": 3.0, "errors": {"propagation_distance": 0.03}},
             {"id": "b", "L": 1e-4, "n_d": 20, "wall_time_s": 0.5, "errors": {"arrival_time": 0.02}},
             {"id": "a2", "L": 1e-4, "n_d": 10, "wall_time_s": 0.1, "errors": {"propagation_distance": 0.03}},
             {"id": "z", "L": 1e-4, "n_d": 80, "wall_time_s": 9.0, "errors": {"propagation_distance": 0}},
             {"id": "s", "L": 1e-4, "n_d": 10, "wall_time_s": 0.2, "method": "spectral_bi",
              "errors": {"propagation_distance": 0.05}}])
        self.assertEqual(curves, [{"method": "fe", "L": 1e-4, "runs": ["a", "b", "c"], "repeats": ["a2"]},
                                  {"method": "spectral_bi", "L": 1e-4, "runs": ["s"], "repeats": []}])
        self.assert_no_console_errors("study (speed-accuracy)")

    def _twin_of_repeat(self, entries):
        """The study's own run of the repeated mesh (BI, L = 1e-4, n_d = 10)."""
        return next(i for i, e in entries.items() if i != self.repeat_run["id"]
                    and e.get("method") == "spectral_bi" and e["L"] == 1e-4 and e["n_d"] == 10)

if __name__ == "__main__":
    run()

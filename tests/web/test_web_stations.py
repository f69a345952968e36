"""The on-fault stations on a run's page in a real browser (headless Chromium, Selenium)
against `slipfront serve` on loopback (docs/web.md, "Tests"):

- the `bimaterial_prakash_clifton` preset by BI (ten stations, every one ruptured): (d) the
  rupture time against x1 has one marker per station at the server's rupture time (in ms, the
  run lasts 0.1 s) and the slip front of /front, the threshold stated; the table lists the
  same times; (e) four panels — slip rate, slip, shear and normal traction against time — each
  with one trace per station named by its x1, holding the /stations values in the stated unit
  (m/s, mm, MPa, MPa), one legend entry per station shared by the four panels; the CSV link
  downloads the stations' CSV;
- (c), the rupture speed of the paper's figures, for that run between two solids given by their
  wave speeds: both solids' c_s and c_p named, the axis to 1.1 c_p of the faster one, the
  overstressed patch shaded;
- the page's header names the run: method, "bimaterial", the law by its scale parameter, n_d;
- a small run with a station the rupture never reaches: no marker for it, "never" in the
  table and in the caption, times in s (the run lasts 3 s);
- a run without stations: no stations card, no empty box, the paper's figures as before.

    /usr/bin/python3 tests/web/test_web_stations.py --binary build/slipfront --web-dir build/share/slipfront/web
"""

import os
import time

import numpy as np
from browser_harness import CONFIG, BrowserCase, run

QUANTITIES = (("slip_rate", "slip rate V [m/s]", 1.0), ("slip", "slip δ [mm]", 1e3),
              ("shear_traction", "shear traction τ [MPa]", 1e-6),
              ("normal_traction", "normal traction σ [MPa]", 1e-6))
# The paper's scene on [-1, 11) at n_d = 5, 3 s, by BI: the slip passes 1.0 and 2.1 and never
# reaches 10.5 (|V| there stays below 1e-4 m/s; tests/server/test_stations_http.py).
SMALL = {"method": "spectral_bi", "name": "small, with stations",
         "geometry": {"nodes_per_meter": 5, "width": 12, "x_min": -1},
         "probe": {"arrival_x1": 3, "spectrum_x1": 3}, "time": {"duration": 3},
         "stations": {"x1": [1.0, 2.1, 10.5], "rupture_threshold": 1e-4}}


class WebStations(BrowserCase):
    @classmethod
    def setUpClass(cls):
        cls.start(workers=2)
        cls.runs = {}
        for key, spec in (("preset", {"preset": "bimaterial_prakash_clifton", "method": "spectral_bi"}),
                          ("small", SMALL),
                          ("plain", {**SMALL, "name": "small, plain", "stations": {}})):
            r = cls.server.submit(spec)
            assert r.status_code == 201, r.text
            cls.runs[key] = r.json()["id"]
        for key, job_id in cls.runs.items():
            job = cls.server.wait_status(job_id, {"succeeded", "failed"}, 240)
            assert job["status"] == "succeeded", job
            cls.runs[key] = job

    def open_stations(self, job_id):
        self.open(f"/#/jobs/{job_id}")
        self.wait(lambda d: self.chart_ready("#fig-rupture-time") and self.chart_ready("#fig-stations"),
                  timeout=60, message="the station figures")

    def traces(self, selector):
        return self.js("return document.querySelector(arguments[0]).data.map(t => ({name: t.name,"
                       " mode: t.mode, x: t.x, y: t.y, xaxis: t.xaxis || 'x', yaxis: t.yaxis || 'y',"
                       " legendgroup: t.legendgroup, showlegend: t.showlegend !== false}))", selector)

    def layout(self, selector, key):
        return self.js("return document.querySelector(arguments[0]).layout[arguments[1]]", selector, key)

    def shot_card(self, selector, name):
        """A screenshot of one element (docs/figures/web-job-stations.png is one)."""
        if not CONFIG["shots"]:
            return
        os.makedirs(CONFIG["shots"], exist_ok=True)
        card = self.css(selector)[0]
        self.driver.set_window_size(1400, 4000)  # the whole card in the window
        self.js("arguments[0].scrollIntoView({block: 'start'})", card)
        time.sleep(0.5)
        card.screenshot(os.path.join(CONFIG["shots"], f"{name}.png"))
        self.driver.set_window_size(1400, 1000)

    def test_preset_rupture_times_and_front(self):
        job = self.runs["preset"]
        st = self.server.get(f"/api/v1/jobs/{job['id']}/stations").json()
        front = self.server.get(f"/api/v1/jobs/{job['id']}/front").json()
        self.open_stations(job["id"])
        self.assertIn("exceeds 0.001 m/s", self.css("#rupture-threshold")[0].text)
        traces = {t["name"]: t for t in self.traces("#fig-rupture-time")}
        markers = traces["stations (|V| > 0.001 m/s)"]
        self.assertEqual(markers["x"], st["x1"])  # every station ruptured
        np.testing.assert_allclose(markers["y"], np.array(st["rupture_time"]) * 1e3, rtol=1e-12)
        line = traces["slip front, every node (|V| > 0.001 m/s)"]
        order = np.argsort(front["x1"])
        np.testing.assert_allclose(line["x"], np.array(front["x1"])[order])
        arrival = np.array([np.nan if t is None else t for t in front["arrival_time"]])[order] * 1e3
        shown = np.array([np.nan if t is None else t for t in line["y"]])
        np.testing.assert_allclose(shown, arrival, rtol=1e-12)  # nan where never, as the front
        self.assertIn("nucleation patch (-10 to 10 m)", traces)
        self.assertEqual(self.layout("#fig-rupture-time", "yaxis")["title"]["text"], "rupture time [ms]")
        self.assertEqual(self.layout("#fig-rupture-time", "xaxis")["title"]["text"], "x1 [m]")
        head, times = self.js("return [...document.querySelectorAll('.stations-table tr')]"
                              ".map(r => [...r.children].map(c => c.textContent))")
        self.assertEqual(head[0], "station x1 [m]")
        self.assertEqual([float(v) for v in head[1:]], st["x1"])
        self.assertEqual(times[0], "rupture time [ms]")
        np.testing.assert_allclose([float(v) for v in times[1:]], np.array(st["rupture_time"]) * 1e3,
                                   rtol=1e-5)  # six digits shown
        self.assert_no_console_errors("stations of the preset")
        self.shot("job-stations")
        self.shot_card("#job-stations", "job-stations-card")

    def test_preset_time_series_per_station(self):
        job = self.runs["preset"]
        st = self.server.get(f"/api/v1/jobs/{job['id']}/stations").json()
        self.assertEqual(st["stride"], 1)
        self.open_stations(job["id"])
        traces = self.traces("#fig-stations")
        names = [f"x1 = {x:g} m" for x in st["x1"]]
        self.assertEqual(len(traces), len(QUANTITIES) * len(names))
        time_ms = np.array(st["time"]) * 1e3
        for k, (key, title, scale) in enumerate(QUANTITIES):
            suffix = str(k + 1) if k else ""
            panel = [t for t in traces if t["yaxis"] == f"y{suffix}"]
            self.assertEqual([t["name"] for t in panel], names, key)
            self.assertEqual(self.layout("#fig-stations", f"yaxis{suffix}")["title"]["text"], title)
            values = np.array(st[key]) * scale
            for i, t in enumerate(panel):
                self.assertEqual(t["xaxis"], f"x{suffix}")
                np.testing.assert_allclose(t["x"], time_ms, rtol=1e-12)
                np.testing.assert_allclose(t["y"], values[:, i], rtol=1e-12, err_msg=f"{key} {names[i]}")
                self.assertEqual(t["legendgroup"], f"station-{i}")
                self.assertEqual(t["showlegend"], k == 0)  # one legend entry per station
        self.assertEqual(self.layout("#fig-stations", "xaxis4")["title"]["text"], "t [ms]")
        self.assertIn("Every time step of the run (3092)", self.css("#stations-caption")[0].text)
        self.assertIn("negative in compression", self.css("#stations-caption")[0].text)
        link = self.css("#stations-csv")[0]
        self.assertTrue(link.get_attribute("href").endswith(f"/api/v1/jobs/{job['id']}/stations.csv"))
        self.js("arguments[0].scrollIntoView({block: 'center'})", link)
        link.click()
        csv = self.downloaded(f"{job['id']}-stations.csv").decode()
        self.assertIn("station_x1,time,slip,slip_rate,shear_traction,normal_traction", csv)
        self.assert_no_console_errors("stations of the preset (time series)")

    def test_preset_rupture_speed_has_both_solids(self):
        # (c) of the paper's figures for a run between two solids given by wave speeds: each
        # solid's c_s and c_p as a named line, the axis to 1.1 c_p of the faster, the patch.
        spec = self.runs["preset"]["spec"]
        self.open_stations(self.runs["preset"]["id"])
        self.wait(lambda d: self.chart_ready("#fig-vr"), message="V_r")
        notes = {a["text"] for a in self.layout("#fig-vr", "annotations")}
        upper, lower = spec["material"], spec["lower"]
        for name, v in (("c_s upper", upper["s_wave_speed"]), ("c_p upper", upper["p_wave_speed"]),
                        ("c_s lower", lower["s_wave_speed"]), ("c_p lower", lower["p_wave_speed"])):
            self.assertIn(f"{name} = {float(f'{v:.3g}'):g} m/s", notes)
        lines = sorted(sh["y0"] for sh in self.layout("#fig-vr", "shapes") if sh["type"] == "line")
        np.testing.assert_allclose(lines, sorted([upper["s_wave_speed"], upper["p_wave_speed"],
                                                  lower["s_wave_speed"], lower["p_wave_speed"]]))
        np.testing.assert_allclose(self.layout("#fig-vr", "yaxis")["range"],
                                   [0, 1.1 * lower["p_wave_speed"]])
        self.assertIn("nucleation patch (-10 to 10 m)", [t["name"] for t in self.traces("#fig-vr")])

    def test_header_names_the_run(self):
        # The method, what is below the interface, the law by its scale parameter, n_d.
        self.open_stations(self.runs["preset"]["id"])
        self.assertTrue(self.css(".pagehead .sub")[0].text.startswith(
            "spectral BI · bimaterial · L = 0.001 m · n_d = 5 /m · id "))
        self.open_stations(self.runs["small"]["id"])  # the paper's law on the rigid plane
        self.assertTrue(self.css(".pagehead .sub")[0].text.startswith("spectral BI · L = "))
        texts = self.driver.execute_async_script(
            "const done = arguments[arguments.length - 1];"
            "import('/app/jobs.js').then(m => done(arguments[0].map(f => m.frictionText({friction: f}))));",
            [{"law": "coulomb"}, {"law": "coulomb", "regularization": "time_scale", "t_star": 3.5e-4},
             {"law": "slip_weakening", "D_c": 0.4},
             {"law": "slip_weakening", "D_c": 7.44e-4, "regularization": "time_scale", "t_star": 3.5e-4},
             {"law": "slip_weakening", "D_c": 1e-3, "regularization": "slip_scale", "L": 1e-4}])
        self.assertEqual(texts, ["Coulomb", "t* = 3.50e-4 s", "slip weakening D_c = 0.4 m",
                                 "slip weakening D_c = 7.44e-4 m, t* = 3.50e-4 s",
                                 "slip weakening D_c = 0.001 m, L = 1.00e-4 m"])

    def test_station_never_reached_is_said(self):
        job = self.runs["small"]
        st = self.server.get(f"/api/v1/jobs/{job['id']}/stations").json()
        self.assertIsNone(st["rupture_time"][2])
        self.open_stations(job["id"])
        markers = next(t for t in self.traces("#fig-rupture-time") if t["mode"] == "markers")
        self.assertEqual(markers["x"], [1.0, 2.1])
        np.testing.assert_allclose(markers["y"], st["rupture_time"][:2], rtol=1e-12)  # in s
        self.assertEqual(self.layout("#fig-rupture-time", "yaxis")["title"]["text"], "rupture time [s]")
        self.assertIn("Never ruptured", self.css("#rupture-time-caption")[0].text)
        self.assertIn("x1 = 10.5 m", self.css("#rupture-time-caption")[0].text)
        self.assertEqual(self.texts(".stations-table tr:last-child td")[-1], "never")
        self.assertIn("exceeds 0.0001 m/s", self.css("#rupture-threshold")[0].text)
        self.assertEqual(len(self.traces("#fig-stations")), 4 * 3)
        self.assert_no_console_errors("stations of the small run")

    def test_run_without_stations_shows_nothing_extra(self):
        job = self.runs["plain"]
        self.assertNotIn("stations", job["spec"])
        self.open(f"/#/jobs/{job['id']}")
        self.wait(lambda d: self.chart_ready("#fig-map") and self.chart_ready("#fig-vt"),
                  timeout=60, message="the paper's figures")
        self.assertEqual(self.css("#job-stations"), [])
        self.assertEqual(self.css("#fig-rupture-time, #fig-stations, #stations-csv"), [])
        self.assertNotIn("station", self.js("return document.getElementById('view').innerText").lower())
        # Every card on the page has something in it (no empty box).
        self.assertEqual(self.js("return [...document.querySelectorAll('#view .card')]"
                                 ".filter(c => !c.innerText.trim()).length"), 0)
        self.assert_no_console_errors("a run without stations")


if __name__ == "__main__":
    run()

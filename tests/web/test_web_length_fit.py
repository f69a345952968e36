"""The length-fit page (web/app/length_fit.js, docs/length-fit.md) in headless Chromium against
`slipfront serve` on loopback: a BI job of the paper's scene with stations at x1 = 4 and 6 m
(L = 3e-4 m) taken by its id, one station chosen and fitted: the verdict, L_m and f_m are the
server's; the stress chart draws the answer's measured and fitted series, the spectrum chart
f_m where the answer puts it. A file upload of a run below L_c (L = 1e-6 m) reads "upper
bound"; a bad record shows its line and column beside the record box.

    /usr/bin/python3 tests/web/test_web_length_fit.py --binary build/slipfront --web-dir build/share/slipfront/web
"""

import os
import tempfile

from browser_harness import BrowserCase, run
from selenium.webdriver.support.ui import Select


def scene(L, stations):
    return {"method": "spectral_bi", "geometry": {"nodes_per_meter": 10}, "friction": {"L": L},
            "stations": {"x1": stations}}


class LengthFitPage(BrowserCase):
    @classmethod
    def setUpClass(cls):
        cls.start(workers=2)
        cls.jobs = {}
        for key, spec in (("rich", scene(3e-4, [4, 6])), ("bound", scene(1e-6, [6]))):
            r = cls.server.submit(spec)
            assert r.status_code == 201, r.text
            job = cls.server.wait_status(r.json()["id"], {"succeeded", "failed"}, 120)
            assert job["status"] == "succeeded", job
            cls.jobs[key] = job["id"]
        cls.tmp = tempfile.mkdtemp(prefix="slipfront-length-fit-")

    def csv(self, key):
        r = self.server.get(f"/api/v1/jobs/{self.jobs[key]}/stations.csv")
        self.assertEqual(r.status_code, 200)
        return r.text

    def answer(self, body):
        r = self.server.post("/api/v1/length-fits", json=body)
        self.assertEqual(r.status_code, 200, r.text)
        return r.json()

    def fit_and_wait(self):
        self.css("#fit-submit")[0].click()
        self.wait(lambda d: self.chart_ready("#fig-fit-stress") and self.chart_ready("#fig-fit-spectrum"),
                  timeout=60, message="the two charts")

    def test_a_jobs_station_is_fitted_as_the_server_says(self):
        self.open("/#/length-fit")
        self.wait(lambda d: self.css("#fit-job"))
        self.css("#fit-job")[0].send_keys(self.jobs["rich"])
        self.css("#fit-job-load")[0].click()
        self.wait(lambda d: self.css("#fit-station")[0].is_displayed(), message="the station list")
        select = Select(self.css("#fit-station")[0])
        self.assertEqual([o.text for o in select.options], ["4", "6"])
        select.select_by_visible_text("6")
        self.fit_and_wait()
        expected = self.answer({"record": self.csv("rich"), "station_x1": 6})
        verdict = self.css("#fit-verdict")[0]
        self.assertEqual(verdict.text, expected["verdict"]["text"])
        self.assertIn("rich", verdict.get_attribute("class"))
        self.assertEqual(self.css("#fit-reason")[0].text, expected["verdict"]["reason"])
        L = float(self.css("#fit-L")[0].text.split()[0])
        self.assertAlmostEqual(L / expected["fit"]["L"], 1, delta=1e-3)  # 4 digits shown
        low, high = expected["fit"]["L_interval_95"]
        self.assertTrue(low <= 3e-4 <= high, expected["fit"])

        traces = {t["name"]: t for t in self.chart_data("#fig-fit-stress")}
        series = expected["series"]
        self.assertEqual(traces["measured"]["x"], series["time"])
        self.assertEqual(traces["measured"]["y"], series["frictional_stress"])
        fitted = next(t for name, t in traces.items() if name.startswith("fitted strength"))
        self.assertEqual(fitted["y"], series["fitted_stress"])
        slipping = traces["measured, slipping (fitted)"]
        self.assertEqual(len(slipping["x"]), expected["record"]["slipping_samples"])
        spectrum = {t["name"]: t for t in self.chart_data("#fig-fit-spectrum")}
        f_m = expected["critical_frequency"]["f_m"]
        line = next(t for name, t in spectrum.items() if name.startswith("f_m ="))
        self.assertEqual(line["x"], [f_m, f_m])
        self.assertTrue(self.js("return document.querySelector('#fig-fit-spectrum')._fullLayout"
                                ".xaxis.type") == "log")
        self.shot("length-fit")
        self.assert_no_console_errors("the length-fit page")

    def test_an_uploaded_record_below_the_critical_length_is_an_upper_bound(self):
        path = os.path.join(self.tmp, "bound.csv")
        with open(path, "w") as f:
            f.write(self.csv("bound"))
        self.open("/#/length-fit")
        self.wait(lambda d: self.css("#fit-file"))
        self.css("#fit-file")[0].send_keys(path)
        self.wait(lambda d: "bound.csv" in self.css("#fit-load-note")[0].text)
        self.assertFalse(self.css("#fit-station")[0].is_displayed())  # one station: no choice
        self.fit_and_wait()
        verdict = self.css("#fit-verdict")[0]
        self.assertIn("the event is not rich enough to measure the length", verdict.text)
        self.assertIn("bound", verdict.get_attribute("class"))
        self.assertIn("the physical length is at most", self.css("#fit-result")[0].text)
        self.shot("length-fit-upper-bound")

    def test_a_bad_record_shows_its_line_and_column(self):
        lines = self.csv("bound").split("\n")
        at = next(i for i, line in enumerate(lines) if line.startswith("6,")) + 3
        cells = lines[at].split(",")
        cells[3] = "fast"
        lines[at] = ",".join(cells)
        self.open("/#/length-fit")
        self.wait(lambda d: self.css("#fit-record"))
        self.js("const r = document.querySelector('#fit-record'); r.value = arguments[0];"
                "r.dispatchEvent(new Event('input'))", "\n".join(lines))
        self.css("#fit-submit")[0].click()
        message = f'line {at + 1}, column "slip_rate": not a number: "fast"'
        self.wait(lambda d: message in " ".join(self.texts(".ferr")), message="the error beside the record")
        self.assertIn("invalid", self.css("#fit-record")[0].get_attribute("class"))
        self.assertTrue(self.css("#fit-result")[0].get_attribute("hidden") is not None)
        self.assert_no_console_errors("the length-fit page", expected=["length-fits"])


if __name__ == "__main__":
    run()

"""The web view in a real browser: headless Chromium driven by Selenium (Debian's chromium,
chromium-driver and python3-selenium) against `slipfront serve` on an ephemeral loopback
port (docs/web.md).

Each page loads with no console error; a hostile job name stays text; a job submitted through
the form appears in the table, shows moving progress on its page and ends with its figures
(Plotly charts drawn from /fields and /front); a field error of the server's problem+json is shown
beside its field; a study started from the form fills in its convergence map; the API docs
render; cancelling needs the owner's token. The figures, the study page's details, the form
built from the schema, the presets and the 404 pages are tested in test_web_views.py.
Screenshots of every page go to --screenshots (build/web-screenshots by ctest).

Exit 77 (ctest: skipped) with a message when Chromium or its driver cannot start.

    /usr/bin/python3 tests/web/test_browser.py --binary build/slipfront --screenshots /tmp/shots
"""

import os
import sys
import time

from browser_harness import CONFIG, BrowserCase, Server, run, server_args
from selenium import webdriver
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "server"))
from server_harness import long_job  # noqa: E402

HOSTILE = '<img src=x onerror="window.__pwned=1">&amp;"\'</td>'


class WebView(BrowserCase):
    @classmethod
    def setUpClass(cls):
        cls.start(workers=2)
        # Jobs that exist before the pages are opened: a quick BI run, a quick FE run and one
        # whose name is markup.
        cls.seeded = {}
        for key, spec in (("bi", {"method": "spectral_bi", "name": "BI L=1e-4",
                                  "tags": ["web", "seed"], "friction": {"L": 1e-4}}),
                          ("fe", {"name": "FE coarse", "geometry": {"nodes_per_meter": 5},
                                  "time": {"duration": 4.0}}),
                          ("hostile", {"method": "spectral_bi", "name": HOSTILE,
                                       "tags": ["<b>bold</b>"], "time": {"duration": 1.0}})):
            r = cls.server.submit(spec)
            assert r.status_code == 201, r.text
            cls.seeded[key] = r.json()["id"]
        for job_id in cls.seeded.values():
            cls.server.wait_status(job_id, {"succeeded", "failed", "cancelled"}, 120)

    # -- tests (run in name order) -------------------------------------------------------
    def test_1_jobs_page_lists_escaped_and_sorts(self):
        self.open("/")
        self.wait(lambda d: len(self.css("#jobs-table tbody tr[data-id]")) >= 3,
                  message="the seeded jobs are listed")
        rows = self.css("#jobs-table tbody tr[data-id]")
        names = [r.find_element(By.CSS_SELECTOR, ".jobname").text for r in rows]
        self.assertIn(HOSTILE, names)  # shown as text...
        self.assertEqual(self.css("#jobs-table img"), [])  # ...never as markup
        self.assertEqual(self.css("#jobs-table b"), [])
        self.assertIsNone(self.driver.execute_script("return window.__pwned"))
        # Filter in the page.
        box = self.css("#job-filter")[0]
        box.send_keys("coarse")
        self.wait(lambda d: len(self.css("#jobs-table tbody tr[data-id]")) == 1)
        self.driver.execute_script(
            "const b = document.getElementById('job-filter'); b.value = '';"
            "b.dispatchEvent(new Event('input'));")
        self.wait(lambda d: len(self.css("#jobs-table tbody tr[data-id]")) >= 3)
        # Sort by L: ascending then descending.
        header = [th for th in self.css("#jobs-table thead th") if th.text.startswith("L [m]")][0]
        header.click()
        self.wait(lambda d: "▲" in self.css("#jobs-table thead th.sorted")[0].text)
        self.assert_no_console_errors("jobs")
        self.shot("jobs")

    def test_2_submit_form_shows_field_errors(self):
        self.open("/#/submit")
        self.wait(lambda d: self.css("#f_material_poisson_ratio"), message="the form is built")
        field = self.css("#f_material_poisson_ratio")[0]
        field.clear()
        field.send_keys("0.7")
        self.css("#job-submit")[0].click()
        self.wait(lambda d: field.find_element(By.XPATH, "..").find_element(
            By.CSS_SELECTOR, ".ferr").text != "", message="the error is beside the field")
        text = field.find_element(By.XPATH, "..").find_element(By.CSS_SELECTOR, ".ferr").text
        self.assertIn("0.5", text)
        self.assertIn("invalid", field.get_attribute("class"))
        # The browser logs the 422 answer itself as a failed resource load: expected here.
        self.assert_no_console_errors("submit (422)", expected=(" 422 ",))
        self.shot("submit-job-error")

    def test_3_job_from_the_form_progresses_and_ends_with_figures(self):
        # The paper's run: the form untouched but for a name (its defaults are the paper's
        # scene; several seconds on this machine, long enough to watch it progress).
        self.open("/#/submit")
        self.wait(lambda d: self.css("#f_geometry_nodes_per_meter"), message="the form is built")
        self.css("#f_name")[0].send_keys("paper run, from the form")
        self.shot("submit-job")
        self.css("#job-submit")[0].click()
        self.wait(lambda d: "#/jobs/" in d.current_url, message="the job page opens")
        job_id = self.driver.current_url.rsplit("/", 1)[1]
        self.assertEqual(len(job_id), 32)
        # Moving progress: at least two different fractions while it runs, or (on a fast
        # machine) a finished run.
        seen = set()
        running_shot = False
        deadline = time.monotonic() + 240
        while time.monotonic() < deadline:
            text = " ".join(self.texts("#job-live .ptext"))
            if "%" in text and "ETA" in text:
                seen.add(text.split("%")[0])
                if not running_shot and len(seen) >= 3:
                    self.shot("job-running")
                    running_shot = True
            if self.chart_ready("#fig-map") and self.chart_ready("#fig-vr"):
                break
            time.sleep(0.15)
        self.assertTrue(self.chart_ready("#fig-map"), "the x1-t map is drawn")
        self.wait(lambda d: self.chart_ready("#fig-vt"), message="V(t) is drawn")
        self.assertTrue(self.chart_ready("#fig-vr"), "V_r(x1) is drawn")
        print(f"progress values seen while running: {sorted(seen)}", file=sys.stderr)
        self.assertGreaterEqual(len(seen), 2, f"progress did not move in the page: {seen}")
        # The map holds a picture: the heat map's image is drawn, from the whole field.
        self.assertTrue(self.css("#fig-map .heatmaplayer image"), "the map's image")
        heat = self.js("const t = document.getElementById('fig-map').data[0];"
                       "return [t.type, t.z.length, t.z[0].length]")
        self.assertEqual(heat[0], "heatmap")
        self.assertGreater(heat[1] * heat[2], 1000)
        self.assertIn("Download HDF5", self.css("#download")[0].text)
        self.assertIn("succeeded", " ".join(self.texts("h1 .badge")))
        # Picking an x1 on the map (a click in its plot area) adds that position to V(t).
        area = self.css("#fig-map .nsewdrag[data-subplot=xy]")[0]
        self.js("arguments[0].scrollIntoView({block: 'center'})", area)
        webdriver.ActionChains(self.driver).move_to_element_with_offset(area, 40, 0).click().perform()
        self.wait(lambda d: len(self.css("#vt-x1")[0].get_attribute("value").split(",")) >= 3,
                  message="the clicked x1 is added to the V(t) positions")
        self.wait(lambda d: len(self.chart_data("#fig-vt")) >= 3, message="V(t) redrawn with it")
        self.assert_no_console_errors("job")
        self.shot("job")
        # The jobs table lists it as succeeded.
        self.open("/")
        self.wait(lambda d: any(r.get_attribute("data-id") == job_id and
                                r.get_attribute("data-status") == "succeeded"
                                for r in self.css("#jobs-table tbody tr[data-id]")))

    def test_4_study_from_the_form_fills_its_map(self):
        self.open("/#/submit/study")
        self.wait(lambda d: self.css("#study-form"))
        self.css("#study-name")[0].send_keys("web study")
        Select(self.css("#study-method")[0]).select_by_value("spectral_bi")
        Select(self.css("#study-kind")[0]).select_by_value("convergence")
        for sel, value in (("#study-L", "1e-3, 1e-4, 5e-5"), ("#study-nd", "10, 20, 40"),
                           ("#study-ndmax", "40")):
            box = self.css(sel)[0]
            box.clear()
            box.send_keys(value)
        # A bad L first: the server's 422 names /convergence/L/1, shown beside the L box.
        box = self.css("#study-L")[0]
        box.clear()
        box.send_keys("1e-3, -1")
        self.css("#study-submit")[0].click()
        self.wait(lambda d: " ".join(self.texts("#study-L ~ .ferr")).strip() != "",
                  message="the L error is beside the L box")
        self.assert_no_console_errors("study form (422)", expected=(" 422 ",))
        box.clear()
        box.send_keys("1e-3, 1e-4, 5e-5")
        self.shot("submit-study")
        self.css("#study-submit")[0].click()
        self.wait(lambda d: "#/studies/" in d.current_url, message="the study page opens")
        self.wait(lambda d: self.css("#study-cmap"), message="the map is shown")
        # The map fills in: cells of finished runs carry a convergence class, until the study
        # has finished with no cell left running.
        self.wait(lambda d: self.css("#study-cmap td.cell[class*='cs-']"), timeout=240,
                  message="a first cell of the map filled in")
        self.wait(lambda d: "finished" in " ".join(self.texts("h1 .badge")), timeout=240,
                  message="the study finished")
        self.wait(lambda d: not self.css("#study-cmap td.st-running, #study-cmap td.st-queued"))
        self.assertGreaterEqual(len(self.css("#study-cmap td.cs-converged")), 3,
                                "each of the three L has a converged cell")
        self.wait(lambda d: " ".join(self.texts("#lc-reason")) not in ("", "—"))
        self.wait(lambda d: self.chart_ready("#fig-speed"), message="the speed-accuracy chart")
        self.wait(lambda d: self.css("#scene-cmap td.cs-converged"))
        self.assert_no_console_errors("study")
        self.shot("study")
        self.open("/#/studies")
        self.wait(lambda d: self.css("#studies-table tbody tr[data-id]"))
        self.assert_no_console_errors("studies")
        self.shot("studies")
        # The jobs table with the study's runs in it.
        self.open("/")
        self.wait(lambda d: len(self.css("#jobs-table tbody tr[data-id]")) >= 10)
        self.assert_no_console_errors("jobs (all)")
        self.shot("jobs-all")

    def test_5_api_docs(self):
        self.open("/api-docs")
        self.wait(lambda d: self.css("#swagger .opblock") or self.css("#swagger .endpoint"),
                  message="the OpenAPI document is rendered")
        self.wait(lambda d: "fields" in self.css("#swagger")[0].text)
        self.assert_no_console_errors("api-docs")
        self.shot("api-docs")

    def test_6_token_stays_out_of_urls(self):
        self.open("/")
        self.wait(lambda d: self.css("#token-input"))
        self.css("#token-input")[0].send_keys("secret-token-123")
        self.css("#token-save")[0].click()
        stored = self.driver.execute_script("return sessionStorage.getItem('slipfront.token')")
        self.assertEqual(stored, "secret-token-123")
        self.assertNotIn("secret", self.driver.current_url)
        self.assertEqual(self.css("#token-input")[0].get_attribute("value"), "")
        self.assertIsNone(self.driver.execute_script("return localStorage.getItem('slipfront.token')"))


    def test_7_cancel_needs_the_owners_token(self):
        # A server with tokens: reading is open, cancelling needs the submitter's token,
        # entered in the page (the answers 401 and 403 are shown beside the button).
        token_file = os.path.join(self.server.data_dir, "tokens")
        with open(token_file, "w") as f:
            f.write("alice:alice-token-1234\nbob:bob-token-5678\n")
        os.chmod(token_file, 0o600)
        shared = Server(CONFIG["binary"], args=server_args(["--workers", "1", "--token-file", token_file])).start()
        try:
            spec = long_job("alice's long run")
            spec["time"]["duration"] = 200.0
            r = shared.submit(spec, headers={"Authorization": "Bearer alice-token-1234"})
            self.assertEqual(r.status_code, 201, r.text)
            job_id = r.json()["id"]
            self.open(f"/#/jobs/{job_id}", server=shared)
            self.wait(lambda d: self.css("#cancel"), message="a Cancel button")

            def cancel_answer():
                # The button is re-rendered every second as the progress moves: click the
                # current one.
                self.driver.execute_script("document.getElementById('cancel').click()")
                self.wait(lambda d: " ".join(self.texts("#cancel-message")).strip() != "")
                return " ".join(self.texts("#cancel-message"))

            def use_token(token):
                self.css("#token-input")[0].send_keys(token)
                self.css("#token-save")[0].click()
                self.driver.execute_script(
                    "document.getElementById('cancel-message').textContent = ''")

            self.assertIn("token", cancel_answer())          # 401: enter your token
            use_token("bob-token-5678")
            self.assertIn("another user", cancel_answer())   # 403: not bob's job
            use_token("alice-token-1234")
            cancel_answer()
            self.wait(lambda d: "cancelled" in " ".join(self.texts("h1 .badge")), timeout=30,
                      message="the job is cancelled")
            self.assertEqual(shared.get(f"/api/v1/jobs/{job_id}").json()["status"], "cancelled")
            self.assertNotIn("token", self.driver.current_url)
            # 401 and 403 are logged by the browser as failed loads: expected here.
            self.assert_no_console_errors("job (401, 403)", expected=(" 401 ", " 403 "))
            self.shot("job-cancelled")
        finally:
            shared.cleanup()

if __name__ == "__main__":
    run()

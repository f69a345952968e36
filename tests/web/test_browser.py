"""The web view in a real browser: headless Chromium driven by Selenium (Debian's chromium,
chromium-driver and python3-selenium) against `slipfront serve` on an ephemeral loopback
port (docs/web.md).

Each page loads with no console error; a hostile job name stays text; a job submitted through
the form appears in the table, shows moving progress on its page and ends with its figures
(canvases drawn from /fields and /front); a field error of the server's problem+json is shown
beside its field; a study started from the form fills in its convergence map; the API docs
render. Screenshots of every page go to --screenshots (build/web-screenshots by ctest).

Exit 77 (ctest: skipped) with a message when Chromium or its driver cannot start.

    /usr/bin/python3 tests/web/test_browser.py --binary build/slipfront --screenshots /tmp/shots
"""

import argparse
import json
import os
import sys
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "server"))
from server_harness import Server, long_job  # noqa: E402

BINARY = None
WEB_DIR = None
SHOTS = None
SKIP = 77

try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.common.exceptions import StaleElementReferenceException
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import Select, WebDriverWait
except ImportError as e:  # pragma: no cover
    print(f"SKIP: python3-selenium is not installed ({e}); apt-get install python3-selenium")
    sys.exit(SKIP)

HOSTILE = '<img src=x onerror="window.__pwned=1">&amp;"\'</td>'


def start_browser():
    options = webdriver.ChromeOptions()
    for path in ("/usr/bin/chromium", "/usr/bin/chromium-browser"):
        if os.path.exists(path):
            options.binary_location = path
            break
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                "--window-size=1400,1000", "--hide-scrollbars", "--force-device-scale-factor=1",
                "--no-first-run", "--disable-extensions", "--disable-background-networking"):
        options.add_argument(arg)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver_path = "/usr/bin/chromedriver"
    service = Service(executable_path=driver_path) if os.path.exists(driver_path) else Service()
    return webdriver.Chrome(service=service, options=options)


class WebView(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        args = ["--workers", "2"] + (["--web-dir", WEB_DIR] if WEB_DIR else [])
        cls.server = Server(BINARY, args=args).start()
        try:
            cls.driver = start_browser()
        except Exception as e:  # noqa: BLE001
            cls.server.cleanup()
            print(f"SKIP: headless Chromium could not start: {e}")
            sys.exit(SKIP)
        cls.driver.set_page_load_timeout(30)
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

    @classmethod
    def tearDownClass(cls):
        try:
            cls.driver.quit()
        finally:
            cls.server.cleanup()

    # -- helpers -------------------------------------------------------------------------
    def open(self, path):
        # A fresh document each time (a change of the #fragment alone would keep the page).
        self.driver.get("about:blank")
        self.driver.get(self.server.url(path))

    def wait(self, predicate, timeout=30, message=""):
        # The pages re-render as they poll: an element read may be replaced meanwhile.
        return WebDriverWait(self.driver, timeout, poll_frequency=0.1,
                             ignored_exceptions=(StaleElementReferenceException, IndexError)
                             ).until(lambda d: predicate(d), message)

    def texts(self, selector):
        return self.driver.execute_script(
            "return [...document.querySelectorAll(arguments[0])].map(e => e.textContent)",
            selector)

    def css(self, selector):
        return self.driver.find_elements(By.CSS_SELECTOR, selector)

    def console_errors(self):
        return [e for e in self.driver.get_log("browser") if e.get("level") == "SEVERE"]

    def assert_no_console_errors(self, page):
        errors = self.console_errors()
        self.assertEqual(errors, [], f"console errors on {page}: {json.dumps(errors, indent=1)}")

    def shot(self, name):
        if not SHOTS:
            return
        os.makedirs(SHOTS, exist_ok=True)
        height = self.driver.execute_script(
            "return Math.max(document.body.scrollHeight, document.documentElement.scrollHeight)")
        self.driver.set_window_size(1400, min(max(int(height) + 40, 900), 4000))
        time.sleep(0.3)
        self.driver.save_screenshot(os.path.join(SHOTS, f"{name}.png"))
        self.driver.set_window_size(1400, 1000)

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
        self.assert_no_console_errors_except_422("submit (422)")
        self.shot("submit-job-error")

    def assert_no_console_errors_except_422(self, page):
        # The browser logs the 422 answer itself as a failed resource load: expected here.
        errors = [e for e in self.console_errors() if "422" not in e.get("message", "")]
        self.assertEqual(errors, [], f"console errors on {page}: {errors}")

    def test_3_job_from_the_form_progresses_and_ends_with_figures(self):
        # The paper's run: the form untouched but for a name (its defaults are the paper's
        # scene; several seconds on this machine, long enough to watch it progress).
        self.open("/#/submit")
        self.wait(lambda d: self.css("#f_geometry_nodes_per_meter"), message="the form is built")
        self.css("#job-name")[0].send_keys("paper run, from the form")
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
            if self.css("#fig-map canvas") and self.css("#fig-vr canvas"):
                break
            time.sleep(0.15)
        self.assertTrue(self.css("#fig-map canvas"), "the x1-t map is drawn")
        self.wait(lambda d: self.css("#fig-vt canvas"), message="V(t) is drawn")
        self.assertTrue(self.css("#fig-vr canvas"), "V_r(x1) is drawn")
        print(f"progress values seen while running: {sorted(seen)}", file=sys.stderr)
        self.assertGreaterEqual(len(seen), 2, f"progress did not move in the page: {seen}")
        # The canvases hold a picture, not a blank.
        filled = self.driver.execute_script(
            "const c = document.querySelector('#fig-map canvas');"
            "const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;"
            "const s = new Set(); for (let i = 0; i < d.length; i += 4 * 97) s.add(d[i] * 65536 + d[i+1] * 256 + d[i+2]);"
            "return s.size;")
        self.assertGreater(filled, 20, "the map has colours")
        self.assertIn("Download HDF5", self.css("#download")[0].text)
        self.assertIn("succeeded", " ".join(self.texts("h1 .badge")))
        # Picking an x1 on the map redraws V(t) with that position.
        canvas = self.css("#fig-map canvas")[0]
        self.driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", canvas)
        webdriver.ActionChains(self.driver).move_to_element_with_offset(canvas, 0, 0).click().perform()
        self.wait(lambda d: len(self.css("#vt-x1")[0].get_attribute("value").split(",")) >= 4)
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
        self.assert_no_console_errors_except_422("study form (422)")
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
        self.wait(lambda d: self.css("#fig-speed canvas"))
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
        args = ["--workers", "1", "--token-file", token_file] + (
            ["--web-dir", WEB_DIR] if WEB_DIR else [])
        shared = Server(BINARY, args=args).start()
        try:
            spec = long_job("alice's long run")
            spec["time"]["duration"] = 200.0
            r = shared.submit(spec, headers={"Authorization": "Bearer alice-token-1234"})
            self.assertEqual(r.status_code, 201, r.text)
            job_id = r.json()["id"]
            self.driver.get("about:blank")
            self.driver.get(shared.url(f"/#/jobs/{job_id}"))
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
            errors = [e for e in self.console_errors()
                      if " 401 " not in e.get("message", "") and " 403 " not in e.get("message", "")]
            self.assertEqual(errors, [])
            self.shot("job-cancelled")
        finally:
            shared.cleanup()

if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    parser.add_argument("--web-dir")
    parser.add_argument("--screenshots")
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    WEB_DIR = args.web_dir
    SHOTS = args.screenshots
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

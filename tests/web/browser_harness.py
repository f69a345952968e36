"""What the browser tests of the web view share (docs/web.md, "Tests"): headless Chromium driven
by Selenium (Debian's chromium, chromium-driver and python3-selenium) with downloads into a
directory, against `slipfront serve` on an ephemeral loopback port, and a TestCase with the
helpers the pages need (waits that survive re-renders, console errors, screenshots, reading a
Plotly chart's data).

Exit 77 (ctest: skipped) with a message when Selenium is missing or Chromium cannot start.
"""

import argparse
import json
import os
import sys
import tempfile
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "server"))
from server_harness import Server  # noqa: E402,F401  (re-exported for the tests)

SKIP = 77

try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.common.exceptions import StaleElementReferenceException
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import WebDriverWait
except ImportError as e:  # pragma: no cover
    print(f"SKIP: python3-selenium is not installed ({e}); apt-get install python3-selenium")
    sys.exit(SKIP)

# The server has no GET /api/v1/presets yet: the form's request for it is an expected 404.
PRESETS_404 = "/api/v1/presets - Failed to load resource: the server responded with a status of 404"

# Set by run(): the server binary, the web files, the screenshot directory.
CONFIG = {"binary": None, "web_dir": None, "shots": None}


def start_browser(download_dir):
    options = webdriver.ChromeOptions()
    for path in ("/usr/bin/chromium", "/usr/bin/chromium-browser"):
        if os.path.exists(path):
            options.binary_location = path
            break
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                "--window-size=1400,1000", "--hide-scrollbars", "--force-device-scale-factor=1",
                "--no-first-run", "--disable-extensions", "--disable-background-networking"):
        options.add_argument(arg)
    options.add_experimental_option("prefs", {"download.default_directory": download_dir,
                                              "download.prompt_for_download": False})
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver_path = "/usr/bin/chromedriver"
    service = Service(executable_path=driver_path) if os.path.exists(driver_path) else Service()
    driver = webdriver.Chrome(service=service, options=options)
    driver.execute_cdp_cmd("Browser.setDownloadBehavior",
                           {"behavior": "allow", "downloadPath": download_dir})
    return driver


def server_args(extra=()):
    return list(extra) + (["--web-dir", CONFIG["web_dir"]] if CONFIG["web_dir"] else [])


class BrowserCase(unittest.TestCase):
    """One server (cls.server, started by the subclass's setUpClass through start()) and one
    browser per test class."""

    @classmethod
    def start(cls, workers=2):
        cls.server = Server(CONFIG["binary"], args=server_args(["--workers", str(workers)])).start()
        cls.downloads = tempfile.mkdtemp(prefix="slipfront-downloads-")
        try:
            cls.driver = start_browser(cls.downloads)
        except Exception as e:  # noqa: BLE001
            cls.server.cleanup()
            print(f"SKIP: headless Chromium could not start: {e}")
            sys.exit(SKIP)
        cls.driver.set_page_load_timeout(30)

    @classmethod
    def tearDownClass(cls):
        try:
            cls.driver.quit()
        finally:
            cls.server.cleanup()

    # -- pages ---------------------------------------------------------------------------
    def open(self, path, server=None):
        # A fresh document each time (a change of the #fragment alone would keep the page).
        self.driver.get("about:blank")
        self.driver.get((server or self.server).url(path))

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

    def js(self, script, *args):
        return self.driver.execute_script(script, *args)

    # -- Plotly charts -------------------------------------------------------------------
    def chart_ready(self, selector):
        return bool(self.js("const g = document.querySelector(arguments[0]);"
                            "return !!(g && g._fullLayout && g.querySelector('.main-svg'))", selector))

    def chart_data(self, selector):
        """The traces of the Plotly chart in `selector` as the page gave them (JSON-safe)."""
        return json.loads(self.js(
            "const g = document.querySelector(arguments[0]);"
            "return JSON.stringify(g.data.map(t => ({type: t.type, mode: t.mode, name: t.name,"
            " x: t.x, y: t.type === 'heatmap' ? null : t.y, customdata: t.type === 'heatmap' ? null : t.customdata,"
            " xaxis: t.xaxis, showlegend: t.showlegend})))", selector))

    def plot_area(self, selector):
        """{left, width} in CSS pixels of the main x-y plot area of a chart, and its x range."""
        return self.js(
            "const g = document.querySelector(arguments[0]);"
            "const r = g.querySelector('.nsewdrag[data-subplot=xy]').getBoundingClientRect();"
            "return {left: r.left, width: r.width, range: g._fullLayout.xaxis.range.slice()}", selector)

    def downloaded(self, name, timeout=20):
        """The bytes of a finished download named `name` (Chrome writes .crdownload first)."""
        path = os.path.join(self.downloads, name)
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if os.path.exists(path) and os.path.getsize(path) > 0:
                with open(path, "rb") as f:
                    return f.read()
            time.sleep(0.1)
        self.fail(f"no download {name} in {timeout} s (have: {os.listdir(self.downloads)})")

    # -- console and screenshots ---------------------------------------------------------
    def console_errors(self, expected=()):
        """SEVERE console entries, less those naming one of `expected` (e.g. a 422 the test
        provoked: the browser logs it as a failed resource load) and the submit form's
        request for the server's presets while the server has none (PRESETS_404)."""
        expected = tuple(expected) + (PRESETS_404,)
        return [e for e in self.driver.get_log("browser") if e.get("level") == "SEVERE"
                and not any(x in e.get("message", "") for x in expected)]

    def assert_no_console_errors(self, page, expected=()):
        errors = self.console_errors(expected)
        self.assertEqual(errors, [], f"console errors on {page}: {json.dumps(errors, indent=1)}")

    def shot(self, name):
        shots = CONFIG["shots"]
        if not shots:
            return
        os.makedirs(shots, exist_ok=True)
        # The window's size includes what is not page (headless Chromium's frame): add it.
        height, frame = self.js("return [Math.max(document.body.scrollHeight, document.documentElement.scrollHeight),"
                                " window.outerHeight - window.innerHeight]")
        self.driver.set_window_size(1400, min(max(int(height) + int(frame) + 20, 900), 4000))
        self.js("window.scrollTo(0, 0)")
        time.sleep(0.5)
        self.driver.save_screenshot(os.path.join(shots, f"{name}.png"))
        self.driver.set_window_size(1400, 1000)


def run():
    """Parses --binary, --web-dir, --screenshots and runs the module's tests."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    parser.add_argument("--web-dir")
    parser.add_argument("--screenshots")
    args, rest = parser.parse_known_args()
    CONFIG.update(binary=os.path.abspath(args.binary), web_dir=args.web_dir,
                  shots=args.screenshots)
    unittest.main(module="__main__", argv=[sys.argv[0]] + rest, verbosity=2)

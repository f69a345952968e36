"""The door for friction laws, seen in the browser: a server built with a toy law of the
tests' own (tests/api/toy_law/exponential_weakening.cpp, one file, no other edit) shows it in
the job form with its fields (and only them), places its check's 422 beside the field, and
labels its runs in the jobs list with the law's own label (docs/architecture.md "Adding a
friction law").

    /usr/bin/python3 tests/web/test_toy_law_form.py --binary build/tests/api/slipfront_with_toy_law \\
        --web-dir build/share/slipfront/web
"""

import json
import os
import sys

from browser_harness import BrowserCase, run
from selenium.webdriver.support.ui import Select

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "clients"))
from slipfront_client.friction_labels import friction_label, labels_of  # noqa: E402

TOY = "exponential_weakening"


class ToyLawForm(BrowserCase):
    @classmethod
    def setUpClass(cls):
        cls.start(workers=1)

    def visible(self, pointer):
        return self.js("const f = document.querySelector(`[data-field='${arguments[0]}']`);"
                       "return !!f && !f.closest('[hidden]')", pointer)

    def test_the_form_and_the_labels_know_the_toy_law(self):
        self.open("/#/submit")
        self.wait(lambda d: self.css("#f_friction_law"), message="the form is built")
        options = [json.loads(o.get_attribute("value")) for o in
                   Select(self.css("#f_friction_law")[0]).options]
        self.assertIn(TOY, options)
        Select(self.css("#f_friction_law")[0]).select_by_value(json.dumps(TOY))
        self.wait(lambda d: self.visible("/friction/mu_s"), message="the toy law's fields")
        for pointer in ("/friction/mu_d", "/friction/D_c", "/friction/regularization"):
            self.assertTrue(self.visible(pointer), pointer)
        for pointer in ("/friction/mu", "/friction/L", "/friction/t_star"):
            self.assertFalse(self.visible(pointer), pointer)
        # Its check (mu_d <= mu_s), answered by the server, lands beside mu_d.
        box = self.css("#f_friction_mu_d")[0]
        box.clear()
        box.send_keys("0.9")
        self.css("#job-submit")[0].click()
        self.wait(lambda d: " ".join(self.texts("[data-field='/friction/mu_d'] > .ferr")).strip(),
                  message="the error beside mu_d")
        self.assertIn("exceeds mu_s", " ".join(self.texts("[data-field='/friction/mu_d'] > .ferr")))
        self.shot("toy_law_form")
        # A run of it is labelled by the law's own label in the jobs list.
        job = {"name": "toy", "geometry": {"nodes_per_meter": 5}, "time": {"duration": 2.0},
               "friction": {"law": TOY, "mu_s": 0.75, "mu_d": 0.5, "D_c": 0.05}}
        r = self.server.submit(job)
        self.assertEqual(r.status_code, 201, r.text)
        self.server.wait_status(r.json()["id"], {"succeeded"}, timeout=120)
        self.open(f"/#/jobs/{r.json()['id']}")
        self.wait(lambda d: "exponential weakening D_c = 0.05 m" in
                  " ".join(self.texts(".sub")), message="the run's friction label")
        self.assert_no_console_errors("toy law", expected=(" 422 ",))
        # The Python client labels it from the same schema.
        labels = labels_of(self.server.get("/api/v1/schema/job.json").json())
        self.assertEqual(friction_label(job["friction"], labels),
                         "exponential weakening D_c = 0.05 m")


if __name__ == "__main__":
    run()

"""The web view's submit form in a real browser (headless Chromium, Selenium) against
`slipfront serve` on loopback (docs/web.md, "Submit" and "Tests"): every field of the server's
job schema with its kind (dropdown for an enum, number box with the schema's bounds,
checkbox), unit and description, shown per method (x-methods); a range error beside its field
after the server's 422; the built-in presets (examples/) and a server-served list; only the
fields that differ from the defaults are sent; nested objects, comma lists, an enum without a
default and a row editor for arrays of objects from a made-up schema, with the server's JSON
pointers landing beside the cell and the list they name.

    /usr/bin/python3 tests/web/test_web_form.py --binary build/slipfront --web-dir build/share/slipfront/web
"""

import json
import os

from browser_harness import BrowserCase, run
from selenium.webdriver.support.ui import Select

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def schema_leaves(schema, prefix=""):
    """(pointer, schema) of every non-object property, as the form lays them out."""
    for name, sub in schema.get("properties", {}).items():
        if sub.get("type") == "object" and "properties" in sub:
            yield from schema_leaves(sub, f"{prefix}/{name}")
        else:
            yield f"{prefix}/{name}", sub


class SubmitForm(BrowserCase):
    @classmethod
    def setUpClass(cls):
        cls.start(workers=1)

    def open_form(self):
        self.open("/#/submit")
        self.wait(lambda d: self.css("#f_geometry_nodes_per_meter"), message="the form is built")

    def test_methods_and_their_labels_come_from_the_server(self):
        # web/app/methods.js: the server's methods (its job schema's method); its built-in
        # list, used when the server cannot say, is the same; the study form offers them, the
        # cheapest first.
        method = self.server.get("/api/v1/schema/job.json").json()["properties"]["method"]
        self.open("/#/submit/study")
        self.wait(lambda d: self.css("#study-method option"), message="the study form")
        seen = self.driver.execute_async_script(
            "const done = arguments[arguments.length - 1];"
            "import('/app/methods.js').then((m) => done({names: m.methodNames(), default: m.defaultMethod(),"
            " labels: m.methodNames().map(m.methodLabel), headings: m.methodNames().map(m.methodHeading),"
            " builtIn: m.BUILT_IN_METHODS, toy: m.methodsOf({properties: {method: {enum: ['toy'], 'x-labels': {toy: {label: 'TOY'}}}}})}));")
        self.assertEqual(seen["names"], method["enum"])
        self.assertEqual(seen["default"], method["default"])
        self.assertEqual(seen["labels"], [method["x-labels"][n]["label"] for n in method["enum"]])
        self.assertEqual(seen["headings"], [method["x-labels"][n]["heading"] for n in method["enum"]])
        self.assertEqual((seen["builtIn"]["names"], seen["builtIn"]["default"], seen["builtIn"]["labels"]),
                         (method["enum"], method["default"], method["x-labels"]))
        self.assertEqual(seen["toy"], {"names": ["toy"], "default": "toy", "labels": {"toy": {"label": "TOY"}}})
        by_cost = sorted(method["enum"], key=lambda n: method["x-labels"][n]["cost_rank"])
        self.assertEqual([o.get_attribute("value") for o in self.css("#study-method option")], by_cost)
        self.assertEqual([o.text for o in self.css("#study-method option")],
                         [f"{n} ({method['x-labels'][n]['run_cost']})" for n in by_cost])

    def test_form_is_built_from_the_schema(self):
        schema = self.server.get("/api/v1/schema/job.json").json()
        self.open_form()
        fields = dict(schema_leaves(schema))
        # "preset" is not a field but the preset box, which fills the form from its spec.
        self.assertIn("quick_nd10", fields.pop("/preset")["enum"])
        self.assertTrue(self.css("#job-preset"))
        for pointer, sub in fields.items():
            f = self.js("const f = document.querySelector(`[data-field='${arguments[0]}']`); if (!f) return null;"
                        "const i = f.querySelector('[data-pointer]');"
                        "return {tag: i.tagName, type: i.type, min: i.min, max: i.max, step: i.step,"
                        " options: [...(i.options || [])].map(o => JSON.parse(o.value)),"
                        " label: f.querySelector('label').textContent, desc: f.querySelector('.desc')?.textContent || ''}",
                        pointer)
            self.assertIsNotNone(f, f"{pointer} has a field")
            if "enum" in sub:
                self.assertEqual((f["tag"], f["options"]), ("SELECT", sub["enum"]), pointer)
            elif sub.get("type") == "boolean":
                self.assertEqual(f["type"], "checkbox", pointer)
            elif sub.get("type") in ("number", "integer"):
                self.assertEqual(f["type"], "number", pointer)
                lo = sub.get("minimum", sub.get("exclusiveMinimum"))
                hi = sub.get("maximum", sub.get("exclusiveMaximum"))
                self.assertEqual(float(f["min"]) if f["min"] else None, lo, pointer)
                self.assertEqual(float(f["max"]) if f["max"] else None, hi, pointer)
                self.assertEqual(f["step"], "1" if sub["type"] == "integer" else "any", pointer)
            if sub.get("x-unit"):
                self.assertIn(f"[{sub['x-unit']}]", f["label"], pointer)
            self.assertTrue(f["desc"], f"{pointer} shows its description")
        # Fields shown per method (x-methods).
        for method in ("spectral_bi", "fe"):
            Select(self.css("#f_method")[0]).select_by_value(json.dumps(method))
            self.wait(lambda d: self.js("return document.getElementById('group_fe').hidden") == (method != "fe"))
            for pointer, sub in fields.items():
                hidden = self.js("return document.querySelector(`[data-field='${arguments[0]}']`).hidden", pointer)
                when = sub.get("x-when")  # with the defaults: the law prakash_clifton, ...
                conditions = when if isinstance(when, list) else [when] if when else []
                unused = bool(conditions) and not any(
                    fields[c["pointer"]]["default"] in c["values"] for c in conditions)
                self.assertEqual(hidden, method not in sub["x-methods"] or unused,
                                 f"{pointer} under {method}")
        # A range error of the server beside its field (threads: 0 .. 256).
        box = self.css("#f_threads")[0]
        box.clear()
        box.send_keys("1000")
        self.css("#job-submit")[0].click()
        self.wait(lambda d: " ".join(self.texts("[data-field='/threads'] > .ferr")).strip(),
                  message="the error beside threads")
        self.assertIn("256", " ".join(self.texts("[data-field='/threads'] > .ferr")))
        self.assertIn("invalid", box.get_attribute("class"))
        self.assertEqual(" ".join(self.texts("[data-field='/material/poisson_ratio'] > .ferr")).strip(), "")
        self.assert_no_console_errors("submit (422)", expected=(" 422 ",))

    def visible(self, pointer):
        return self.js("const f = document.querySelector(`[data-field='${arguments[0]}']`);"
                       "return !!f && !f.closest('[hidden]')", pointer)

    def choose(self, pointer, value):
        Select(self.css(f"[data-field='{pointer}'] select")[0]).select_by_value(json.dumps(value))

    def test_fields_follow_the_choices_they_depend_on(self):
        """x-order and x-when of the schema: a choice comes before the fields it chooses, and
        a field shows only with the choice that uses it (mu_s with slip_weakening); what is
        hidden is not sent; no field sticks out of its group."""
        schema = self.server.get("/api/v1/schema/job.json").json()
        self.assertEqual(schema["properties"]["friction"]["x-order"][:2], ["law", "regularization"])
        self.open_form()
        order = self.js("return [...document.querySelectorAll('#group_friction [data-field]')]"
                        ".map(f => f.dataset.field)")
        self.assertEqual(order, [f"/friction/{n}" for n in schema["properties"]["friction"]["x-order"]])
        nucleation = self.js("return [...document.querySelectorAll('#group_nucleation [data-field]')]"
                             ".map(f => f.dataset.field)")
        self.assertEqual(nucleation[:2], ["/nucleation/enabled", "/nucleation/type"])
        # The paper's law: mu, L and v_star; none of slip weakening's, no regularisation choice.
        for pointer in ("/friction/mu", "/friction/L", "/friction/v_star"):
            self.assertTrue(self.visible(pointer), pointer)
        for pointer in ("/friction/mu_s", "/friction/mu_d", "/friction/D_c", "/friction/t_star",
                        "/friction/regularization", "/nucleation/x1_min", "/lower/density"):
            self.assertFalse(self.visible(pointer), pointer)
        self.choose("/friction/law", "slip_weakening")
        self.wait(lambda d: self.visible("/friction/mu_s"), message="mu_s with slip_weakening")
        self.assertTrue(self.visible("/friction/D_c") and self.visible("/friction/regularization"))
        self.assertFalse(self.visible("/friction/mu"))
        self.assertFalse(self.visible("/friction/t_star"))
        self.choose("/friction/regularization", "time_scale")
        self.wait(lambda d: self.visible("/friction/t_star"), message="t_star with time_scale")
        self.choose("/nucleation/type", "overstressed_patch")
        self.wait(lambda d: self.visible("/nucleation/x1_min"))
        self.assertFalse(self.visible("/nucleation/a"))
        self.choose("/lower/solid", "elastic")
        self.wait(lambda d: self.visible("/lower/density"))
        # Back to the paper's law: its regularisation choice is hidden, and so is t_star.
        self.choose("/friction/law", "prakash_clifton")
        self.wait(lambda d: not self.visible("/friction/t_star"))
        self.choose("/friction/law", "slip_weakening")
        self.wait(lambda d: self.visible("/friction/t_star"))
        # No input or table sticks out of its group (a grid cell as wide as its column).
        outside = self.js(
            "return [...document.querySelectorAll('#job-fields fieldset:not([hidden])')].flatMap(fs => {"
            " const r = fs.getBoundingClientRect();"
            " return [...fs.querySelectorAll('input, select, table')].filter(i => i.offsetParent)"
            "  .filter(i => { const b = i.getBoundingClientRect(); return b.right > r.right + 1; })"
            "  .map(i => i.id || i.tagName); })")
        self.assertEqual(outside, [])
        self.assertIn("wide", self.css("#group_profiles")[0].get_attribute("class"))
        # A slip-weakening BI job from the form: what is shown is sent, and the server takes it.
        self.choose("/method", "spectral_bi")
        self.choose("/nucleation/type", "ellipse")
        self.choose("/lower/solid", "rigid")
        self.choose("/friction/regularization", "none")
        for pointer, value in (("/friction/mu_s", "0.7"), ("/friction/D_c", "0.002"),
                               ("/time/duration", "2")):
            box = self.css(f"[data-field='{pointer}'] input")[0]
            box.clear()
            box.send_keys(value)
        self.js("window.__sent = []; const f = window.fetch; window.fetch = (u, o) => {"
                " if (o && o.method === 'POST' && String(u).endsWith('/api/v1/jobs')) window.__sent.push(JSON.parse(o.body)); return f(u, o); };")
        self.css("#job-submit")[0].click()
        self.wait(lambda d: "#/jobs/" in d.current_url, message="the job page opens")
        sent = self.js("return window.__sent")[0]
        self.assertEqual(sent["friction"], {"law": "slip_weakening", "mu_s": 0.7, "D_c": 0.002})
        self.assertNotIn("lower", sent)
        self.assertNotIn("nucleation", sent)
        job = self.server.get(f"/api/v1/jobs/{self.driver.current_url.rsplit('/', 1)[1]}").json()
        self.assertEqual((job["spec"]["friction"]["law"], job["spec"]["friction"]["mu_s"]),
                         ("slip_weakening", 0.7))
        self.assert_no_console_errors("submit (choices)")

    def test_presets_fill_the_form_and_only_changes_are_sent(self):
        # The server's presets (GET /api/v1/presets): the scene presets and examples/.
        served = self.server.get("/api/v1/presets").json()["presets"]
        examples = [p["name"] + ".json" for p in served]
        specs = [p["spec"] for p in served]
        self.assertIn("quick_nd10.json", examples)
        self.open_form()
        self.wait(lambda d: len(Select(self.css("#job-preset")[0]).options) == 1 + len(specs))
        names = [o.text for o in Select(self.css("#job-preset")[0]).options]
        self.assertEqual(names[1:], [p["title"] for p in served])
        # Record what the form sends.
        self.js("window.__sent = []; const f = window.fetch; window.fetch = (u, o) => {"
                " if (o && o.method === 'POST' && String(u).endsWith('/api/v1/jobs')) window.__sent.push(JSON.parse(o.body)); return f(u, o); };")
        quick = examples.index("quick_nd10.json")
        Select(self.css("#job-preset")[0]).select_by_index(1 + quick)
        self.wait(lambda d: self.css("#f_geometry_nodes_per_meter")[0].get_attribute("value") == "10")
        self.assertIn("from the server", self.css("#preset-note")[0].text)
        self.css("#job-submit")[0].click()
        self.wait(lambda d: "#/jobs/" in d.current_url, message="the job page opens")
        sent = self.js("return window.__sent")[0]
        defaults = self.server.get("/api/v1/job-defaults", params={"method": "fe"}).json()["spec"]
        expected = {"method": "fe"}
        for section, value in specs[quick].items():
            if isinstance(value, dict):
                changed = {k: v for k, v in value.items() if defaults[section].get(k) != v}
                if changed:
                    expected[section] = changed
            elif defaults.get(section) != value:
                expected[section] = value
        self.assertEqual(sent, expected)
        job = self.server.get(f"/api/v1/jobs/{self.driver.current_url.rsplit('/', 1)[1]}").json()
        self.assertEqual(job["spec"]["geometry"]["nodes_per_meter"], 10)
        self.assertEqual(job["name"], specs[quick]["name"])

    def test_the_server_checks_the_job_while_one_types(self):
        """POST /jobs/validate while typing: a rock-scale preset's watching values derived from
        its scene are written into their fields, with where they come from, and not sent; a
        stress out of scale with the material is warned about beside its field; the cost
        estimate beside the submit button follows the job."""
        served = self.server.get("/api/v1/presets").json()["presets"]
        rock = [p["name"] for p in served].index("rock_patch_nd2")
        self.open_form()
        self.wait(lambda d: len(Select(self.css("#job-preset")[0]).options) == 1 + len(served))
        self.js("window.__sent = []; const f = window.fetch; window.fetch = (u, o) => {"
                " if (o && o.method === 'POST' && String(u).endsWith('/api/v1/jobs')) window.__sent.push(JSON.parse(o.body)); return f(u, o); };")
        Select(self.css("#job-preset")[0]).select_by_index(1 + rock)
        window = "[data-field='/time/arrest_window']"
        self.wait(lambda d: self.css("#f_time_arrest_window")[0].get_attribute("value") == "0.005",
                  message="the derived arrest window in its field")
        self.assertIn("derived: a tenth of the duration 0.05 s", " ".join(self.texts(f"{window} > .fwarn")))
        self.wait(lambda d: "steps of dt" in self.css("#memory-estimate")[0].text,
                  message="the cost estimate")
        self.assertIn("on this server", self.css("#memory-estimate")[0].text)
        self.shot("form-rock-derived")
        duration = self.css("#f_time_duration")[0]
        duration.clear()
        duration.send_keys("0.08")
        self.wait(lambda d: self.css("#f_time_arrest_window")[0].get_attribute("value") == "0.008",
                  message="the arrest window follows the duration")
        # A stress in MPa on the paper's material: warned beside the field, the job still valid.
        Select(self.css("#job-preset")[0]).select_by_index(1 + [p["name"] for p in served].index("quick_nd10"))
        self.wait(lambda d: self.css("#f_geometry_nodes_per_meter")[0].get_attribute("value") == "10")
        for pointer, value in (("normal_stress", "-120e6"), ("shear_stress", "70e6")):
            box = self.css(f"#f_loading_{pointer}")[0]
            box.clear()
            box.send_keys(value)
        normal = "[data-field='/loading/normal_stress'] > .fwarn"
        self.wait(lambda d: "times the shear modulus" in " ".join(self.texts(normal)),
                  message="the stress warned about beside its field")
        self.shot("form-stress-warning")
        # The rock preset submitted: its derived values are not sent (the server derives them).
        Select(self.css("#job-preset")[0]).select_by_index(1 + rock)
        self.wait(lambda d: self.css("#f_time_arrest_window")[0].get_attribute("value") == "0.005")
        self.css("#job-submit")[0].click()
        self.wait(lambda d: "#/jobs/" in d.current_url, message="the job page opens")
        sent = self.js("return window.__sent")[0]
        self.assertNotIn("arrest_window", sent.get("time", {}))
        self.assertNotIn("probe", sent)
        job = self.server.get(f"/api/v1/jobs/{self.driver.current_url.rsplit('/', 1)[1]}").json()
        self.assertEqual(job["spec"]["time"]["arrest_window"], 0.005)
        self.assert_no_console_errors("validation while typing")

    def test_server_served_presets_plug_in(self):
        listing = {"presets": [{"name": "srv-bi", "title": "BI at L = 1e-4 m (served)",
                                "description": "from the server",
                                "spec": {"method": "spectral_bi", "friction": {"L": 1e-4}}}]}
        script = self.driver.execute_cdp_cmd("Page.addScriptToEvaluateOnNewDocument", {"source": (
            "const real = window.fetch; window.fetch = (u, o) => String(u).endsWith('/api/v1/presets')"
            f" ? Promise.resolve(new Response(JSON.stringify({json.dumps(listing)}),"
            " {status: 200, headers: {'Content-Type': 'application/json'}})) : real(u, o);")})
        try:
            self.open_form()
            self.wait(lambda d: len(Select(self.css("#job-preset")[0]).options) == 2)
            Select(self.css("#job-preset")[0]).select_by_index(1)
            self.wait(lambda d: self.css("#f_method")[0].get_attribute("value") == '"spectral_bi"')
            self.assertEqual(float(self.css("#f_friction_L")[0].get_attribute("value")), 1e-4)
            self.assertIn("from the server", self.css("#preset-note")[0].text)
            self.assertTrue(self.js("return document.getElementById('group_fe').hidden"))
        finally:
            self.driver.execute_cdp_cmd("Page.removeScriptToEvaluateOnNewDocument", script)

    def test_schema_form_takes_nested_objects_and_arrays(self):
        # Fields of the kinds the job schema is about to gain: a nested solid, a list of
        # numbers, a list of objects, an enum without a default, an enum shown for one
        # method only.
        schema = {"type": "object", "properties": {
            "method": {"enum": ["fe", "spectral_bi"], "default": "fe", "type": "string"},
            "lower": {"type": "object", "properties": {"material": {"type": "object", "properties": {
                "density": {"type": "number", "exclusiveMinimum": 0, "default": 1.0, "x-unit": "kg/m^3"}}}}},
            "stations": {"type": "object", "properties": {"x1": {
                "type": "array", "items": {"type": "number"}, "default": [6, 10], "x-unit": "m"}}},
            "profiles": {"type": "array", "default": [], "items": {"type": "object", "properties": {
                "x1": {"type": "number", "default": 0, "x-unit": "m"},
                "field": {"enum": ["slip", "slip_velocity"], "type": "string", "default": "slip"}}}},
            "nucleation": {"type": "object", "properties": {  # no default: "not set"
                "type": {"enum": ["ellipse", "gaussian"], "type": "string"}}},
            "friction": {"type": "object", "properties": {
                "regularization": {"enum": ["none", "prakash_clifton"], "type": "string",
                                   "default": "prakash_clifton", "x-methods": ["fe"]}}}}}
        self.open("/#/jobs")
        self.driver.execute_async_script(
            "const done = arguments[arguments.length - 1];"
            "Promise.all([import('/app/schema_form.js'), import('/app/form_errors.js')]).then(([sf, fe]) => {"
            " const form = document.createElement('form'); form.id = 'made-up'; document.getElementById('view').append(form);"
            " const f = new sf.SchemaForm(arguments[0]); form.append(f.element); f.write({}, {}); f.showMethod('spectral_bi');"
            " window.__form = f; window.__errors = (e) => fe.showErrors(form, document.createElement('div'), e); done(); });",
            schema)
        self.assertEqual(self.css("#made-up #f_lower_material_density")[0].get_attribute("type"), "number")
        self.assertTrue(self.js("return document.querySelector(\"[data-field='/friction/regularization']\").hidden"))
        stations = self.css("#f_stations_x1")[0]
        self.assertEqual(stations.get_attribute("value"), "6, 10")
        stations.clear()
        stations.send_keys("2, 4.5, 8")
        for _ in range(2):
            self.css("#f_profiles_add")[0].click()
        self.css("#f_profiles_1_x1")[0].clear()
        self.css("#f_profiles_1_x1")[0].send_keys("7.5")
        Select(self.css("#f_profiles_1_field")[0]).select_by_value('"slip_velocity"')
        self.assertEqual(self.js("return window.__form.changes({})"), {
            "stations": {"x1": [2, 4.5, 8]},
            "profiles": [{"x1": 0, "field": "slip"}, {"x1": 7.5, "field": "slip_velocity"}]})
        # An enumeration without a default is "not set" until chosen, and only then sent.
        Select(self.css("#f_nucleation_type")[0]).select_by_value('"gaussian"')
        self.assertEqual(self.js("return window.__form.changes({}).nucleation"), {"type": "gaussian"})
        # Removing a row keeps what was typed in the others.
        self.css("#f_profiles tbody tr:first-child button")[0].click()
        self.assertEqual(self.js("return window.__form.changes({}).profiles"),
                         [{"x1": 7.5, "field": "slip_velocity"}])
        self.css("#f_profiles_add")[0].click()
        # The server's pointers land beside the cell and the list they name.
        self.js("window.__errors({message: 'invalid', status: 422, errors: ["
                "{pointer: '/profiles/1/x1', reason: 'outside the domain'},"
                "{pointer: '/stations/x1/2', reason: 'beyond the width'}]})")
        self.assertEqual(self.texts("#f_profiles_1_x1 ~ .ferr"), ["outside the domain"])
        self.assertEqual(self.texts("[data-field='/stations/x1'] > .ferr"), ["beyond the width"])
        self.assertEqual(self.texts("#f_profiles_0_x1 ~ .ferr"), [""])



if __name__ == "__main__":
    run()

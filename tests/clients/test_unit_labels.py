"""Run labels of the client's figures (results.run_label, Result.label): a run is told from the
others by its method (FE/BI), what is below the interface when not the rigid plane, the
friction law by its scale parameter (L for the slip scale, t* for the time scale, D_c for slip
weakening, "Coulomb" for none) and n_d; the paper's scene keeps its "L = 5e-05 m, n_d = 40".
The curves of the plots carry these labels, and the rupture-speed plot shades the overstressed
patch and names both solids' wave speeds at a bimaterial interface.

    /usr/bin/python3 -m unittest discover -s tests/clients -p 'test_unit*.py'
"""

import json
import os
import unittest

import harness
import numpy as np
from slipfront_client import methods
from slipfront_client.plots import common, cost, speed, velocity
from slipfront_client.results import Result, friction_label, run_label

PRESETS = os.path.join(harness.REPO, "presets")


def preset(name, method):
    """The spec of a built-in preset (presets/NAME.json) by `method`."""
    with open(os.path.join(PRESETS, f"{name}.json")) as f:
        return {**json.load(f)["spec"], "method": method}


def paper(method, L=5e-5, n_d=40):
    return {"method": method, "friction": {"law": "prakash_clifton", "mu": 0.75, "L": L,
                                           "v_star": 1.0}, "geometry": {"nodes_per_meter": n_d}}


def result(spec, x1=(0.0, 5.0, 10.0)):
    """A Result with a small made-up record: |V| rising at every node, a front at 1 m/s."""
    x = np.array(x1)
    t = np.linspace(0.0, 10.0, 11)
    v = np.outer(t, np.ones_like(x)) * 1e-3
    return Result("made-up.h5", x, t, v, np.zeros_like(v), x, x.copy(), np.ones_like(x), spec=spec)


class RunLabels(unittest.TestCase):
    def test_paper_scene_keeps_its_label_behind_the_method(self):
        fe, bi = run_label(paper("fe")), run_label(paper("spectral_bi"))
        self.assertEqual(fe, "FE, L = 5e-05 m, n_d = 40")
        self.assertEqual(bi, "BI, L = 5e-05 m, n_d = 40")
        self.assertNotEqual(fe, bi)  # the same scene by both methods reads apart
        self.assertEqual(result(paper("fe")).label(), fe)

    def test_mesh_damping_and_a_note_are_named(self):
        damped = {**paper("fe", 5e-6, 80), "fe": {"mesh_damping": 0.1}}
        self.assertEqual(run_label(damped), "FE, L = 5e-06 m, mesh damping 0.1, n_d = 80")
        self.assertEqual(run_label({**paper("fe"), "fe": {"mesh_damping": 0}}),
                         "FE, L = 5e-05 m, n_d = 40")  # the undamped default reads as before
        r = result(paper("fe", 5e-6, 160))
        r.note = "not converged"
        self.assertEqual(r.label(), "FE, L = 5e-06 m, n_d = 160 (not converged)")

    def test_method_from_the_metrics_or_fe_by_default(self):
        spec = paper("fe")
        del spec["method"]
        self.assertEqual(run_label(spec, {"method": "spectral_bi"}), "BI, L = 5e-05 m, n_d = 40")
        self.assertEqual(run_label(spec), "FE, L = 5e-05 m, n_d = 40")  # the job's default

    def test_each_law_by_its_scale_parameter(self):
        cases = (({"law": "coulomb"}, "Coulomb"),
                 ({"law": "coulomb", "regularization": "none"}, "Coulomb"),
                 ({"law": "coulomb", "regularization": "slip_scale", "L": 1e-3}, "L = 0.001 m"),
                 ({"law": "coulomb", "regularization": "time_scale", "t_star": 3.5e-4},
                  "t* = 0.00035 s"),
                 ({"law": "prakash_clifton", "L": 1e-5}, "L = 1e-05 m"),
                 ({"L": 1e-5}, "L = 1e-05 m"),  # the default law
                 ({"law": "slip_weakening", "D_c": 0.4}, "slip weakening D_c = 0.4 m"),
                 ({"law": "slip_weakening", "D_c": 7.44e-4, "regularization": "time_scale",
                   "t_star": 3.5e-4}, "slip weakening D_c = 0.000744 m, t* = 0.00035 s"),
                 ({"law": "slip_weakening", "D_c": 1e-3, "regularization": "slip_scale",
                   "L": 1e-4}, "slip weakening D_c = 0.001 m, L = 0.0001 m"),
                 ({"law": "prakash_clifton"}, "L = ? m"))  # a spec without its L says so
        for friction, expected in cases:
            self.assertEqual(friction_label(friction), expected, friction)

    def test_a_slip_weakening_run_is_not_read_as_n_d_only(self):
        # The old label of a law without L was "n_d = 10" alone.
        spec = preset("bimaterial_slip_weakening", "spectral_bi")
        self.assertEqual(run_label(spec), "BI, bimaterial, slip weakening D_c = 0.000744 m, "
                                          f"t* = 0.00035 s, n_d = {spec['geometry']['nodes_per_meter']:g}")
        other = {**spec, "friction": {**spec["friction"], "D_c": 1e-3}}
        self.assertNotEqual(run_label(other), run_label(spec))

    def test_presets_by_both_methods(self):
        for name, middle in (("bimaterial_prakash_clifton", "bimaterial, L = 0.001 m"),
                             ("scec_tpv3_2d", "full space, slip weakening D_c = 0.4 m")):
            n_d = preset(name, "fe")["geometry"]["nodes_per_meter"]
            self.assertEqual(run_label(preset(name, "fe")), f"FE, {middle}, n_d = {n_d:g}")
            self.assertEqual(run_label(preset(name, "spectral_bi")), f"BI, {middle}, n_d = {n_d:g}")

    def test_identical_solids_in_either_form_are_a_full_space(self):
        moduli = {"density": 1.0, "young_modulus": 2.5, "poisson_ratio": 0.25}
        speeds = {"density": 1.0, "s_wave_speed": 1.0, "p_wave_speed": 3 ** 0.5}
        spec = {**paper("fe"), "material": moduli, "lower": {"solid": "elastic", **speeds}}
        self.assertEqual(run_label(spec), "FE, full space, L = 5e-05 m, n_d = 40")
        spec["lower"]["density"] = 1.1
        self.assertEqual(run_label(spec), "FE, bimaterial, L = 5e-05 m, n_d = 40")
        spec["lower"] = {"solid": "rigid"}
        self.assertEqual(run_label(spec), "FE, L = 5e-05 m, n_d = 40")


class MethodsFromTheServer(unittest.TestCase):
    """The methods and their labels come from the server's job schema (methods.py): a method
    the client has never heard of gets its labels and a style of its own, with no other edit."""

    SCHEMA = {"properties": {"method": {
        "enum": ["fe", "spectral_bi", "toy"], "default": "fe",
        "x-labels": {"fe": {"label": "FE", "title": "finite elements"},
                     "spectral_bi": {"label": "BI", "title": "spectral boundary integral"},
                     "toy": {"label": "TOY", "heading": "toy FE", "title": "toy elements"}}}}}

    class Api:
        def __init__(self, schema=None):
            self.schema, self.calls = schema, 0

        def job_schema(self):
            self.calls += 1
            if self.schema is None:
                raise ConnectionError("no server")
            return self.schema

    def tearDown(self):
        methods.reset()

    def test_a_toy_method_of_the_server_is_labelled_and_styled(self):
        api = self.Api(self.SCHEMA)
        methods.use(api)
        self.assertEqual(api.calls, 0)  # read when first needed
        self.assertEqual(run_label(paper("toy")), "TOY, L = 5e-05 m, n_d = 40")
        self.assertEqual(api.calls, 1)
        self.assertEqual(methods.names(), ["fe", "spectral_bi", "toy"])
        self.assertEqual((methods.heading("toy"), methods.title("toy")), ("toy FE", "toy elements"))
        styles = [common.method_style({"method": m}) for m in methods.names()]
        self.assertEqual(len({(s["ls"], s["marker"]) for s in styles}), 3)
        self.assertEqual(cost.style_of("toy")["label"], "TOY (toy elements)")
        self.assertEqual(api.calls, 1)

    def test_offline_the_built_in_methods(self):
        self.assertFalse(methods.load(self.Api(None)))
        self.assertEqual(methods.names(), ["fe", "spectral_bi"])
        self.assertEqual(run_label(paper("spectral_bi")), "BI, L = 5e-05 m, n_d = 40")
        self.assertEqual(cost.style_of("spectral_bi")["label"], "BI (spectral boundary integral)")
        self.assertEqual(cost.style_of("other")["label"], "other")  # not listed: its name


class LabelledCurves(unittest.TestCase):
    def test_velocity_and_speed_curves_tell_the_methods_apart(self):
        runs = [result(paper("fe")), result(paper("spectral_bi"))]
        fig, data = velocity.plot_velocity(runs, positions=(5.0,))
        legend = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
        self.assertEqual(legend, ["FE, L = 5e-05 m, n_d = 40", "BI, L = 5e-05 m, n_d = 40"])
        self.assertEqual(set(data) - {"windows"}, set(legend))
        fig, data = speed.plot_speed(runs)
        legend = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
        self.assertIn("FE, L = 5e-05 m, n_d = 40", legend)
        self.assertIn("BI, L = 5e-05 m, n_d = 40", legend)

    def test_speed_plot_of_a_bimaterial_run(self):
        spec = preset("bimaterial_prakash_clifton", "spectral_bi")
        fig, data = speed.plot_speed([result(spec, x1=(-20.0, 0.0, 20.0))])
        self.assertEqual(data["nucleation_patch"], (-10.0, 10.0))  # the overstressed patch
        self.assertEqual((data["c_s"], data["c_p"]), (2620.0, 4537.973))
        self.assertEqual((data["c_s_lower"], data["c_p_lower"]), (3091.6, 5354.808))
        names = [t.get_text().strip() for t in fig.axes[0].texts]
        self.assertEqual(names, ["$c_s$ upper", "$c_p$ upper", "$c_s$ lower", "$c_p$ lower"])
        self.assertAlmostEqual(fig.axes[0].get_ylim()[1], 1.1 * 5354.808)
        self.assertIn("nucleation patch (-10 to 10 m)",
                      [t.get_text() for t in fig.axes[0].get_legend().get_texts()])


if __name__ == "__main__":
    unittest.main()

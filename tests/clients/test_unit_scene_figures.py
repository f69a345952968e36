"""Figures that follow the job (Result.positions, Result.event_window, Result.thresholds and the
map and velocity plots that use them) and a study's headline answer block (report.answer_lines,
studies.summary_lines; docs/studies.md "The answer"):

- a run's places to watch are its own stations, else its probes — never the paper's 6 and 10 m
  unless the job's are there;
- the map opens on the event (where and when |V| exceeded 1 % of its peak, and the front), the
  whole box on request; the front and the stations are labelled with their thresholds;
- the answer block comes first, its verdict before every other number, each labelled.

    /usr/bin/python3 -m unittest discover -s tests/clients -p 'test_unit*.py'
"""

import unittest

import harness
import numpy as np
from slipfront_client import report, studies
from slipfront_client.plots import slip_map, velocity
from slipfront_client.results import Result

REPO = harness.REPO  # importing harness also puts clients/ on the path


def made_up(spec, metrics=None):
    """A run on x1 in [-100, 100) every 2 m over 0..1 s whose slip covers x1 in [-20, 40] and
    t up to 0.2 s (|V| = 1 m/s there), the front across the same nodes."""
    x = np.arange(-100.0, 100.0, 2.0)
    t = np.linspace(0.0, 1.0, 101)
    v = np.zeros((t.size, x.size))
    inside = (x >= -20) & (x <= 40)
    v[np.ix_((t > 0.01) & (t <= 0.2), inside)] = 1.0
    arrival = np.where(inside, np.abs(x) / 400.0, np.nan)
    return Result("made-up.h5", x, t, v, np.zeros_like(v), x, arrival, np.full_like(x, np.nan),
                  spec=spec, metrics=metrics or {"front_threshold": 1e-3})


class Positions(unittest.TestCase):
    def test_stations_first_spread_along_them(self):
        run = made_up({"stations": {"x1": [50, -10, 0, 10, 20, 30, 40], "rupture_threshold": 1e-3}})
        self.assertEqual([x for x, _ in run.positions(most=4)], [-10.0, 10.0, 30.0, 50.0])
        self.assertEqual({what for _, what in run.positions()}, {"station"})

    def test_else_the_jobs_probes(self):
        run = made_up({"probe": {"arrival_x1": 100.0, "spectrum_x1": 40.0}})
        self.assertEqual(run.positions(), [(40.0, "probe.spectrum_x1"), (100.0, "probe.arrival_x1")])
        same = made_up({"probe": {"arrival_x1": 6.0, "spectrum_x1": 6.0}})
        self.assertEqual(same.positions(), [(6.0, "probe.spectrum_x1")])

    def test_the_velocity_plot_and_the_map_draw_them(self):
        run = made_up({"probe": {"arrival_x1": 30.0, "spectrum_x1": 10.0}})
        _, data = velocity.plot_velocity([run])
        label = run.label()
        self.assertEqual(sorted(data[label]), [10.0, 30.0])
        _, data = slip_map.plot_map(run)
        self.assertEqual(data["probes"], [10.0, 30.0])


class EventWindow(unittest.TestCase):
    def test_the_map_opens_on_the_event_and_the_whole_box_on_request(self):
        run = made_up({})
        (x0, x1), (t0, t1) = run.event_window()
        self.assertAlmostEqual(x0, -20 - 6.0)  # 10 % of the 60 m span each side
        self.assertAlmostEqual(x1, 40 + 6.0)
        self.assertEqual(t0, 0.0)
        self.assertAlmostEqual(t1, 0.2 + 0.15 * 0.2)
        fig, data = slip_map.plot_map(run)
        ax = fig.axes[0]
        np.testing.assert_allclose(ax.get_xlim(), (x0, x1))
        np.testing.assert_allclose(ax.get_ylim(), (t0, t1))
        fig, data = slip_map.plot_map(run, whole=True)
        self.assertIsNone(data["window"])
        self.assertLess(fig.axes[0].get_xlim()[0], -99)

    def test_nothing_slipped_no_window(self):
        run = made_up({})
        run.slip_velocity[:] = 0
        self.assertIsNone(run.event_window())


class Thresholds(unittest.TestCase):
    def test_one_threshold_unless_the_job_gives_two_each_labelled(self):
        stations = {"x1": [0.0, 20.0], "rupture_threshold": 1e-3}
        metrics = {"front_threshold": 1e-3,
                   "stations": [{"x1": 0.0, "rupture_time": 0.0}, {"x1": 20.0, "rupture_time": 0.05}]}
        run = made_up({"stations": stations}, metrics)
        self.assertEqual(run.thresholds(), (1e-3, 1e-3))
        fig, _ = slip_map.plot_map(run)
        labels = fig.axes[0].get_legend_handles_labels()[1]
        self.assertIn("slip front (|V| > 0.001 m/s)", labels)
        self.assertIn("station rupture times (|V| > 0.001 m/s, as the front)", labels)
        two = made_up({"stations": dict(stations, rupture_threshold=1e-2)}, metrics)
        labels = slip_map.plot_map(two)[0].axes[0].get_legend_handles_labels()[1]
        self.assertIn("station rupture times (|V| > 0.01 m/s)", labels)


ANSWER = {"state": "found", "verdict": "L_c = 8e-07 m, in [8e-07, 1.6e-06) m",
          "meaning": "below L_c the regularisation no longer changes the rupture",
          "certainty": "the L search's rule, from 20 runs",
          "others": [{"label": "spectral estimate: an order of magnitude, not the rule's answer",
                      "value": 9.38e-05, "unit": "m"},
                     {"label": "the paper's value", "value": 1e-05, "unit": "m"}]}


class AnswerBlock(unittest.TestCase):
    def test_the_verdict_comes_first_every_other_number_labelled(self):
        study = {"id": "s", "status": "finished", "L_c": 8e-07,
                 "spectral_critical_length": 9.38e-05, "answer": ANSWER, "runs": []}
        lines = report.answer_lines(study)
        self.assertEqual(lines[0], "**L_c = 8e-07 m, in [8e-07, 1.6e-06) m**.")
        text = "\n".join(lines)
        self.assertLess(text.index("What it means"), text.index("How sure"))
        self.assertIn("- 9.38e-05 m: spectral estimate: an order of magnitude, not the rule's "
                      "answer", text)
        self.assertIn("- 1e-05 m: the paper's value", text)
        shown = studies.summary_lines(study)
        first_number = next(i for i, line in enumerate(shown) if "e-0" in line)
        self.assertTrue(shown[first_number].startswith("the answer: L_c = 8e-07 m"), shown)
        self.assertIn("spectral estimate (an order of magnitude from the filter law, not the "
                      "rule's answer): 9.38e-05", "\n".join(shown))

    def test_an_l_searchs_runs_and_maps_are_named_for_what_they_are(self):
        """`study show` of an L search: its plain-Coulomb runs listed as "coulomb" (not under
        the base's L), and an L that did not converge said so with its finest mesh, never
        "converged from n_d = -"."""
        def run(L, n_d, regime=None):
            row = {"job_id": f"{L}-{n_d}-{regime}", "L": L, "n_d": n_d,
                   "job_status": "succeeded", "convergence": {"status": "unknown"}}
            if regime:
                row["regime"] = regime
            return row
        study = {"id": "s", "status": "finished", "kind": "convergence",
                 "runs": [run(3.2e-06, 10), run(3.2e-06, 20), run(1.6e-06, 10),
                          run(1.6e-06, 20), run(3.2e-06, 10, "coulomb"),
                          run(3.2e-06, 20, "coulomb")],
                 "convergence_map": {"converged_n_d": {"3.2e-06": 20, "1.6e-06": None}}}
        shown = studies.summary_lines(study)
        rows = [line.split() for line in shown if line.split()[-1:] and "-" in line.split()[-1]
                and line.split()[-1].endswith(("None", "coulomb"))]
        self.assertEqual([(r[0], r[-1].endswith("coulomb")) for r in rows],
                         [("3.2e-06", False), ("3.2e-06", False), ("1.6e-06", False),
                          ("1.6e-06", False), ("coulomb", True), ("coulomb", True)])
        self.assertIn("L = 3.2e-06: converged from n_d = 20", shown)
        self.assertIn("L = 1.6e-06: not converged (no two successive meshes agree up to "
                      "n_d = 20)", shown)
        self.assertFalse([line for line in shown if "n_d = -" in line], shown)

    def test_the_reproduction_report_opens_with_the_l_searchs_answer(self):
        from slipfront_client.reproduction_report import opening_lines
        search = {"id": "search", "method": "spectral_bi", "search": {"state": "found"},
                  "answer": ANSWER}
        fe = {"id": "fe", "critical_length": {"reason": "no L meets the rule: ...",
                                              "steps_in_L": [{"agree": False}]}}
        lines = opening_lines(search, fe, None)
        self.assertEqual(lines[:2], ["## The answer\n", "From the BI L search `search`:\n"])
        self.assertEqual(lines[2], "**L_c = 8e-07 m, in [8e-07, 1.6e-06) m**.")
        self.assertIn("- no L meets the rule: the FE convergence study over the paper's L "
                      "(docs/reproduction.md \"L_c verdict, by method\")", lines)

    def test_an_older_server_without_the_block_gives_the_verdict_alone(self):
        self.assertEqual(report.answer_lines({"L_c": 1e-5}), ["**L_c = 1e-05 m**."])


if __name__ == "__main__":
    unittest.main()

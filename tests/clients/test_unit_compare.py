"""What tells compared runs apart (slipfront_client.compare): the fields flattened and the ones
that differ (first, then those only some runs have, then the identical ones), a field only one
method has counted as differing, the spread of the numbers, the legend texts (the run
label, then every other spec field that differs and every run has; a repeated run named by
its short id), and the table marking the differing fields with '*' and hiding the identical
ones but the key fields unless asked.

    /usr/bin/python3 -m unittest discover -s tests/clients -p 'test_unit*.py'
"""

import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "clients"))
from slipfront_client.compare import (MISSING, compare_labels, compare_rows,  # noqa: E402
                                      flatten, scatter_defaults, table_lines)


def job(job_id, method="fe", L=1e-4, n_d=10, duration=16.0, distance=15.0, **spec):
    return {"id": job_id * 32, "status": "succeeded", "name": "",
            "spec": {"method": method, "friction": {"law": "prakash_clifton", "L": L},
                     "geometry": {"nodes_per_meter": n_d}, "time": {"duration": duration},
                     "name": job_id, **spec},
            "metrics": {"propagation_distance": distance, "rupture_speed": {"max": 1.5}}}


class Compare(unittest.TestCase):
    def test_flatten_keeps_lists_as_leaves(self):
        self.assertEqual(flatten({"a": {"b": 1, "c": [1, 2]}, "d": "x"}),
                         {"a.b": 1, "a.c": [1, 2], "d": "x"})

    def test_rows_mark_what_differs(self):
        rows = {(r["group"], r["key"]): r for r in compare_rows(
            [job("a"), job("b", method="spectral_bi", spectral_bi={"corrector_passes": 1})])}
        self.assertTrue(rows["spec", "method"]["differs"])
        self.assertFalse(rows["spec", "friction.L"]["differs"])
        only_bi = rows["spec", "spectral_bi.corrector_passes"]
        self.assertEqual(only_bi["values"], [MISSING, 1])
        self.assertTrue(only_bi["differs"])
        self.assertNotIn(("spec", "name"), rows)  # the job's name is a run field
        self.assertFalse(rows["spec", "method"]["partial"])
        self.assertTrue(only_bi["partial"])
        self.assertIsNone(only_bi["spread"])
        self.assertEqual(rows["metrics", "rupture_speed.max"]["values"], [1.5, 1.5])

    def test_real_differences_come_first(self):
        keys = [r["key"] for r in compare_rows(
            [job("a"), job("b", method="spectral_bi", spectral_bi={"corrector_passes": 1})])
                if r["group"] == "spec"]
        self.assertEqual(keys[:2], ["method", "spectral_bi.corrector_passes"])
        self.assertEqual(keys[2:], ["friction.law", "friction.L", "geometry.nodes_per_meter",
                                    "time.duration"])

    def test_labels_say_the_method_and_every_other_difference(self):
        labels = compare_labels([job("a"), job("b", method="spectral_bi")])
        self.assertEqual(labels, ["FE, L = 0.0001 m, n_d = 10", "BI, L = 0.0001 m, n_d = 10"])
        labels = compare_labels([job("a", n_d=10, duration=3.0), job("b", n_d=20, duration=16.0)])
        self.assertEqual(labels, ["FE, L = 0.0001 m, n_d = 10, time.duration = 3",
                                  "FE, L = 0.0001 m, n_d = 20, time.duration = 16"])
        # A field only one run has is in the table, not in the legends.
        labels = compare_labels([job("a"), job("b", method="spectral_bi",
                                                spectral_bi={"corrector_passes": 1})])
        self.assertNotIn("corrector", labels[1])

    def test_a_repeated_run_gets_its_short_id(self):
        self.assertEqual(compare_labels([job("a"), job("b")]),
                         ["FE, L = 0.0001 m, n_d = 10 (aaaaaaaa)",
                          "FE, L = 0.0001 m, n_d = 10 (bbbbbbbb)"])

    def test_table_marks_differences_and_hides_identical_fields(self):
        jobs = [job("a", distance=15.4), job("b", method="spectral_bi", distance=15.0)]
        rows = compare_rows(jobs)
        lines = table_lines(jobs, rows, compare_labels(jobs, rows))
        self.assertEqual(lines[0], f"run 1: {'a' * 32}  FE, L = 0.0001 m, n_d = 10")
        method = next(line for line in lines if line.lstrip("* ").startswith("method"))
        self.assertTrue(method.startswith("* method"), method)
        self.assertEqual(method.split()[2:], ["fe", "spectral_bi"])
        self.assertTrue(any(line.split() == ["friction.L", "0.0001", "0.0001"] for line in lines))
        # The spread of the numbers that differ: (15.4 - 15) / 15.4.
        self.assertTrue(any(line.split() == ["*", "propagation_distance", "15.4", "15", "2.6", "%"]
                            for line in lines))
        self.assertFalse(any("time.duration" in line for line in lines))  # identical: hidden
        self.assertTrue(any("identical not shown" in line for line in lines))
        every = table_lines(jobs, rows, compare_labels(jobs, rows), show_all=True)
        self.assertTrue(any(line.split() == ["time.duration", "16", "16"] for line in every))

    def test_scatter_defaults_to_the_parameter_that_differs(self):
        self.assertEqual(scatter_defaults(compare_rows([job("a"), job("b", method="spectral_bi")])),
                         ("method", "propagation_distance"))
        self.assertEqual(scatter_defaults(compare_rows([job("a", n_d=10), job("b", n_d=20)]))[0],
                         "geometry.nodes_per_meter")


if __name__ == "__main__":
    unittest.main()

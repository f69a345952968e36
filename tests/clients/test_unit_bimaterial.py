"""The bimaterial study's requests and measurements (clients/slipfront_client/bimaterial.py),
no server needed.

    /usr/bin/python3 -m unittest discover -s tests/clients -p 'test_unit*.py'
"""

import unittest

import harness
from slipfront_client import bimaterial as bm

assert harness.CLIENTS  # importing harness put clients/ on sys.path

BASE = {"method": "spectral_bi", "threads": 1,
        "friction": {"law": "prakash_clifton", "mu": 0.7, "v_star": 0.26},
        "geometry": {"width": 600, "x_min": -300}, "tags": ["preset"]}


def job(n_d, beta, peak, distance, arrival, outcome="running_at_end", status="succeeded"):
    spec = bm.coulomb_job(BASE, n_d, beta)
    return {"id": f"{n_d}-{beta}", "status": status, "spec": spec,
            "metrics": {"outcome": outcome, "max_slip_velocity": peak, "steps": 10,
                        "simulated_time": 0.1, "propagation_distance": distance,
                        "arrival_time_at_probe": arrival,
                        "warnings": ["... is ill-posed: ..."]}}


class BimaterialTest(unittest.TestCase):
    def test_merge_is_rfc7396(self):
        out = bm.merge({"a": {"b": 1, "c": 2}, "d": 3}, {"a": {"b": None, "e": 4}, "d": [1]})
        self.assertEqual(out, {"a": {"c": 2, "e": 4}, "d": [1]})

    def test_coulomb_job_drops_the_regularisation_and_sets_mesh_and_step(self):
        spec = bm.coulomb_job(BASE, 10, 0.25)
        self.assertEqual(spec["friction"], {"law": "coulomb", "mu": 0.7})
        self.assertEqual(spec["geometry"]["nodes_per_meter"], 10)
        self.assertEqual(spec["spectral_bi"], {"time_step_factor": 0.25})
        self.assertEqual(BASE["friction"]["law"], "prakash_clifton")  # base untouched

    def test_coulomb_rows_pair_meshes_of_the_same_step_factor_only(self):
        jobs = [job(5, 0.5, 10.0, 100.0, 0.01), job(10, 0.5, 40.0, 100.1, 0.01),
                job(20, 0.25, 80.0, 100.0, 0.01), job(5, 0.25, 9.0, 100.0, 0.01)]
        rows = bm.coulomb_rows(jobs)
        self.assertEqual([(r["beta"], r["n_d"]) for r in rows],
                         [(0.5, 5.0), (0.5, 10.0), (0.25, 5.0), (0.25, 20.0)])
        # 5 -> 10 at beta 0.5: distance 0.1 %, arrival 0: converged by the rule; the beta
        # 0.25 run at n_d = 20 is not the partner of the beta 0.5 run at 10
        self.assertEqual([r["convergence"] for r in rows],
                         ["converged", "unknown", "converged", "unknown"])
        ratios = bm.peak_ratios(rows)
        self.assertEqual(ratios[0.5], [(5.0, 10.0, 4.0)])
        self.assertEqual(ratios[0.25], [(5.0, 20.0, 80.0 / 9.0)])


if __name__ == "__main__":
    unittest.main()

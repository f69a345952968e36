"""Studies over real HTTP on loopback (docs/studies-api.md): grid and convergence studies of
tiny jobs run by the real solver, the stored convergence statuses, map and L_c, cache reuse
across studies, the supervisor resuming after a crash, the shared convergence map of two
users, error paths, the failure_regimes preset's detections, and cancelling a study.

    /usr/bin/python3 tests/server/test_studies.py --binary build/slipfront
"""

import argparse
import json
import os
import sys
import tempfile
import time
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import Server, long_job  # noqa: E402
from server_harness import wait_study as wait_finished  # noqa: E402

BINARY = None
STUDIES = "/api/v1/studies"
STATUSES = {"converged", "not_converged", "unknown", "diverged", "pending", "failed"}

# A tiny scene: 12 m x 4 m, probes inside it, 3 s simulated. Runs take well under a second.
BASE = {"geometry": {"width": 12, "x_min": -1, "height": 4},
        "probe": {"arrival_x1": 3, "spectrum_x1": 2}, "time": {"duration": 3}}


def base(**friction):
    b = json.loads(json.dumps(BASE))
    if friction:
        b["friction"] = friction
    return b


def post_study(server, body, headers=None):
    return server.post(STUDIES, data=json.dumps(body),
                       headers={"Content-Type": "application/json", **(headers or {})})


class Studies(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.server = Server(BINARY, args=["--workers", "2", "--queue-limit", "40"]).start()

    @classmethod
    def tearDownClass(cls):
        code = cls.server.terminate()
        cls.server.cleanup()
        assert code == 0, f"server exit code {code}"

    def create(self, body, status=201):
        r = post_study(self.server, body)
        self.assertEqual(r.status_code, status, r.text)
        return r

    def test_grid_study_runs_jobs_and_stores_statuses_and_map(self):
        r = self.create({"name": "grid", "tags": ["t1"], "base": base(),
                         "grid": {"L": [5e-5, 1e-4], "n_d": [5, 10]}})
        self.assertTrue(r.headers["Location"].startswith(STUDIES + "/"))
        created = r.json()
        self.assertEqual(created["kind"], "grid")
        self.assertEqual(created["progress"]["total"], 4)
        study = wait_finished(self.server, created["id"])
        self.assertEqual(study["progress"], {"done": 4, "total": 4, "fraction": 1.0})
        self.assertEqual(len(study["runs"]), 4)
        for run in study["runs"]:
            self.assertEqual(run["job_status"], "succeeded")
            self.assertIn(run["convergence"]["status"], STATUSES - {"pending"})
            if run["n_d"] == 5:  # judged against n_d = 10 with both relative changes
                self.assertEqual(run["convergence"]["partner_n_d"], 10)
                self.assertIsNotNone(run["convergence"]["changes"]["propagation_distance"])
            else:
                self.assertEqual(run["convergence"]["status"], "unknown")
        cmap = study["convergence_map"]
        self.assertEqual(cmap["L"], [5e-5, 1e-4])
        self.assertEqual(cmap["n_d"], [5, 10])
        self.assertEqual(len(cmap["cells"]), 4)
        self.assertIn("L_c", study["critical_length"])
        # The runs are ordinary jobs carrying the study id.
        jobs = self.server.get("/api/v1/jobs", params={"study_id": study["id"]}).json()["jobs"]
        self.assertEqual(sorted(j["id"] for j in jobs), sorted(r["job_id"] for r in study["runs"]))
        for job in jobs:
            self.assertEqual(job["study_id"], study["id"])
            self.assertEqual(job["scene_hash"], study["scene_hash"])
            self.assertIn("t1", job["tags"])
        listed = self.server.get(STUDIES).json()["studies"]
        self.assertIn(study["id"], [s["id"] for s in listed])
        # Speed and accuracy: cost of every run; no converged L here, so no reference.
        sa = self.server.get(f"{STUDIES}/{study['id']}/speed-accuracy").json()
        self.assertEqual(len(sa["runs"]), 4)
        for entry in sa["runs"]:
            self.assertGreater(entry["wall_time_s"], 0)
            self.assertGreater(entry["memory_bytes"], 0)

    def test_critical_length_of_a_controlled_case_and_speed_accuracy(self):
        # mu = 1.2 with the default load: no rupture at any L or mesh. Every L is
        # mesh-converged at n_d = 5 (both meshes agree: no rupture), every L agrees with the
        # smaller ones, so L_c is the largest L, reported as a lower bound.
        r = self.create({"name": "controlled", "base": base(mu=1.2),
                         "grid": {"L": [5e-5, 1e-4, 2e-4], "n_d": [5, 10]}})
        study = wait_finished(self.server, r.json()["id"])
        self.assertEqual(study["L_c"], 2e-4)
        self.assertEqual(study["critical_length"]["L_c"], 2e-4)
        self.assertIn("at least", study["critical_length"]["reason"])
        self.assertEqual(study["convergence_map"]["converged_n_d"],
                         {"5e-05": 5, "0.0001": 5, "0.0002": 5})
        for run in study["runs"]:
            self.assertEqual(run["outcome"], "no_rupture")
            self.assertEqual(run["convergence"]["status"],
                             "converged" if run["n_d"] == 5 else "unknown")
        sa = self.server.get(f"{STUDIES}/{study['id']}/speed-accuracy").json()
        self.assertEqual(sa["probe"]["x1"], 2.0)
        for entry in sa["runs"]:
            self.assertIsNotNone(entry["reference_run_id"])
            self.assertIn("slip_velocity_l2", entry["errors"])
            if entry["id"] == entry["reference_run_id"]:
                self.assertEqual(entry["errors"]["propagation_distance"], 0.0)
                # 0, or null with the reason when the record is zero (no slip at the probe).
                if entry["errors"]["slip_velocity_l2"] is None:
                    self.assertIn("slip_velocity_l2_unavailable", entry)
                else:
                    self.assertEqual(entry["errors"]["slip_velocity_l2"], 0.0)

    def test_identical_runs_are_reused_across_studies(self):
        body = {"name": "first", "base": base(v_star=2e-4), "grid": {"L": [5e-5], "n_d": [5, 10]}}
        first = wait_finished(self.server, self.create(body).json()["id"])
        body["name"] = "second"
        second = self.create(body).json()
        # Every run reused at once: the study is finished in the 201 answer.
        self.assertEqual(second["status"], "finished")
        originals = {r["n_d"]: r["job_id"] for r in first["runs"]}
        for run in second["runs"]:
            self.assertEqual(run["cached_from"], originals[run["n_d"]])
            self.assertEqual(run["job_status"], "succeeded")
        self.assertEqual(second["scene_hash"], first["scene_hash"])
        body["fresh"] = True
        third = wait_finished(self.server, self.create(body).json()["id"])
        self.assertTrue(all(r["cached_from"] is None for r in third["runs"]))

    def test_convergence_study_refines_until_the_cap(self):
        r = self.create({"name": "conv", "base": base(),
                         "convergence": {"L": [5e-5], "n_d": [5, 10, 20], "n_d_max": 20}})
        created = r.json()
        self.assertEqual(sorted(run["n_d"] for run in created["runs"]), [5, 10])
        study = wait_finished(self.server, created["id"])
        meshes = sorted(run["n_d"] for run in study["runs"])
        plan = study["refinement"]["5e-05"]
        # 5 vs 10 does not converge on this tiny scene: the supervisor adds n_d = 20.
        self.assertEqual(meshes, [5, 10, 20], study["refinement"])
        self.assertIn(plan["state"], {"converged", "not_converged_at_cap"})

    def test_l_search_stops_where_the_meshes_stop(self):
        # On the tiny scene every run is still slipping at the end, so no L mesh-converges:
        # the search tries the first L and the next, and stops at the mesh cap.
        r = self.create({"name": "search", "base": base(),
                         "convergence": {"search": {"from": 1e-4, "factor": 2}, "n_d": [5, 10]}})
        created = r.json()
        own = [run for run in created["runs"] if "regime" not in run]
        self.assertEqual(sorted(run["L"] for run in own), [1e-4, 1e-4])
        # The tiny scene is on the rigid plane with mu = 0.75 < 1: plain Coulomb is well-posed,
        # and its first two meshes run beside the L (docs/studies-api.md "L search").
        coulomb = [run for run in created["runs"] if run.get("regime") == "coulomb"]
        self.assertEqual(sorted(run["n_d"] for run in coulomb), [5, 10])
        self.assertTrue(created["request"]["convergence"]["search"]["coulomb"])
        study = wait_finished(self.server, created["id"])
        search = study["search"]
        self.assertEqual(search["state"], "mesh_cap", search)
        self.assertIn("status", search["coulomb"])
        self.assertEqual(search["searched_L"], [1e-4, 5e-5])
        self.assertEqual(sorted({run["L"] for run in study["runs"]}), [5e-5, 1e-4])
        self.assertIn("stopped at the mesh cap", search["reason"])
        self.assertIsNone(study["L_c"])
        # Its runs carry the stations the rule measures the arrival time at (docs/metrics.md).
        job = self.server.get(f"/api/v1/jobs/{study['runs'][0]['job_id']}").json()
        stations = job["spec"]["stations"]
        self.assertEqual(len(stations["x1"]), 32)
        self.assertAlmostEqual(stations["x1"][0], -1 + 12 / 64)

    def test_errors(self):
        cases = [
            ({"grid": {"L": [1e-5, 2e-5, -1], "n_d": [5]}}, "/grid/L/2", "must be > 0"),
            ({"grid": {"L": [1e-5], "n_d": []}}, "/grid/n_d", None),
            ({"base": {"friction": {"L": 1e-5}}, "grid": {"L": [1e-5], "n_d": [5]}},
             "/base/friction/L", None),
            ({"base": {"material": {"poisson_ratio": 0.7}}, "grid": {"L": [1e-5], "n_d": [5]}},
             "/base/material/poisson_ratio", None),
            ({"grid": {"L": [1e-5], "n_d": [5]}, "bogus": 1}, "/bogus", "unknown field"),
            ({"name": "no kind"}, "", None),
            ({"preset": "nope"}, "/preset", None),
            ({"convergence": {"L": [1e-5], "n_d": [20, 10]}}, "/convergence/n_d", None),
            ({"grid": {"L": [1e-5], "n_d": [5]}, "priority": 1000}, "/priority", None),
            ({"convergence": {"L": [1e-5], "search": {}}}, "/convergence", None),
            ({"convergence": {"search": {"from": 1e-5, "floor": 1e-5}}},
             "/convergence/search/floor", None),
            ({"convergence": {"search": {"confirm": 2.5}}}, "/convergence/search/confirm", None),
            ({"convergence": {"search": {"factor": 1.0}}}, "/convergence/search/factor",
             "must be a number in [1.1, 100]"),
            ({"convergence": {"search": {"from": 1e-5, "floor": 5e-6, "factor": 2}}},
             "/convergence/search", None),  # two L only: the rule needs three
            ({"convergence": {"search": {"bogus": 1}}}, "/convergence/search/bogus",
             "unknown field"),
            ({"grid": {"L": [1e-5], "n_d": [5]}, "priority": 18446744073709551615}, "/priority",
             "must be an integer in [-100, 100]"),
        ]
        for body, pointer, reason in cases:
            r = post_study(self.server, body)
            self.assertEqual(r.status_code, 422, (body, r.text))
            self.assertTrue(r.headers["Content-Type"].startswith("application/problem+json"))
            errors = {e["pointer"]: e["reason"] for e in r.json()["errors"]}
            self.assertIn(pointer, errors, (body, errors))
            if reason:
                self.assertEqual(errors[pointer], reason)
        r = self.server.post(STUDIES, data="{not json", headers={"Content-Type": "application/json"})
        self.assertEqual(r.status_code, 400)
        for path in [f"{STUDIES}/{'0' * 32}", f"{STUDIES}/nope", f"{STUDIES}/{'0' * 32}/speed-accuracy"]:
            r = self.server.get(path)
            self.assertEqual(r.status_code, 404, path)
            self.assertEqual(r.headers["Content-Type"], "application/problem+json")
        self.assertEqual(self.server.get("/api/v1/convergence-map").status_code, 400)
        self.assertEqual(self.server.get("/api/v1/convergence-map",
                                         params={"scene": "xyz"}).status_code, 400)
        self.assertEqual(self.server.get("/api/v1/convergence-map",
                                         params={"study": "0" * 32}).status_code, 404)
        empty = self.server.get("/api/v1/convergence-map", params={"scene": "a" * 64}).json()
        self.assertEqual(empty["count"], 0)
        self.assertEqual(self.server.get(STUDIES, params={"limit": 0}).status_code, 400)

    def test_failure_regimes_are_detected(self):
        r = self.create({"name": "failures", "base": base(), "preset": "failure_regimes"})
        study = wait_finished(self.server, r.json()["id"])
        regimes = {g["regime"]: g for g in study["regimes"]}
        self.assertEqual(set(regimes), {"regularised", "coulomb", "explicit_euler",
                                         "unstable_time_step", "mu_1.2", "bimaterial_coulomb"})
        for name in ("explicit_euler", "unstable_time_step"):
            g = regimes[name]
            self.assertTrue(g["finding"].startswith("detected: every run diverged"), g["finding"])
            for run in g["runs"]:
                # Reported as a failure, not as a plausible-looking result.
                self.assertEqual(run["job_status"], "failed")
                self.assertEqual(run["outcome"], "diverged")
                self.assertEqual(run["convergence_status"], "diverged")
                self.assertIn("diverged", run["error"])
            statuses = {c["status"] for c in g["convergence_map"]["cells"]}
            self.assertEqual(statuses, {"diverged"})
        coulomb = regimes["coulomb"]
        self.assertEqual(sorted(r["n_d"] for r in coulomb["runs"]), [10, 20, 40])
        self.assertNotIn("converged", {r["convergence_status"] for r in coulomb["runs"]})
        # Coulomb between two different solids: ill-posed, so refinement never settles.
        bimaterial = regimes["bimaterial_coulomb"]
        self.assertEqual(sorted(r["n_d"] for r in bimaterial["runs"]), [10, 20, 40])
        self.assertNotIn("converged", {r["convergence_status"] for r in bimaterial["runs"]})
        self.assertTrue(bimaterial["finding"].startswith("no mesh convergence"),
                        bimaterial["finding"])
        self.assertEqual(regimes["explicit_euler"]["runs"][0]["L"], 5e-6)
        # Each regime is its own scene, so its own map.
        scenes = {g["scene_hash"] for g in study["regimes"]}
        self.assertEqual(len(scenes), 6)
        for run in study["runs"]:
            self.assertIn(run["regime"], regimes)
        self.assertEqual(study["convergence_map"], regimes["regularised"]["convergence_map"])


ALICE = {"Authorization": "Bearer alice-token-123"}
BOB = {"Authorization": "Bearer bob-token-4567"}


def token_server_args(data_dir):
    """One worker and a token file of two users, alice and bob (headers ALICE, BOB)."""
    tokens = os.path.join(data_dir, "tokens")
    with open(tokens, "w") as f:
        f.write("alice:alice-token-123\nbob:bob-token-4567\n")
    os.chmod(tokens, 0o600)
    return ["--workers", "1", "--token-file", tokens]


class SharedMapAndRestart(unittest.TestCase):
    """Two users on a token server; then a crash mid-study and a restart."""

    def test_shared_map_and_supervisor_resumes_after_restart(self):
        data_dir = tempfile.mkdtemp(prefix="slipfront-studies-")
        args = token_server_args(data_dir)
        server = Server(BINARY, data_dir=data_dir, args=args).start()
        try:
            self.assertEqual(post_study(server, {"grid": {"L": [1e-4], "n_d": [5]}}).status_code,
                             401)
            b = base(v_star=3e-4)
            sa = post_study(server, {"name": "a", "base": b, "grid": {"L": [1e-4], "n_d": [5]}},
                            ALICE).json()
            sb = post_study(server, {"name": "b", "base": b, "grid": {"L": [1e-4], "n_d": [10]}},
                            BOB).json()
            # A plain job of the same scene counts too.
            job = dict(json.loads(json.dumps(b)), geometry=dict(b["geometry"], nodes_per_meter=8),
                       friction={"v_star": 3e-4, "L": 1e-4})
            jr = server.submit(job, headers=ALICE)
            self.assertEqual(jr.status_code, 201, jr.text)
            for s in (sa, sb):
                wait_finished(server, s["id"])
            server.wait_status(jr.json()["id"], {"succeeded", "failed"})
            self.assertEqual(sa["scene_hash"], sb["scene_hash"])
            self.assertEqual(jr.json()["scene_hash"], sa["scene_hash"])
            m = server.get("/api/v1/convergence-map", params={"study": sa["id"]}).json()
            self.assertEqual(m["count"], 3)
            self.assertEqual({r["submitted_by"] for r in m["runs"]}, {"alice", "bob"})
            self.assertEqual(m["convergence_map"]["n_d"], [5, 8, 10])
            coarse = [c for c in m["convergence_map"]["cells"] if c["n_d"] == 5][0]
            self.assertEqual(coarse["partner_n_d"], 8)  # alice's run judged against another run
            self.assertIn(coarse["status"], {"converged", "not_converged"})
            by_scene = server.get("/api/v1/convergence-map",
                                  params={"scene": sa["scene_hash"]}).json()
            self.assertEqual(by_scene["convergence_map"], m["convergence_map"])

            # A convergence study behind a long job on the single worker, then a crash
            # (SIGKILL) while none of its runs has finished.
            blocker = server.submit(long_job(), headers=ALICE).json()
            server.wait_status(blocker["id"], {"running"})
            created = post_study(server, {"name": "restart", "base": base(v_star=4e-4),
                                          "priority": 10,
                                          "convergence": {"L": [5e-5], "n_d": [5, 10, 20],
                                                          "n_d_max": 20}}, ALICE).json()
            self.assertEqual(len(created["runs"]), 2)
            now = server.get(f"{STUDIES}/{created['id']}").json()
            self.assertEqual(now["progress"]["done"], 0)
            server.kill()
            server.cleanup()  # closes its pipes; the data dir is kept (not its own)
            server = Server(BINARY, data_dir=data_dir, args=args).start()
            # Priority 10 runs the study's jobs before the re-queued long job.
            study = wait_finished(server, created["id"])
            self.assertEqual(sorted(r["n_d"] for r in study["runs"]), [5, 10, 20])
            self.assertTrue(all(r["job_status"] == "succeeded" for r in study["runs"]))
            self.assertIn("submitted n_d = 20", server.read_log())
            server.post(f"/api/v1/jobs/{blocker['id']}/cancel", headers=ALICE)
        finally:
            server.terminate()
            server.own_dir = True
            server.cleanup()


class Cancel(unittest.TestCase):
    """POST /studies/{id}/cancel: the queued run cancelled, the running one stopped, no
    further mesh submitted, and the status kept across a restart; 401/403/404/409."""

    def test_cancel_stops_a_convergence_study_for_good(self):
        data_dir = tempfile.mkdtemp(prefix="slipfront-cancel-")
        args = token_server_args(data_dir)
        server = Server(BINARY, data_dir=data_dir, args=args).start()
        try:
            # One worker: n_d = 30 runs (about 10 s), n_d = 60 waits; n_d = 120 would follow.
            body = {"name": "to cancel", "base": {"time": {"duration": 16.0, "stop_on_arrest": False}},
                    "convergence": {"L": [5e-5], "n_d": [30, 60, 120], "n_d_max": 120}}
            created = post_study(server, body, ALICE).json()
            runs = {r["n_d"]: r["job_id"] for r in created["runs"]}
            self.assertEqual(sorted(runs), [30, 60])
            server.wait_status(runs[30], {"running"})
            url = f"{STUDIES}/{created['id']}/cancel"

            self.assertEqual(server.post(url).status_code, 401)
            self.assertEqual(server.post(url, headers=BOB).status_code, 403)
            self.assertEqual(server.post(f"{STUDIES}/{'0' * 32}/cancel", headers=ALICE).status_code,
                             404)
            r = server.post(url, headers=ALICE)
            self.assertEqual(r.status_code, 202, r.text)  # the running run is still stopping
            answer = r.json()
            self.assertEqual(answer["status"], "cancelled")
            self.assertEqual(answer["cancelled_jobs"], [runs[60]])
            self.assertEqual(answer["cancel_requested_jobs"], [runs[30]])
            for job_id in runs.values():
                self.assertEqual(server.wait_status(job_id, {"cancelled"}, timeout=60.0)["status"],
                                 "cancelled")
            again = server.post(url, headers=ALICE)
            self.assertEqual(again.status_code, 409, again.text)
            self.assertIn("already cancelled", again.json()["detail"])

            def settled():  # the supervisor stores the progress after the worker's status
                deadline = time.monotonic() + 30
                while time.monotonic() < deadline:
                    study = server.get(f"{STUDIES}/{created['id']}").json()
                    if study["progress"]["done"] == 2:
                        return study
                    time.sleep(0.05)
                raise AssertionError(f"progress not stored: {study}")

            def check(study):
                self.assertEqual(study["status"], "cancelled")
                self.assertEqual(study["refinement"]["5e-05"]["state"], "cancelled")
                self.assertEqual(sorted(r["n_d"] for r in study["runs"]), [30, 60])
                self.assertEqual(study["progress"]["done"], 2)
                self.assertTrue(study["finished_at"])

            check(settled())
            listed = server.get(STUDIES, params={"status": "cancelled"}).json()["studies"]
            self.assertEqual([s["id"] for s in listed], [created["id"]])
            self.assertEqual(server.get(STUDIES, params={"status": "running"}).json()["count"], 0)

            # A restart neither resumes nor refines it.
            self.assertEqual(server.terminate(), 0)
            server.cleanup()
            server = Server(BINARY, data_dir=data_dir, args=args).start()
            check(settled())
            self.assertNotIn("submitted n_d = 120", server.read_log())
            self.assertEqual(server.get("/api/v1/jobs", params={"status": "queued"}).json()["count"], 0)
        finally:
            server.terminate()
            server.own_dir = True
            server.cleanup()


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

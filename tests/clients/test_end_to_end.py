"""slipfront-client against a real `slipfront serve` (ephemeral port, temporary data dir,
real solver on tiny jobs): submit --wait, status, list, download (sha256, resume),
cancel, exit codes, studies, and every figure from the downloaded HDF5.

    /usr/bin/python3 tests/clients/test_end_to_end.py --binary build/slipfront
"""

import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import unittest

import h5py
import numpy as np

from harness import LONG, SCRIPT, TINY, Server, binary_from_argv, run_client, wait_until
from slipfront_client import methods
from slipfront_client.api import Api
from slipfront_client.result_download import download_result
from slipfront_client.plots import slip_map
from slipfront_client.results import load_result

BINARY = None


def sha256(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


class EndToEnd(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.server = Server(BINARY, args=["--workers", "2"]).start()
        cls.tmp = tempfile.mkdtemp(prefix="slipfront-client-e2e-")
        cls.job_file = os.path.join(cls.tmp, "tiny.json")
        with open(cls.job_file, "w") as f:
            json.dump(TINY, f)
        cls.api = Api(cls.server.base)
        # A small grid over L x n_d, tagged, each submitted and waited for by the client.
        cls.grid = {}
        for L in ("1e-4", "5e-5"):
            for n_d in ("5", "10"):
                r = cls.client("submit", cls.job_file, "--set", f"friction.L={L}",
                               "--set", f"geometry.nodes_per_meter={n_d}", "--tag", "grid",
                               "--name", f"grid L={L} n_d={n_d}", "--wait")
                assert r.returncode == 0, r.stderr
                cls.grid[(L, n_d)] = r.stdout.strip().splitlines()[-1]
        cls.job_id = cls.grid[("5e-5", "10")]
        cls.h5 = os.path.join(cls.tmp, "result.h5")
        r = cls.client("download", cls.job_id, "-o", cls.h5)
        assert r.returncode == 0, r.stderr

    @classmethod
    def tearDownClass(cls):
        cls.api.close()
        cls.server.stop()
        shutil.rmtree(cls.tmp, ignore_errors=True)

    @classmethod
    def client(cls, *args, **kw):
        env = {"XDG_CACHE_HOME": os.path.join(cls.tmp, "cache")}
        return run_client(*args, server=cls.server.base, env=env, **kw)

    # -- jobs ---------------------------------------------------------------------------

    def test_the_offline_methods_are_the_servers(self):
        # The client's built-in list (methods.py, used when the server cannot say) is the
        # server's registry of methods (its job schema's method).
        methods.reset()
        try:
            self.assertTrue(methods.load(self.api))
            self.assertEqual(methods.names(), methods.BUILT_IN["names"])
            self.assertEqual(methods.default(), methods.BUILT_IN["default"])
            for name in methods.names():
                for key, value in methods.BUILT_IN["labels"][name].items():
                    self.assertEqual(methods._labels(name).get(key), value, (name, key))
        finally:
            methods.reset()

    def test_submit_wait_download_in_one_command(self):
        out = os.path.join(self.tmp, "one.h5")
        r = self.client("submit", "-", "--set", "friction.L=2e-5", "--fresh", "--priority", "5",
                        "--wait", "--download", out, stdin=json.dumps(TINY))
        self.assertEqual(r.returncode, 0, r.stderr)
        job = self.api.job(r.stdout.strip())
        self.assertEqual(job["status"], "succeeded")
        self.assertEqual(job["priority"], 5)
        self.assertEqual(job["spec"]["friction"]["L"], 2e-5)
        self.assertEqual(sha256(out), job["result"]["sha256"])
        self.assertIn("%", r.stderr)           # the progress bar
        self.assertIn("t = ", r.stderr)

    def test_presets_list_show_and_submit(self):
        r = self.client("presets")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stdout.splitlines()[0].split()[:3], ["name", "origin", "title"])
        self.assertIn("quick_nd10", r.stdout)
        r = self.client("presets", "quick_nd10")
        self.assertEqual(json.loads(r.stdout)["geometry"]["nodes_per_meter"], 10)
        self.assertNotEqual(self.client("presets", "none_such").returncode, 0)
        # --preset with --set: the server expands the preset and merges the changes over it.
        r = self.client("submit", "--preset", "quick_nd10", "--set", "time.duration=0.5",
                        "--set", "method=spectral_bi", "--dry-run")
        self.assertEqual(json.loads(r.stdout), {"preset": "quick_nd10", "time": {"duration": 0.5},
                                                "method": "spectral_bi"})
        r = self.client("submit", "--preset", "quick_nd10", "--set", "time.duration=0.5",
                        "--set", "method=spectral_bi", "--wait")
        self.assertEqual(r.returncode, 0, r.stderr)
        job = self.api.job(r.stdout.strip().splitlines()[-1])
        self.assertEqual((job["status"], job["spec"]["method"]), ("succeeded", "spectral_bi"))
        self.assertEqual(job["spec"]["geometry"]["nodes_per_meter"], 10)
        self.assertEqual(job["spec"]["time"]["duration"], 0.5)

    def test_status_human_and_json(self):
        r = self.client("status", self.job_id)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("succeeded", r.stdout)
        self.assertIn("outcome", r.stdout)
        r = self.client("status", self.job_id, "--fields", "status,metrics")
        doc = json.loads(r.stdout)
        self.assertEqual(set(doc), {"id", "status", "metrics"})
        self.assertEqual(self.client("status", "0" * 32).returncode, 1)

    def test_list_filters_projection_and_pagination(self):
        r = self.client("list", "--tag", "grid", "--json")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual({j["id"] for j in json.loads(r.stdout)}, set(self.grid.values()))
        r = self.client("list", "--tag", "grid", "--L-min", "6e-5", "--n-d-max", "7",
                        "--fields", "status,name", "--json")
        jobs = json.loads(r.stdout)
        self.assertEqual([j["id"] for j in jobs], [self.grid[("1e-4", "5")]])
        self.assertEqual(set(jobs[0]), {"id", "status", "name"})
        r = self.client("list", "--tag", "grid", "--limit", "3", "--fields", "status")
        self.assertEqual(len(r.stdout.strip().splitlines()), 1 + 3)  # header + 3 rows
        # Pages of one job each: the cursor is followed to the end.
        paged = list(self.api.list_jobs({"tag": "grid"}, page_size=1))
        self.assertEqual([j["id"] for j in paged],
                         [j["id"] for j in self.api.list_jobs({"tag": "grid"})])
        self.assertEqual(len(paged), 4)

    def test_download_matches_server_sha_and_resumes(self):
        job = self.api.job(self.job_id)
        self.assertEqual(sha256(self.h5), job["result"]["sha256"])
        self.assertEqual(os.path.getsize(self.h5), job["result"]["size"])
        # A partial file is continued with a Range request, not fetched again.
        partial = os.path.join(self.tmp, "partial.h5")
        with open(self.h5, "rb") as src, open(partial + ".part", "wb") as dst:
            dst.write(src.read(job["result"]["size"] // 3))
        path, sha, fetched = download_result(self.api, self.job_id, partial)
        self.assertEqual(sha, job["result"]["sha256"])
        self.assertEqual(sha256(path), sha)
        self.assertEqual(fetched, job["result"]["size"] - job["result"]["size"] // 3)
        self.assertFalse(os.path.exists(partial + ".part"))
        # Up to date: nothing fetched. Corrupt: fetched again and verified.
        self.assertEqual(download_result(self.api, self.job_id, partial)[2], 0)
        with open(partial, "r+b") as f:
            f.seek(100)
            f.write(b"garbage")
        r = self.client("download", self.job_id, "-o", partial)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(sha256(partial), sha)

    def test_bad_job_exits_2_with_pointers(self):
        r = self.client("submit", self.job_file, "--set", "geometry.nodes_per_meter=-1",
                        "--set", "friction.bogus=1")
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("/geometry/nodes_per_meter: ", r.stderr)
        self.assertIn("/friction/bogus: ", r.stderr)
        self.assertEqual(self.client("submit", "--set", "no-equals-sign").returncode, 2)
        self.assertEqual(self.client("submit", "/no/such/job.json").returncode, 2)
        self.assertEqual(self.client("list", "--limit", "x").returncode, 2)

    def test_diverged_job_exits_3(self):
        r = self.client("submit", self.job_file, "--set", "friction.strength_update=explicit_euler",
                        "--set", "friction.L=1e-7", "--wait")
        self.assertEqual(r.returncode, 3, r.stderr)
        self.assertIn("diverged", r.stderr)

    def test_cancel_while_waiting_exits_4(self):
        job_file = os.path.join(self.tmp, "long.json")
        with open(job_file, "w") as f:
            json.dump(LONG, f)
        env = dict(os.environ, SLIPFRONT_SERVER=self.server.base)
        waiter = subprocess.Popen(["/usr/bin/python3", SCRIPT, "submit", job_file, "--fresh",
                                   "--name", "to-cancel", "--wait"], env=env,
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        try:
            job = wait_until(lambda: next(iter(self.api.list_jobs(
                {"name": "to-cancel", "status": "running"})), None), timeout=30)
            r = self.client("cancel", job["id"], "--wait")
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("cancelled", r.stdout)
            out, err = waiter.communicate(timeout=30)
            self.assertEqual(waiter.returncode, 4, err)
            self.assertEqual(out.strip(), job["id"])
        finally:
            if waiter.poll() is None:
                waiter.kill()
                waiter.communicate()
        r = self.client("status", job["id"], "--exit-status")
        self.assertEqual(r.returncode, 4)
        r = self.client("cancel", job["id"])  # already final: 409
        self.assertEqual(r.returncode, 1)
        self.assertIn("already finished", r.stderr)

    def test_unreachable_server_exits_1(self):
        r = run_client("list", "--server", "http://127.0.0.1:9", "--http-timeout", "2")
        self.assertEqual(r.returncode, 1)
        self.assertIn("nothing answers at", r.stderr)

    def test_study(self):
        r = self.client("study", "create", "--base", self.job_file, "--L", "1e-4,5e-5",
                        "--n-d", "5,10", "--name", "e2e study", "--wait", "--wait-timeout", "60",
                        "--json")
        self.assertEqual(r.returncode, 0, r.stderr)
        study = json.loads(r.stdout)
        self.assertEqual(study["status"], "finished", study)
        cells = {(c["L"], c["n_d"]) for c in study["convergence_map"]["cells"]}
        self.assertEqual(cells, {(1e-4, 5), (1e-4, 10), (5e-5, 5), (5e-5, 10)})
        # The finest mesh of each L has no finer partner: its status is unknown.
        finest = [c for c in study["convergence_map"]["cells"] if c["n_d"] == 10]
        self.assertTrue(all(c["status"] == "unknown" for c in finest), finest)

    def test_l_search_study(self):
        # No L list: the server walks down from --from; on the tiny scene no L mesh-converges,
        # so the search stops at the mesh cap after two L and says so.
        r = self.client("study", "create", "--base", self.job_file, "--search", "--from", "1e-4",
                        "--factor", "2", "--n-d", "5,10", "--wait", "--wait-timeout", "60")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("L search (mesh_cap): stopped at the mesh cap", r.stdout)
        self.assertIn("tried L = 0.0001, 5e-05", r.stdout)
        r = self.client("study", "create", "--base", self.job_file, "--search", "--L", "1e-4")
        self.assertEqual(r.returncode, 2)
        self.assertIn("either --L or --search", r.stderr)
        r = self.client("study", "create", "--base", self.job_file, "--L", "1e-4", "--factor", "3",
                        "--n-d", "5,10")
        self.assertEqual(r.returncode, 2)
        self.assertIn("need --search", r.stderr)

    def test_accuracy_target(self):
        # One metric at a stated accuracy on the tiny FE scene (docs/studies-api.md "Accuracy
        # target"): the answer with its estimate and the meshes it took, or the cap.
        r = self.client("accuracy", "propagation_distance", "5%", "--base", self.job_file,
                        "--method", "fe", "--n-d", "5,10,20", "--wait-timeout", "60", "--json")
        self.assertEqual(r.returncode, 0, r.stderr)
        answer = json.loads(r.stdout)["accuracy"]
        self.assertIn(answer["state"], ("met", "mesh_cap", "failed"), answer)
        self.assertEqual(answer["method"], {"name": "fe", "reason": "asked for (accuracy.method)"})
        self.assertEqual(answer["target"]["tolerance"], 0.05)
        r = self.client("study", "show", json.loads(r.stdout)["id"])
        self.assertIn("accuracy target: propagation_distance within 5 %", r.stdout)
        self.assertNotIn("L_c", r.stdout)
        r = self.client("accuracy", "arrest_position", "half")
        self.assertEqual(r.returncode, 2)
        self.assertIn("tolerance 'half'", r.stderr)

    def test_bi_study_and_both_methods(self):
        bi_base = os.path.join(self.tmp, "bi_base.json")
        base = json.loads(json.dumps(TINY))
        del base["geometry"]["height"]
        base["method"] = "spectral_bi"
        with open(bi_base, "w") as f:
            json.dump(base, f)
        ids = {}
        for method, path in (("fe", self.job_file), ("spectral_bi", bi_base)):
            r = self.client("study", "create", "--base", path, "--L", "1e-4,5e-5", "--n-d", "5,10",
                            "--name", f"e2e {method}", "--wait", "--wait-timeout", "60", "--json")
            self.assertEqual(r.returncode, 0, r.stderr)
            study = json.loads(r.stdout)
            self.assertEqual((study["status"], study.get("method")), ("finished", method))
            ids[method] = study["id"]
        self.assertIsInstance(study.get("cross_method"), list)
        self.assertTrue(study.get("counterpart_scene_hash"))
        r = self.client("study", "show", ids["spectral_bi"])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("method spectral_bi", r.stdout)
        self.assertRegex(r.stdout, r"verdict: (L_c = |no L meets the rule|L_c undetermined)")
        # the cost chart's rows of both studies, each run with its method
        from slipfront_client.commands_plot import study_cost_rows
        rows, reference = study_cost_rows(self.api, [ids["fe"], ids["spectral_bi"]])
        self.assertEqual({r["method"] for r in rows}, {"fe", "spectral_bi"})
        if reference == "converged":  # the server's errors: every run of both scenes
            for method in ("fe", "spectral_bi"):
                self.assertGreaterEqual(sum(r["method"] == method for r in rows), 4, rows)
        else:  # no L converged: errors against the finest run of each L and method
            self.assertEqual(reference, "unconverged")
            for r in rows:
                self.assertLess(r["n_d"], r["reference_n_d"])
                self.assertGreater(r["error"], 0)

    def test_study_cancel(self):
        long_base = os.path.join(self.tmp, "long_base.json")
        with open(long_base, "w") as f:
            json.dump({k: v for k, v in LONG.items() if k != "geometry"}, f)
        r = self.client("study", "create", "--base", long_base, "--L", "5e-5,1e-5",
                        "--n-d", "30", "--name", "e2e cancel")
        self.assertEqual(r.returncode, 0, r.stderr)
        study_id = r.stdout.strip()
        r = self.client("study", "cancel", study_id)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertRegex(r.stdout, rf"^{study_id} cancelled: \d queued run\(s\) cancelled, "
                                   r"\d running run\(s\) stopping$")
        r = self.client("study", "cancel", study_id)  # not running any more: 409
        self.assertEqual(r.returncode, 1)
        self.assertIn("not running", r.stderr)
        r = self.client("study", "show", study_id, "--json")
        self.assertEqual(json.loads(r.stdout)["status"], "cancelled")

    # -- figures ------------------------------------------------------------------------

    def assertFigures(self, stdout, count):
        paths = stdout.split()
        self.assertEqual(len(paths), count, stdout)
        for path in paths:
            self.assertGreater(os.path.getsize(path), 5000, path)
            with open(path, "rb") as f:
                head = f.read(8)
            self.assertTrue(head.startswith(b"\x89PNG") or head.startswith(b"%PDF"), path)
        return paths

    def plot(self, *args):
        out = os.path.join(self.tmp, "figs")
        r = self.client("plot", *args, "-o", out, "--format", "png,pdf")
        self.assertEqual(r.returncode, 0, r.stderr)
        return r.stdout

    def test_plot_map_and_its_data(self):
        self.assertFigures(self.plot("map", self.h5, "--probes", "2,3"), 2)
        _, data = slip_map.plot_map(load_result(self.h5))
        with h5py.File(self.h5, "r") as f:
            np.testing.assert_array_equal(data["x1"], f["interface/x1"][()])
            np.testing.assert_array_equal(data["time"], f["interface/time"][()])
            np.testing.assert_array_equal(data["abs_slip_velocity"],
                                          np.abs(f["interface/slip_velocity"][()]))
            arrival = f["front/arrival_time"][()]
            known = np.isfinite(arrival)
            np.testing.assert_array_equal(data["front_time"], arrival[known])
            np.testing.assert_array_equal(data["front_x1"], f["front/x1"][()][known])
        self.assertGreater(data["front_x1"].size, 5)
        self.assertEqual(data["abs_slip_velocity"].shape, (data["time"].size, data["x1"].size))

    def test_plot_velocity_and_speed_from_files_and_job_ids(self):
        ids = [self.grid[("1e-4", "10")], self.grid[("5e-5", "10")]]
        self.assertFigures(self.plot("velocity", self.h5, *ids, "--x1", "2,3"), 2)
        self.assertFigures(self.plot("speed", self.h5, *ids, "--stem", "speed_runs"), 2)
        self.assertFigures(self.plot("speed", "--front-json", *ids, "--stem", "speed_json"), 2)

    def test_plot_convergence_from_runs_and_json(self):
        self.assertFigures(self.plot("convergence", "--tag", "grid"), 2)
        self.assertFigures(self.plot("convergence", *self.grid.values(), "--stem", "conv_files"), 2)
        points = os.path.join(self.tmp, "points.json")
        with open(points, "w") as f:
            json.dump([{"L": 1e-4, "n_d": 20, "status": "converged"},
                       {"L": 1e-5, "n_d": 20, "status": "not_converged"},
                       {"L": 1e-6, "n_d": 20, "status": "diverged"},
                       {"L": 1e-5, "n_d": 40, "status": "pending"},
                       {"L": 1e-5, "n_d": 80, "status": "unknown"}], f)
        self.assertFigures(self.plot("convergence", "--map", points, "--critical-length", "1e-5",
                                     "--stem", "conv_json"), 2)

    def test_plot_never_overwrites_silently(self):
        out = os.path.join(self.tmp, "figs-again")
        first = self.client("plot", "filter", "--L", "1e-4", "-o", out)
        self.assertEqual(first.returncode, 0, first.stderr)
        path = first.stdout.strip()
        self.assertEqual(path, os.path.join(out, "filter.png"))
        before = os.stat(path).st_mtime_ns
        again = self.client("plot", "filter", "--L", "1e-5", "-o", out)
        self.assertEqual(again.returncode, 2, again.stdout)
        self.assertIn(f"{path} exists: give --force to replace", again.stderr)
        self.assertEqual(os.stat(path).st_mtime_ns, before)
        forced = self.client("plot", "filter", "--L", "1e-5", "-o", out, "--force")
        self.assertEqual(forced.returncode, 0, forced.stderr)
        self.assertNotEqual(os.stat(path).st_mtime_ns, before)
        # map: one figure per source, map_SOURCE; two sources, one refused before any is drawn
        r = self.client("plot", "map", self.h5, "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        stem = os.path.splitext(os.path.basename(self.h5))[0]
        self.assertEqual(r.stdout.split(), [os.path.join(out, f"map_{stem}.png")])
        job = self.grid[("1e-4", "10")]
        r = self.client("plot", "map", job, self.h5, "-o", out)
        self.assertEqual(r.returncode, 2, r.stdout)
        self.assertFalse(os.path.exists(os.path.join(out, f"map_{job}.png")))

    def test_plot_filter_and_cost(self):
        self.assertFigures(self.plot("filter", *self.grid.values()), 2)
        self.assertFigures(self.plot("filter", "--L", "1e-4,1e-5", "--n-d", "10,40",
                                     "--stem", "filter_paper"), 2)
        self.assertFigures(self.plot("cost", "--tag", "grid"), 2)
        rows = os.path.join(self.tmp, "cost.json")
        with open(rows, "w") as f:
            json.dump([{"L": 1e-4, "n_d": n, "wall_time_s": n ** 2 / 50, "error": 1 / n}
                       for n in (10, 20, 40)], f)
        self.assertFigures(self.plot("cost", "--data", rows, "--stem", "cost_json"), 2)


if __name__ == "__main__":
    BINARY, argv = binary_from_argv(sys.argv)
    started = time.monotonic()
    result = unittest.main(argv=argv, exit=False)
    print(f"end-to-end client tests: {time.monotonic() - started:.1f} s", file=sys.stderr)
    sys.exit(0 if result.result.wasSuccessful() else 1)

"""Studies kept like runs, over real HTTP on loopback against `slipfront serve` with its real
SQLite file and result files (docs/server.md "Keep, annotate, share"): a study's tags added,
removed and replaced and its note; archive hides it from GET /studies until asked for;
delete removes the study with its runs and their result files, refused while it runs (and
while a cancelled run still stops); only its owner changes it on a shared server; bad
changes are refused naming the field, nothing changed.

    /usr/bin/python3 tests/server/test_study_keep.py --binary build/slipfront
"""

import argparse
import json
import os
import sys
import tempfile
import time
import unittest

import requests

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import Server, wait_study  # noqa: E402

BINARY = None
STUDIES = "/api/v1/studies"
BASE = {"geometry": {"width": 12, "x_min": -1, "height": 4},
        "probe": {"arrival_x1": 3, "spectrum_x1": 2}, "time": {"duration": 3}}
JSON = {"Content-Type": "application/json"}


def grid(name, L, tags=(), n_d=(5,), base=None):
    return {"name": name, "tags": list(tags), "grid": {"L": [L], "n_d": list(n_d)},
            "base": base or BASE}


def long_study(name):
    """One run of about 20 s (server_harness.long_job): the study runs while the test acts."""
    base = {"time": {"duration": 16.0, "stop_on_arrest": False}}
    return {"name": name, "grid": {"L": [5e-5], "n_d": [50]}, "base": base}


class StudyKeep(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.server = Server(BINARY, args=["--workers", "1"]).start()

    @classmethod
    def tearDownClass(cls):
        code = cls.server.terminate()
        cls.server.cleanup()
        assert code == 0, code

    def create(self, body, headers=None):
        r = self.server.post(STUDIES, data=json.dumps(body), headers={**JSON, **(headers or {})})
        self.assertEqual(r.status_code, 201, r.text)
        return r.json()

    def finished(self, body):
        return wait_study(self.server, self.create(body)["id"], timeout=120)

    def patch(self, study_id, body, **kw):
        return self.server.session.patch(self.server.url(f"{STUDIES}/{study_id}"),
                                         data=json.dumps(body), headers=JSON, timeout=10, **kw)

    def study(self, study_id):
        return self.server.get(f"{STUDIES}/{study_id}").json()

    def listed(self, **params):
        r = self.server.get(STUDIES, params={"limit": 1000, **params})
        self.assertEqual(r.status_code, 200, r.text)
        return [s["id"] for s in r.json()["studies"]]

    def test_tags_and_note(self):
        study = self.finished(grid("kept study", 6.1e-4, tags=["kammer2014", "draft"]))
        self.assertEqual((study["tags"], study["note"], study["archived_at"]),
                         (["kammer2014", "draft"], "", None))
        r = self.patch(study["id"], {"tags_add": ["fig-3"], "tags_remove": ["draft"],
                                     "note": "the L sweep of Fig. 3\nmesh checked"})
        self.assertEqual(r.status_code, 200, r.text)
        self.assertEqual(r.json()["tags"], ["kammer2014", "fig-3"])
        got = self.study(study["id"])
        self.assertEqual(got["tags"], ["kammer2014", "fig-3"])
        self.assertEqual(got["note"], "the L sweep of Fig. 3\nmesh checked")
        self.assertEqual(got["runs"], study["runs"], "a change of tags touched its runs")
        r = self.patch(study["id"], {"tags": ["only"]})
        self.assertEqual(r.json()["tags"], ["only"])
        self.assertEqual(r.json()["note"], "the L sweep of Fig. 3\nmesh checked")
        cases = [({"tags": ["a"], "tags_add": ["b"]}, "/tags_add"),
                 ({"tags_add": ["x" * 65]}, "/tags_add/0"),
                 ({"note": "bell \u0007"}, "/note"),
                 ({"colour": "red"}, "/colour"),
                 ({}, "")]
        for body, pointer in cases:
            r = self.patch(study["id"], body)
            self.assertEqual(r.status_code, 422, f"{body}: {r.text}")
            self.assertIn(pointer, [e["pointer"] for e in r.json()["errors"]], r.text)
        self.assertEqual(self.study(study["id"])["tags"], ["only"])
        self.assertEqual(self.patch("0" * 32, {"note": "x"}).status_code, 404)
        r = self.server.session.patch(self.server.url(f"{STUDIES}/{study['id']}"), data="{",
                                      headers=JSON)
        self.assertEqual(r.status_code, 400)

    def test_archive_hides_it_until_asked_for(self):
        study = self.finished(grid("archived study", 6.3e-4))
        self.assertIn(study["id"], self.listed())
        r = self.server.post(f"{STUDIES}/{study['id']}/archive")
        self.assertEqual(r.status_code, 200, r.text)
        archived_at = r.json()["archived_at"]
        self.assertIsNotNone(archived_at)
        self.assertNotIn(study["id"], self.listed())
        self.assertIn(study["id"], self.listed(archived="include"))
        self.assertIn(study["id"], self.listed(archived="only"))
        self.assertEqual(self.study(study["id"])["archived_at"], archived_at)  # served by id
        r = self.server.post(f"{STUDIES}/{study['id']}/archive")
        self.assertEqual(r.json()["archived_at"], archived_at, "archived twice: a new time")
        r = self.server.get(STUDIES, params={"archived": "yes"})
        self.assertEqual(r.status_code, 400)
        self.assertEqual(r.json()["errors"][0]["pointer"], "/query/archived")
        r = self.server.post(f"{STUDIES}/{study['id']}/restore")
        self.assertEqual((r.status_code, r.json()["archived_at"]), (200, None))
        self.assertIn(study["id"], self.listed())

    def test_delete_removes_the_study_its_runs_and_their_files(self):
        study = self.finished(grid("deleted study", 6.5e-4, n_d=(5, 6)))
        job_ids = [run["job_id"] for run in study["runs"]]
        self.assertEqual(len(job_ids), 2)
        results = os.path.join(self.server.data_dir, "results")
        files = [os.path.join(results, f"{j}.h5") for j in job_ids]
        self.assertTrue(all(os.path.exists(f) for f in files))
        r = self.server.session.delete(self.server.url(f"{STUDIES}/{study['id']}"), timeout=30)
        self.assertEqual(r.status_code, 200, r.text)
        self.assertEqual(sorted(r.json()["deleted_jobs"]), sorted(job_ids))
        self.assertEqual(r.json()["results_deleted"], 2)
        self.assertEqual(self.server.get(f"{STUDIES}/{study['id']}").status_code, 404)
        for job_id in job_ids:
            self.assertEqual(self.server.get(f"/api/v1/jobs/{job_id}").status_code, 404)
        self.assertFalse(any(os.path.exists(f) for f in files), "a result file stayed")
        self.assertNotIn(study["id"], self.listed(archived="include"))
        r = self.server.session.delete(self.server.url(f"{STUDIES}/{study['id']}"), timeout=30)
        self.assertEqual(r.status_code, 404)

    def test_a_result_shared_with_a_run_outside_the_study_stays(self):
        study = self.finished(grid("shared study", 6.7e-4))
        run = self.server.get(f"/api/v1/jobs/{study['runs'][0]['job_id']}").json()
        hit = self.server.submit(run["spec"])  # the same job alone: a cache hit of the run
        self.assertEqual((hit.status_code, hit.json()["cache"]), (201, "hit"), hit.text)
        r = self.server.session.delete(self.server.url(f"{STUDIES}/{study['id']}"), timeout=30)
        self.assertEqual(r.status_code, 200, r.text)
        self.assertEqual(r.json()["results_deleted"], 0)
        got = self.server.get(hit.json()["result"]["url"])
        self.assertEqual(got.status_code, 200, "the hit lost the file it shares")
        self.assertEqual(len(got.content), run["result"]["size"])

    def test_the_cross_method_table_holds_the_studys_own_L(self):
        """Two studies of one scene at other L: each study's cross-method table lists its own
        L only (before: every L the scene had in the database)."""
        first = self.finished(grid("cross first", 7.5e-4))
        second = self.finished(grid("cross second", 7.7e-4))
        self.assertEqual(first["scene_hash"], second["scene_hash"])
        for study, L in ((first, 7.5e-4), (second, 7.7e-4)):
            rows = self.study(study["id"])["cross_method"]
            self.assertEqual([row["L"] for row in rows], [L], study["name"])
        scene = self.server.get("/api/v1/convergence-map", params={"study": first["id"]}).json()
        self.assertGreaterEqual(scene["count"], 2, "the shared map still has both")

    def test_a_running_study_is_not_deleted_until_cancelled_and_stopped(self):
        study = self.create(long_study("running study"))
        url = self.server.url(f"{STUDIES}/{study['id']}")
        job_id = study["runs"][0]["job_id"]
        self.server.wait_status(job_id, {"running"}, timeout=60)
        r = self.server.session.delete(url, timeout=30)
        self.assertEqual(r.status_code, 409, r.text)
        self.assertIn("cancel it first", r.json()["detail"])
        self.assertEqual(self.server.get(f"/api/v1/jobs/{job_id}").json()["status"], "running")
        r = self.server.post(f"{STUDIES}/{study['id']}/cancel")
        self.assertIn(r.status_code, (200, 202), r.text)
        # Cancelled; its run stops at its next step: until then 409, then deleted.
        deadline = time.monotonic() + 30
        while True:
            r = self.server.session.delete(url, timeout=30)
            if r.status_code != 409 or time.monotonic() > deadline:
                break
            self.assertIn("still stopping", r.json()["detail"])
            time.sleep(0.1)
        self.assertEqual(r.status_code, 200, r.text)
        self.assertEqual(r.json()["deleted_jobs"], [job_id])
        self.assertEqual(self.server.get(f"/api/v1/jobs/{job_id}").status_code, 404)


class StudyArchive(unittest.TestCase):
    """A study that is over, exported with its runs as one archive and imported into a second
    server: the study, its runs and their files, listed as they were; imported twice, stored
    once; refused while it runs; a damaged study.json refused naming it, nothing stored."""

    @classmethod
    def setUpClass(cls):
        cls.server = Server(BINARY, args=["--workers", "1"]).start()
        cls.other = Server(BINARY, args=["--workers", "1"]).start()

    @classmethod
    def tearDownClass(cls):
        codes = [s.terminate() for s in (cls.server, cls.other)]
        for s in (cls.server, cls.other):
            s.cleanup()
        assert codes == [0, 0], codes

    def counts(self, server):
        jobs = server.get("/api/v1/jobs", params={"archived": "include"}).json()["count"]
        studies = server.get(STUDIES, params={"archived": "include"}).json()["count"]
        return jobs, studies

    def test_a_study_moves_with_its_runs_once(self):
        r = self.server.post(STUDIES, headers=JSON, data=json.dumps(
            grid("moved study", 7.1e-4, tags=["fig-3"], n_d=(5, 6))))
        self.assertEqual(r.status_code, 201, r.text)
        study = wait_study(self.server, r.json()["id"], timeout=120)
        self.server.session.patch(self.server.url(f"{STUDIES}/{study['id']}"), headers=JSON,
                                  data=json.dumps({"note": "moved with its runs"}), timeout=10)
        r = self.server.get(f"{STUDIES}/{study['id']}/export", timeout=60)
        self.assertEqual(r.status_code, 200, r.text)
        self.assertEqual(r.headers["Content-Type"], "application/x-tar")
        archive = r.content
        import io
        import tarfile
        with tarfile.open(fileobj=io.BytesIO(archive)) as tar:
            names = set(tar.getnames())
            manifest = json.loads(tar.extractfile("manifest.json").read())
        self.assertEqual(manifest["study"], "study.json")
        self.assertIn("study.json", names)
        job_ids = sorted(run["job_id"] for run in study["runs"])
        self.assertEqual(sorted(run["id"] for run in manifest["runs"]), job_ids)

        r = self.other.post("/api/v1/imports", data=archive, timeout=60)
        self.assertEqual(r.status_code, 201, r.text)
        self.assertEqual(r.json()["study"], {"id": study["id"], "original_id": study["id"],
                                             "url": f"{STUDIES}/{study['id']}",
                                             "skipped": False})
        self.assertEqual(r.json()["count"], 2)
        there = self.other.get(f"{STUDIES}/{study['id']}").json()
        for key in ("name", "kind", "status", "L_c", "request", "scene_hash", "progress"):
            self.assertEqual(there[key], study[key], key)
        self.assertEqual((there["tags"], there["note"]), (["fig-3"], "moved with its runs"))
        self.assertEqual([(x["job_id"], x["n_d"], x["convergence"]) for x in there["runs"]],
                         [(x["job_id"], x["n_d"], x["convergence"]) for x in study["runs"]])
        for job_id in job_ids:
            job = self.other.get(f"/api/v1/jobs/{job_id}").json()
            self.assertEqual(job["study_id"], study["id"])
            self.assertEqual(job["imported_from"]["id"], job_id)
            self.assertEqual(self.other.get(job["result"]["url"]).status_code, 200)
        # Twice: nothing stored, the study and its runs said to be there already.
        before = self.counts(self.other)
        r = self.other.post("/api/v1/imports", data=archive, timeout=60)
        self.assertEqual(r.status_code, 200, r.text)
        self.assertTrue(r.json()["study"]["skipped"])
        self.assertEqual(sorted(s["id"] for s in r.json()["skipped"]), job_ids)
        self.assertEqual(self.counts(self.other), before)
        # The imported study is kept like any: deleted with its runs and their files.
        r = self.other.session.delete(self.other.url(f"{STUDIES}/{study['id']}"), timeout=30)
        self.assertEqual(r.status_code, 200, r.text)
        self.assertEqual(sorted(r.json()["deleted_jobs"]), job_ids)
        self.assertEqual(r.json()["results_deleted"], 2)
        self.assertEqual(os.listdir(os.path.join(self.other.data_dir, "results")), [])

    def test_a_running_study_and_a_damaged_study_json_are_refused(self):
        r = self.server.post(STUDIES, headers=JSON, data=json.dumps(long_study("not yet")))
        self.assertEqual(r.status_code, 201, r.text)
        study_id = r.json()["id"]
        r = self.server.get(f"{STUDIES}/{study_id}/export", timeout=60)
        self.assertEqual(r.status_code, 409, r.text)
        self.assertIn("is running", r.json()["detail"])
        self.server.post(f"{STUDIES}/{study_id}/cancel")
        self.assertEqual(self.server.get(f"{STUDIES}/{'0' * 32}/export").status_code, 404)
        # A study.json whose run is not in the archive, re-signed: refused naming it.
        r = self.server.post(STUDIES, headers=JSON, data=json.dumps(grid("damaged", 7.3e-4)))
        study = wait_study(self.server, r.json()["id"], timeout=120)
        archive = self.server.get(f"{STUDIES}/{study['id']}/export", timeout=60).content
        import hashlib
        import io
        import tarfile
        with tarfile.open(fileobj=io.BytesIO(archive)) as tar:
            files = {m.name: tar.extractfile(m).read() for m in tar.getmembers()}
        doc = json.loads(files["study.json"])
        doc["runs"][0]["job_id"] = "f" * 32
        files["study.json"] = json.dumps(doc).encode()
        manifest = json.loads(files["manifest.json"])
        for f in manifest["files"]:
            f["size"] = len(files[f["name"]])
            f["sha256"] = hashlib.sha256(files[f["name"]]).hexdigest()
        files["manifest.json"] = json.dumps(manifest).encode()
        out = io.BytesIO()
        with tarfile.open(fileobj=out, mode="w", format=tarfile.USTAR_FORMAT) as tar:
            for name, data in files.items():
                info = tarfile.TarInfo(name)
                info.size = len(data)
                tar.addfile(info, io.BytesIO(data))
        before = self.counts(self.other)
        r = self.other.post("/api/v1/imports", data=out.getvalue(), timeout=60)
        self.assertEqual(r.status_code, 422, r.text)
        self.assertIn("study.json#/runs/0/job_id", r.json()["detail"])
        self.assertEqual(self.counts(self.other), before)

class StudyOwners(unittest.TestCase):
    """With a token file, only a study's owner changes or deletes it; without a token, 401."""

    @classmethod
    def setUpClass(cls):
        cls.tokens = tempfile.NamedTemporaryFile("w", suffix=".tokens", delete=False)
        cls.tokens.write("alice:alice-secret-token\nbob:bob-secret-token\n")
        cls.tokens.close()
        cls.server = Server(BINARY, args=["--workers", "1", "--token-file",
                                          cls.tokens.name]).start()

    @classmethod
    def tearDownClass(cls):
        code = cls.server.terminate()
        cls.server.cleanup()
        os.unlink(cls.tokens.name)
        assert code == 0, code

    def test_only_the_owner_changes_a_study(self):
        alice = {"Authorization": "Bearer alice-secret-token"}
        bob = {"Authorization": "Bearer bob-secret-token"}
        s = self.server
        r = s.post(STUDIES, data=json.dumps(grid("alices study", 6.9e-4, tags=["mine"])),
                   headers={**JSON, **alice})
        self.assertEqual(r.status_code, 201, r.text)
        study = wait_study(s, r.json()["id"], timeout=120)
        url = s.url(f"{STUDIES}/{study['id']}")
        body = json.dumps({"tags_add": ["bobs"]})
        self.assertEqual(requests.patch(url, data=body, headers=JSON).status_code, 401)
        self.assertEqual(requests.delete(url).status_code, 401)
        for request in (lambda h: requests.patch(url, data=body, headers={**JSON, **h}),
                        lambda h: requests.post(url + "/archive", headers=h),
                        lambda h: requests.post(url + "/restore", headers=h),
                        lambda h: requests.delete(url, headers=h)):
            r = request(bob)
            self.assertEqual(r.status_code, 403, r.text)
            self.assertIn("another user", r.json()["detail"])
        got = s.get(f"{STUDIES}/{study['id']}").json()
        self.assertEqual((got["tags"], got["archived_at"]), (["mine"], None))
        r = requests.patch(url, data=body, headers={**JSON, **alice})
        self.assertEqual(r.status_code, 200, r.text)
        self.assertEqual(requests.post(url + "/archive", headers=alice).status_code, 200)
        r = requests.delete(url, headers=alice)
        self.assertEqual(r.status_code, 200, r.text)
        self.assertEqual(s.get(f"/api/v1/jobs/{study['runs'][0]['job_id']}").status_code, 404)


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

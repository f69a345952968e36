"""Keep, annotate, share over real HTTP on loopback, with the servers' real
SQLite files and HDF5 result files: tags and a note edited after submission, archive and
restore, delete with the result file (and what a cache hit shares), export of runs as one tar
file and its import into a second server, byte for byte; tampered and hostile archives refused
naming the member, nothing stored.

    /usr/bin/python3 tests/server/test_keep_share.py --binary build/slipfront
"""

import argparse
import hashlib
import io
import json
import os
import sys
import tarfile
import tempfile
import unittest

import h5py
import numpy as np
import requests

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import TINY, Server, long_job, wait_study  # noqa: E402

BINARY = None
JOBS = "/api/v1/jobs"


def tiny(name, L=None, **extra):
    spec = json.loads(json.dumps(TINY))
    spec["name"] = name
    if L is not None:
        spec["friction"] = {"L": L}
    spec.update(extra)
    return spec


def sha256(data):
    return hashlib.sha256(data).hexdigest()


def members(tar_bytes):
    with tarfile.open(fileobj=io.BytesIO(tar_bytes)) as tar:
        return {m.name: tar.extractfile(m).read() for m in tar.getmembers()}


def make_tar(files):
    """A tar of (name, bytes) pairs, as an export would be packed by hand."""
    out = io.BytesIO()
    with tarfile.open(fileobj=out, mode="w", format=tarfile.USTAR_FORMAT) as tar:
        for name, data in files:
            info = tarfile.TarInfo(name)
            info.size = len(data)
            tar.addfile(info, io.BytesIO(data))
    return out.getvalue()


class KeepAndShare(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.server = Server(BINARY, args=["--workers", "1"]).start()
        cls.other = Server(BINARY, args=["--workers", "1",
                                         "--max-import-bytes", "3000000"]).start()

    @classmethod
    def tearDownClass(cls):
        codes = [s.terminate() for s in (cls.server, cls.other)]
        for s in (cls.server, cls.other):
            s.cleanup()
        assert codes == [0, 0], codes

    def run_job(self, spec, server=None, **params):
        server = server or self.server
        r = server.submit(spec, params=params)
        self.assertEqual(r.status_code, 201, r.text)
        return server.wait_status(r.json()["id"], {"succeeded"}, timeout=60)

    def patch(self, job_id, body, server=None, **kw):
        server = server or self.server
        return server.session.patch(server.url(f"{JOBS}/{job_id}"), data=json.dumps(body),
                                    headers={"Content-Type": "application/json",
                                             **kw.pop("headers", {})}, timeout=10, **kw)

    def delete(self, job_id, **kw):
        return self.server.session.delete(self.server.url(f"{JOBS}/{job_id}"), timeout=10, **kw)

    def stored_path(self, job, server=None):
        """The file the job's row points at: its own, or the run its cache hit reused."""
        server = server or self.server
        owner = job["cached_from"] or job["id"]
        return os.path.join(server.data_dir, "results", owner + ".h5")

    def names_listed(self, name, **params):
        r = self.server.get(JOBS, params={"name": name, **params})
        self.assertEqual(r.status_code, 200, r.text)
        return [j["id"] for j in r.json()["jobs"]]

    # --- tags and note -------------------------------------------------------------------

    def test_tags_and_note_edited_after_submission(self):
        job = self.run_job(tiny("annotated", tags=["draft"]))
        self.assertEqual(job["tags"], ["draft"])
        self.assertEqual(job["note"], "")
        r = self.patch(job["id"], {"tags": ["fig-2", "keep"], "note": "mesh study\nsee p. 4"})
        self.assertEqual(r.status_code, 200, r.text)
        got = self.server.get(f"{JOBS}/{job['id']}").json()
        self.assertEqual(got["tags"], ["fig-2", "keep"])
        self.assertEqual(got["note"], "mesh study\nsee p. 4")
        self.assertEqual(self.server.get(JOBS, params={"tag": "fig-2"}).json()["jobs"][0]["id"],
                         job["id"])
        # Only the note: the tags stay.
        r = self.patch(job["id"], {"note": ""})
        self.assertEqual(r.json()["tags"], ["fig-2", "keep"])
        self.assertEqual(r.json()["note"], "")

    def test_tags_added_and_removed_keep_the_others(self):
        job = self.run_job(tiny("tags-add-remove", tags=["kammer2014", "L=5e-5", "nd=40"]))
        r = self.patch(job["id"], {"tags_add": ["fig-2", "nd=40"], "tags_remove": ["L=5e-5"]})
        self.assertEqual(r.status_code, 200, r.text)
        self.assertEqual(r.json()["tags"], ["kammer2014", "nd=40", "fig-2"])
        got = self.server.get(f"{JOBS}/{job['id']}").json()
        self.assertEqual(got["tags"], ["kammer2014", "nd=40", "fig-2"])
        # Removing a tag the run does not have, or adding one it has: no error, no change.
        r = self.patch(job["id"], {"tags_remove": ["never-there"], "tags_add": ["fig-2"]})
        self.assertEqual(r.status_code, 200, r.text)
        self.assertEqual(r.json()["tags"], ["kammer2014", "nd=40", "fig-2"])
        # Replacing every tag stays possible, with "tags" alone.
        r = self.patch(job["id"], {"tags": ["only"]})
        self.assertEqual(r.json()["tags"], ["only"])
        self.assertEqual(self.server.get(JOBS, params={"tag": "only"}).json()["jobs"][0]["id"],
                         job["id"])

    def test_tag_changes_at_once_all_hold(self):
        """Eight clients each add three tags at the same time: the store changes the tags it
        holds under its write lock, so none of the 24 is lost to another's change."""
        import concurrent.futures
        job = self.run_job(tiny("tags-at-once", tags=["base"]))

        def add(i):
            return self.patch(job["id"], {"tags_add": [f"c{i}-{k}" for k in range(3)]}).status_code

        with concurrent.futures.ThreadPoolExecutor(8) as pool:
            codes = list(pool.map(add, range(8)))
        self.assertEqual(codes, [200] * 8)
        tags = self.server.get(f"{JOBS}/{job['id']}").json()["tags"]
        self.assertEqual(sorted(tags), sorted(["base"] + [f"c{i}-{k}" for i in range(8)
                                                         for k in range(3)]))

    def test_invalid_tag_changes_name_the_field_and_change_nothing(self):
        job = self.run_job(tiny("refused-tag-changes", tags=["kept"]))
        cases = [
            ({"tags": ["a"], "tags_add": ["b"]}, "/tags_add"),
            ({"tags": ["a"], "tags_remove": ["kept"]}, "/tags_remove"),
            ({"tags_add": ["x"], "tags_remove": ["y", "x"]}, "/tags_remove/1"),
            ({"tags_add": ["ok", "x" * 65]}, "/tags_add/1"),
            ({"tags_remove": "kept"}, "/tags_remove"),
            ({"tags_add": [f"t{i}" for i in range(32)]}, "/tags_add"),  # 33 with "kept"
        ]
        for body, pointer in cases:
            r = self.patch(job["id"], body)
            self.assertEqual(r.status_code, 422, f"{body}: {r.text}")
            self.assertIn(pointer, [e["pointer"] for e in r.json()["errors"]], r.text)
            self.assertEqual(self.server.get(f"{JOBS}/{job['id']}").json()["tags"], ["kept"],
                             f"{body} changed the tags")
        r = self.patch(job["id"], {"tags_add": [f"t{i}" for i in range(32)]})
        self.assertIn("33 tags", r.text)

    def test_invalid_changes_name_the_field_and_change_nothing(self):
        job = self.run_job(tiny("refused-changes", tags=["kept"]))
        cases = [
            ({"tags": ["ok", "bell\u0007"]}, "/tags/1"),
            ({"tags": ["x" * 65]}, "/tags/0"),
            ({"tags": [f"t{i}" for i in range(33)]}, "/tags"),
            ({"tags": "one"}, "/tags"),
            ({"note": 5}, "/note"),
            ({"note": "x" * 4097}, "/note"),
            ({"note": "escape \u001b[31m"}, "/note"),
            ({"colour": "red"}, "/colour"),
            ({}, ""),
        ]
        for body, pointer in cases:
            r = self.patch(job["id"], body)
            self.assertEqual(r.status_code, 422, f"{body}: {r.text}")
            self.assertEqual(r.headers["Content-Type"], "application/problem+json")
            self.assertIn(pointer, [e["pointer"] for e in r.json()["errors"]], r.text)
        r = self.server.session.patch(self.server.url(f"{JOBS}/{job['id']}"), data="{",
                                      headers={"Content-Type": "application/json"})
        self.assertEqual(r.status_code, 400)
        self.assertEqual(self.patch("0" * 32, {"note": "x"}).status_code, 404)
        got = self.server.get(f"{JOBS}/{job['id']}").json()
        self.assertEqual((got["tags"], got["note"]), (["kept"], ""))

    # --- archive and restore -------------------------------------------------------------

    def test_archived_runs_are_hidden_until_asked_for(self):
        job = self.run_job(tiny("archived-one"))
        self.assertEqual(self.names_listed("archived-one"), [job["id"]])
        r = self.server.post(f"{JOBS}/{job['id']}/archive")
        self.assertEqual(r.status_code, 200, r.text)
        self.assertIsNotNone(r.json()["archived_at"])
        self.assertEqual(self.names_listed("archived-one"), [])
        self.assertEqual(self.names_listed("archived-one", archived="include"), [job["id"]])
        self.assertEqual(self.names_listed("archived-one", archived="only"), [job["id"]])
        csv = self.server.get(JOBS, params={"name": "archived-one", "format": "csv"}).text
        self.assertNotIn(job["id"], csv)
        csv = self.server.get(JOBS, params={"name": "archived-one", "format": "csv",
                                            "archived": "include"}).text
        self.assertIn(job["id"], csv)
        # Archived, never deleted: the run and its file are still served.
        self.assertEqual(self.server.get(f"{JOBS}/{job['id']}").status_code, 200)
        self.assertEqual(self.server.get(job["result"]["url"]).status_code, 200)
        r = self.server.post(f"{JOBS}/{job['id']}/restore")
        self.assertEqual(r.status_code, 200, r.text)
        self.assertIsNone(r.json()["archived_at"])
        self.assertEqual(self.names_listed("archived-one"), [job["id"]])
        r = self.server.get(JOBS, params={"archived": "maybe"})
        self.assertEqual(r.status_code, 400)
        self.assertEqual(r.json()["errors"][0]["pointer"], "/query/archived")

    # --- delete --------------------------------------------------------------------------

    def test_delete_removes_the_row_and_the_file_and_a_resubmission_recomputes(self):
        spec = tiny("deleted", L=4.1e-4)
        job = self.run_job(spec)
        path = self.stored_path(job)
        self.assertTrue(os.path.exists(path))
        r = self.delete(job["id"])
        self.assertEqual(r.status_code, 200, r.text)
        self.assertEqual(r.json(), {"id": job["id"], "deleted": True, "result_deleted": True})
        self.assertFalse(os.path.exists(path))
        self.assertEqual(self.server.get(f"{JOBS}/{job['id']}").status_code, 404)
        self.assertEqual(self.delete(job["id"]).status_code, 404)
        r = self.server.submit(spec)
        self.assertEqual(r.status_code, 201, r.text)
        self.assertEqual(r.json()["cache"], "miss")
        again = self.server.wait_status(r.json()["id"], {"succeeded"}, timeout=60)
        self.assertIsNone(again["cached_from"])
        self.assertEqual(again["metrics"]["propagation_distance"],
                         job["metrics"]["propagation_distance"])
        self.assertEqual(self.server.get(again["result"]["url"]).status_code, 200)

    def test_a_result_shared_by_cache_hits_goes_with_the_last_of_them(self):
        spec = tiny("shared", L=4.3e-4)
        first = self.run_job(spec)
        hit = self.server.submit(spec).json()
        self.assertEqual((hit["cache"], hit["cached_from"]), ("hit", first["id"]))
        path = self.stored_path(first)
        body = self.server.get(first["result"]["url"]).content
        r = self.delete(first["id"])
        self.assertEqual(r.json()["result_deleted"], False, r.text)
        self.assertTrue(os.path.exists(path))
        # The hit still has its result, and a new identical submission reuses it.
        self.assertEqual(self.server.get(hit["result"]["url"]).content, body)
        again = self.server.submit(spec).json()
        self.assertEqual((again["cache"], again["cached_from"]), ("hit", hit["id"]))
        self.assertEqual(self.delete(hit["id"]).json()["result_deleted"], False)
        self.assertEqual(self.server.get(again["result"]["url"]).content, body)
        self.assertEqual(self.delete(again["id"]).json()["result_deleted"], True)
        self.assertFalse(os.path.exists(path))
        fresh = self.server.submit(spec).json()
        self.assertEqual(fresh["cache"], "miss")
        self.server.wait_status(fresh["id"], {"succeeded"}, timeout=60)

    def test_a_running_job_is_not_deleted(self):
        r = self.server.submit(long_job("delete-while-running"))
        job_id = r.json()["id"]
        r = self.delete(job_id)
        self.assertEqual(r.status_code, 409, r.text)
        self.assertIn("cancel it first", r.json()["detail"])
        self.server.post(f"{JOBS}/{job_id}/cancel")
        self.server.wait_status(job_id, {"cancelled"}, timeout=60)
        self.assertEqual(self.delete(job_id).status_code, 200)

    def test_a_run_of_a_study_is_archived_not_deleted_and_exports_with_its_study(self):
        body = {"name": "kept study", "grid": {"L": [6.7e-4], "n_d": [5]},
                "base": {"geometry": {"width": 12, "x_min": -1, "height": 4},
                         "probe": {"arrival_x1": 3, "spectrum_x1": 2}, "time": {"duration": 3}}}
        r = self.server.post("/api/v1/studies", data=json.dumps(body),
                             headers={"Content-Type": "application/json"})
        self.assertEqual(r.status_code, 201, r.text)
        study = wait_study(self.server, r.json()["id"], timeout=120)
        job_id = study["runs"][0]["job_id"]
        r = self.delete(job_id)
        self.assertEqual(r.status_code, 409, r.text)
        self.assertIn(study["id"], r.json()["detail"])
        self.assertIn("archive it instead", r.json()["detail"])
        self.assertEqual(self.server.get(f"{JOBS}/{job_id}").status_code, 200)
        self.assertEqual(self.server.post(f"{JOBS}/{job_id}/archive").status_code, 200)
        again = self.server.get(f"/api/v1/studies/{study['id']}").json()
        self.assertEqual([run["job_id"] for run in again["runs"]], [job_id])  # still its run
        r = self.server.get("/api/v1/exports", params={"study_id": study["id"]}, timeout=60)
        self.assertEqual(r.status_code, 404, "an archived run was exported by filter")
        r = self.server.get("/api/v1/exports", params={"study_id": study["id"],
                                                       "archived": "include"}, timeout=60)
        self.assertEqual(r.status_code, 200, r.text)
        manifest = json.loads(members(r.content)["manifest.json"])
        self.assertEqual([run["id"] for run in manifest["runs"]], [job_id])

    # --- export and import ---------------------------------------------------------------

    def test_export_then_import_into_a_second_server_round_trips(self):
        a = self.run_job(tiny("shared-a", L=4.5e-4, tags=["paper"]))
        b = self.run_job(tiny("shared-b", L=4.7e-4, tags=["paper"]))
        self.patch(a["id"], {"note": "Fig. 2 run"})
        r = self.server.get("/api/v1/exports", params={"ids": f"{a['id']},{b['id']},{a['id']}"},
                            timeout=60)
        self.assertEqual(r.status_code, 200, r.text)
        self.assertEqual(r.headers["Content-Type"], "application/x-tar")
        files = members(r.content)
        manifest = json.loads(files["manifest.json"])
        self.assertEqual(manifest["format"], "slipfront-runs")
        self.assertEqual([run["id"] for run in manifest["runs"]], [a["id"], b["id"]])
        for f in manifest["files"]:
            self.assertEqual(sha256(files[f["name"]]), f["sha256"], f["name"])
        self.assertEqual(set(files), {"manifest.json"} | {f["name"] for f in manifest["files"]})

        r = self.other.post("/api/v1/imports", data=r.content, timeout=60,
                            headers={"Content-Type": "application/x-tar"})
        self.assertEqual(r.status_code, 201, r.text)
        imported = {run["original_id"]: run["id"] for run in r.json()["imported"]}
        # A server that has none of these ids keeps them.
        self.assertEqual(imported, {a["id"]: a["id"], b["id"]: b["id"]})
        for original in (a, b):
            got = self.other.get(f"{JOBS}/{original['id']}").json()
            self.assertEqual(got["status"], "succeeded")
            self.assertEqual(got["spec"], original["spec"])
            self.assertEqual(got["spec_sha256"], original["spec_sha256"])
            self.assertEqual(got["metrics"], original["metrics"])
            self.assertEqual(got["tags"], ["paper"])
            self.assertEqual(got["imported_from"]["id"], original["id"])
            self.assertEqual(got["imported_from"]["submitted_by"], "anonymous")
            self.assertEqual(got["imported_from"]["server"]["code_version"],
                             original["code_version"])
            mine = self.server.get(original["result"]["url"]).content
            theirs = self.other.get(got["result"]["url"]).content
            self.assertEqual(sha256(theirs), sha256(mine))
            self.assertEqual(got["result"]["sha256"], original["result"]["sha256"])
            self.assertEqual(self.other.get(f"{JOBS}/{got['id']}/front").json(),
                             self.server.get(f"{JOBS}/{original['id']}/front").json())
            path = os.path.join(self.other.data_dir, "results", got["id"] + ".h5")
            with h5py.File(path, "r") as h5, \
                    h5py.File(self.stored_path(original), "r") as mine_h5:
                np.testing.assert_array_equal(h5["interface/slip_velocity"][...],
                                              mine_h5["interface/slip_velocity"][...])
        self.assertEqual(self.other.get(f"{JOBS}/{a['id']}").json()["note"], "Fig. 2 run")
        # Stored again on request (again=true): the ids are taken now, so the copy gets a new one.
        again = self.other.post("/api/v1/imports", data=self.server.get(
            "/api/v1/exports", params={"ids": a["id"]}, timeout=60).content, timeout=60,
            params={"again": "true"})
        self.assertEqual(again.status_code, 201, again.text)
        self.assertNotEqual(again.json()["imported"][0]["id"], a["id"])
        self.assertEqual(again.json()["skipped"], [])

    def count(self, server):
        return server.get(JOBS, params={"archived": "include"}).json()["count"]

    def import_archive(self, server, archive, **params):
        return server.post("/api/v1/imports", data=archive, timeout=60, params=params,
                           headers={"Content-Type": "application/x-tar"})

    def test_an_archive_imported_twice_stores_its_runs_once(self):
        a = self.run_job(tiny("twice-a", L=5.3e-4))
        b = self.run_job(tiny("twice-b", L=5.5e-4))
        archive = self.server.get("/api/v1/exports", params={"ids": f"{a['id']},{b['id']}"},
                                  timeout=60).content
        r = self.import_archive(self.other, archive)
        self.assertEqual(r.status_code, 201, r.text)
        self.assertEqual((r.json()["count"], r.json()["skipped"]), (2, []))
        before = self.count(self.other)
        files = sorted(os.listdir(os.path.join(self.other.data_dir, "results")))
        # The same archive again: nothing stored, 200, each run named with the run it is.
        r = self.import_archive(self.other, archive)
        self.assertEqual(r.status_code, 200, r.text)
        self.assertEqual((r.json()["imported"], r.json()["count"]), ([], 0))
        skipped = {s["original_id"]: s for s in r.json()["skipped"]}
        self.assertEqual(set(skipped), {a["id"], b["id"]})
        for original in (a, b):
            self.assertEqual(skipped[original["id"]]["id"], original["id"])
            self.assertEqual(skipped[original["id"]]["reason"], "same_origin")
            self.assertEqual(skipped[original["id"]]["url"], f"{JOBS}/{original['id']}")
        self.assertEqual(self.count(self.other), before)
        self.assertEqual(sorted(os.listdir(os.path.join(self.other.data_dir, "results"))), files)
        # An archive of one new run and one already there: the new one only.
        c = self.run_job(tiny("twice-c", L=5.7e-4))
        mixed = self.server.get("/api/v1/exports", params={"ids": f"{a['id']},{c['id']}"},
                                timeout=60).content
        r = self.import_archive(self.other, mixed)
        self.assertEqual(r.status_code, 201, r.text)
        self.assertEqual([run["original_id"] for run in r.json()["imported"]], [c["id"]])
        self.assertEqual([s["original_id"] for s in r.json()["skipped"]], [a["id"]])
        self.assertEqual(self.count(self.other), before + 1)
        # Back home: the second server's copies came from here, so the first server skips
        # them (their origin followed through imported_from), and so does a round trip.
        back = self.other.get("/api/v1/exports", params={"ids": f"{a['id']},{c['id']}"},
                              timeout=60).content
        home_before = self.count(self.server)
        r = self.import_archive(self.server, back)
        self.assertEqual(r.status_code, 200, r.text)
        self.assertEqual({(s["original_id"], s["id"], s["reason"]) for s in r.json()["skipped"]},
                         {(a["id"], a["id"], "same_origin"), (c["id"], c["id"], "same_origin")})
        self.assertEqual(self.count(self.server), home_before)
        # A bad query is refused by name, nothing stored.
        r = self.import_archive(self.other, archive, again="yes")
        self.assertEqual(r.status_code, 400, r.text)
        self.assertEqual(r.json()["errors"][0]["pointer"], "/query/again")
        r = self.import_archive(self.other, archive, colour="red")
        self.assertEqual(r.status_code, 400, r.text)
        self.assertEqual(r.json()["errors"][0]["pointer"], "/query/colour")
        self.assertEqual(self.count(self.other), before + 1)

    def test_a_run_with_the_same_spec_and_result_is_skipped(self):
        """A run under another id (another server's copy, renamed) whose spec and result file
        are those of a run here: skipped as the same result."""
        job, archive = self.exported("same-result", 5.9e-4)
        files = members(archive)
        new_id = "ab" * 16
        manifest = json.loads(files["manifest.json"])
        record = json.loads(files[f"runs/{job['id']}/job.json"])
        record["id"] = new_id
        renamed = {"manifest.json": None,
                   f"runs/{new_id}/job.json": (json.dumps(record) + "\n").encode(),
                   f"runs/{new_id}/result.h5": files[f"runs/{job['id']}/result.h5"]}
        manifest["runs"] = [{"id": new_id, "job": f"runs/{new_id}/job.json",
                             "result": f"runs/{new_id}/result.h5"}]
        manifest["files"] = [{"name": n, "size": len(d), "sha256": sha256(d)}
                             for n, d in renamed.items() if d is not None]
        renamed["manifest.json"] = json.dumps(manifest).encode()
        before = self.count(self.server)
        r = self.import_archive(self.server, make_tar(renamed.items()))
        self.assertEqual(r.status_code, 200, r.text)
        self.assertEqual(r.json()["skipped"][0]["original_id"], new_id)
        self.assertEqual(r.json()["skipped"][0]["id"], job["id"])
        self.assertEqual(r.json()["skipped"][0]["reason"], "same_result")
        self.assertIn(job["result"]["sha256"], r.json()["skipped"][0]["detail"])
        self.assertEqual(self.count(self.server), before)
        self.assertEqual(self.server.get(f"{JOBS}/{new_id}").status_code, 404)

    def test_export_by_search(self):
        job = self.run_job(tiny("searched", L=4.9e-4, tags=["by-search"]))
        r = self.server.get("/api/v1/exports", params={"tag": "by-search"}, timeout=60)
        self.assertEqual(r.status_code, 200, r.text)
        manifest = json.loads(members(r.content)["manifest.json"])
        self.assertEqual([run["id"] for run in manifest["runs"]], [job["id"]])
        self.assertEqual(self.server.get("/api/v1/exports").status_code, 400)
        self.assertEqual(self.server.get("/api/v1/exports",
                                         params={"ids": "0" * 32}).status_code, 404)

    def exported(self, name, L):
        job = self.run_job(tiny(name, L=L))
        r = self.server.get("/api/v1/exports", params={"ids": job["id"]}, timeout=60)
        self.assertEqual(r.status_code, 200, r.text)
        return job, r.content

    def assert_refused(self, archive, where):
        before = self.other.get(JOBS, params={"archived": "include"}).json()["count"]
        r = self.other.post("/api/v1/imports", data=archive, timeout=60)
        self.assertEqual(r.status_code, 422, r.text)
        self.assertIn(where, r.json()["detail"])
        after = self.other.get(JOBS, params={"archived": "include"}).json()["count"]
        self.assertEqual(after, before, "a refused archive stored runs")
        return r.json()["detail"]

    def test_a_tampered_member_is_refused_by_name(self):
        job, archive = self.exported("tampered", 5.1e-4)
        files = members(archive)
        name = f"runs/{job['id']}/result.h5"
        flipped = bytearray(files[name])
        flipped[len(flipped) // 2] ^= 0xFF
        files[name] = bytes(flipped)
        detail = self.assert_refused(make_tar(files.items()), name)
        self.assertIn("SHA-256", detail)
        # A metric changed in job.json: refused naming that member.
        files = members(archive)
        record_name = f"runs/{job['id']}/job.json"
        record = json.loads(files[record_name])
        record["metrics"]["propagation_distance"] = 1.0
        files[record_name] = json.dumps(record).encode()
        self.assert_refused(make_tar(files.items()), record_name)
        # A member the manifest does not list.
        files = members(archive)
        files["runs/extra.txt"] = b"x"
        self.assert_refused(make_tar(files.items()), "runs/extra.txt")
        self.assertFalse(os.path.exists(os.path.join(self.other.data_dir, "results",
                                                     job["id"] + ".h5")))

    def test_an_archive_above_the_import_limit_gets_413(self):
        r = self.other.post("/api/v1/imports", data=b"\0" * 3_500_000, timeout=60)
        self.assertEqual(r.status_code, 413, r.text[:300])
        self.assertIn("3000000", r.json()["detail"])
        # The limit is the import's only: a JSON body keeps the 1 MiB of --max-body-bytes.
        r = self.other.post(JOBS, data=b" " * 1_200_000,
                            headers={"Content-Type": "application/json"}, timeout=60)
        self.assertEqual(r.status_code, 413, r.text[:300])

    def test_hostile_member_names_are_refused(self):
        job, archive = self.exported("hostile", 5.3e-4)
        files = members(archive)
        outside = os.path.join(os.path.dirname(self.other.data_dir), "evil.txt")
        for name in ("../evil.txt", "runs/../../evil.txt", "/tmp/evil.txt", "runs/a\\b"):
            detail = self.assert_refused(make_tar(list(files.items()) + [(name, b"evil")]),
                                        "unsafe name")
            self.assertIn("member", detail)
        self.assertFalse(os.path.exists(outside))
        # A symbolic link member.
        out = io.BytesIO()
        with tarfile.open(fileobj=out, mode="w", format=tarfile.USTAR_FORMAT) as tar:
            link = tarfile.TarInfo("manifest.json")
            link.type = tarfile.SYMTYPE
            link.linkname = "/etc/passwd"
            tar.addfile(link)
        self.assert_refused(out.getvalue(), "not a regular file")
        self.assert_refused(b"not a tar file at all" * 100, "checksum")
        self.assert_refused(archive[:len(archive) // 2], "")


class Owners(unittest.TestCase):
    """With a token file, only a run's owner changes it; without a token, 401."""

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

    def test_only_the_owner_changes_a_run(self):
        alice = {"Authorization": "Bearer alice-secret-token"}
        bob = {"Authorization": "Bearer bob-secret-token"}
        s = self.server
        r = s.submit(tiny("alices", tags=["mine"]), headers=alice)
        self.assertEqual(r.status_code, 201, r.text)
        job_id = r.json()["id"]
        s.wait_status(job_id, {"succeeded"})
        url = s.url(f"{JOBS}/{job_id}")
        body = json.dumps({"tags": ["bobs"]})
        json_type = {"Content-Type": "application/json"}
        self.assertEqual(requests.patch(url, data=body, headers=json_type).status_code, 401)
        for request in (lambda h: requests.patch(url, data=body, headers={**json_type, **h}),
                        lambda h: requests.post(url + "/archive", headers=h),
                        lambda h: requests.post(url + "/restore", headers=h),
                        lambda h: requests.delete(url, headers=h)):
            r = request(bob)
            self.assertEqual(r.status_code, 403, r.text)
            self.assertIn("another user", r.json()["detail"])
        self.assertEqual(requests.delete(url).status_code, 401)
        self.assertEqual(s.get(f"{JOBS}/{job_id}").json()["tags"], ["mine"])
        r = requests.patch(url, data=body, headers={**json_type, **alice})
        self.assertEqual(r.status_code, 200, r.text)
        self.assertEqual(requests.post(url + "/archive", headers=alice).status_code, 200)
        self.assertEqual(requests.post(
            s.url("/api/v1/imports"), data=b"x").status_code, 401)
        self.assertEqual(requests.delete(url, headers=alice).status_code, 200)


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

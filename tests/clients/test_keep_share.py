"""slipfront-client tag, note, archive, restore, delete, export-runs and import-runs against
two real `slipfront serve` processes (ephemeral loopback ports, temporary data dirs): what the
commands change is what the server then answers, and an export imported into the second
server gives back the same result file, byte for byte.

    /usr/bin/python3 tests/clients/test_keep_share.py --binary build/slipfront
"""

import hashlib
import json
import os
import shutil
import socket
import sys
import tarfile
import tempfile
import unittest

import requests

from harness import TINY, Server, binary_from_argv, run_client

BINARY = None


class ClientKeepShare(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.server = Server(BINARY, args=["--workers", "1"]).start()
        cls.other = Server(BINARY, args=["--workers", "1"]).start()
        cls.tmp = tempfile.mkdtemp(prefix="slipfront-client-keep-")

    @classmethod
    def tearDownClass(cls):
        cls.server.stop()
        cls.other.stop()
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def client(self, *args, server=None, stdin=None):
        return run_client(*args, server=(server or self.server).base, stdin=stdin)

    def submit(self, name, L):
        job = dict(json.loads(json.dumps(TINY)), name=name, friction={"L": L})
        path = os.path.join(self.tmp, name + ".json")
        with open(path, "w") as f:
            json.dump(job, f)
        r = self.client("submit", path, "--wait")
        self.assertEqual(r.returncode, 0, r.stderr)
        return r.stdout.strip().splitlines()[-1]

    def job(self, job_id, server=None):
        return requests.get(f"{(server or self.server).base}/api/v1/jobs/{job_id}",
                            timeout=10).json()

    def test_tag_note_archive_restore_delete(self):
        job_id = self.submit("client-keep", 6.1e-4)
        r = self.client("tag", job_id, "fig-2", "keep")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(self.job(job_id)["tags"], ["fig-2", "keep"])
        # Tags given alone are added: the others stay.
        r = self.client("tag", job_id, "nd=40")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(self.job(job_id)["tags"], ["fig-2", "keep", "nd=40"])
        self.assertIn("tags=fig-2,keep,nd=40", r.stdout)
        r = self.client("tag", job_id, "--add", "paper", "--remove", "keep", "absent")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(self.job(job_id)["tags"], ["fig-2", "nd=40", "paper"])
        # No change asked: the tags as they are.
        r = self.client("tag", job_id)
        self.assertEqual((r.returncode, r.stdout.strip()),
                         (0, f"{job_id} tags=fig-2,nd=40,paper"))
        r = self.client("tag", job_id, "--set", "x", "--add", "y")
        self.assertEqual(r.returncode, 2, r.stdout)
        self.assertIn("--set", r.stderr)
        self.assertEqual(self.job(job_id)["tags"], ["fig-2", "nd=40", "paper"])
        # Replacing every tag is said: --set.
        r = self.client("tag", job_id, "--set", "fig-2", "keep")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(self.job(job_id)["tags"], ["fig-2", "keep"])
        r = self.client("note", job_id, "-", stdin="first line\nsecond line\n")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(self.job(job_id)["note"], "first line\nsecond line\n")
        r = self.client("tag", job_id, "bad\ttag")
        self.assertEqual(r.returncode, 2, r.stdout)
        self.assertIn("/tags_add/0", r.stderr)
        self.assertEqual(self.job(job_id)["tags"], ["fig-2", "keep"])
        self.assertEqual(self.client("archive", job_id).returncode, 0)
        listed = self.client("list", "--name", "client-keep", "--json")
        self.assertEqual(json.loads(listed.stdout), [])
        listed = self.client("list", "--name", "client-keep", "--archived", "only", "--json")
        self.assertEqual([j["id"] for j in json.loads(listed.stdout)], [job_id])
        self.assertEqual(self.client("restore", job_id).returncode, 0)
        self.assertIsNone(self.job(job_id)["archived_at"])
        r = self.client("delete", job_id, stdin="n\n")
        self.assertEqual(r.returncode, 2)
        self.assertEqual(self.job(job_id)["id"], job_id)
        r = self.client("delete", job_id, stdin="")  # no answer: not deleted
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertEqual(self.job(job_id)["id"], job_id)
        r = self.client("delete", job_id, "--yes")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("with its result file", r.stdout)
        self.assertFalse(os.path.exists(os.path.join(self.server.data_dir, "results",
                                                     job_id + ".h5")))

    def test_list_shows_a_cache_hits_original_wall_time_marked_cached(self):
        first = self.submit("client-original", 7.9e-4)
        second = self.submit("client-reused", 7.9e-4)  # the same physics: a cache hit
        hit = self.job(second)
        self.assertEqual(hit["cached_from"], first)
        r = self.client("list", "--name", "client-reused")
        self.assertEqual(r.returncode, 0, r.stderr)
        original = hit["metrics"]["wall_time_s"]
        self.assertIn(f"{original:.4g} (cached)", r.stdout)
        r = self.client("list", "--name", "client-original")
        self.assertNotIn("cached", r.stdout)

    def test_study_tag_note_archive_restore_delete(self):
        base = {"geometry": {"width": 12, "x_min": -1, "height": 4},
                "probe": {"arrival_x1": 3, "spectrum_x1": 2}, "time": {"duration": 3}}
        r = requests.post(f"{self.server.base}/api/v1/studies", timeout=30,
                          json={"name": "client study", "tags": ["draft"], "base": base,
                                "grid": {"L": [6.9e-4], "n_d": [5]}})
        self.assertEqual(r.status_code, 201, r.text)
        study_id = r.json()["id"]
        self.assertEqual(self.client("study", "wait", study_id).returncode, 0)
        url = f"{self.server.base}/api/v1/studies/{study_id}"
        r = self.client("study", "tag", study_id, "fig-3", "--remove", "draft")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stdout.strip(), f"{study_id} tags=fig-3")
        self.assertEqual(requests.get(url, timeout=10).json()["tags"], ["fig-3"])
        r = self.client("study", "note", study_id, "the L sweep")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(requests.get(url, timeout=10).json()["note"], "the L sweep")
        self.assertEqual(self.client("study", "archive", study_id).returncode, 0)
        listed = self.client("study", "list", "--json")
        self.assertNotIn(study_id, [s["id"] for s in json.loads(listed.stdout)])
        listed = self.client("study", "list", "--archived", "only", "--json")
        self.assertEqual([s["id"] for s in json.loads(listed.stdout)], [study_id])
        self.assertEqual(self.client("study", "restore", study_id).returncode, 0)
        self.assertIsNone(requests.get(url, timeout=10).json()["archived_at"])
        job_id = requests.get(url, timeout=10).json()["runs"][0]["job_id"]
        # Export with its run; imported on the second server, and a second time: stored once.
        archive = os.path.join(self.tmp, "study.tar")
        r = self.client("study", "export", study_id, "-o", archive)
        self.assertEqual((r.returncode, r.stdout.strip()), (0, archive), r.stderr)
        r = self.client("import-runs", archive, server=self.other)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stdout.strip().splitlines(),
                         [job_id, f"study {study_id} imported with its runs"])
        there = requests.get(f"{self.other.base}/api/v1/studies/{study_id}", timeout=10).json()
        self.assertEqual((there["tags"], there["note"], [x["job_id"] for x in there["runs"]]),
                         (["fig-3"], "the L sweep", [job_id]))
        r = self.client("import-runs", archive, server=self.other)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn(f"study {study_id} skipped, already here", r.stdout)
        r = self.client("study", "delete", study_id, stdin="n\n")
        self.assertEqual(r.returncode, 2)
        self.assertEqual(requests.get(url, timeout=10).status_code, 200)
        r = self.client("study", "delete", study_id, "--yes")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stdout.strip(), f"{study_id} deleted with 1 run(s) and 1 result file(s)")
        self.assertEqual(requests.get(url, timeout=10).status_code, 404)
        self.assertEqual(self.job(job_id).get("status"), 404)
        r = self.client("study", "delete", study_id, "--yes")
        self.assertNotEqual(r.returncode, 0)

    def test_export_runs_then_import_runs(self):
        first = self.submit("client-export-1", 6.3e-4)
        second = self.submit("client-export-2", 6.5e-4)
        self.assertEqual(self.client("tag", first, "share").returncode, 0)
        self.assertEqual(self.client("tag", second, "share").returncode, 0)
        archive = os.path.join(self.tmp, "runs.tar")
        r = self.client("export-runs", "--tag", "share", "-o", archive)
        self.assertEqual(r.returncode, 0, r.stderr)
        r = self.client("export-runs", "--tag", "share", "-o", archive)
        self.assertEqual(r.returncode, 2, "an existing archive was overwritten")
        # By ids: POST /exports, the ids in the body.
        by_ids = os.path.join(self.tmp, "by-ids.tar")
        r = self.client("export-runs", first, second, "-o", by_ids)
        self.assertEqual(r.returncode, 0, r.stderr)
        with tarfile.open(by_ids) as tar:
            self.assertEqual({m.name for m in tar.getmembers() if m.name.endswith("job.json")},
                             {f"runs/{first}/job.json", f"runs/{second}/job.json"})
        r = self.client("import-runs", archive, "--json", server=self.other)
        self.assertEqual(r.returncode, 0, r.stderr)
        imported = {run["original_id"]: run["id"] for run in json.loads(r.stdout)["imported"]}
        self.assertEqual(set(imported), {first, second})
        for original, copy in imported.items():
            mine = requests.get(f"{self.server.base}/api/v1/jobs/{original}/result.h5",
                                timeout=30).content
            theirs = requests.get(f"{self.other.base}/api/v1/jobs/{copy}/result.h5",
                                  timeout=30).content
            self.assertEqual(hashlib.sha256(theirs).hexdigest(),
                             hashlib.sha256(mine).hexdigest())
            self.assertEqual(self.job(copy, self.other)["imported_from"]["id"], original)
        # The same archive again: nothing stored, each run said to be there already.
        count = requests.get(f"{self.other.base}/api/v1/jobs", timeout=10).json()["count"]
        r = self.client("import-runs", archive, server=self.other)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(sorted(r.stdout.splitlines()),
                         sorted(f"{imported[i]} skipped, already here: the run {i} of "
                                f"{socket.gethostname()} is already here as job {imported[i]}"
                                for i in (first, second)))
        self.assertEqual(requests.get(f"{self.other.base}/api/v1/jobs", timeout=10)
                         .json()["count"], count)
        # --again stores copies under new ids.
        r = self.client("import-runs", archive, "--again", "--json", server=self.other)
        self.assertEqual(r.returncode, 0, r.stderr)
        copies = json.loads(r.stdout)
        self.assertEqual((copies["count"], copies["skipped"]), (2, []))
        self.assertFalse({run["id"] for run in copies["imported"]} & {first, second})
        # A damaged archive: refused (exit 2) naming the member, nothing stored.
        with open(archive, "rb") as f:
            data = bytearray(f.read())
        data[-2048] ^= 0xFF  # inside the last result file's content
        damaged = os.path.join(self.tmp, "damaged.tar")
        with open(damaged, "wb") as f:
            f.write(bytes(data))
        r = self.client("import-runs", damaged, server=self.other)
        self.assertEqual(r.returncode, 2, r.stdout)
        self.assertIn("result.h5", r.stderr)


if __name__ == "__main__":
    BINARY, rest = binary_from_argv(sys.argv[1:])
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

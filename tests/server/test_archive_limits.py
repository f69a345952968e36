"""Run archives (GET/POST /api/v1/exports, POST /api/v1/imports) under hostile use and faults,
over real HTTP against real servers and data dirs (docs/reliability.md "What bounds the
disk"): exports that are never read are cut and their disk bounded; an import writes no more
than it uploads, stores all its runs or none (a full disk, SIGKILL), and leaves no result file
without a row; imported records and result files are checked before anything is stored.

One source server (two users with tokens) computes a run and makes cache hits of it, so that
archives of many runs cost no solver time; a few target servers take the imports.

    /usr/bin/python3 tests/server/test_archive_limits.py --binary build/slipfront
"""

import argparse
import hashlib
import io
import json
import os
import random
import socket
import sqlite3
import subprocess
import sys
import tarfile
import tempfile
import threading
import time
import unittest
import uuid

import h5py
import requests


sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import TINY, Server  # noqa: E402

BINARY = None
JOBS = "/api/v1/jobs"
ALICE = {"Authorization": "Bearer alice-secret-token"}
BOB = {"Authorization": "Bearer bob-secret-token"}
SEND_TIMEOUT_S = 3
# A run of about 0.3 MB of result; its cache hits are runs of their own in an archive.
JOB = dict(TINY, name="archived", geometry={"nodes_per_meter": 10},
           time={"duration": 4.0, "stop_on_arrest": False}, output={"interval": 0.005})
RUNS = 60

SOURCE = None        # the source server (alice's runs)
# The imports here store the same archive many times: again=true stores runs already there.
AGAIN = {"again": "true"}
RUN_IDS = []         # its RUNS finished runs: one computed, the others cache hits of it
TOKEN_FILE = None


def sha256(data):
    return hashlib.sha256(data).hexdigest()


def members(tar_bytes):
    with tarfile.open(fileobj=io.BytesIO(tar_bytes)) as tar:
        return {m.name: tar.extractfile(m).read() for m in tar.getmembers()}


def make_tar(files):
    """A tar of (name, bytes) pairs, as an archive would be packed by hand."""
    out = io.BytesIO()
    with tarfile.open(fileobj=out, mode="w", format=tarfile.USTAR_FORMAT) as tar:
        for name, data in files:
            info = tarfile.TarInfo(name)
            info.size = len(data)
            tar.addfile(info, io.BytesIO(data))
    return out.getvalue()


def resign(files):
    """The archive `files` (name -> bytes) with its manifest's sizes and SHA-256 recomputed,
    as a forger would."""
    manifest = json.loads(files["manifest.json"])
    manifest["files"] = [{"name": n, "size": len(d), "sha256": sha256(d)}
                         for n, d in files.items() if n != "manifest.json"]
    files = dict(files)
    files["manifest.json"] = json.dumps(manifest).encode()
    return make_tar(files.items())


def export(ids, headers=ALICE, server=None):
    server = server or SOURCE
    r = server.get("/api/v1/exports", params={"ids": ",".join(ids)}, headers=headers, timeout=60)
    assert r.status_code == 200, r.text[:300]
    return r.content


def open_export_files(pid):
    """The unlinked export-* files the server process holds open."""
    held = []
    for fd in os.listdir(f"/proc/{pid}/fd"):
        try:
            target = os.readlink(f"/proc/{pid}/fd/{fd}")
        except OSError:
            continue
        if "/export-" in target:
            held.append(target)
    return held


def stray_files(data_dir):
    """Files of results/ that no row of the stopped or running server refers to."""
    with sqlite3.connect(os.path.join(data_dir, "slipfront.db")) as db:
        referenced = {r[0] for r in db.execute(
            "SELECT result_path FROM jobs WHERE result_path IS NOT NULL")}
    return sorted(p for p in (f"results/{n}" for n in os.listdir(
        os.path.join(data_dir, "results"))) if p not in referenced)


def imported_counts(data_dir):
    with sqlite3.connect(os.path.join(data_dir, "slipfront.db")) as db:
        return db.execute("SELECT count(*) FROM jobs WHERE imported_from IS NOT NULL").fetchone()[0]


def setUpModule():
    global SOURCE, TOKEN_FILE
    TOKEN_FILE = tempfile.NamedTemporaryFile("w", suffix=".tokens", delete=False)
    TOKEN_FILE.write("alice:alice-secret-token\nbob:bob-secret-token\n")
    TOKEN_FILE.close()
    args = ["--workers", "1", "--token-file", TOKEN_FILE.name]
    SOURCE = Server(BINARY, args=args).start()
    r = SOURCE.submit(JOB, headers=ALICE)
    assert r.status_code == 201, r.text
    RUN_IDS.append(SOURCE.wait_status(r.json()["id"], {"succeeded"}, timeout=120)["id"])
    for i in range(RUNS - 1):  # cache hits: finished at once
        r = SOURCE.submit(dict(JOB, name=f"archived-{i}"), headers=ALICE)
        assert r.status_code == 201 and r.json()["cache"] == "hit", r.text
        RUN_IDS.append(r.json()["id"])


def tearDownModule():
    if SOURCE:
        code = SOURCE.terminate()
        SOURCE.cleanup()
        assert code == 0, code
    os.unlink(TOKEN_FILE.name)


def restart_source(extra_args, while_stopped=None):
    """SOURCE again on its data dir with more flags (and `while_stopped(data_dir)` run first)."""
    global SOURCE
    assert SOURCE.terminate() == 0
    if while_stopped:
        while_stopped(SOURCE.data_dir)
    SOURCE = Server(BINARY, data_dir=SOURCE.data_dir,
                    args=["--workers", "1", "--token-file", TOKEN_FILE.name] + extra_args).start()
    SOURCE.own_dir = True


class UnreadExports(unittest.TestCase):
    """Clients that ask for an archive and never read it: before, each held an unlinked
    export file for the 600 s write timeout, without a token and without a bound."""

    def test_unread_exports_are_cut_and_their_disk_is_bounded(self):
        third = RUN_IDS[:RUNS // 3]
        size = len(export(third))
        # Room for two unread archives of a third of the runs, not three (and export threads
        # for all three: the bound refuses the third, not --max-exports).
        restart_source(["--send-timeout-s", str(SEND_TIMEOUT_S), "--max-exports", "4",
                        "--max-export-bytes", str(int(size * 2.5))])
        self.assertEqual(SOURCE.get("/api/v1/exports", params={"ids": third[0]}).status_code, 401)
        host, port = SOURCE.base[len("http://"):].split(":")
        sockets = []
        try:
            for chunk in (RUN_IDS[:RUNS // 3], RUN_IDS[RUNS // 3:2 * RUNS // 3]):
                s = socket.create_connection((host, int(port)), timeout=10)
                s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
                s.sendall((f"GET /api/v1/exports?ids={','.join(chunk)} HTTP/1.1\r\n"
                           f"Host: {host}\r\nAuthorization: {ALICE['Authorization']}\r\n\r\n")
                          .encode())
                sockets.append(s)
            # Each archive's file is made once its size is reserved.
            deadline = time.monotonic() + 20
            while len(open_export_files(SOURCE.proc.pid)) < 2 and time.monotonic() < deadline:
                time.sleep(0.02)
            held_at = time.monotonic()
            self.assertEqual(len(open_export_files(SOURCE.proc.pid)), 2)
            # The bound is taken: the next archive waits, a larger one than the bound never fits.
            busy = SOURCE.get("/api/v1/exports", params={"ids": ",".join(RUN_IDS[2 * RUNS // 3:])},
                              headers=ALICE, timeout=30)
            self.assertEqual(busy.status_code, 503, busy.content[:300])
            self.assertIn("Retry-After", busy.headers)
            self.assertIn("--max-export-bytes", busy.json()["detail"])
            too_big = SOURCE.get("/api/v1/exports", params={"ids": ",".join(RUN_IDS)},
                                 headers=ALICE, timeout=30)
            self.assertEqual(too_big.status_code, 422, too_big.content[:300])
            # Small answers still pass.
            self.assertEqual(SOURCE.get("/healthz").status_code, 200)
            # Cut after the send timeout: their files are released, the disk is free again.
            while open_export_files(SOURCE.proc.pid) and time.monotonic() < held_at + 30:
                time.sleep(0.1)
            released_after = time.monotonic() - held_at
            self.assertEqual(open_export_files(SOURCE.proc.pid), [])
            # Written, then not read for SEND_TIMEOUT_S (before: held for the 600 s write
            # timeout); the margin is for writing them on a loaded machine.
            self.assertLess(released_after, SEND_TIMEOUT_S + 10)
            print(f"two unread archives of {size / 1e6:.1f} MB released "
                  f"{released_after:.1f} s after they were held (--send-timeout-s "
                  f"{SEND_TIMEOUT_S})", file=sys.stderr)
            again = SOURCE.get("/api/v1/exports", params={"ids": ",".join(third)}, headers=ALICE,
                               timeout=60)
            self.assertEqual(again.status_code, 200, again.content[:300])
            self.assertEqual(len(again.content), size)
        finally:
            for s in sockets:
                s.close()


def seed_failed_runs(data_dir, count):
    """`count` failed runs (no result file) in the stopped server's database, copies of
    RUN_IDS[0]'s row; returns their ids."""
    ids = [uuid.uuid4().hex for _ in range(count)]
    with sqlite3.connect(os.path.join(data_dir, "slipfront.db")) as db:
        cols = [r[1] for r in db.execute("PRAGMA table_info(jobs)") if r[1] != "seq"]
        row = dict(zip(cols, db.execute(f"SELECT {', '.join(cols)} FROM jobs WHERE id = ?",
                                        (RUN_IDS[0],)).fetchone()))
        for i, job_id in enumerate(ids):
            row.update(id=job_id, name=f"failed-{i}", status="failed", error="seeded",
                       result_path=None, result_size=0, result_sha256=None, cached_from=None,
                       idempotency_key=None)
            db.execute(f"INSERT INTO jobs ({', '.join(cols)}) VALUES "
                       f"({', '.join('?' * len(cols))})", [row[c] for c in cols])
    return ids


class ExportByManyIds(unittest.TestCase):
    """Before: 500 ids made a URL over 16 KB (431), though the docs promise 1000 runs."""

    def test_a_post_takes_a_thousand_ids(self):
        ids = []
        restart_source([], lambda data_dir: ids.extend(seed_failed_runs(data_dir, 998)))
        ids = ids + RUN_IDS[:2]
        r = SOURCE.get("/api/v1/exports", params={"ids": ",".join(ids[:500])}, headers=ALICE)
        self.assertEqual(r.status_code, 431, r.content[:300])  # more than a URL holds
        r = SOURCE.post("/api/v1/exports", json={"ids": ids}, headers=ALICE, timeout=60)
        self.assertEqual(r.status_code, 200, r.content[:300])
        files = members(r.content)
        self.assertEqual([run["id"] for run in json.loads(files["manifest.json"])["runs"]], ids)
        self.assertEqual(len(files), 1 + 1000 + 2)
        # Refusals name the entry.
        for body, status, pointer in (({"ids": ids + ["0" * 32]}, 422, "/ids"),
                                      ({"ids": ["0" * 32]}, 404, "/ids/0"),
                                      ({"ids": [ids[0], 7]}, 422, "/ids/1"),
                                      ({"ids": ids[:1], "tag": "x"}, 422, "/ids"),
                                      ({"ids": []}, 422, "/ids")):
            r = SOURCE.post("/api/v1/exports", json=body, headers=ALICE)
            self.assertEqual(r.status_code, status, r.content[:300])
            self.assertEqual(r.json()["errors"][0]["pointer"], pointer)
        self.assertEqual(SOURCE.post("/api/v1/exports", json={"ids": ids[:1]}).status_code, 401)


def mount_tmpfs(test, options):
    """A tmpfs mounted with `options` (e.g. "size=24m,nr_inodes=30") on a new directory;
    skips the test unless mount works (root). Unmounted at cleanup."""
    mount = tempfile.mkdtemp(prefix="slipfront-tmpfs-")
    r = subprocess.run(["mount", "-t", "tmpfs", "-o", options, "tmpfs", mount],
                       capture_output=True, text=True)
    if r.returncode != 0:
        os.rmdir(mount)
        test.skipTest("cannot mount a tmpfs here (needs root): " + r.stderr.strip())

    def unmount():
        subprocess.run(["umount", "-l", mount], capture_output=True)
        os.rmdir(mount)
    test.addCleanup(unmount)
    return mount


class Imports(unittest.TestCase):
    """What an import stores: each run's own result member once, all runs or none."""

    @classmethod
    def setUpClass(cls):
        cls.target = Server(BINARY, args=["--workers", "1", "--token-file",
                                          TOKEN_FILE.name]).start()
        cls.five = export(RUN_IDS[:5])

    @classmethod
    def tearDownClass(cls):
        code = cls.target.terminate()
        cls.target.cleanup()
        assert code == 0, code

    def post(self, archive, headers=ALICE, server=None):
        server = server or self.target
        return server.post("/api/v1/imports", data=archive, headers=headers, timeout=120,
                           params=AGAIN)

    def assert_refused(self, archive, where):
        before = imported_counts(self.target.data_dir)
        files = sorted(os.listdir(os.path.join(self.target.data_dir, "results")))
        r = self.post(archive)
        self.assertEqual(r.status_code, 422, r.content[:500])
        self.assertIn(where, r.json()["detail"])
        self.assertEqual(imported_counts(self.target.data_dir), before, "a refused archive stored")
        self.assertEqual(sorted(os.listdir(os.path.join(self.target.data_dir, "results"))), files,
                         "a refused archive wrote result files")
        return r.json()["detail"]

    def test_one_result_member_named_by_many_runs_is_refused(self):
        """Before: 201, and the one member was written once per run naming it."""
        files = members(self.five)
        manifest = json.loads(files["manifest.json"])
        shared = files[f"runs/{RUN_IDS[0]}/result.h5"]
        files = {n: d for n, d in files.items() if not n.endswith("/result.h5")}
        files["shared/result.h5"] = shared
        for run in manifest["runs"]:
            run["result"] = "shared/result.h5"
        files["manifest.json"] = json.dumps(manifest).encode()
        detail = self.assert_refused(resign(files), "must be its own member")
        self.assertIn(f"runs/{RUN_IDS[0]}/result.h5", detail)
        # One run's own member named by another run: refused the same way.
        files = members(self.five)
        manifest = json.loads(files["manifest.json"])
        manifest["runs"][1]["result"] = manifest["runs"][0]["result"]
        del files[f"runs/{RUN_IDS[1]}/result.h5"]
        files["manifest.json"] = json.dumps(manifest).encode()
        self.assert_refused(resign(files), "must be its own member")

    def test_a_result_that_is_not_a_result_file_is_refused(self):
        """Before: a result member that is not HDF5 was stored (201), and its reads were 500."""
        run_id = RUN_IDS[0]
        name = f"runs/{run_id}/result.h5"
        original = members(self.five)[name]

        def with_result(data):
            files = members(self.five)
            files[name] = data
            record = json.loads(files[f"runs/{run_id}/job.json"])
            record["result"]["sha256"] = sha256(data)
            files[f"runs/{run_id}/job.json"] = json.dumps(record).encode()
            return resign(files)

        detail = self.assert_refused(with_result(b"not HDF5 at all " * 1000), name)
        self.assertIn("not an HDF5 file", detail)
        for change, reason in ((lambda f: f.__delitem__("energy"), "no group /energy"),
                               (lambda f: f["interface"].__delitem__("slip"),
                                "no dataset /interface/slip"),
                               (lambda f: f.attrs.__setitem__("spec", json.dumps(dict(
                                   json.loads(f.attrs["spec"]),
                                   friction=dict(json.loads(f.attrs["spec"])["friction"],
                                                 L=7.8e-4)))),
                                "another run's")):
            with tempfile.NamedTemporaryFile(suffix=".h5") as copy:
                copy.write(original)
                copy.flush()
                with h5py.File(copy.name, "r+") as f:
                    change(f)
                with open(copy.name, "rb") as f:
                    altered = f.read()
            detail = self.assert_refused(with_result(altered), name)
            self.assertIn(reason, detail)

    def test_a_result_damaged_later_answers_410_never_500(self):
        r = self.post(export(RUN_IDS[5:6]))
        self.assertEqual(r.status_code, 201, r.content[:300])
        job_id = r.json()["imported"][0]["id"]
        # A file whose size and SHA-256 are the stored ones but that is no result (a file an
        # older server imported unchecked).
        garbage = b"\0" * 4096
        with open(os.path.join(self.target.data_dir, "results", job_id + ".h5"), "wb") as f:
            f.write(garbage)
        with sqlite3.connect(os.path.join(self.target.data_dir, "slipfront.db"), timeout=10) as db:
            db.execute("UPDATE jobs SET result_size = ?, result_sha256 = ? WHERE id = ?",
                       (len(garbage), sha256(garbage), job_id))
        for path in ("fields/slip", "stations", "stations.csv", "result.xdmf"):
            r = self.target.get(f"{JOBS}/{job_id}/{path}")
            self.assertEqual(r.status_code, 410, f"{path}: {r.content[:300]}")
            self.assertIn("damaged", r.json()["detail"])
            self.assertNotIn(self.target.data_dir, r.text)

    def test_a_forged_run_is_a_cache_source_for_its_importer_only(self):
        """Before: a run edited and re-signed (another L, arrest at -999 m) was served to
        another user as a cache hit of the new spec."""
        run_id = RUN_IDS[6]
        files = members(export([run_id]))
        record = json.loads(files[f"runs/{run_id}/job.json"])
        forged_L = 7.8e-4
        record["spec"]["friction"]["L"] = forged_L
        record["metrics"]["arrest_position"] = -999.0
        with tempfile.NamedTemporaryFile(suffix=".h5") as copy:
            copy.write(files[f"runs/{run_id}/result.h5"])
            copy.flush()
            with h5py.File(copy.name, "r+") as f:
                spec = json.loads(f.attrs["spec"])
                spec["friction"]["L"] = forged_L
                f.attrs["spec"] = json.dumps(spec)
            with open(copy.name, "rb") as f:
                files[f"runs/{run_id}/result.h5"] = f.read()
        record["result"]["sha256"] = sha256(files[f"runs/{run_id}/result.h5"])
        files[f"runs/{run_id}/job.json"] = json.dumps(record).encode()
        r = self.post(resign(files))
        self.assertEqual(r.status_code, 201, r.content[:300])
        forged_id = r.json()["imported"][0]["id"]
        spec = dict(JOB, name="asks-for-the-forged-L", friction={"L": forged_L})
        theirs = self.target.submit(spec, headers=BOB)
        self.assertEqual(theirs.status_code, 201, theirs.content[:300])
        self.assertEqual(theirs.json()["cache"], "miss")
        self.assertIsNone(theirs.json()["cached_from"])
        # Its importer may reuse what they imported.
        mine = self.target.submit(spec, headers=ALICE)
        self.assertEqual(mine.json()["cache"], "hit", mine.content[:300])
        self.assertEqual(mine.json()["cached_from"], forged_id)
        # A cache hit of the forged run is no source for others either.
        again = self.target.submit(dict(spec, name="again"), headers=BOB)
        self.assertNotIn(again.json()["cached_from"], (forged_id, mine.json()["id"]))
        for job in (theirs, again):  # no run left writing into results/ for the next test
            self.target.wait_status(job.json()["id"], {"succeeded"}, timeout=120)

    def edited(self, change, run_id=None):
        """An archive of one run whose job.json `change(record)` edited, re-signed."""
        run_id = run_id or RUN_IDS[7]
        files = members(export([run_id]))
        record = json.loads(files[f"runs/{run_id}/job.json"])
        change(record)
        files[f"runs/{run_id}/job.json"] = json.dumps(record).encode()
        return resign(files), f"runs/{run_id}/job.json"

    def test_every_number_and_time_of_a_record_is_checked(self):
        """Before: progress.steps 1e300 was stored as -9223372036854775808, and any non-empty
        text was taken as a time."""
        def set_in(path, value):
            def change(record):
                target = record
                for key in path[:-1]:
                    target = target[key]
                target[path[-1]] = value
            return change
        for path, value, where in (
                (("progress", "steps"), 1e300, "#/progress/steps"),
                (("progress", "steps"), 2.5, "#/progress/steps"),
                (("progress", "fraction"), 7, "#/progress/fraction"),
                (("wall_time_s",), -1, "#/wall_time_s"),
                (("metrics", "steps"), 1e300, "#/metrics/steps"),
                (("metrics", "arrest_position"), "far", "#/metrics/arrest_position"),
                (("created_at",), "not a time; DROP TABLE jobs", "#/created_at"),
                (("finished_at",), "2024-02-30T00:00:00.000Z", "#/finished_at"),
                (("front", "x1"), [1, 2], "#/front"),
                (("imported_from",), {"chain": "x" * 20000}, "#/imported_from")):
            archive, member = self.edited(set_in(path, value))
            detail = self.assert_refused(archive, member + where)
            self.assertLess(len(detail), 1000)

    def test_metrics_of_other_names_are_left_out_with_a_warning(self):
        """Before: one run whose metrics had 20,000 keys added 20,083 columns to every
        run-table export."""
        def columns():
            r = self.target.get(JOBS, params={"format": "csv", "archived": "include"}, timeout=60)
            self.assertEqual(r.status_code, 200)
            return r.text.splitlines()[0].split(",")
        before = len(columns())
        archive, member = self.edited(
            lambda record: record["metrics"].update({f"column_{i}": i for i in range(20000)}))
        r = self.post(archive)
        self.assertEqual(r.status_code, 201, r.content[:300])
        warnings = r.json()["warnings"]
        self.assertEqual(len(warnings), 1, warnings)
        self.assertIn(member + "#/metrics: 20000 name(s)", warnings[0])
        self.assertLess(len(r.content), 4000)
        job = self.target.get(f"{JOBS}/{r.json()['imported'][0]['id']}").json()
        self.assertNotIn("column_0", job["metrics"])
        self.assertIn("arrest_position", job["metrics"])
        self.assertEqual(len(columns()), before)

    def test_an_import_writes_no_more_than_it_uploads(self):
        results = os.path.join(self.target.data_dir, "results")
        before = set(os.listdir(results))
        archive = export(RUN_IDS[:10])
        r = self.post(archive)
        self.assertEqual(r.status_code, 201, r.content[:500])
        self.assertEqual(r.json()["count"], 10)
        written = sum(os.path.getsize(os.path.join(results, n))
                      for n in set(os.listdir(results)) - before)
        self.assertLessEqual(written, len(archive))
        self.assertEqual(stray_files(self.target.data_dir), [])


class ImportOnAFullDisk(unittest.TestCase):
    """Before: 40 runs into a data dir without room for them answered 500 with part of them
    stored, and the retry stored them again."""

    def test_a_full_disk_stores_nothing_and_the_retry_stores_all_once(self):
        # Bytes for one archive, but inodes for about 20 files: creating the 21st file of the
        # import fails with ENOSPC, as a full disk does, while statvfs shows free bytes.
        mount = mount_tmpfs(self, "size=24m,nr_inodes=30")
        os.mkdir(os.path.join(mount, "data"))
        server = Server(BINARY, data_dir=os.path.join(mount, "data"),
                        args=["--workers", "1", "--token-file", TOKEN_FILE.name,
                              "--min-free-bytes", str(1 << 20)]).start()
        try:
            archive = export(RUN_IDS[:40])
            r = server.post("/api/v1/imports", data=archive, headers=ALICE, timeout=120,
                            params=AGAIN)
            self.assertEqual(r.status_code, 503, r.content[:500])
            self.assertIn("Retry-After", r.headers)
            self.assertEqual(imported_counts(server.data_dir), 0)
            self.assertEqual(os.listdir(os.path.join(server.data_dir, "results")), [])
            # Room again: the retry stores every run, once.
            subprocess.run(["mount", "-o", "remount,nr_inodes=10000", mount], check=True)
            r = server.post("/api/v1/imports", data=archive, headers=ALICE, timeout=120,
                            params=AGAIN)
            self.assertEqual(r.status_code, 201, r.content[:500])
            self.assertEqual(imported_counts(server.data_dir), 40)
            self.assertEqual(stray_files(server.data_dir), [])
            # Now the disk cannot take the archive again above --min-free-bytes: refused
            # before a byte is written, and so is an export of it.
            r = server.post("/api/v1/imports", data=archive, headers=ALICE, timeout=120,
                            params=AGAIN)
            self.assertEqual(r.status_code, 503, r.content[:500])
            self.assertIn("free space", r.json()["detail"])
            self.assertEqual(imported_counts(server.data_dir), 40)
            ids = [run["id"] for run in json.loads(members(archive)["manifest.json"])["runs"]]
            r = server.get("/api/v1/exports", params={"ids": ",".join(ids)}, headers=ALICE,
                           timeout=60)
            self.assertEqual(r.status_code, 503, r.content[:500])
            self.assertIn("free space", r.json()["detail"])
        finally:
            code = server.terminate()
            self.assertEqual(code, 0)


class KilledDuringImportsAndDeletes(unittest.TestCase):
    """SIGKILL while an import or deletes run: after the restart an import is there whole or
    not at all, and no result file is left without a row. Before: part of an import stayed,
    and files without a row in 5 of 15 kills during imports, 2 during deletes."""

    def test_sigkill_leaves_whole_imports_and_no_stray_file(self):
        archive = export(RUN_IDS[:40])
        rng = random.Random(int(os.environ.get("SLIPFRONT_FAULT_SEED", "7")))
        data_dir = tempfile.mkdtemp(prefix="slipfront-test-")
        args = ["--workers", "1", "--token-file", TOKEN_FILE.name]
        server = Server(BINARY, data_dir=data_dir, args=args).start()
        started = time.monotonic()
        r = server.post("/api/v1/imports", data=archive, headers=ALICE, timeout=120,
                            params=AGAIN)
        self.assertEqual(r.status_code, 201, r.content[:300])
        took = time.monotonic() - started
        landed = {"import": 0, "delete": 0}
        try:
            for i in range(int(os.environ.get("SLIPFRONT_KILL_ITERATIONS", "6"))):
                kind = "delete" if i % 3 == 2 else "import"
                before = imported_counts(data_dir)
                if kind == "import":
                    work = lambda s=server: s.post("/api/v1/imports", data=archive,
                                                    headers=ALICE, timeout=120, params=AGAIN)
                else:
                    ids = [j["id"] for j in server.get(
                        JOBS, params={"limit": 1000}).json()["jobs"]][:40]
                    work = lambda s=server, ids=ids: [
                        s.session.delete(s.url(f"{JOBS}/{i}"), headers=ALICE, timeout=30)
                        for i in ids]
                done = threading.Event()

                def run(work=work, done=done):
                    try:
                        work()
                        done.set()
                    except requests.RequestException:
                        pass
                thread = threading.Thread(target=run)
                thread.start()
                time.sleep(rng.uniform(0.1, 0.9) * took)
                server.kill()
                thread.join(timeout=30)
                if not done.is_set():
                    landed[kind] += 1
                server = Server(BINARY, data_dir=data_dir, args=args).start()
                count = imported_counts(data_dir)
                if kind == "import":
                    self.assertIn(count, (before, before + 40), f"kill {i}: {before} -> {count}")
                self.assertEqual(stray_files(data_dir), [], f"kill {i} ({kind})")
                with sqlite3.connect(os.path.join(data_dir, "slipfront.db")) as db:
                    self.assertEqual(db.execute("PRAGMA integrity_check").fetchone()[0], "ok")
                for job in server.get(JOBS, params={"limit": 1000}).json()["jobs"]:
                    self.assertTrue(os.path.exists(os.path.join(data_dir, "results",
                                                                job["id"] + ".h5")), job["id"])
            print(f"SIGKILLs that landed during the work: {landed}", file=sys.stderr)
            self.assertGreater(landed["import"], 0, "no kill landed during an import")
        finally:
            server.kill()
            server.own_dir = True
            server.cleanup()

    def test_check_reports_and_start_up_removes_files_without_a_row(self):
        """Before: `slipfront check` said ok, and start-up kept them for ever."""
        server = Server(BINARY, args=["--workers", "1"]).start()
        data_dir = server.data_dir
        try:
            self.assertEqual(server.terminate(), 0)
            results = os.path.join(data_dir, "results")
            stray = ["0123456789abcdef0123456789abcdef.h5", "notes.txt"]
            for name in stray:
                with open(os.path.join(results, name), "wb") as f:
                    f.write(b"x" * 1000)
            check = subprocess.run([BINARY, "check", data_dir], capture_output=True, text=True,
                                   timeout=60)
            self.assertEqual(check.returncode, 1, check.stdout + check.stderr)
            for name in stray:
                self.assertIn(f"results/{name}: no job refers to it", check.stdout)
            server = Server(BINARY, data_dir=data_dir, args=["--workers", "1"]).start()
            self.assertEqual(os.listdir(results), [])
            self.assertIn("results/notes.txt removed: no job refers to it", server.read_log())
            self.assertEqual(server.terminate(), 0)
            check = subprocess.run([BINARY, "check", data_dir], capture_output=True, text=True,
                                   timeout=60)
            self.assertEqual((check.returncode, check.stdout.strip()), (0, "ok"))
        finally:
            server.kill()
            server.own_dir = True
            server.cleanup()


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

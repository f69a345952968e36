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
import socket
import sqlite3
import sys
import tarfile
import tempfile
import time
import unittest


sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import TINY, Server  # noqa: E402

BINARY = None
JOBS = "/api/v1/jobs"
ALICE = {"Authorization": "Bearer alice-secret-token"}
BOB = {"Authorization": "Bearer bob-secret-token"}
SEND_TIMEOUT_S = 2
# A run of about 0.3 MB of result; its cache hits are runs of their own in an archive.
JOB = dict(TINY, name="archived", geometry={"nodes_per_meter": 10},
           time={"duration": 4.0, "stop_on_arrest": False}, output={"interval": 0.005})
RUNS = 60

SOURCE = None        # the source server (alice's runs)
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


def open_export_files(pid, size=0):
    """The unlinked export-* files of at least `size` bytes the server process holds open."""
    held = []
    for fd in os.listdir(f"/proc/{pid}/fd"):
        try:
            target = os.readlink(f"/proc/{pid}/fd/{fd}")
            if "/export-" in target and os.stat(f"/proc/{pid}/fd/{fd}").st_size >= size:
                held.append(target)
        except OSError:
            continue
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


def restart_source(extra_args):
    """SOURCE again on its data dir with more flags."""
    global SOURCE
    assert SOURCE.terminate() == 0
    SOURCE = Server(BINARY, data_dir=SOURCE.data_dir,
                    args=["--workers", "1", "--token-file", TOKEN_FILE.name] + extra_args).start()
    SOURCE.own_dir = True


class UnreadExports(unittest.TestCase):
    """Clients that ask for an archive and never read it: before, each held an unlinked
    export file for the 600 s write timeout, without a token and without a bound."""

    def test_unread_exports_are_cut_and_their_disk_is_bounded(self):
        third = RUN_IDS[:RUNS // 3]
        size = len(export(third))
        # Room for two unread archives of a third of the runs, not three.
        restart_source(["--send-timeout-s", str(SEND_TIMEOUT_S),
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
            deadline = time.monotonic() + 20
            # Both written whole (their exports no longer take an export thread).
            while (len(open_export_files(SOURCE.proc.pid, size)) < 2
                   and time.monotonic() < deadline):
                time.sleep(0.05)
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
            while open_export_files(SOURCE.proc.pid) and time.monotonic() < held_at + 15:
                time.sleep(0.1)
            released_after = time.monotonic() - held_at
            self.assertEqual(open_export_files(SOURCE.proc.pid), [])
            self.assertLess(released_after, SEND_TIMEOUT_S + 4)
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
        return server.post("/api/v1/imports", data=archive, headers=headers, timeout=120)

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


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

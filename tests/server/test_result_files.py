"""Result files that are not what the database says: a damaged
file (truncated, zeroed, bytes flipped, even with its mtime put back) answers as gone and is
never reused by the cache; a FIFO or a directory in the file's place answers at once without
stalling the server; no answer quotes a server path; no HDF5 complaint at exit.

    /usr/bin/python3 tests/server/test_result_files.py --binary build/slipfront
"""

import argparse
import hashlib
import json
import os
import sys
import threading
import time
import unittest

import requests

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import TERMINAL, TINY, Server  # noqa: E402

BINARY = None
JOBS = "/api/v1/jobs"


def truncate(path):
    with open(path, "r+b") as f:
        f.truncate(os.path.getsize(path) // 2)


def zero(path):
    size = os.path.getsize(path)
    with open(path, "r+b") as f:
        f.write(b"\0" * size)


def flip(path):
    size = os.path.getsize(path)
    with open(path, "r+b") as f:
        f.seek(size // 2)
        byte = f.read(1)
        f.seek(size // 2)
        f.write(bytes([byte[0] ^ 0xFF]))


def flip_keeping_mtime(path):
    st = os.stat(path)
    flip(path)
    os.utime(path, ns=(st.st_atime_ns, st.st_mtime_ns))


class DamagedResults(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.server = Server(BINARY, args=["--workers", "1"]).start()

    @classmethod
    def tearDownClass(cls):
        code = cls.server.terminate()
        log = cls.server.read_log()
        cls.server.cleanup()
        assert code == 0, f"server exit code {code}"
        # HDF5 once complained at exit after the server had read corrupt files.
        assert "infinite loop closing library" not in log, log[-3000:]

    def run_job(self, name):
        r = self.server.submit(dict(TINY, name=name), params={"fresh": "true"})
        self.assertEqual(r.status_code, 201, r.text)
        return self.server.wait_status(r.json()["id"], {"succeeded"}, timeout=60)

    def result_path(self, job):
        return os.path.join(self.server.data_dir, "results", job["id"] + ".h5")

    def assert_no_server_path(self, response):
        self.assertNotIn(self.server.data_dir, response.text)
        self.assertNotIn(os.path.realpath(self.server.data_dir), response.text)

    def check_damage(self, damage):
        # Its own physics (L), so that the cache of the other cases does not interfere.
        L = {"truncate": 5.1e-5, "zero": 5.2e-5, "flip": 5.3e-5, "flip_keeping_mtime": 5.4e-5}
        spec = dict(TINY, name=f"damaged-{damage.__name__}",
                    friction={"L": L[damage.__name__]})
        r = self.server.submit(spec)
        self.assertEqual(r.status_code, 201, r.text)
        job = self.server.wait_status(r.json()["id"], {"succeeded"}, timeout=60)
        url = job["result"]["url"]
        ok = self.server.get(url)
        self.assertEqual(ok.status_code, 200)  # verified once, then kept while unchanged
        self.assertEqual(hashlib.sha256(ok.content).hexdigest(), job["result"]["sha256"])
        damage(self.result_path(job))
        for path in (url, f"{JOBS}/{job['id']}/result.xdmf",
                     f"{JOBS}/{job['id']}/fields/slip_velocity"):
            r = self.server.get(path)
            self.assertEqual(r.status_code, 410, f"{damage.__name__} {path}: {r.text[:300]}")
            self.assertIn("damaged", r.json()["detail"])
            self.assertNotIn("ETag", r.headers)
            self.assert_no_server_path(r)
        # A new identical job is not a cache hit of the damaged file: it runs again.
        again = self.server.submit(dict(spec, name=spec["name"] + "-again"))
        self.assertEqual(again.status_code, 201, again.text)
        self.assertEqual(again.json()["cache"], "miss", again.text)
        done = self.server.wait_status(again.json()["id"], TERMINAL, timeout=60)
        self.assertEqual(done["status"], "succeeded", done)
        fresh = self.server.get(done["result"]["url"])
        self.assertEqual(fresh.status_code, 200)
        self.assertEqual(hashlib.sha256(fresh.content).hexdigest(), done["result"]["sha256"])

    def test_truncated_file_is_gone_and_runs_again(self):
        self.check_damage(truncate)

    def test_zeroed_file_is_gone_and_runs_again(self):
        self.check_damage(zero)

    def test_flipped_byte_is_gone_and_runs_again(self):
        self.check_damage(flip)

    def test_flipped_byte_with_the_old_mtime_is_noticed(self):
        self.check_damage(flip_keeping_mtime)

    def test_a_damage_before_the_first_read_after_start_is_noticed(self):
        """Verified on its first use after a start: a file damaged while no server ran."""
        job = self.run_job("damaged-while-stopped")
        flip_keeping_mtime(self.result_path(job))
        server = type(self).server
        self.assertEqual(server.terminate(), 0)
        server.own_dir = False  # the next server takes the directory over
        server.cleanup()
        restarted = Server(BINARY, data_dir=server.data_dir, args=["--workers", "1"]).start()
        restarted.own_dir = True
        type(self).server = restarted
        r = self.server.get(job["result"]["url"])
        self.assertEqual(r.status_code, 410, r.text)

    def test_fifo_in_place_of_the_result_stalls_nothing(self):
        """Before: opening a FIFO blocked both I/O threads; /healthz stalled."""
        job = self.run_job("fifo")
        path = self.result_path(job)
        os.remove(path)
        os.mkfifo(path)
        answers = {}

        def fetch(what, url):
            try:
                answers[what] = requests.get(self.server.url(url), timeout=8).status_code
            except requests.RequestException as e:
                answers[what] = type(e).__name__
        threads = [threading.Thread(target=fetch, args=(f"{what}-{k}", url))
                   for k in range(3)
                   for what, url in (("download", job["result"]["url"]),
                                     ("xdmf", f"{JOBS}/{job['id']}/result.xdmf"),
                                     ("field", f"{JOBS}/{job['id']}/fields/slip_velocity"))]
        for t in threads:
            t.start()
        time.sleep(0.3)
        t0 = time.monotonic()
        health = requests.get(self.server.url("/healthz"), timeout=8)
        health_s = time.monotonic() - t0
        for t in threads:
            t.join(timeout=10)
        # Unblock a reader still waiting on the FIFO (before the fix), then clean up.
        try:
            fd = os.open(path, os.O_WRONLY | os.O_NONBLOCK)
            os.close(fd)
        except OSError:
            pass
        os.remove(path)
        self.assertEqual(health.status_code, 200)
        self.assertLess(health_s, 1.0, f"/healthz took {health_s:.2f} s")
        self.assertEqual(set(answers.values()), {410}, answers)

    def test_directory_in_place_of_the_result_gets_an_answer(self):
        job = self.run_job("directory")
        path = self.result_path(job)
        os.remove(path)
        os.mkdir(path)
        try:
            for url in (job["result"]["url"], f"{JOBS}/{job['id']}/result.xdmf",
                        f"{JOBS}/{job['id']}/fields/slip_velocity"):
                r = self.server.get(url)
                self.assertEqual(r.status_code, 410, f"{url}: {r.text[:300]}")
                self.assertIn("not a regular file", r.json()["detail"])
                self.assert_no_server_path(r)
        finally:
            os.rmdir(path)

    def test_missing_dataset_answers_without_a_server_path(self):
        """A file whose hash is right but which lacks what is asked: no path in the answer."""
        job = self.run_job("no-path")
        r = self.server.get(f"{JOBS}/{job['id']}/fields/slip_velocity",
                            params={"x1_min": "1e300", "x1_max": "1e301"})
        self.assert_no_server_path(r)
        r = self.server.get(f"{JOBS}/{job['id']}/result.xdmf")
        self.assertEqual(r.status_code, 200)
        self.assert_no_server_path(r)
        self.assertIn(job["id"] + ".h5", r.text)
        body = json.dumps(self.server.get(f"{JOBS}/{job['id']}").json())
        self.assertNotIn(self.server.data_dir, body)


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

"""The client as an installable package (docs/python-api.md): it installs offline into a
venv that sees Debian's numpy, h5py, matplotlib and requests (the README's command), its
console script runs, its version is the server's (project VERSION in CMakeLists.txt and `slipfront --version`), the
notebook clients/examples/tour.ipynb runs under nbconvert in a kernel of that venv against a
live loopback server, and the command
line lists, filters and exports runs, lists studies, and explains a server that does not
answer.

    /usr/bin/python3 tests/clients/test_package.py --binary build/slipfront
"""

import csv
import hashlib
import io
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET
from unittest import mock

import h5py

from harness import CLIENTS, REPO, Server, binary_from_argv

BINARY = None


def cmake_version():
    with open(os.path.join(REPO, "CMakeLists.txt")) as f:
        match = re.search(r"project\(slipfront VERSION ([0-9.]+)", f.read())
    assert match, "no project(slipfront VERSION ...) in CMakeLists.txt"
    return match.group(1)


class InstalledPackageTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="slipfront-venv-")
        venv = os.path.join(cls.tmp, "venv")
        subprocess.run(["/usr/bin/python3", "-m", "venv", "--system-site-packages", venv],
                       check=True, timeout=120)
        install = subprocess.run(
            [os.path.join(venv, "bin", "pip"), "install", "--no-index",
             "--disable-pip-version-check", CLIENTS],
            capture_output=True, text=True, timeout=300)
        if install.returncode != 0:
            raise AssertionError(f"pip install failed:\n{install.stdout}\n{install.stderr}")
        cls.python = os.path.join(venv, "bin", "python")
        cls.script = os.path.join(venv, "bin", "slipfront-client")
        cls.server = Server(BINARY).start()
        cls.env = {k: v for k, v in os.environ.items()
                   if k not in ("SLIPFRONT_SERVER", "SLIPFRONT_TOKEN", "PYTHONPATH")}
        cls.env["SLIPFRONT_CONFIG"] = os.path.join(cls.tmp, "no-such-config.toml")
        cls.env["XDG_CACHE_HOME"] = os.path.join(cls.tmp, "cache")
        cls.env["MPLBACKEND"] = "Agg"

    @classmethod
    def tearDownClass(cls):
        cls.server.stop()
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def client(self, *args, env=None, timeout=120):
        e = dict(self.env, SLIPFRONT_SERVER=self.server.base)
        e.update(env or {})
        return subprocess.run([self.script, *args], capture_output=True, text=True, env=e,
                              timeout=timeout, cwd=self.tmp)

    def test_1_installed_outside_the_checkout(self):
        where = subprocess.run(
            [self.python, "-c", "import slipfront_client, sys; print(slipfront_client.__file__)"],
            capture_output=True, text=True, env=self.env, cwd=self.tmp, check=True)
        self.assertIn(os.path.join(self.tmp, "venv"), where.stdout)

    def test_2_version_is_the_servers(self):
        r = self.client("--version")
        self.assertEqual(r.returncode, 0, r.stderr)
        client_version = r.stdout.strip().split()[-1]
        self.assertEqual(client_version, cmake_version(),
                         "clients/slipfront_client/__init__.py __version__ differs from the "
                         "project VERSION in CMakeLists.txt")
        server = subprocess.run([BINARY, "--version"], capture_output=True, text=True, check=True)
        self.assertEqual(server.stdout.split()[1].split("+")[0], client_version)
        metadata = subprocess.run(
            [self.python, "-c", "import importlib.metadata as m; print(m.version('slipfront-client'))"],
            capture_output=True, text=True, env=self.env, cwd=self.tmp, check=True)
        self.assertEqual(metadata.stdout.strip(), client_version)

    def test_3_notebook_runs_against_the_server(self):
        """clients/examples/tour.ipynb, executed top to bottom by nbconvert (Debian's
        python3-nbconvert) in a kernel of the venv (python3-ipykernel): submit, study,
        compare, export, with the installed package against the loopback server."""
        jupyter = os.path.join(self.tmp, "jupyter")
        kernel = os.path.join(jupyter, "kernels", "slipfront-venv")
        os.makedirs(kernel, exist_ok=True)
        with open(os.path.join(kernel, "kernel.json"), "w") as f:
            json.dump({"argv": [self.python, "-m", "ipykernel_launcher", "-f",
                                "{connection_file}"],
                       "display_name": "slipfront venv", "language": "python"}, f)
        out = os.path.join(self.tmp, "tour")
        env = dict(self.env, SLIPFRONT_SERVER=self.server.base, SLIPFRONT_TOUR_OUT=out,
                   JUPYTER_PATH=jupyter, JUPYTER_RUNTIME_DIR=os.path.join(jupyter, "runtime"),
                   IPYTHONDIR=os.path.join(self.tmp, "ipython"),
                   PYDEVD_DISABLE_FILE_VALIDATION="1")
        env.pop("MPLBACKEND")  # the kernel's own choice, as in Jupyter
        notebook = os.path.join(CLIENTS, "examples", "tour.ipynb")
        r = subprocess.run(["/usr/bin/python3", "-m", "nbconvert", "--to", "notebook",
                            "--execute", notebook, "--output-dir", out,
                            "--ExecutePreprocessor.kernel_name=slipfront-venv",
                            "--ExecutePreprocessor.timeout=600"],
                           capture_output=True, text=True, env=env, timeout=900, cwd=self.tmp)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr[-4000:])
        with open(os.path.join(out, "tour.ipynb")) as f:
            executed = json.load(f)
        outputs = [o for c in executed["cells"] if c["cell_type"] == "code" for o in c["outputs"]]
        self.assertFalse([o for o in outputs if o["output_type"] == "error"])
        text = "".join("".join(o["text"]) for o in outputs if o["output_type"] == "stream")
        self.assertIn(f"from {os.path.join(self.tmp, 'venv')}", text)  # the installed package
        self.assertRegex(text, r"job [0-9a-f]{32}: arrested, arrest at")
        self.assertRegex(text, r"slip velocity \(\d+, \d+\)")
        self.assertRegex(text, r"study [0-9a-f]{32}: finished")
        self.assertRegex(text, r"6 of 6 runs arrested")
        self.assertRegex(text, r"L = 0.0001 m +L = 2e-05 m")
        self.assertIn("metrics.arrest_position", text)
        images = [o for o in outputs if "image/png" in o.get("data", {})]
        self.assertEqual(len(images), 4)  # map, V(t), rupture speed, the two runs' V(t)
        for name in ("map.png", "velocity.png", "speed.png", "compare_velocity.png"):
            self.assertGreater(os.path.getsize(os.path.join(out, name)), 10000, name)
        with open(os.path.join(out, "runs.csv")) as f:
            rows = list(csv.DictReader(f))
        self.assertEqual(len(rows), 7)  # the tour's run and its study's six
        for row in rows:
            self.assertRegex(row["result_sha256"], r"^[0-9a-f]{64}$")
            self.assertEqual(row["result_url"],
                             f"{self.server.base}/api/v1/jobs/{row['id']}/result.h5")
        sidecar = ET.parse(os.path.join(out, "paper_run.xdmf")).getroot()
        self.assertEqual({i.text.split(":")[0] for i in sidecar.iter("DataItem")
                          if i.get("Format") == "HDF"}, {"paper_run.h5"})
        self.assertTrue(os.path.exists(os.path.join(out, "paper_run.h5")))

    def test_4_list_filters_and_exports(self):
        r = self.client("submit", "--wait", "--quiet", "--tag", "pkg",
                        "--set", "method=spectral_bi", "--set", "friction.L=1e-4",
                        "--set", "time.duration=3")
        self.assertEqual(r.returncode, 0, r.stderr)
        job_id = r.stdout.strip()
        r = self.client("list", "--where", "tag=pkg", "--where", "friction.L>=1e-4",
                        "--format", "csv")
        self.assertEqual(r.returncode, 0, r.stderr)
        rows = list(csv.DictReader(io.StringIO(r.stdout)))
        self.assertEqual([row["id"] for row in rows], [job_id])
        self.assertEqual(float(rows[0]["spec.friction.L"]), 1e-4)
        self.assertIn("metrics.arrest_position", rows[0])
        r = self.client("list", "--where", "tag=pkg", "--format", "json")
        self.assertEqual([j["id"] for j in json.loads(r.stdout)], [job_id])
        r = self.client("list", "--where", "method=spectral_bi", "--sort", "-friction.L")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn(job_id, r.stdout)
        r = self.client("list", "--where", "friction.L<lots")
        self.assertEqual(r.returncode, 2)
        self.assertIn("/query/where: friction.L is a number; 'lots' is not a finite number",
                      r.stderr)
        r = self.client("download", job_id, "-o", os.path.join(self.tmp, "pkg.h5"), "--xdmf")
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(self.tmp, "pkg.xdmf")) as f:
            sidecar = f.read()
        self.assertIn(">pkg.h5:/interface/slip_velocity<", sidecar)
        self.assertNotIn(f"{job_id}.h5", sidecar)
        r = self.client("study", "list")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertRegex(r.stdout.splitlines()[0], r"^id\s+status\s+kind\s+method\s+runs")

    def test_6_export_provenance_integers_and_xdmf(self):
        """A run downloaded under another name with its XDMF sidecar, then exported: the
        sidecar is a temporal collection (one grid per recorded time) naming the file beside
        it; the run table carries the provenance columns, `tags` filters as `tag` does, whole
        numbers print as integers."""
        h5 = os.path.join(self.tmp, "renamed run.h5")
        r = self.client("submit", "--wait", "--quiet", "--tag", "prov",
                        "--set", "method=spectral_bi", "--set", "geometry.nodes_per_meter=10",
                        "--set", "time.duration=2", "--download", h5, "--xdmf")
        self.assertEqual(r.returncode, 0, r.stderr)
        job_id = r.stdout.strip()
        xdmf = os.path.join(self.tmp, "renamed run.xdmf")
        root = ET.parse(xdmf).getroot()
        collection = root.find("Domain/Grid")
        self.assertEqual((collection.get("GridType"), collection.get("CollectionType")),
                         ("Collection", "Temporal"))
        steps = collection.findall("Grid")
        with h5py.File(h5, "r") as f:
            times = f["interface/time"][()]
        self.assertEqual(len(steps), len(times))
        self.assertEqual([float(g.find("Time").get("Value")) for g in steps], list(times))
        referenced = {item.text.split(":")[0] for item in root.iter("DataItem")
                      if item.get("Format") == "HDF"}
        self.assertEqual(referenced, {"renamed run.h5"})
        self.assertTrue(os.path.exists(os.path.join(os.path.dirname(xdmf), "renamed run.h5")))

        r = self.client("list", "--where", "tags=prov", "--format", "csv")
        self.assertEqual(r.returncode, 0, r.stderr)
        rows = list(csv.DictReader(io.StringIO(r.stdout)))
        self.assertEqual([row["id"] for row in rows], [job_id])
        row = rows[0]
        job = json.loads(self.client("status", job_id, "--json").stdout)
        with open(h5, "rb") as f:
            self.assertEqual(row["result_sha256"], hashlib.sha256(f.read()).hexdigest())
        self.assertEqual(row["result_url"], f"{self.server.base}/api/v1/jobs/{job_id}/result.h5")
        self.assertEqual(row["result_size_bytes"], str(os.path.getsize(h5)))
        for column in ("spec_sha256", "scene_hash", "code_version"):
            self.assertEqual(row[column], job[column], column)
        self.assertEqual(row["tags"], "prov")
        # Whole numbers as integers: in the table, in --json and in the status lines.
        self.assertEqual(row["spec.geometry.nodes_per_meter"], "10")
        self.assertRegex(row["memory_estimate_bytes"], r"^[0-9]+$")
        self.assertEqual(row["metrics.steps"], str(job["metrics"]["steps"]))
        self.assertIsInstance(job["spec"]["geometry"]["nodes_per_meter"], int)
        self.assertIsInstance(job["memory_estimate_bytes"], int)
        status = self.client("status", job_id).stdout
        self.assertIn("n_d = 10,", status)
        self.assertNotRegex(status, r"\b10\.0\b")
        ndjson = self.client("list", "--where", "tags=prov", "--format", "ndjson").stdout
        exported = json.loads(ndjson.splitlines()[0])
        self.assertEqual(exported["spec.geometry.nodes_per_meter"], 10)
        self.assertIn('"spec.geometry.nodes_per_meter":10,', ndjson)
        self.assertEqual(exported["result_url"], row["result_url"])

    def test_5_friendly_message_when_nothing_listens(self):
        r = self.client("list", "--server", "http://127.0.0.1:9")
        self.assertEqual(r.returncode, 1)
        self.assertIn("nothing answers at http://127.0.0.1:9 (from --server)",
                      r.stderr)
        self.assertNotIn("Traceback", r.stderr)
        config = os.path.join(self.tmp, "client.toml")
        with open(config, "w") as f:
            f.write('server = "http://127.0.0.1:9"\n')
        env = dict(self.env, SLIPFRONT_CONFIG=config)
        env.pop("SLIPFRONT_SERVER", None)
        r = subprocess.run([self.script, "list"], capture_output=True, text=True, env=env,
                           timeout=60, cwd=self.tmp)
        self.assertIn(f"nothing answers at http://127.0.0.1:9 (from {config})", r.stderr)


class RunsDataframeTest(unittest.TestCase):
    """runs_dataframe: a DataFrame with pandas, plain records without it."""

    class FakeApi:
        def export_runs(self, fmt, filters, limit=None):
            assert fmt == "ndjson" and filters["where"] == "outcome=arrested"
            return ('{"id": "a", "spec.friction.L": 1e-4, "outcome": "arrested", '
                    '"created_at": "2026-11-23T17:00:00Z"}\n'
                    '{"id": "b", "spec.friction.L": 5e-5, "outcome": "arrested", '
                    '"created_at": "2026-11-23T18:00:00Z"}\n')

    def test_records_without_pandas(self):
        sys.path.insert(0, CLIENTS)
        from slipfront_client.workflow import runs_dataframe
        with mock.patch.dict(sys.modules, {"pandas": None}):
            records = runs_dataframe(self.FakeApi(), where="outcome=arrested")
        self.assertEqual([r["id"] for r in records], ["a", "b"])

    def test_dataframe_with_pandas(self):
        import pandas
        sys.path.insert(0, CLIENTS)
        from slipfront_client.workflow import runs_dataframe
        frame = runs_dataframe(self.FakeApi(), where="outcome=arrested")
        self.assertIsInstance(frame, pandas.DataFrame)
        self.assertEqual(list(frame.index), ["a", "b"])
        self.assertEqual(frame.loc["b", "spec.friction.L"], 5e-5)
        self.assertEqual(str(frame["created_at"].dtype), "datetime64[ns, UTC]")


if __name__ == "__main__":
    BINARY, rest = binary_from_argv(sys.argv[1:])
    BINARY = os.path.abspath(BINARY)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

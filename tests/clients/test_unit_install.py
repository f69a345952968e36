"""The in-tree build backend (clients/_backend/slipfront_backend.py) and the config reader
without tomllib: what `pip install ./clients` builds, checked without pip (the install
itself: test_install_offline.py)."""

import base64
import hashlib
import os
import shutil
import sys
import tempfile
import tomllib
import unittest
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
CLIENTS = os.path.normpath(os.path.join(HERE, "..", "..", "clients"))
sys.path.insert(0, os.path.join(CLIENTS, "_backend"))
sys.path.insert(0, CLIENTS)

import slipfront_backend as backend  # noqa: E402
from slipfront_client import __version__, config  # noqa: E402


class PyprojectReader(unittest.TestCase):
    def test_reads_clients_pyproject_as_tomllib_does(self):
        path = os.path.join(CLIENTS, "pyproject.toml")
        with open(path, "rb") as f:
            expected = tomllib.load(f)
        tables = backend.read_pyproject(path)
        project = dict(tables["project"])
        project["optional-dependencies"] = tables["project.optional-dependencies"]
        project["scripts"] = tables["project.scripts"]
        self.assertEqual(project, expected["project"])
        self.assertEqual(tables["build-system"], expected["build-system"])

    def test_a_form_it_does_not_know_is_an_error(self):
        with tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False) as f:
            f.write('[project]\nname = "x"\nversion = 1979-05-27\n')
        try:
            with self.assertRaisesRegex(ValueError, "line 3: cannot read value"):
                backend.read_pyproject(f.name)
        finally:
            os.unlink(f.name)


class Wheel(unittest.TestCase):
    def build(self, hook):
        out = tempfile.mkdtemp(prefix="slipfront-wheel-")
        self.addCleanup(shutil.rmtree, out)
        name = hook(out)
        self.assertEqual(name, f"slipfront_client-{__version__}-py3-none-any.whl")
        wheel = zipfile.ZipFile(os.path.join(out, name))
        self.addCleanup(wheel.close)
        return wheel

    def check_record(self, wheel):
        info = f"slipfront_client-{__version__}.dist-info"
        record = wheel.read(f"{info}/RECORD").decode().splitlines()
        listed = {}
        for line in record:
            name, digest, size = line.rsplit(",", 2)
            listed[name] = (digest, size)
        self.assertEqual(set(listed), set(wheel.namelist()))
        for name, (digest, size) in listed.items():
            if name.endswith("RECORD"):
                continue
            data = wheel.read(name)
            sha = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
            self.assertEqual((digest, size), (f"sha256={sha}", str(len(data))), name)
        return info

    def test_wheel_holds_the_package_and_its_metadata(self):
        wheel = self.build(backend.build_wheel)
        info = self.check_record(wheel)
        names = wheel.namelist()
        for module in ("slipfront_client/__init__.py", "slipfront_client/cli.py",
                       "slipfront_client/plots/common.py", "slipfront_client/friction_labels.json"):
            self.assertIn(module, names)
        self.assertFalse([n for n in names if "__pycache__" in n])
        metadata = wheel.read(f"{info}/METADATA").decode()
        self.assertIn(f"Version: {__version__}\n", metadata)
        self.assertIn("Name: slipfront-client\n", metadata)
        self.assertIn("Requires-Python: >=3.9\n", metadata)
        self.assertIn('Requires-Dist: numpy; extra == "full"', metadata)
        self.assertNotRegex(metadata, r"Requires-Dist: [a-z0-9]+\n")  # no required dependency
        self.assertIn("slipfront-client = slipfront_client.cli:main",
                      wheel.read(f"{info}/entry_points.txt").decode())

    def test_editable_wheel_points_at_the_checkout(self):
        wheel = self.build(backend.build_editable)
        self.check_record(wheel)
        self.assertEqual(wheel.read("_slipfront_client_editable.pth").decode().strip(), CLIENTS)


class ConfigWithoutTomllib(unittest.TestCase):
    TEXT = ('# the server\nserver = "http://host:8080"  # a comment\n\n'
            'token = "a\\"b\\\\c"\n')

    def test_string_lines_read_as_tomllib_reads_them(self):
        self.assertEqual(config.parse_string_lines(self.TEXT), tomllib.loads(self.TEXT))

    def test_other_forms_name_the_line(self):
        with self.assertRaisesRegex(ValueError, "line 2: expected key = \"string\""):
            config.parse_string_lines('server = "x"\n[table]\n')


if __name__ == "__main__":
    unittest.main()

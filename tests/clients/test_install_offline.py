"""The client installs anywhere (docs/python-api.md "Install"): offline, into a venv made
WITHOUT system site packages (as a pyenv or conda Python gives: no setuptools, no wheel, no
numpy, no requests, no package index), with the README's command

    VENV/bin/pip install --no-index ./clients

and, from that venv, `slipfront-client --help` and `import slipfront_client` work, a command
that needs a missing package names it (exit 2, no traceback), and an editable install
(`pip install -e`, PEP 660) points at the checkout. No server and no compiled binary needed.

    /usr/bin/python3 tests/clients/test_install_offline.py [--python /path/to/python3.9 ...]

With --python (repeatable) the venvs are made by those interpreters (default: the one
running this test).
"""

import os
import shutil
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
CLIENTS = os.path.join(os.path.dirname(HERE), "..", "clients")
CLIENTS = os.path.normpath(CLIENTS)
PYTHONS = []


def clean_env(tmp):
    """No PYTHONPATH to the checkout, no pip config or index from the caller, pip offline."""
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(("PYTHON", "PIP_", "SLIPFRONT_", "VIRTUAL_ENV", "CONDA"))}
    env.update(PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1", PIP_CONFIG_FILE=os.devnull,
               HOME=tmp, XDG_CACHE_HOME=os.path.join(tmp, "cache"),
               SLIPFRONT_CONFIG=os.path.join(tmp, "no-such-config.toml"))
    return env


class OfflineInstall(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="slipfront-install-")
        self.env = clean_env(self.tmp)

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def run_in(self, args, timeout=120):
        return subprocess.run(args, capture_output=True, text=True, env=self.env,
                              timeout=timeout, cwd=self.tmp)

    def make_venv(self, python, name):
        venv = os.path.join(self.tmp, name)
        r = self.run_in([python, "-m", "venv", venv])  # no --system-site-packages
        self.assertEqual(r.returncode, 0, r.stderr)
        return venv

    def install(self, venv, *args):
        r = self.run_in([os.path.join(venv, "bin", "pip"), "install", "--no-index", *args],
                        timeout=300)
        self.assertEqual(r.returncode, 0, f"pip install {' '.join(args)} failed:\n"
                                          f"{r.stdout}\n{r.stderr}")

    def check_venv(self, venv, package_dir):
        python = os.path.join(venv, "bin", "python")
        # The venv really is bare: neither numpy nor requests (else the test proves nothing).
        r = self.run_in([python, "-c", "import numpy"])
        self.assertNotEqual(r.returncode, 0, "numpy importable: not a venv without site packages")
        r = self.run_in([python, "-c", "import requests"])
        self.assertNotEqual(r.returncode, 0, "requests importable")

        r = self.run_in([python, "-c", "import slipfront_client as sf; print(sf.__file__); "
                                       "print(sf.__version__)"])
        self.assertEqual(r.returncode, 0, r.stderr)
        where, version = r.stdout.split()
        self.assertTrue(where.startswith(package_dir), f"{where} is not under {package_dir}")
        self.assertRegex(version, r"^\d+\.\d+\.\d+$")

        script = os.path.join(venv, "bin", "slipfront-client")
        r = self.run_in([script, "--help"])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("usage: slipfront-client", r.stdout)
        self.assertIn("exit codes:", r.stdout)
        r = self.run_in([script, "--version"])
        self.assertEqual(r.stdout.strip(), f"slipfront-client {version}")

        # A command that talks to the server needs requests: it says so, with no traceback.
        r = self.run_in([script, "list", "--server", "http://127.0.0.1:9"])
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("this needs the Python package requests", r.stderr)
        self.assertIn("apt install python3-requests", r.stderr)
        self.assertNotIn("Traceback", r.stderr)
        # One that draws needs matplotlib (the file check comes after it).
        r = self.run_in([script, "plot", "map", os.path.join(self.tmp, "x.h5")])
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertRegex(r.stderr, r"this needs the Python package (matplotlib|numpy|h5py)")
        self.assertNotIn("Traceback", r.stderr)

    def test_install_from_the_checkout(self):
        for python in PYTHONS:
            with self.subTest(python=python):
                venv = self.make_venv(python, "venv")
                self.install(venv, CLIENTS)
                self.check_venv(venv, venv)
                # Nothing written into the checkout (no build/, no *.egg-info).
                leftovers = [n for n in os.listdir(CLIENTS)
                             if n == "build" or n.endswith(".egg-info")]
                self.assertEqual(leftovers, [])
                shutil.rmtree(venv)

    def test_editable_install(self):
        venv = self.make_venv(PYTHONS[0], "venv-editable")
        self.install(venv, "-e", CLIENTS)
        self.check_venv(venv, os.path.join(CLIENTS, "slipfront_client"))


if __name__ == "__main__":
    rest, it = [], iter(sys.argv[1:])
    for arg in it:
        if arg == "--python":
            PYTHONS.append(next(it))
        else:
            rest.append(arg)
    PYTHONS = PYTHONS or [sys.executable]
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)

"""The notebook functions of slipfront_client (docs/python-api.md) stay functions once the
modules behind them are loaded: `sf.download` was the module download.py (shadowing the
function) as soon as anything had downloaded a result.

    /usr/bin/python3 -m unittest discover -s tests/clients -p 'test_unit*.py'
"""

import importlib
import unittest

import harness

assert harness.CLIENTS  # importing harness put clients/ on sys.path
import slipfront_client as sf  # noqa: E402


class PublicNamesTest(unittest.TestCase):
    def test_every_public_name_is_what_its_module_defines(self):
        # Load every module first: a submodule named like a public function would replace it.
        for module in set(sf._PUBLIC.values()) | {"result_download", "commands_jobs"}:
            importlib.import_module(f"slipfront_client.{module}")
        for name, module in sf._PUBLIC.items():
            defined = getattr(importlib.import_module(f"slipfront_client.{module}"), name)
            self.assertIs(getattr(sf, name), defined, name)
        self.assertTrue(callable(sf.download))


if __name__ == "__main__":
    unittest.main()

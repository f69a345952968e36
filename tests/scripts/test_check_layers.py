#!/usr/bin/env python3
"""scripts/check_layers.py on small trees made for the purpose: it passes a tree that keeps the
order, and fails, naming the file and line, on each habit broken (a back-arrow between the
layers or between the server's floors, a handler that includes the store, a server folder that
is no floor, a header without its opening comment); and it passes this repository."""

import os
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CHECKER = os.path.join(ROOT, "scripts", "check_layers.py")


def check(root):
    run = subprocess.run([sys.executable, CHECKER, "--root", root], capture_output=True, text=True)
    return run.returncode, run.stderr


class CheckLayers(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory(prefix="check-layers-")
        self.root = self.dir.name
        self.write("solver/model.hpp", "// The model.\n#pragma once\n")
        self.write("api/run.hpp", '// Running.\n#pragma once\n#include "solver/model.hpp"\n')
        self.write("server/core/job.hpp", '// The job.\n#pragma once\n#include "api/run.hpp"\n')
        self.write("server/db/store.hpp", '// The store.\n#pragma once\n#include "server/core/job.hpp"\n')
        self.write("server/services/service.hpp",
                   '// The service.\n#pragma once\n#include "server/db/store.hpp"\n')
        self.write("server/http/handlers.cpp", '#include "server/services/service.hpp"\n')
        self.write("server/app.cpp", '#include "server/http/handlers.cpp"\n#include <vector>\n')
        self.write("app/main.cpp", '#include "server/app.cpp"\n')

    def tearDown(self):
        self.dir.cleanup()

    def write(self, path, text):
        full = os.path.join(self.root, path)
        os.makedirs(os.path.dirname(full), exist_ok=True)
        with open(full, "w") as f:
            f.write(text)

    def assertFails(self, *expected):
        status, errors = check(self.root)
        self.assertEqual(status, 1, errors)
        for text in expected:
            self.assertIn(text, errors)

    def test_a_tree_in_order_passes(self):
        self.assertEqual(check(self.root), (0, ""))

    def test_a_back_arrow_inside_the_server_fails(self):
        self.write("server/core/job.cpp", '#include "server/core/job.hpp"\n#include "server/db/store.hpp"\n')
        self.assertFails("server/core/job.cpp:2: includes server/db/store.hpp: "
                         "server/core may not include server/db")

    def test_a_back_arrow_between_layers_fails(self):
        self.write("solver/model.cpp", '// x\n#include "api/run.hpp"\n')
        self.assertFails("solver/model.cpp:2: includes api/run.hpp: solver may not include api")

    def test_a_handler_that_includes_the_store_fails(self):
        self.write("server/http/jobs.cpp", '#include "server/db/store.hpp"\n')
        self.assertFails("server/http/jobs.cpp:1: includes server/db/store.hpp",
                         "handlers see services only")

    def test_a_server_folder_that_is_no_floor_fails(self):
        self.write("server/jobs/queue.cpp", '#include "server/core/job.hpp"\n')
        self.assertFails("server/jobs/ is no floor")

    def test_a_header_without_its_opening_comment_fails(self):
        self.write("server/core/bare.hpp", "#pragma once\n// late comment\n")
        self.write("tests/helper.hpp", "\n// after a blank line\n")
        self.assertFails("server/core/bare.hpp:1: a header opens with a comment",
                         "tests/helper.hpp:1: a header opens with a comment")

    def test_this_repository_passes(self):
        status, errors = check(ROOT)
        self.assertEqual(status, 0, errors)


if __name__ == "__main__":
    unittest.main()

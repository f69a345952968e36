#!/usr/bin/env python3
"""scripts/check_doc_refs.py on small git trees made for the purpose: it passes a tree whose
references resolve (a section by its heading, numbered or with more words, several sections
after one file, a quote broken over two comment lines, a path from the root or from the citing
file's folder), and fails, naming the file and line, on a section that is no heading, a doc or
source file that does not exist, and a tracker number; CHANGELOG.md is not read; and it passes
this repository."""

import os
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CHECKER = os.path.join(ROOT, "scripts", "check_doc_refs.py")


# The word the checker looks for, spelt apart so that this file cites no tracker itself.
TRACKER = "iss" + "ue"

def check(root):
    run = subprocess.run([sys.executable, CHECKER, "--root", root], capture_output=True, text=True)
    return run.returncode, run.stdout


class CheckDocRefs(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory(prefix="check-doc-refs-")
        self.root = self.dir.name
        subprocess.run(["git", "init", "-q", self.root], check=True)
        self.write("docs/metrics.md", "# Metrics\n\n## 7. Critical length\n\n"
                   "### `/stations` — every step\n\n```sh\n# Not a heading\n```\n")
        self.write("docs/studies.md", 'The rule (metrics.md "Critical length").\n')
        self.write("solver/law.hpp", "// The law (docs/metrics.md \"Critical length\",\n"
                   "// \"/stations\"); solver/law.cpp.\n")
        self.write("solver/law.cpp", "// Long quotes: docs/metrics.md \"Critical\n// length\".\n")
        self.write("web/app/job.js", "// The list app/presets.js holds; solver/law.hpp.\n")
        self.write("web/app/presets.js", "\n")
        self.write("CHANGELOG.md", "- Fixed (" + TRACKER + " 3; docs/gone.md \"Old\").\n")

    def tearDown(self):
        self.dir.cleanup()

    def write(self, path, text):
        full = os.path.join(self.root, path)
        os.makedirs(os.path.dirname(full), exist_ok=True)
        with open(full, "w") as f:
            f.write(text)
        subprocess.run(["git", "-C", self.root, "add", path], check=True)

    def assertFails(self, *expected):
        status, out = check(self.root)
        self.assertEqual(status, 1, out)
        for text in expected:
            self.assertIn(text, out)

    def test_a_tree_whose_references_resolve_passes(self):
        status, out = check(self.root)
        self.assertEqual(status, 0, out)
        self.assertIn("resolves", out)

    def test_a_section_that_is_no_heading_fails(self):
        self.write("api/a.cpp", '// x\n// (docs/metrics.md "Critical length", "Not a heading")\n')
        self.assertFails('api/a.cpp:2: docs/metrics.md has no section "Not a heading"')

    def test_a_section_of_a_doc_inside_docs_is_read_from_docs(self):
        self.write("docs/web.md", 'See studies.md "Critical length".\n')
        self.assertFails('docs/web.md:1: docs/studies.md has no section "Critical length"')

    def test_a_doc_that_does_not_exist_fails(self):
        self.write("api/b.py", '"""See docs/moved.md "Anything"."""\n')
        self.assertFails("api/b.py:1: docs/moved.md does not exist")

    def test_a_source_file_that_moved_fails(self):
        self.write("docs/x.md", "# X\n\nThe step (solver/nucleation.cpp).\n")
        self.assertFails("docs/x.md:3: solver/nucleation.cpp does not exist")

    def test_a_tracker_number_fails(self):
        self.write("tests/t.py", "# The bound (" + TRACKER.title() + " 22 item 9).\n")
        self.assertFails('tests/t.py:1: cites the tracker ("' + TRACKER.title() + ' 22")')

    def test_this_repository_passes(self):
        status, out = check(ROOT)
        self.assertEqual(status, 0, out)


if __name__ == "__main__":
    unittest.main()

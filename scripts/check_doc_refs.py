#!/usr/bin/python3
"""Check that the references in code and docs resolve, and that none cites the tracker.

Three kinds of reference, in every tracked text file:
  - a section of a doc, written `docs/X.md "Section"` (or `X.md "Section"` and
    `[X.md](X.md) "Section"` inside docs/; more sections may follow: `"A", "B"`): the file
    must exist and each quoted name must be a Markdown heading of it (compared without the
    heading's number, as in "## 7. Cost estimate", backticks, case and runs of spaces; the
    quote may be the heading's beginning: "Endpoints" for "Endpoints (all JSON; ...)");
  - a source file, written as a path from the repository root (`solver/interface/law.hpp`,
    `tests/server/test_http.py`) or from a folder holding the citing file: it must exist (a
    `*` in the name must match a file);
  - a tracker number ("issue" and a number): code and docs must read on their own, so none
    may appear (CHANGELOG.md, the history, is not read).
Prints one line per broken reference (file:line: what) and a one-line summary; exits 1 if
any is broken. Run from anywhere: /usr/bin/python3 scripts/check_doc_refs.py [--root DIR]
(DIR a git work tree; by default this repository).
"""

import argparse
import glob
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TOP_DIRS = ("api", "app", "bench", "clients", "cmake", "deploy", "docs", "examples",
            "presets", "scripts", "server", "solver", "tests", "web")
TEXT_EXTENSIONS = (".cpp", ".hpp", ".h", ".cc", ".py", ".md", ".txt", ".cmake", ".sh",
                   ".js", ".html", ".css", ".json", ".toml", ".cfg", ".ini", ".service",
                   ".conf", ".yml", ".yaml")
# A doc name followed by quoted sections: "docs/X.md", "X.md" or "[X.md](X.md)".
SECTION = r'"[\w/`][^"{}\[\];=]*"'
DOC_REF = re.compile(r'(?<![\w/.-])((?:docs/)?[\w-]+\.md)(?:\]\([\w/.-]+\.md\))?'
                     r'((?:\s*(?:,|and)?\s*%s)+)' % SECTION)
QUOTED = re.compile(r'"([^"]+)"')
# A path from the repository root: a top-level folder, then names, then an extension.
SOURCE_REF = re.compile(r'(?<![\w/.~$-])((?:%s)/[\w.*/-]*\w\.[\w*]+)' % "|".join(TOP_DIRS))
SOURCE_EXTENSIONS = re.compile(r'\.(cpp|hpp|h|cc|py|md|txt|sh|js|html|css|json|cmake|\*)$')
# Files not read: the history (it tells what was true then, in the words of then), this
# script (its docstring shows the forms it checks) and fixtures that name files on purpose.
NOT_CHECKED = ("CHANGELOG.md", "scripts/check_doc_refs.py", "tests/scripts/test_check_layers.py",
               "tests/scripts/test_check_doc_refs.py")
# A file a script writes (a report not yet generated) may be named by that script.
WRITTEN_BY = {("clients/rsf_study.py", "docs/rsf-study.md")}
# Files the build writes (web/CMakeLists.txt, web/presets.cmake), named as the web view's.
BUILT = ("app/presets.json", "app/vendor.json")
# docs/web.md names the web view's files from web/ (app/style.css).
BASES = {"docs/web.md": "web"}
# A name that stands for any: docs/X.md, presets/NAME.json.
PLACEHOLDER = re.compile(r"(^|/)[A-Z]+\.")
TRACKER = re.compile(r'\bissues? [0-9]+\b', re.IGNORECASE)


def tracked_files():
    out = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True,
                         check=True).stdout
    return [f for f in out.splitlines()
            if f.endswith(TEXT_EXTENSIONS) or os.path.basename(f) == "CMakeLists.txt"]


def normalise(title):
    """A heading or quote as compared: without its number ("## 7. Cost estimate"), backticks,
    emphasis, case and runs of spaces."""
    title = re.sub(r"^\s*[0-9]+[a-z]?\.\s+", "", title)
    return " ".join(title.replace("`", "").replace("*", "").split()).lower()


_headings = {}


def headings(path):
    """The headings of a Markdown file (outside code fences), normalised."""
    if path not in _headings:
        found = []
        fenced = False
        with open(os.path.join(ROOT, path), encoding="utf-8") as f:
            for line in f:
                if line.startswith("```"):
                    fenced = not fenced
                elif not fenced and re.match(r"#{1,6} ", line):
                    found.append(normalise(line.lstrip("#")))
        _headings[path] = found
    return _headings[path]


def section_found(doc, section):
    want = normalise(section)
    for heading in headings(doc):
        if heading == want or (heading.startswith(want) and
                               not heading[len(want)].isalnum()):
            return True
    return False


def line_of(text, offset):
    return text.count("\n", 0, offset) + 1


def check_doc_refs(path, text, problems):
    # A quote broken over lines (comment markers included) reads as one.
    flat, where = flatten(text)
    for m in DOC_REF.finditer(flat):
        name = m.group(1)
        if PLACEHOLDER.search(name):
            continue
        if name.startswith("docs/"):
            doc = name
        elif path.startswith("docs/"):
            doc = "docs/" + name
        else:
            continue  # "README.md" and the like outside docs/ name no section of docs/
        line = where[m.start()]
        if not os.path.isfile(os.path.join(ROOT, doc)):
            problems.append("%s:%d: %s does not exist" % (path, line, doc))
            continue
        for section in QUOTED.findall(m.group(2)):
            if not section_found(doc, section):
                problems.append('%s:%d: %s has no section "%s"' % (path, line, doc, section))


def flatten(text):
    """The text with line breaks (and the comment markers after them) read as one space,
    and for each character of the result the line it came from."""
    out, where = [], []
    line = 1
    i = 0
    while i < len(text):
        if text[i] == "\n":
            line += 1
            j = i + 1
            m = re.match(r"[ \t]*(?://+|#+(?= )|\*(?!\*))?[ \t]*", text[j:])
            i = j + (m.end() if m else 0)
            out.append(" ")
            where.append(line)
            continue
        out.append(text[i])
        where.append(line)
        i += 1
    return "".join(out), where


def check_source_refs(path, text, problems):
    for number, line in enumerate(text.splitlines(), 1):
        for m in SOURCE_REF.finditer(line):
            ref = m.group(1).rstrip(".")
            if not SOURCE_EXTENSIONS.search(ref) or PLACEHOLDER.search(ref):
                continue  # not a source file, or a placeholder such as presets/NAME.json
            if (path, ref) in WRITTEN_BY or ref in BUILT:
                continue
            if not source_found(path, ref):
                problems.append("%s:%d: %s does not exist" % (path, number, ref))


def source_found(path, ref):
    """Whether ref names a file: from the repository root, or from a folder holding the
    citing file (web/app/job.js may say app/presets.json)."""
    if path in BASES and glob.glob(os.path.join(ROOT, BASES[path], ref)):
        return True
    folder = os.path.dirname(path)
    while True:
        if glob.glob(os.path.join(ROOT, folder, ref)):
            return True
        if not folder:
            return False
        folder = os.path.dirname(folder)


def check_tracker(path, text, problems):
    for number, line in enumerate(text.splitlines(), 1):
        for m in TRACKER.finditer(line):
            problems.append('%s:%d: cites the tracker ("%s"): say what is meant'
                            % (path, number, m.group(0)))


def main():
    global ROOT
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--root", default=ROOT, help="the work tree to check")
    ROOT = os.path.abspath(parser.parse_args().root)
    problems = []
    files = tracked_files()
    for path in files:
        if path in NOT_CHECKED:
            continue
        try:
            with open(os.path.join(ROOT, path), encoding="utf-8") as f:
                text = f.read()
        except (UnicodeDecodeError, FileNotFoundError):
            continue
        check_doc_refs(path, text, problems)
        check_source_refs(path, text, problems)
        check_tracker(path, text, problems)
    for p in problems:
        print(p)
    if problems:
        print("check_doc_refs: %d broken references in %d files" % (len(problems), len(files)))
        return 1
    print("check_doc_refs: every doc section and source path cited in %d files resolves; "
          "no tracker numbers" % len(files))
    return 0


if __name__ == "__main__":
    sys.exit(main())

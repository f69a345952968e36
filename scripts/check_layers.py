#!/usr/bin/env python3
"""Two habits of the C++ code, checked from the sources alone (no build; docs/architecture.md):

1. No #include runs against the layer order. The floors, from the top down:

       app -> server -> api -> solver, and inside server/:
       server (its top files: the wiring) -> http -> services -> run -> db -> core

   A file may include files of its own floor and of the floors below it, never above. One
   more rule inside the server: http (the handlers) sees the services and the core, not the
   runners (run/) or the storage (db/).

2. Every header opens with a comment saying what it holds: its first line is `// <text>`.

Usage: check_layers.py [--root DIR]   (exit status 1 and one line per finding if any)
"""

import argparse
import os
import re
import sys

# (floor, folder) from the top down. Subfolders belong to their folder's floor (api/study/,
# solver/spectral/, server/run/slurm/, server/db/migrations/), except that every folder of
# server/ must be one of its floors.
FLOORS = [
    ("app", "app/"),
    ("server", "server/"),
    ("server/http", "server/http/"),
    ("server/services", "server/services/"),
    ("server/run", "server/run/"),
    ("server/db", "server/db/"),
    ("server/core", "server/core/"),
    ("api", "api/"),
    ("solver", "solver/"),
]

# Pairs (includer, included) that the order alone would allow, with the reason they are not.
FORBIDDEN = {
    ("server/http", "server/run"): "handlers see services only (docs/architecture.md)",
    ("server/http", "server/db"): "handlers see services only (docs/architecture.md)",
}

# Where headers are looked for: the layers and the code beside them.
HEADER_DIRS = ["app", "server", "api", "solver", "tests", "bench"]
HEADER_SUFFIXES = (".hpp", ".h")
SOURCE_SUFFIXES = (".cpp", ".hpp", ".h", ".cc")

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
RANK = {name: rank for rank, (name, _) in enumerate(FLOORS)}
ORDER_TEXT = " -> ".join(name.split("/")[-1] for name, _ in FLOORS)


def floor_of(path):
    """The floor of a repository-relative path; None outside the layers; the folder itself
    for a folder of server/ that is no floor."""
    if path.startswith("server/") and path.count("/") > 1:
        folder = "server/" + path.split("/")[1] + "/"
        named = [name for name, prefix in FLOORS if prefix == folder]
        return named[0] if named else folder
    for name, prefix in FLOORS:
        if path.startswith(prefix):
            return name
    return None


def source_files(root, top_dirs, suffixes):
    for top in top_dirs:
        for folder, dirs, files in os.walk(os.path.join(root, top)):
            dirs[:] = sorted(d for d in dirs if d != "node_modules" and not d.startswith("."))
            for name in sorted(files):
                if name.endswith(suffixes):
                    yield os.path.relpath(os.path.join(folder, name), root).replace(os.sep, "/")


def resolve(root, includer, included):
    """The repository path an include names (root-relative first, then beside the file)."""
    for candidate in (included, os.path.join(os.path.dirname(includer), included)):
        candidate = os.path.normpath(candidate).replace(os.sep, "/")
        if os.path.isfile(os.path.join(root, candidate)):
            return candidate
    return None


def include_findings(root):
    layer_dirs = sorted({prefix.split("/")[0] for _, prefix in FLOORS})
    unknown = set()
    for path in source_files(root, layer_dirs, SOURCE_SUFFIXES):
        here = floor_of(path)
        if here is not None and here not in RANK:
            if here not in unknown:
                unknown.add(here)
                yield f"{path}: {here} is no floor ({ORDER_TEXT}); a new floor goes in " \
                      "scripts/check_layers.py and docs/architecture.md"
            continue
        with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
            lines = f.readlines()
        for number, line in enumerate(lines, 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            target = resolve(root, path, match.group(1))
            there = floor_of(target) if target else None
            if there is None or there not in RANK:
                continue
            if RANK[there] < RANK[here]:
                yield f"{path}:{number}: includes {target}: {here} may not include {there}, " \
                      f"which is above it ({ORDER_TEXT})"
            elif (here, there) in FORBIDDEN:
                yield f"{path}:{number}: includes {target}: {here} may not include {there}: " \
                      f"{FORBIDDEN[(here, there)]}"


def header_findings(root):
    for path in source_files(root, HEADER_DIRS, HEADER_SUFFIXES):
        with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
            first = f.readline().rstrip("\n")
        if not re.match(r"^// \S", first):
            yield f"{path}:1: a header opens with a comment saying what it holds " \
                  f"('// ...'), not {first!r}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--root", default=os.path.join(os.path.dirname(__file__), ".."))
    root = os.path.abspath(parser.parse_args().root)
    findings = list(include_findings(root)) + list(header_findings(root))
    for finding in findings:
        print("check_layers: " + finding, file=sys.stderr)
    if findings:
        return 1
    print("check_layers: includes follow the layer order; every header says what it holds")
    return 0


if __name__ == "__main__":
    sys.exit(main())

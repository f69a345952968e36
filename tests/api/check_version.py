"""`slipfront version` names the commit the binary was built from.

The version is regenerated on every build (cmake/write_version.cmake), so after a commit
and a rebuild it must equal `git describe` of the source tree. Only the `-dirty` suffix
may differ: editing a file after the build is allowed to leave it out of date.
Usage: check_version.py SLIPFRONT SOURCE_DIR
"""
import re
import subprocess
import sys


def strip_dirty(text):
    return re.sub(r"-dirty$", "", text)


def main(binary, source_dir):
    printed = subprocess.run([binary, "version"], capture_output=True, text=True, check=True)
    match = re.fullmatch(r"slipfront (\S+)\+(\S+)\n", printed.stdout)
    if not match:
        sys.exit(f"unexpected `slipfront version` output: {printed.stdout!r}")
    try:
        described = subprocess.run(["git", "describe", "--always", "--dirty", "--tags"],
                                   cwd=source_dir, capture_output=True, text=True)
        expected = described.stdout.strip() if described.returncode == 0 else "unknown"
    except OSError:  # no git at all (a source tarball): the build wrote "unknown" too
        expected = "unknown"
    if strip_dirty(match.group(2)) != strip_dirty(expected):
        sys.exit(f"binary says {match.group(2)!r}, the source tree is {expected!r}: "
                 "the code version was not regenerated at build time")
    print(f"version {match.group(1)}+{match.group(2)} matches the source tree ({expected})")


if __name__ == "__main__":
    main(*sys.argv[1:3])

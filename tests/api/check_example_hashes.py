#!/usr/bin/python3
"""The examples keep the spec hashes they had before later job fields existed
(tests/api/data/example_spec_hashes.json), and an empty "stations" section, in any of its
spellings, leaves every hash as it is, while stations change it.

usage: check_example_hashes.py SLIPFRONT EXAMPLES_DIR HASHES.json
"""
import json
import os
import re
import subprocess
import sys
import tempfile


def spec_hash(slipfront, job):
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(job, f)
    try:
        done = subprocess.run([slipfront, "validate", f.name], capture_output=True, text=True,
                              timeout=60)
    finally:
        os.remove(f.name)
    found = re.search(r"^spec_sha256: ([0-9a-f]{64})$", done.stdout, re.M)
    if done.returncode != 0 or not found:
        sys.exit(f"validate {json.dumps(job)[:200]}: exit {done.returncode}: {done.stderr}")
    return found.group(1)


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    slipfront, examples, hashes_path = sys.argv[1:4]
    with open(hashes_path) as f:
        expected = json.load(f)["spec_sha256"]
    names = sorted(n for n in os.listdir(examples) if n.endswith(".json"))
    if sorted(expected) != names:
        sys.exit(f"the examples {names} are not those of {hashes_path}: {sorted(expected)}")
    for name in names:
        with open(os.path.join(examples, name)) as f:
            job = json.load(f)
        got = spec_hash(slipfront, job)
        if got != expected[name]:
            sys.exit(f"{name}: spec_sha256 {got}, was {expected[name]}")
        for empty in ({}, {"x1": []}, {"x1": [], "rupture_threshold": 0.01}):
            if spec_hash(slipfront, dict(job, stations=empty)) != got:
                sys.exit(f"{name}: \"stations\": {json.dumps(empty)} changes the spec hash")
        if spec_hash(slipfront, dict(job, stations={"x1": [0]})) == got:
            sys.exit(f"{name}: a station leaves the spec hash as it is")
        print(f"ok {name}: {got}")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Runs one command and checks its exit code and output (the CLI tests of tests/api).

usage: run_cli_case.py --exit N [--stdout REGEX]... [--stderr REGEX]... [--stdin FILE]
                       [--stdout-lacks REGEX]... [--stderr-lacks REGEX]...
                       [--absent PATH]... -- COMMAND ARGS...

Every --stdout/--stderr regular expression must be found in that stream (re.M), and no
--stdout-lacks/--stderr-lacks one; every --absent path (and any PATH.tmp.*) must not exist
after the command.
"""
import argparse
import glob
import os
import re
import subprocess
import sys


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exit", type=int, required=True)
    parser.add_argument("--stdout", action="append", default=[])
    parser.add_argument("--stderr", action="append", default=[])
    parser.add_argument("--stdout-lacks", action="append", default=[])
    parser.add_argument("--stderr-lacks", action="append", default=[])
    parser.add_argument("--stdin")
    parser.add_argument("--absent", action="append", default=[])
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    command = args.command[1:] if args.command[:1] == ["--"] else args.command

    stdin = open(args.stdin, "rb") if args.stdin else subprocess.DEVNULL
    run = subprocess.run(command, stdin=stdin, capture_output=True, text=True, timeout=300)
    problems = []
    if run.returncode != args.exit:
        problems.append(f"exit code {run.returncode}, expected {args.exit}")
    for stream, patterns in (("stdout", args.stdout), ("stderr", args.stderr)):
        text = getattr(run, stream)
        problems += [f"{stream} lacks /{p}/" for p in patterns if not re.search(p, text, re.M)]
    for stream, patterns in (("stdout", args.stdout_lacks), ("stderr", args.stderr_lacks)):
        text = getattr(run, stream)
        problems += [f"{stream} has /{p}/" for p in patterns if re.search(p, text, re.M)]
    for path in args.absent:
        problems += [f"{p} exists" for p in [path] + glob.glob(path + ".tmp.*") if os.path.exists(p)]
    if problems:
        print("command:", " ".join(command))
        print("stdout:", run.stdout)
        print("stderr:", run.stderr)
        sys.exit("\n".join(problems))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""One command line. Every command of `slipfront` answers --help (exit 0,
stdout) with a usage line and an options table that list the same flags, `slipfront help
COMMAND` says the same, every flag the docs name is in the help of its command, and a flag
several commands take is one flag: the same help and the same error everywhere.

usage: cli_help.py SLIPFRONT SOURCE_DIR
"""
import os
import re
import subprocess
import sys

COMMANDS = ["run", "validate", "schema", "presets", "stations", "fit-length", "serve", "check",
            "calibrate"]


def run(*args):
    return subprocess.run(list(args), capture_output=True, text=True, timeout=60,
                          stdin=subprocess.DEVNULL)


def options_table(help_text):
    """{flag: its help row} of the options table (continuation lines joined)."""
    table = help_text.split("\noptions:\n", 1)[1].split("\n\n", 1)[0]
    rows = {}
    flag = None
    for line in table.splitlines():
        m = re.match(r"^  (?:-h, )?(--[a-z-]+)(?: \S+)?\s*(.*)$", line)
        if m:
            flag = m.group(1)
            rows[flag] = m.group(2).strip()
        elif flag:
            rows[flag] += " " + line.strip()
    return rows


def usage_flags(help_text):
    usage = help_text.split("\n\n", 1)[0]
    return re.findall(r"\[(--[a-z-]+)", usage)


def documented_flags(source):
    """{command: flags} named by the docs: the CLI block of docs/api-job-spec.md and the flag
    tables of docs/server.md and docs/cluster.md (serve)."""
    flags = {}
    with open(os.path.join(source, "docs", "api-job-spec.md")) as f:
        block = f.read().split("## The CLI", 1)[1].split("```", 2)[1]
    for line in block.splitlines():
        m = re.match(r"^slipfront ([a-z-]+) ", line)
        if m and m.group(1) in COMMANDS:
            flags.setdefault(m.group(1), set()).update(re.findall(r"\[(--[a-z-]+)", line))
    for page in ("server.md", "cluster.md"):
        with open(os.path.join(source, "docs", page)) as f:
            flags.setdefault("serve", set()).update(re.findall(r"^\| `(--[a-z-]+)` \|", f.read(), re.M))
    return flags


def main(binary, source):
    problems = []
    top = run(binary, "--help")
    if top.returncode != 0 or not re.search(r"^usage:$", top.stdout, re.M):
        sys.exit(f"slipfront --help: exit {top.returncode}\n{top.stdout}{top.stderr}")
    listed = re.search(r"^  slipfront ([a-z|-]+) --help$", top.stdout, re.M)
    if listed is None or listed.group(1).split("|") != COMMANDS:
        problems.append(f"slipfront --help lists {listed and listed.group(1)}, not {COMMANDS}")

    tables = {}
    for command in COMMANDS:
        helped = run(binary, command, "--help")
        if helped.returncode != 0 or not helped.stdout.startswith(f"usage: slipfront {command}"):
            problems.append(f"{command} --help: exit {helped.returncode}, {helped.stdout[:80]!r}"
                            f" {helped.stderr[:200]!r}")
            continue
        if run(binary, "help", command).stdout != helped.stdout:
            problems.append(f"slipfront help {command} differs from {command} --help")
        if run(binary, command, "-h").stdout != helped.stdout:
            problems.append(f"{command} -h differs from {command} --help")
        tables[command] = options_table(helped.stdout)
        in_usage = usage_flags(helped.stdout) + ["--help"]
        if sorted(in_usage) != sorted(tables[command]):
            problems.append(f"{command}: the usage line has {in_usage}, the options table "
                            f"{sorted(tables[command])}")
        if f"  slipfront {command}" not in top.stdout:
            problems.append(f"slipfront --help does not show {command}'s usage")

    for command, flags in documented_flags(source).items():
        missing = sorted(flags - set(tables.get(command, {})))
        if missing:
            problems.append(f"{command} --help lacks {missing}, which the docs name")

    # One flag, one meaning: the same help and the same error wherever it is taken.
    quick = os.path.join(source, "examples", "quick_nd10.json")
    shared = {"--max-memory": (["run", "validate", "serve"], "lots"),
              "--threads": (["run", "validate"], "many")}
    for flag, (commands, bad_value) in shared.items():
        helps = {tables[c][flag].split("; 0 or no flag:")[0] for c in commands if c in tables}
        if len(helps) != 1:
            problems.append(f"{flag} is described {len(helps)} ways: {helps}")
        reasons = set()
        for command in commands:
            job = [] if command == "serve" else [quick]
            failed = run(binary, command, *job, flag, bad_value)
            prefix = f"slipfront {command}: "
            if failed.returncode != 2 or not failed.stderr.startswith(prefix):
                problems.append(f"{command} {flag} {bad_value}: exit {failed.returncode}, "
                                f"{failed.stderr!r}")
            reasons.add(failed.stderr[len(prefix):].replace(f"slipfront {command} --help", "HELP"))
        if len(reasons) != 1:
            problems.append(f"{flag} {bad_value} is refused {len(reasons)} ways: {reasons}")

    if problems:
        sys.exit("\n".join(problems))
    print(f"{len(tables)} commands: help, usage and options agree; shared flags are one")


if __name__ == "__main__":
    main(*sys.argv[1:])

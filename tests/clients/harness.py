"""Shared by the client tests: where the client lives, how to run it, and a real
`slipfront serve` on an ephemeral loopback port with a temporary data dir."""

import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
CLIENTS = os.path.join(REPO, "clients")
SCRIPT = os.path.join(CLIENTS, "slipfront-client")
if CLIENTS not in sys.path:
    sys.path.insert(0, CLIENTS)

# `slipfront serve --port 0` in a temporary data dir; `base` is its URL, stop() ends it and
# removes the directory.
from slipfront_client import local_server  # noqa: E402

Server = local_server.Server

# A tiny job: n_d = 5 on a 12 m x 5 m domain, 3 s simulated; well under a second.
# The probes must lie in the domain [x_min, x_min + width) = [-1, 11).
TINY = {
    "geometry": {"nodes_per_meter": 5, "width": 12, "height": 5, "x_min": -1},
    "time": {"duration": 3},
    "probe": {"arrival_x1": 3, "spectrum_x1": 3},
}

# A job that runs for about 20 s (for cancel tests); always cancelled early.
LONG = {"geometry": {"nodes_per_meter": 50}, "time": {"duration": 16, "stop_on_arrest": False}}


def binary_from_argv(argv):
    """Take `--binary PATH` out of argv (ctest passes it); fall back to $SLIPFRONT_BINARY or
    build/slipfront. Returns (binary, remaining argv)."""
    rest, binary = [], os.environ.get("SLIPFRONT_BINARY")
    it = iter(argv)
    for arg in it:
        if arg == "--binary":
            binary = next(it, None)
        elif arg.startswith("--binary="):
            binary = arg.split("=", 1)[1]
        else:
            rest.append(arg)
    return binary or os.path.join(REPO, "build", "slipfront"), rest


def run_client(*args, server=None, timeout=60, env=None, stdin=None):
    """Run the client script; return the CompletedProcess (text)."""
    e = dict(os.environ)
    e.pop("SLIPFRONT_TOKEN", None)
    if server:
        e["SLIPFRONT_SERVER"] = server
    e.update(env or {})
    return subprocess.run(["/usr/bin/python3", SCRIPT, *args], capture_output=True, text=True,
                          timeout=timeout, env=e, input=stdin)


def wait_until(predicate, timeout=30.0, interval=0.1):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        value = predicate()
        if value:
            return value
        time.sleep(interval)
    raise AssertionError(f"condition not met within {timeout} s")

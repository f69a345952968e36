"""Import of one archive of N runs (one computed, N-1 cache hits: one spec), twice, into a
second server: the second import skips every run (docs/server.md "Export and import"). Times
both POST /imports on loopback.

    /usr/bin/python3 bench/import/import_twice.py [N] [--binary=build/slipfront]
"""
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "tests", "server"))
from server_harness import TINY, Server  # noqa: E402

args = [a for a in sys.argv[1:] if not a.startswith("--binary")]
BINARY = next((a.split("=", 1)[1] for a in sys.argv[1:] if a.startswith("--binary=")),
              "build/slipfront")
N = int(args[0]) if args else 300
src = Server(BINARY, args=["--workers", "1"]).start()
dst = Server(BINARY, args=["--workers", "1"]).start()
try:
    first = src.submit(dict(TINY, name="bench-0")).json()
    ids = [src.wait_status(first["id"], {"succeeded"})["id"]]
    for i in range(1, N):
        r = src.submit(dict(TINY, name=f"bench-{i}")).json()
        assert r["cache"] == "hit"
        ids.append(r["id"])
    archive = src.post("/api/v1/exports", json={"ids": ids}, timeout=300).content
    print(f"{N} runs, archive {len(archive)} bytes")
    for attempt in ("first", "second"):
        t0 = time.monotonic()
        r = dst.post("/api/v1/imports", data=archive, timeout=600)
        dt = time.monotonic() - t0
        body = r.json()
        print(f"{attempt} import: HTTP {r.status_code}, {body['count']} stored, "
              f"{len(body['skipped'])} skipped, {dt:.2f} s")
finally:
    for s in (src, dst):
        s.terminate()
        s.cleanup()

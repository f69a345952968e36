"""What verifying result files costs a download (docs/reliability.md: broken result
files are never served as intact).

Runs one job with a result file of a few MB, then times its first full download (the server
hashes the file on its first use) and 30 one-byte Range downloads (verified already: an open
and an fstat each). Compare two builds by running it with each binary. The hash rate itself
is OpenSSL's: `openssl dgst -sha256 FILE` on a large file gives it.

    /usr/bin/python3 bench/load/result_verification.py --binary build/slipfront
"""

import argparse
import os
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tests", "server"))
from server_harness import TINY, Server  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--binary", default="build/slipfront")
    args = parser.parse_args()
    server = Server(os.path.abspath(args.binary), args=["--workers", "1"]).start()
    try:
        spec = dict(TINY, name="verification-cost", geometry={"nodes_per_meter": 20},
                    time={"duration": 6.0}, output={"interval": 2e-5})
        r = server.submit(spec, params={"fresh": "true"})
        job = server.wait_status(r.json()["id"], {"succeeded"}, timeout=300)
        size = os.path.getsize(os.path.join(server.data_dir, "results", job["id"] + ".h5"))
        url = job["result"]["url"]
        t0 = time.monotonic()
        server.get(url, timeout=60)
        first = time.monotonic() - t0
        times = []
        for _ in range(30):
            t0 = time.monotonic()
            server.get(url, headers={"Range": "bytes=0-0"})
            times.append(time.monotonic() - t0)
        print(f"file {size / 1e6:.1f} MB: first full GET {first * 1000:.0f} ms; one-byte Range "
              f"GET median {statistics.median(times) * 1000:.2f} ms, "
              f"max {max(times) * 1000:.2f} ms")
    finally:
        server.terminate()
        server.cleanup()


if __name__ == "__main__":
    main()

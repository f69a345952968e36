"""Load test of the job server while every worker runs a simulation.

Starts `slipfront serve` (2 workers, temporary data dir, loopback, ephemeral port), keeps
both workers busy with long jobs, then measures:
  1. GET /api/v1/jobs/{id} at a fixed rate (default 500 req/s, open loop: latency counted
     from each request's scheduled time, so a stalled server cannot hide its queueing);
  2. GET /api/v1/jobs/{id} at full speed with wrk (throughput ceiling, latency percentiles);
  3. POST /api/v1/jobs with wrk (identical tiny job: validation + cache hit + committed INSERT).
Writes the figures to RESULTS.md beside this script.

    /usr/bin/python3 bench/load/load_test.py --binary build/slipfront [--rate 500 --seconds 10]
"""

import argparse
import asyncio
import datetime
import json
import os
import platform
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tests", "server"))
from server_harness import TERMINAL, TINY, Server  # noqa: E402

BUSY_JOB = {"name": "load-busy", "geometry": {"nodes_per_meter": 40},
            "time": {"duration": 16.0, "stop_on_arrest": False}}


async def paced_get(host, port, path, rate, seconds, connections):
    request = (f"GET {path} HTTP/1.1\r\nHost: {host}\r\n\r\n").encode()
    queue = asyncio.Queue()
    latencies, errors = [], [0]

    async def worker():
        reader, writer = await asyncio.open_connection(host, port)
        try:
            while True:
                scheduled = await queue.get()
                if scheduled is None:
                    return
                writer.write(request)
                await writer.drain()
                header = await reader.readuntil(b"\r\n\r\n")
                status = int(header[9:12])
                length = int(re.search(rb"(?i)content-length: *(\d+)", header).group(1))
                await reader.readexactly(length)
                latencies.append(time.perf_counter() - scheduled)
                if status != 200:
                    errors[0] += 1
        finally:
            writer.close()

    tasks = [asyncio.create_task(worker()) for _ in range(connections)]
    start = time.perf_counter() + 0.2
    total = int(rate * seconds)
    for i in range(total):
        t = start + i / rate
        delay = t - time.perf_counter()
        if delay > 0:
            await asyncio.sleep(delay)
        queue.put_nowait(t)
    for _ in tasks:
        queue.put_nowait(None)
    await asyncio.wait_for(asyncio.gather(*tasks), timeout=seconds + 30)
    elapsed = time.perf_counter() - start
    return latencies, errors[0], elapsed


def percentile(values, p):
    values = sorted(values)
    k = min(len(values) - 1, max(0, int(round(p / 100.0 * (len(values) - 1)))))
    return values[k]


def run_wrk(url, seconds, connections, script=None):
    cmd = ["wrk", "-t1", f"-c{connections}", f"-d{seconds}s", "--latency", "--timeout", "5s"]
    if script:
        cmd += ["-s", script]
    out = subprocess.run(cmd + [url], capture_output=True, text=True, timeout=seconds + 30)
    text = out.stdout
    rps = float(re.search(r"Requests/sec:\s+([\d.]+)", text).group(1))
    lat = {}
    for p in ("50", "90", "99"):
        m = re.search(rf"\s{p}(?:\.000)?%\s+([\d.]+)(us|ms|s)", text)
        value, unit = float(m.group(1)), m.group(2)
        lat[p] = value / 1000.0 if unit == "us" else value * 1000.0 if unit == "s" else value
    non2xx = re.search(r"Non-2xx or 3xx responses: (\d+)", text)
    return {"rps": rps, "p50_ms": lat["50"], "p90_ms": lat["90"], "p99_ms": lat["99"],
            "non_2xx": int(non2xx.group(1)) if non2xx else 0, "command": " ".join(cmd + [url])}


def machine():
    cpu = "unknown"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return f"{cpu}, {os.cpu_count()} cores, {platform.system()} {platform.release()}"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--binary", required=True)
    ap.add_argument("--rate", type=float, default=500.0)
    ap.add_argument("--seconds", type=float, default=10.0)
    ap.add_argument("--connections", type=int, default=8)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--output", default=os.path.join(HERE, "RESULTS.md"))
    args = ap.parse_args()

    server = Server(os.path.abspath(args.binary),
                    args=["--workers", str(args.workers), "--queue-limit", "100000"]).start()
    try:
        # A finished tiny job: the one polled (its JSON carries spec and metrics: ~2 KB).
        r = server.submit(dict(TINY, name="load"))
        polled = r.json()["id"]
        server.wait_status(polled, TERMINAL)
        busy = [server.submit(BUSY_JOB, params={"fresh": "true"}).json()["id"]
                for _ in range(args.workers * 4)]
        for job_id in busy[: args.workers]:
            server.wait_status(job_id, {"running"}, timeout=30)
        size = len(server.get(f"/api/v1/jobs/{polled}").content)
        host, port = server.base[len("http://"):].split(":")

        def still_busy():
            running = server.get("/metrics").text
            return int(re.search(r"^slipfront_jobs_running (\d+)", running, re.M).group(1))

        latencies, errors, elapsed = asyncio.run(
            paced_get(host, int(port), f"/api/v1/jobs/{polled}", args.rate, args.seconds,
                      args.connections))
        paced_running = still_busy()
        wrk_get = run_wrk(server.url(f"/api/v1/jobs/{polled}"), int(args.seconds), args.connections)
        get_running = still_busy()
        wrk_post = run_wrk(server.url("/api/v1/jobs"), int(args.seconds), 4,
                           os.path.join(HERE, "post_job.lua"))
        post_running = still_busy()
        for job_id in busy:
            server.post(f"/api/v1/jobs/{job_id}/cancel")
    finally:
        server.terminate()
        server.cleanup()

    paced = {"requests": len(latencies), "errors": errors,
             "achieved_rps": len(latencies) / elapsed,
             "p50_ms": 1000 * percentile(latencies, 50), "p90_ms": 1000 * percentile(latencies, 90),
             "p99_ms": 1000 * percentile(latencies, 99), "max_ms": 1000 * max(latencies)}
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    verdict = "met" if paced["p99_ms"] < 50 and paced["achieved_rps"] >= 0.95 * args.rate else "NOT met"
    text = f"""# Load test of the job server

Measured {now} by `bench/load/load_test.py` (merge into docs/performance.md).

- Machine: {machine()}
- Server: `slipfront serve --workers {args.workers}` on 127.0.0.1 (Release build, 2 I/O
  threads); both workers run a simulation (n_d = 40, 16 s simulated, one core each) for
  the whole measurement: jobs running at the end of each phase: {paced_running}, {get_running}, {post_running}.
  The load generator shares the same cores.
- Command: `/usr/bin/python3 bench/load/load_test.py --binary build/slipfront --rate {args.rate:g} --seconds {args.seconds:g}`
- Polled resource: GET /api/v1/jobs/{{id}} of a finished job ({size} bytes of JSON, read from SQLite).

| phase | requests/s | p50 ms | p90 ms | p99 ms | errors |
| --- | ---: | ---: | ---: | ---: | ---: |
| GET /jobs/{{id}}, paced at {args.rate:g}/s, {args.connections} keep-alive connections (open loop) | {paced['achieved_rps']:.0f} | {paced['p50_ms']:.2f} | {paced['p90_ms']:.2f} | {paced['p99_ms']:.2f} | {paced['errors']} |
| GET /jobs/{{id}}, wrk at full speed, {args.connections} connections | {wrk_get['rps']:.0f} | {wrk_get['p50_ms']:.2f} | {wrk_get['p90_ms']:.2f} | {wrk_get['p99_ms']:.2f} | {wrk_get['non_2xx']} |
| POST /jobs (same tiny job: validate, cache hit, committed INSERT), wrk, 4 connections | {wrk_post['rps']:.0f} | {wrk_post['p50_ms']:.2f} | {wrk_post['p90_ms']:.2f} | {wrk_post['p99_ms']:.2f} | {wrk_post['non_2xx']} |

Target (p99 < 50 ms for status polls at {args.rate:g} requests/s with both cores busy): **{verdict}**
(paced max latency {paced['max_ms']:.1f} ms over {paced['requests']} requests).

wrk commands: `{wrk_get['command']}`; `{wrk_post['command']}`.
POST /jobs commits each job with `PRAGMA synchronous = FULL` (an fsync per submission), so
its rate is bounded by the disk's flush latency, not by the CPU.
"""
    with open(args.output, "w") as f:
        f.write(text)
    print(text)
    print(json.dumps({"paced": paced, "wrk_get": wrk_get, "wrk_post": wrk_post}, indent=1))


if __name__ == "__main__":
    main()

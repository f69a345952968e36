"""The SLURM executor against the local one on this machine (docs/cluster.md, "Measured"):

  1. submission overhead: N tiny spectral-BI jobs one after the other (each submitted when
     the previous one has finished), POST → succeeded, per executor;
  2. throughput: a 100-run grid study (10 L x 10 n_d, spectral BI), POST → finished.

The SLURM side is the single-host cluster of tests/server/slurm_cluster.py with this
machine's CPUs; the local side is `--workers` = CPUs. Needs root (the daemons).

    /usr/bin/python3 bench/slurm/executor_overhead.py --binary build/slipfront [--jobs 20]
"""

import argparse
import json
import os
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tests", "server"))
from server_harness import Server, wait_study  # noqa: E402
from slurm_cluster import SingleHostCluster  # noqa: E402

TINY_BI = {"method": "spectral_bi", "time": {"duration": 3}}


def sequential_latency(server, jobs):
    latencies = []
    for i in range(jobs):
        spec = {**TINY_BI, "friction": {"L": 1e-4 * (1 + i * 1e-3)}}
        t0 = time.monotonic()
        r = server.submit({**spec, "fresh": True})
        assert r.status_code == 201, r.text
        job = server.wait_status(r.json()["id"], {"succeeded", "failed", "cancelled"},
                                 timeout=120, interval=0.02)
        assert job["status"] == "succeeded", job
        latencies.append(time.monotonic() - t0)
    return latencies


def sbatch_seconds(cluster, calls=20):
    """Median wall time of one `sbatch` (a held job, cancelled afterwards): the cost of a
    submission on the server's side."""
    import subprocess
    times, ids = [], []
    for _ in range(calls):
        t0 = time.monotonic()
        r = subprocess.run(["sbatch", "--parsable", "--hold", "--mem=10M", "--wrap", "true"],
                           capture_output=True, text=True, env=cluster.env(), timeout=30)
        times.append(time.monotonic() - t0)
        assert r.returncode == 0, r.stderr
        ids.append(r.stdout.strip())
    subprocess.run(["scancel"] + ids, env=cluster.env(), timeout=30)
    return statistics.median(times)


def study_time(server):
    L = [1e-4 * 0.8 ** k for k in range(10)]
    n_d = [5 + k for k in range(10)]
    body = {"base": TINY_BI, "grid": {"L": L, "n_d": n_d}}
    t0 = time.monotonic()
    r = server.post("/api/v1/studies", data=json.dumps(body),
                    headers={"Content-Type": "application/json"})
    assert r.status_code == 201, r.text
    study = wait_study(server, r.json()["id"], timeout=1800)
    elapsed = time.monotonic() - t0
    jobs = server.get("/api/v1/jobs", params={"study_id": study["id"], "limit": 200}).json()
    statuses = [j["status"] for j in jobs["jobs"]]
    assert len(statuses) == 100 and set(statuses) == {"succeeded"}, statuses
    runs = [j["wall_time_s"] for j in jobs["jobs"]]
    return elapsed, statistics.median(runs)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    parser.add_argument("--jobs", type=int, default=20)
    parser.add_argument("--poll", default="2")
    args = parser.parse_args()
    binary = os.path.abspath(args.binary)
    cpus = os.cpu_count() or 1
    report = {"cpus": cpus, "load_before": os.getloadavg()}

    local = Server(binary, args=["--workers", str(cpus)]).start()
    try:
        lat = sequential_latency(local, args.jobs)
        report["local_latency_median_s"] = statistics.median(lat)
        report["local_study_s"], report["local_run_median_s"] = study_time(local)
    finally:
        local.cleanup()

    cluster = SingleHostCluster(cpus=cpus).start()
    os.environ["SLURM_CONF"] = cluster.conf
    try:
        report["sbatch_median_s"] = sbatch_seconds(cluster)
        slurm = Server(binary, args=["--executor", "slurm", "--slurm-poll-interval-s",
                                     args.poll]).start()
        try:
            lat = sequential_latency(slurm, args.jobs)
            report["slurm_latency_median_s"] = statistics.median(lat)
            report["slurm_latency_min_s"] = min(lat)
            report["slurm_latency_max_s"] = max(lat)
            report["slurm_study_s"], report["slurm_run_median_s"] = study_time(slurm)
        finally:
            slurm.cleanup()
    finally:
        cluster.stop()
    report["slurm_poll_interval_s"] = float(args.poll)
    report["load_after"] = os.getloadavg()
    print(json.dumps(report, indent=1))


if __name__ == "__main__":
    main()

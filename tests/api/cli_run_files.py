#!/usr/bin/python3
"""`slipfront run --progress-file P --report-file R` (what the SLURM executor follows): the
progress file is valid JSON with the run's progress, the report holds the printed metrics,
the front and the result file's size and SHA-256; a diverged run's report says so; no
temporary files are left behind.

usage: cli_run_files.py SLIPFRONT JOB.json DIVERGING.json WORK_DIR
"""
import hashlib
import json
import os
import subprocess
import sys


def run(slipfront, job, work_dir, stem):
    progress = os.path.join(work_dir, stem + ".progress.json")
    report = os.path.join(work_dir, stem + ".report.json")
    result = os.path.join(work_dir, stem + ".h5")
    for p in (progress, report, result):
        if os.path.exists(p):
            os.remove(p)
    r = subprocess.run([slipfront, "run", job, "--output", result, "--quiet", "--threads", "1",
                        "--progress-file", progress, "--report-file", report],
                       capture_output=True, text=True, timeout=300)
    return r, progress, report, result


def main():
    slipfront, job, diverging, work_dir = sys.argv[1:5]
    os.makedirs(work_dir, exist_ok=True)

    r, progress, report, result = run(slipfront, job, work_dir, "files")
    if r.returncode != 0:
        sys.exit(f"exit code {r.returncode}\nstderr: {r.stderr}")
    printed = json.loads(r.stdout)
    with open(progress) as f:
        p = json.load(f)
    for key in ("fraction", "time", "duration", "steps", "eta_s"):
        if key not in p:
            sys.exit(f"progress file lacks {key}: {p}")
    if not 0 < p["fraction"] <= 1 or p["steps"] <= 0:
        sys.exit(f"progress file shows no progress: {p}")
    with open(report) as f:
        rep = json.load(f)
    if rep["diverged"] is not False:
        sys.exit("a run that did not diverge reports diverged")
    if rep["metrics"]["outcome"] != printed["outcome"] or rep["metrics"]["steps"] != printed["steps"]:
        sys.exit("the report's metrics are not the printed ones")
    if not isinstance(rep["front"], dict) or "arrival_time" not in rep["front"]:
        sys.exit(f"the report has no front: {rep['front']!r}"[:300])
    with open(result, "rb") as f:
        content = f.read()
    if rep["result_file"]["sha256"] != hashlib.sha256(content).hexdigest() or \
            rep["result_file"]["bytes"] != len(content):
        sys.exit("the report's result_file does not describe the file")
    leftovers = [n for n in os.listdir(work_dir) if n.startswith("files") and n.endswith(".tmp")]
    if leftovers:
        sys.exit(f"temporary files left: {leftovers}")

    r, progress, report, result = run(slipfront, diverging, work_dir, "diverging_files")
    if r.returncode != 3:
        sys.exit(f"a diverging run exited with {r.returncode}, expected 3\n{r.stderr}")
    with open(report) as f:
        rep = json.load(f)
    if rep["diverged"] is not True or not rep["message"] or rep["result_file"] is not None:
        sys.exit(f"a diverged run's report: {json.dumps(rep)[:300]}")
    if os.path.exists(result):
        sys.exit("a diverged run left a result file")


if __name__ == "__main__":
    main()

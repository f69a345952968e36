#!/usr/bin/python3
"""`slipfront run JOB --output RESULT.h5` end to end: exit code, the metrics JSON on stdout,
the result file's size and SHA-256, and its layout (check_result_file.py).

usage: cli_end_to_end.py SLIPFRONT JOB.json WORK_DIR
"""
import hashlib
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_result_file  # noqa: E402


def main():
    slipfront, job_path, work_dir = sys.argv[1:4]
    os.makedirs(work_dir, exist_ok=True)
    result = os.path.join(work_dir, "end_to_end.h5")
    if os.path.exists(result):
        os.remove(result)

    run = subprocess.run([slipfront, "run", job_path, "--output", result], capture_output=True,
                         text=True, timeout=300)
    if run.returncode != 0:
        sys.exit(f"exit code {run.returncode}\nstderr: {run.stderr}")
    lines = run.stdout.strip().splitlines()
    if len(lines) != 1:
        sys.exit(f"stdout holds {len(lines)} lines, expected one JSON object:\n{run.stdout}")
    metrics = json.loads(lines[0])
    for key in check_result_file.METRICS + ["spec_sha256", "result_file"]:
        if key not in metrics:
            sys.exit(f"printed metrics lack {key}")

    with open(result, "rb") as f:
        content = f.read()
    if metrics["result_file"]["sha256"] != hashlib.sha256(content).hexdigest():
        sys.exit("result_file.sha256 is not the SHA-256 of the file")
    if metrics["result_file"]["bytes"] != len(content):
        sys.exit("result_file.bytes is not the file size")

    sys.argv = ["check_result_file.py", result]
    check_result_file.main()
    with open(job_path) as f:
        job = json.load(f)
    import h5py
    with h5py.File(result, "r") as f:
        spec = json.loads(f.attrs["spec"])
        if spec["name"] != job["name"]:
            sys.exit("the stored spec is not the job's")
        if f.attrs["spec_sha256"] != metrics["spec_sha256"]:
            sys.exit("spec_sha256 differs between the file and stdout")
        stored = json.loads(f.attrs["metrics"])
        if stored["outcome"] != metrics["outcome"] or stored["steps"] != metrics["steps"]:
            sys.exit("the stored metrics differ from the printed ones")
    os.remove(result)


if __name__ == "__main__":
    main()

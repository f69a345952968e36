#!/usr/bin/python3
"""SIGINT during `slipfront run`: the run stops, exit code 130, no result file is left.

usage: cli_interrupt.py SLIPFRONT WORK_DIR
"""
import glob
import json
import os
import signal
import subprocess
import sys
import time


def main():
    slipfront, work_dir = sys.argv[1:3]
    os.makedirs(work_dir, exist_ok=True)
    job = os.path.join(work_dir, "interrupt.json")
    result = os.path.join(work_dir, "interrupt.h5")
    with open(job, "w") as f:  # the paper's mesh, long enough to be interrupted
        json.dump({"time": {"duration": 60, "stop_on_arrest": False}}, f)

    process = subprocess.Popen([slipfront, "run", job, "--output", result], text=True,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    deadline = time.monotonic() + 60
    while not glob.glob(result + ".tmp.*"):  # the run has started writing
        if process.poll() is not None or time.monotonic() > deadline:
            sys.exit("the run did not start writing its result file")
        time.sleep(0.05)
    time.sleep(0.5)
    process.send_signal(signal.SIGINT)
    stdout, stderr = process.communicate(timeout=60)

    if process.returncode != 130:
        sys.exit(f"exit code {process.returncode}, expected 130\nstderr: {stderr}")
    if "interrupted" not in stderr:
        sys.exit(f"stderr does not say the run was interrupted: {stderr}")
    if stdout.strip():
        sys.exit(f"an interrupted run printed metrics: {stdout}")
    left = [p for p in [result] + glob.glob(result + ".tmp.*") if os.path.exists(p)]
    if left:
        sys.exit(f"files left behind: {left}")


if __name__ == "__main__":
    main()

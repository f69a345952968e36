#!/usr/bin/python3
"""The paper's question at a bimaterial interface: is there a critical length L_c?

    /usr/bin/python3 clients/bimaterial_study.py                 # full study, own server
    /usr/bin/python3 clients/bimaterial_study.py --server http://127.0.0.1:8080
    /usr/bin/python3 clients/bimaterial_study.py --quick         # CI-short, checks the shape

The `bimaterial_prakash_clifton` preset (two different solids, mu = 0.7, the paper's
Prakash-Clifton law) by the spectral BI method: a convergence study over L through the
studies API (POST /api/v1/studies, the server's mesh-convergence and critical-length rules,
docs/studies.md), and plain Coulomb friction on the same scene under mesh refinement (single
jobs; the same convergence rule applied by the client). Starts `slipfront serve` (niced) in
a temporary data dir unless --server is given, waits, downloads the result files it draws
and writes docs/bimaterial-study.md with figures under docs/figures/bimaterial/.
With --quick the scene is small (200 m, 30 ms) and coarse; the script checks the shape of
the results and exits 1 when a check fails (ctest bimaterial_study_quick).
The work is done by slipfront_client.bimaterial and slipfront_client.bimaterial_report.
"""

import argparse
import os
import shutil
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
REPO = os.path.dirname(HERE)

from slipfront_client import bimaterial as bm  # noqa: E402
from slipfront_client.api import Api  # noqa: E402
from slipfront_client.bimaterial_report import report  # noqa: E402
from slipfront_client.local_server import Server, default_binary, log  # noqa: E402
from slipfront_client.reproduction import loadavg, progress_line, study_wall, wait_study  # noqa: E402


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--server", help="use this server instead of starting one")
    p.add_argument("--token", default=os.environ.get("SLIPFRONT_TOKEN"))
    p.add_argument("--binary", default=None, help="slipfront executable (default build/slipfront)")
    p.add_argument("--workers", type=int, default=min(2, os.cpu_count() or 1))
    p.add_argument("--data-dir", help="server data dir when starting one (default: temporary)")
    p.add_argument("--quick", action="store_true", help="CI-short version with shape checks")
    p.add_argument("--out", help="report path (default docs/bimaterial-study.md; quick: a temp dir)")
    p.add_argument("--format", default="png", help="figure formats, e.g. png,pdf (default png)")
    p.add_argument("--fresh", action="store_true", help="recompute runs the server already has")
    p.add_argument("--timeout", type=float, help="give up waiting after this many seconds")
    p.add_argument("--study-id", help="report on this existing BI study instead of creating one "
                   "(a new build's runs are not reused: the code version is part of the reuse "
                   "key)")
    p.add_argument("--coulomb-ids", help="with --study-id: the Coulomb jobs (comma-separated), in "
                   "the order of the ladder")
    args = p.parse_args(argv)
    if bool(args.study_id) != bool(args.coulomb_ids):
        p.error("--study-id and --coulomb-ids go together")
    if args.quick:
        args.L, args.ladder, args.coulomb = bm.QUICK_L, bm.QUICK_LADDER, bm.QUICK_COULOMB
        args.out = args.out or os.path.join(tempfile.mkdtemp(prefix="slipfront-bistudy-"),
                                            "bimaterial_quick.md")
    else:
        args.L, args.ladder, args.coulomb = bm.FULL_L, bm.FULL_LADDER, bm.FULL_COULOMB
        args.out = args.out or os.path.join(REPO, "docs", "bimaterial-study.md")
    return args


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    server, tmp = None, None
    t_start = time.time()
    try:
        if args.server:
            url = args.server
        else:
            data_dir = args.data_dir or tempfile.mkdtemp(prefix="slipfront-bistudy-data-")
            tmp = None if args.data_dir else data_dir
            os.makedirs(data_dir, exist_ok=True)
            server = Server(args.binary or default_binary(), data_dir,
                            ["--workers", str(args.workers)], startup_timeout=30,
                            preexec_fn=lambda: os.nice(10)).start()
            url = server.url
            log(f"server {url} (pid {server.proc.pid}, data {data_dir}, niced)")
        api = Api(url, token=args.token, timeout=60)
        base = bm.bi_scene(api, args.quick)
        if args.study_id:
            study = api.study(args.study_id)
            coulomb_ids = [i.strip() for i in args.coulomb_ids.split(",") if i.strip()]
            log(f"reporting on study {study['id']} and Coulomb runs {coulomb_ids}")
        else:
            study = api.create_study(bm.study_body(base, args.L, args.ladder, args.quick,
                                                   args.fresh))
            log(f"created study {study['id']}: {progress_line(study)}")
            coulomb_ids = bm.submit_coulomb(api, base, args.coulomb, args.quick, args.fresh)
            log(f"submitted Coulomb runs {coulomb_ids}")
        study = wait_study(api, study["id"], args.timeout)
        coulomb = bm.wait_jobs(api, coulomb_ids, log, timeout=args.timeout)
        wall = time.time() - t_start
        run = {"base": base, "wall": wall, "study_wall": study_wall(study),
               "loadavg": loadavg(), "server": server, "coulomb_jobs": coulomb}
        return report(args, api, study, run)
    finally:
        if server:
            server.stop()
        if tmp:
            shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())

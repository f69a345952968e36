#!/usr/bin/python3
"""Reproduce Kammer et al. 2014 with slipfront's studies API and write a report.

    /usr/bin/python3 clients/reproduce_paper.py                      # full study, own server
    /usr/bin/python3 clients/reproduce_paper.py --n-d-max 80         # cap the FE n_d ladder
    /usr/bin/python3 clients/reproduce_paper.py --server http://127.0.0.1:8080
    /usr/bin/python3 clients/reproduce_paper.py --quick              # CI-short, asserts the maps

Starts `slipfront serve` in a temporary data dir (or uses --server), submits four studies
of the same scene: two convergence studies over the paper's L (POST /api/v1/studies: L x the
n_d ladder, refined by the server until two successive meshes agree or the cap is reached), one
by FE and one by the spectral boundary integral (`"base": {"method": "spectral_bi"}`), an FE
study with the vanishing mesh-scale damping at L = 5e-6 m (where the undamped lattice does not
converge; docs/small-l-study.md), and a BI L search
(`"convergence": {"search": {"from": 3.2e-6, "factor": 2}}`, docs/studies-api.md "L search")
that finds L_c without an L list. It waits with progress, downloads the result
files it draws, and writes a Markdown report (default docs/reproduction.md) that leads with the
answer by each method (BI from the L search, FE from its convergence study), the paper's L_c
beside ours with the measured reason they differ, then every figure of the paper (Fig. 2-6)
from our runs under <report dir>/figures/reproduction/.

Every number in the report is computed from the studies' runs. With --quick the scene is
small and coarse, and the script checks the shape of both maps; it exits 1 when a check
fails (tests/reproduction runs it under ctest). The work is done by
slipfront_client.reproduction (studies, report) and slipfront_client.report (verdicts,
cross-method table).
"""

import argparse
import os
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
REPO = os.path.dirname(HERE)

from slipfront_client.api import Api  # noqa: E402
from slipfront_client.local_server import Server, default_binary, log  # noqa: E402
from slipfront_client.reproduction import (  # noqa: E402
    BI_LADDER, FULL_L, FULL_LADDER, QUICK_BASE, QUICK_BI_LADDER, QUICK_L, QUICK_LADDER,
    DAMPED, QUICK_SEARCH, SEARCH, damped_body, loadavg, progress_line, report, search_body,
    study_body, study_wall, wait_study)


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--server", help="use this server instead of starting one")
    p.add_argument("--token", default=os.environ.get("SLIPFRONT_TOKEN"))
    p.add_argument("--binary", default=None, help="slipfront executable (default build/slipfront)")
    p.add_argument("--workers", type=int, default=min(2, os.cpu_count() or 1))
    p.add_argument("--data-dir", help="server data dir when starting one (default: temporary)")
    p.add_argument("--study-id", help="report on this existing FE study instead of creating one")
    p.add_argument("--bi-study-id", help="report on this existing BI study instead of creating one")
    p.add_argument("--search-study-id", help="report on this existing BI L search instead of "
                   "creating one")
    p.add_argument("--damped-study-id", help="report on this existing FE study with the mesh "
                   "damping instead of creating one")
    p.add_argument("--no-damped", action="store_true",
                   help="leave out the FE study with the mesh damping at L = 5e-6 m")
    p.add_argument("--quick", action="store_true", help="CI-short version with shape checks")
    p.add_argument("--n-d-max", type=int, default=None, help="cap of the FE n_d ladder (default 160; quick 10)")
    p.add_argument("--bi-n-d-max", type=int, default=None,
                   help="cap of the BI n_d ladder (default 320; quick 40)")
    p.add_argument("--out", help="report path (default docs/reproduction.md; quick: a temp dir)")
    p.add_argument("--format", default="png", help="figure formats, e.g. png,pdf (default png)")
    p.add_argument("--fresh", action="store_true", help="recompute runs the server already has")
    p.add_argument("--timeout", type=float, help="give up waiting after this many seconds")
    args = p.parse_args(argv)
    if args.quick:
        args.L, args.ladder, args.base, args.search = QUICK_L, QUICK_LADDER, QUICK_BASE, QUICK_SEARCH
        args.damped = None
        args.n_d_max = args.n_d_max or max(QUICK_LADDER)
        args.bi_ladder, args.bi_n_d_max = QUICK_BI_LADDER, args.bi_n_d_max or max(QUICK_BI_LADDER)
        args.out = args.out or os.path.join(tempfile.mkdtemp(prefix="slipfront-repro-"),
                                            "reproduction_quick.md")
    else:
        args.L, args.ladder, args.base, args.search = FULL_L, FULL_LADDER, None, SEARCH
        args.damped = None if args.no_damped else DAMPED
        args.n_d_max = args.n_d_max or 160
        args.bi_ladder, args.bi_n_d_max = BI_LADDER, args.bi_n_d_max or max(BI_LADDER)
        args.out = args.out or os.path.join(REPO, "docs", "reproduction.md")
    return args


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    args.script_t0 = time.time()
    args.load_at_start = loadavg()
    server = None
    tmp = None
    try:
        if args.server:
            url = args.server
        else:
            binary = args.binary or default_binary()
            data_dir = args.data_dir or tempfile.mkdtemp(prefix="slipfront-repro-data-")
            tmp = data_dir if not args.data_dir else None
            os.makedirs(data_dir, exist_ok=True)
            server = Server(binary, data_dir, ["--workers", str(args.workers)],
                            startup_timeout=30).start()
            url = server.url
            log(f"server {url} (pid {server.proc.pid}, data {data_dir})")
        api = Api(url, token=args.token, timeout=60)
        studies = {}
        kinds = [("fe", args.study_id), ("spectral_bi", args.bi_study_id),
                 ("search", args.search_study_id)]
        if args.damped or args.damped_study_id:
            kinds.append(("damped", args.damped_study_id))
        for kind, given in kinds:
            if given:
                studies[kind] = api.study(given)
                log(f"using {kind} study {given}")
            else:
                body = (search_body(args) if kind == "search" else damped_body(args)
                        if kind == "damped" else study_body(args, kind))
                studies[kind] = api.create_study(body)
                log(f"created {kind} study {studies[kind]['id']}: {progress_line(studies[kind])}")
        t0 = time.time()
        for kind, s in studies.items():
            studies[kind] = wait_study(api, s["id"], args.timeout)
        wall = time.time() - t0
        # again: the cross-method table holds every run of both scenes, now all final
        study, bi_study = api.study(studies["fe"]["id"]), studies["spectral_bi"]
        wall = study_wall(study) or wall  # the server's created_at -> finished_at
        args.loadavg = ("not recorded (report written later with --study-id)" if args.study_id
                        else loadavg())
        speed = [api.get_json(f"/api/v1/studies/{s['id']}/speed-accuracy") for s in (study, bi_study)]
        bi = {"study": bi_study, "speed_acc": speed[1], "wall": study_wall(bi_study)}
        search = {"study": studies["search"], "wall": study_wall(studies["search"])}
        damped = ({"study": studies["damped"], "wall": study_wall(studies["damped"])}
                  if "damped" in studies else None)
        return report(args, api, study, speed[0], wall, server, bi, search, damped)
    finally:
        if server:
            server.stop()
        if tmp and args.quick:
            import shutil
            shutil.rmtree(tmp, ignore_errors=True)



if __name__ == "__main__":
    sys.exit(main())

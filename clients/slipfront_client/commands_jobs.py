"""The job subcommands: submit, validate, status, list, cancel, download, presets, stations."""

import argparse
import os
import sys

from . import jobspec
from .result_download import download_result, write_xdmf
from .errors import ServerError, UsageError
from .output import job_summary, log, print_json, provenance_lines, table, warning_lines
from .waiting import FINAL, ProgressBar, check_outcome, wait_for_job


def add_parsers(sub, common):
    p = sub.add_parser("submit", parents=[common], help="submit a job (optionally wait and download)",
                       description="Submit a job file (or '-' for stdin; none = the paper's scene) "
                                   "with inline overrides. Prints the job id.")
    p.add_argument("job", nargs="?", help="job JSON file, or - for stdin")
    p.add_argument("--preset", metavar="NAME",
                   help="start from a preset (`presets` lists them); the file and --set change it")
    p.add_argument("--set", dest="overrides", action="append", default=[], metavar="PATH=VALUE",
                   help="override a field, e.g. --set friction.L=1e-5 (value is JSON or text)")
    p.add_argument("--name", help="job name")
    p.add_argument("--tag", dest="tags", action="append", default=[], help="add a tag (repeatable)")
    p.add_argument("--fresh", action="store_true", help="run even if an identical job succeeded")
    p.add_argument("--priority", type=int, help="integer in [-100, 100]; higher runs first")
    p.add_argument("--wait", action="store_true", help="wait for the job, with a progress bar")
    p.add_argument("--wait-timeout", type=float, help="give up waiting after this many seconds")
    p.add_argument("--download", metavar="FILE", help="after --wait, download the result here")
    p.add_argument("--xdmf", action="store_true",
                   help="with --download, also write the XDMF sidecar (ParaView, VisIt) beside "
                        "it, as FILE.xdmf")
    p.add_argument("--dry-run", action="store_true", help="print the job JSON and do not submit")
    p.set_defaults(func=cmd_submit)

    p = sub.add_parser("validate", parents=[common], help="check a job without submitting it",
                       description="Check a job as submit would (the same file, --preset and "
                                   "--set): prints ok, its spec hash, the cost estimate, the "
                                   "values it takes that it did not give (derived or default, "
                                   "with where they come from) and its warnings; exit 2 with "
                                   "the errors of an invalid job.")
    p.add_argument("job", nargs="?", help="job JSON file, or - for stdin")
    p.add_argument("--preset", metavar="NAME", help="start from a preset")
    p.add_argument("--set", dest="overrides", action="append", default=[], metavar="PATH=VALUE",
                   help="override a field, e.g. --set friction.L=1e-5")
    p.set_defaults(func=cmd_validate)

    p = sub.add_parser("presets", parents=[common], help="list the presets, or show one",
                       description="The presets a job may start from: the field's standard "
                                   "scenes and the example jobs (docs/presets.md). With NAME, "
                                   "its job as JSON (save it, edit it, submit it), or submit "
                                   "--preset NAME directly.")
    p.add_argument("name", nargs="?")
    p.set_defaults(func=cmd_presets)

    p = sub.add_parser("status", parents=[common], help="show a job")
    p.add_argument("id")
    p.add_argument("--fields", help="comma-separated top-level fields (JSON output)")
    p.add_argument("--exit-status", action="store_true",
                   help="exit 3 if the job failed or diverged, 4 if it was cancelled")
    p.set_defaults(func=cmd_status)

    p = sub.add_parser("list", parents=[common], help="list, search and export runs",
                       description="List jobs (newest first, or --sort), filtered by --where "
                                   "conditions on any spec field, metric or job column "
                                   "(docs/server.md, 'Searching and exporting runs').",
                       epilog="examples:\n"
                              "  slipfront-client list --where 'friction.L<1e-4' "
                              "--where 'metrics.arrest_position>12'\n"
                              "  slipfront-client list --where method=spectral_bi "
                              "--sort -friction.L --format csv > runs.csv",
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--where", action="append", default=[], metavar="CONDITION",
                   help="FIELD OP VALUE, e.g. friction.L<1e-4, metrics.outcome=arrested, "
                        "tag=paper, created_at>=2026-11-01 (repeatable: all must hold)")
    p.add_argument("--sort", metavar="FIELDS",
                   help="comma-separated fields, '-' for descending, e.g. -metrics.arrest_position")
    p.add_argument("--format", choices=["table", "json", "csv", "ndjson"], default=None,
                   help="table (default), json (the jobs as the API shows them), csv or ndjson "
                        "(the flat run table: spec fields, metrics, cost, convergence status)")
    p.add_argument("--status", help="comma-separated: queued,running,succeeded,failed,cancelled")
    p.add_argument("--tag")
    p.add_argument("--name")
    p.add_argument("--outcome", choices=["arrested", "running_at_end", "no_rupture", "diverged"])
    p.add_argument("--submitted-by")
    p.add_argument("--spec-sha256")
    p.add_argument("--archived", choices=["exclude", "include", "only"],
                   help="archived runs: left out (exclude, the default), with the others, or only")
    p.add_argument("--L-min", type=float)
    p.add_argument("--L-max", type=float)
    p.add_argument("--n-d-min", type=float)
    p.add_argument("--n-d-max", type=float)
    p.add_argument("--limit", type=int, help="at most this many jobs (0 = all; default 50 for "
                   "table and json, all for csv and ndjson); pages are followed as needed")
    p.add_argument("--fields", help="comma-separated fields to show (server-side projection)")
    p.set_defaults(func=cmd_list)

    p = sub.add_parser("cancel", parents=[common], help="cancel a job")
    p.add_argument("id")
    p.add_argument("--wait", action="store_true", help="wait until the job has stopped")
    p.set_defaults(func=cmd_cancel)

    p = sub.add_parser("download", parents=[common], help="download a job's HDF5 result")
    p.add_argument("id")
    p.add_argument("-o", "--output", help="file to write (default ID.h5)")
    p.add_argument("--xdmf", action="store_true",
                   help="also write the XDMF sidecar (ParaView, VisIt) beside it, as FILE.xdmf")
    p.set_defaults(func=cmd_download)

    p = sub.add_parser("stations", parents=[common], help="a job's on-fault stations",
                       description="The rupture time at each station of a finished job, or with "
                                   "--csv every step in the long format (station_x1,time,slip,"
                                   "slip_rate,shear_traction,normal_traction; units in the "
                                   "header comments).")
    p.add_argument("id")
    p.add_argument("--csv", metavar="FILE", help="write the CSV to FILE ('-': standard output)")
    p.set_defaults(func=cmd_stations)


def cmd_submit(args, ctx):
    if args.download and not args.wait:
        raise UsageError("--download needs --wait")
    if args.xdmf and not args.download:
        raise UsageError("--xdmf needs --download FILE")
    if args.priority is not None and not -100 <= args.priority <= 100:
        raise UsageError("--priority must be an integer in [-100, 100]")
    spec = jobspec.build_job(args.job, args.overrides, args.name, args.tags, preset=args.preset)
    if args.dry_run:
        print_json(spec)
        return 0
    api = ctx.api()
    job = api.submit(spec, fresh=True if args.fresh else None, priority=args.priority)
    if not args.quiet:
        cache = job.get("cache")
        log(f"submitted job {job['id']} ({job['status']}"
            + (f", cache {cache}" if cache and cache != "miss" else "") + ")")
        for line in warning_lines(job.get("warnings"), indent="warning: "):
            log(line)
    if not args.wait:
        print_json(job) if args.json else print(job["id"])
        return 0
    bar = ProgressBar(enabled=not args.quiet)
    try:
        job = wait_for_job(api, job["id"], progress=bar, timeout=args.wait_timeout)
    finally:
        bar.close()
    print_json(job) if args.json else print(job["id"])
    if not args.quiet and not args.json:
        for line in job_summary(job)[1:]:
            log(line)
    check_outcome(job)
    if args.download:
        path, sha, _ = download_result(api, job["id"], args.download, log=log)
        if not args.quiet:
            log(f"result written to {path} (sha256 {sha})")
        if args.xdmf:
            xdmf = write_xdmf(api, job["id"], path)
            if not args.quiet:
                log(f"XDMF sidecar written to {xdmf}")
    return 0



def cmd_validate(args, ctx):
    spec = jobspec.build_job(args.job, args.overrides, None, [], preset=args.preset)
    answer = ctx.api().validate(spec)
    if args.json:
        print_json(answer)
        return 0 if answer.get("valid", True) else 2
    if answer.get("valid") is False:
        for e in answer.get("errors") or []:
            print(f"{e.get('pointer') or '(body)'}: {e.get('reason')}", file=sys.stderr)
        return 2
    print("ok")
    print(f"spec_sha256: {answer.get('spec_sha256')}")
    for line in estimate_lines(answer.get("estimate")):
        print(line)
    taken = provenance_lines(answer.get("provenance"), indent="  ")
    if taken:
        print("values not given:")
        for line in taken:
            print(line)
    for line in warning_lines(answer.get("warnings"), indent="warning: "):
        print(line)
    return 0


def estimate_lines(estimate):
    """The cost estimate before a run (docs/performance.md "Cost estimate"), a line each."""
    if not estimate:
        return []
    return [f"{key}: {value}" for key, value in estimate.items() if not isinstance(value, dict)]


def cmd_presets(args, ctx):
    api = ctx.api()
    if args.name:
        preset = api.preset(args.name)
        print_json(preset if args.json else preset["spec"])
        return 0
    presets = api.presets()
    if args.json:
        print_json(presets)
    else:
        for line in table(presets, [("name", lambda p: p["name"]), ("origin", lambda p: p["origin"]),
                                    ("title", lambda p: p["title"])]):
            print(line)
    return 0


def cmd_status(args, ctx):
    fields = [f for f in (args.fields or "").split(",") if f]
    job = ctx.api().job(args.id, fields=fields or None)
    if args.json or fields:
        print_json(job)
    else:
        print("\n".join(job_summary(job)))
    if args.exit_status and job.get("status") in FINAL:
        check_outcome(job)
    return 0


def wall_time_shown(job):
    """A run's wall time; a cache hit ran nothing (its own is 0 s): the original run's solver
    wall time (its metrics), marked cached."""
    if not job.get("cached_from"):
        return job.get("wall_time_s")
    original = (job.get("metrics") or {}).get("wall_time_s")
    return f"{original:.4g} (cached)" if isinstance(original, (int, float)) else "cached"


LIST_COLUMNS = [
    ("id", lambda j: j.get("id")),
    ("status", lambda j: j.get("status")),
    ("L", lambda j: ((j.get("spec") or {}).get("friction") or {}).get("L")),
    ("n_d", lambda j: ((j.get("spec") or {}).get("geometry") or {}).get("nodes_per_meter")),
    ("outcome", lambda j: (j.get("metrics") or {}).get("outcome")),
    ("wall_s", lambda j: wall_time_shown(j)),
    ("name", lambda j: j.get("name")),
]


def cmd_list(args, ctx):
    fmt = args.format or ("json" if args.json else "table")
    if args.limit is None:
        args.limit = 0 if fmt in ("csv", "ndjson") else 50
    if args.limit < 0:
        raise UsageError("--limit must be >= 0")
    filters = {"status": args.status, "tag": args.tag, "name": args.name, "outcome": args.outcome,
               "submitted_by": args.submitted_by, "spec_sha256": args.spec_sha256,
               "L_min": args.L_min, "L_max": args.L_max, "n_d_min": args.n_d_min,
               "n_d_max": args.n_d_max, "archived": args.archived}
    fields = [f for f in (args.fields or "").split(",") if f]
    if fields:
        filters["fields"] = ",".join(fields)
    filters = {k: (repr(v) if isinstance(v, float) else v) for k, v in filters.items()}
    if args.where:
        filters["where"] = ";".join(args.where)
    filters["sort"] = args.sort
    if fmt in ("csv", "ndjson"):
        if fields:
            raise UsageError(f"--fields applies to the table and json formats, not {fmt}")
        sys.stdout.write(ctx.api().export_runs(fmt, filters, limit=args.limit or None))
        return 0
    jobs = list(ctx.api().list_jobs(filters, limit=args.limit or None))
    if fmt == "json":
        print_json(jobs)
    elif fields:
        cols = [("id", lambda j: j.get("id"))] + [(f, (lambda j, f=f: j.get(f))) for f in fields
                                                   if f != "id"]
        print("\n".join(table(jobs, cols)))
    else:
        print("\n".join(table(jobs, LIST_COLUMNS)))
    return 0


def cmd_cancel(args, ctx):
    api = ctx.api()
    try:
        job = api.cancel(args.id)
    except ServerError as e:
        if e.status == 409:
            raise ServerError(f"job {args.id} has already finished; nothing to cancel") from e
        raise
    if args.wait and job.get("status") not in FINAL:
        job = wait_for_job(api, args.id)
    print_json(job) if args.json else print(f"{job['id']} {job['status']}"
                                            + ("" if job["status"] in FINAL else " (cancel requested)"))
    return 0


def cmd_download(args, ctx):
    output = args.output or f"{args.id}.h5"
    if os.path.isdir(output):
        output = os.path.join(output, f"{args.id}.h5")
    path, sha, fetched = download_result(ctx.api(), args.id, output, log=log)
    if not args.quiet:
        log(f"{path}: {'up to date' if fetched == 0 else f'{fetched} bytes fetched'}, sha256 {sha}")
    print(path)
    if args.xdmf:
        print(write_xdmf(ctx.api(), args.id, path))
    return 0


def cmd_stations(args, ctx):
    from . import stations  # here: numpy only for the commands that need it

    text = ctx.api().stations_csv(args.id)
    if args.csv == "-":
        sys.stdout.write(text)
        return 0
    if args.csv:
        with open(args.csv, "w", encoding="utf-8") as f:
            f.write(text)
        if not args.quiet:
            log(f"stations of job {args.id} written to {args.csv}")
        return 0
    st = stations.parse_stations_csv(text)
    rows = stations.summary_rows(st)
    if args.json:
        print_json({"rupture_threshold": st.rupture_threshold, "stations": rows})
        return 0
    print(f"rupture threshold {st.rupture_threshold:g} m/s, {st.time.size} steps")
    print("\n".join(table(rows, [("station_x1 [m]", lambda r: r["x1"]),
                                  ("rupture_time [s]", lambda r: r["rupture_time"]),
                                  ("peak slip rate [m/s]", lambda r: r["peak_slip_rate"]),
                                  ("peak time [s]", lambda r: r["peak_time"]),
                                  ("final slip [m]", lambda r: r["final_slip"])])))
    return 0

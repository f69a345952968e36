"""`study create|wait|show|cancel`: a grid of runs over L × n_d (docs/studies-api.md)."""

from . import commands_keep, jobspec, methods, studies
from .errors import ServerError, UsageError
from .output import log, print_json, table


def floats(text, option):
    try:
        values = [float(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise UsageError(f"{option} {text!r}: expected comma-separated numbers") from None
    if not values:
        raise UsageError(f"{option}: give at least one value")
    return values


def add_parsers(sub, common):
    p = sub.add_parser("study", parents=[common],
                       help="studies: create, list, wait, show, cancel, tag, note, archive, "
                            "restore, export, delete",
                       description="Studies over L x n_d (needs the server's studies API).")
    ssub = p.add_subparsers(
        dest="study_command",
        metavar="create|list|wait|show|cancel|tag|note|archive|restore|export|delete",
        required=True)

    ls = ssub.add_parser("list", parents=[common], help="list studies, newest first")
    ls.add_argument("--status", choices=["running", "finished", "cancelled"])
    ls.add_argument("--archived", choices=["exclude", "include", "only"],
                    help="archived studies: left out (default), listed too, or alone")
    ls.add_argument("--limit", type=int, default=50, help="at most this many (0 = all)")
    ls.set_defaults(func=cmd_list)

    c = ssub.add_parser("create", parents=[common], help="create a study")
    c.add_argument("file", nargs="?", help="a study JSON sent as is (else build one from --base)")
    c.add_argument("--base", help="base job JSON file (default: the paper's scene)")
    c.add_argument("--set", dest="overrides", action="append", default=[], metavar="PATH=VALUE")
    c.add_argument("--L", dest="lengths", help="comma-separated L values [m]")
    c.add_argument("--n-d", dest="densities", help="comma-separated n_d values [nodes/m] "
                   "(with --convergence: the ladder, default 10,20,40,80,160)")
    c.add_argument("--convergence", action="store_true",
                   help="a convergence study: the server refines each L along the n_d ladder "
                        "until two successive meshes agree (instead of the full grid)")
    c.add_argument("--n-d-max", type=float, help="with --convergence or --search: cap of the ladder")
    c.add_argument("--search", action="store_true",
                   help="an L search instead of --L: down from --from by --factor until the "
                        "critical-length rule is met, the mesh cap or --floor stops it")
    c.add_argument("--from", dest="search_from", type=float, help="with --search: the first L [m] "
                   "(default 5e-5)")
    c.add_argument("--factor", type=float, help="with --search: each next L = L / factor (default 2)")
    c.add_argument("--floor", type=float, help="with --search: the smallest L tried "
                   "(default from / 1000)")
    c.add_argument("--confirm", type=int, help="with --search: how many smallest L must agree "
                   "(default 2)")
    c.add_argument("--name")
    c.add_argument("--tag", dest="tags", action="append", default=[])
    c.add_argument("--wait", action="store_true", help="wait for every run, then summarise")
    c.add_argument("--wait-timeout", type=float)
    c.set_defaults(func=cmd_create)

    w = ssub.add_parser("wait", parents=[common], help="wait for a study, then summarise")
    w.add_argument("id")
    w.add_argument("--wait-timeout", type=float)
    w.set_defaults(func=cmd_wait)

    s = ssub.add_parser("show", parents=[common], help="summarise a study")
    s.add_argument("id")
    s.set_defaults(func=cmd_show)

    x = ssub.add_parser("cancel", parents=[common],
                        help="cancel a study: no further runs, its queued/running runs cancelled")
    x.add_argument("id")
    x.set_defaults(func=cmd_cancel)

    t = ssub.add_parser("tag", parents=[common],
                        help="add or remove a study's tags; --set replaces them all")
    commands_keep.add_tag_arguments(t)
    t.set_defaults(func=cmd_tag)

    n = ssub.add_parser("note", parents=[common], help="set a study's note ('' clears it)")
    n.add_argument("id")
    n.add_argument("text", help="the note; '-' reads it from standard input")
    n.set_defaults(func=cmd_note)

    a = ssub.add_parser("archive", parents=[common],
                        help="hide a study from `study list` (never deleted)")
    a.add_argument("id")
    a.set_defaults(func=cmd_archive, archived=True)

    r = ssub.add_parser("restore", parents=[common], help="list an archived study again")
    r.add_argument("id")
    r.set_defaults(func=cmd_archive, archived=False)

    e = ssub.add_parser("export", parents=[common],
                        help="write a study that is over with its runs as one tar archive "
                             "(import-runs stores it on a server)")
    e.add_argument("id")
    e.add_argument("-o", "--output", required=True, help="the .tar file to write")
    e.set_defaults(func=cmd_export)

    d = ssub.add_parser("delete", parents=[common],
                        help="delete a study that is over with its runs and their result files "
                             "(owner only)")
    d.add_argument("id")
    d.add_argument("--yes", action="store_true", help="do not ask for confirmation")
    d.set_defaults(func=cmd_delete)


def add_accuracy_parser(sub, common):
    a = sub.add_parser(
        "accuracy", parents=[common], help="one metric at a stated accuracy",
        description="Ask the server for one metric within a relative error: it picks the method "
                    "and the first mesh, refines until its error estimate meets the target and "
                    "answers with the value, the estimate and the cost (docs/studies-api.md "
                    "\"Accuracy target\").")
    a.add_argument("metric", help="arrest_position, propagation_distance, arrival_time_at_probe, "
                                  "max_slip_velocity, rupture_speed.max or rupture_speed.mean")
    a.add_argument("tolerance", help="the relative error allowed: 0.005 or 0.5%%")
    a.add_argument("--L", dest="length", type=float, help="friction.L [m] (default 5e-5)")
    a.add_argument("--method", choices=["auto", *methods.names()],
                   help="default auto: spectral_bi where it applies")
    a.add_argument("--base", help="base job JSON file (default: the paper's scene)")
    a.add_argument("--set", dest="overrides", action="append", default=[], metavar="PATH=VALUE")
    a.add_argument("--n-d", dest="densities", help="the mesh ladder (default 10,20,40,80,160)")
    a.add_argument("--n-d-max", type=float, help="cap of the ladder")
    a.add_argument("--name")
    a.add_argument("--tag", dest="tags", action="append", default=[])
    a.add_argument("--no-wait", dest="wait", action="store_false",
                   help="print the study id and return (default: wait and summarise)")
    a.add_argument("--wait-timeout", type=float)
    a.set_defaults(func=cmd_accuracy)


def tolerance_value(text):
    """0.005 or "0.5%" -> 0.005."""
    try:
        return float(text[:-1]) / 100.0 if text.endswith("%") else float(text)
    except ValueError:
        raise UsageError(f"tolerance {text!r}: expected a number or a percentage") from None


def accuracy_body(args):
    base = jobspec.build_job(args.base, args.overrides)
    dropped = studies.drop_study_fields(base)
    if dropped and not args.quiet:
        log(f"base: {', '.join(dropped)} removed (set --L; the service chooses n_d)")
    accuracy = {"metric": args.metric, "tolerance": tolerance_value(args.tolerance)}
    for key, value in (("L", args.length), ("method", args.method), ("n_d_max", args.n_d_max)):
        if value is not None:
            accuracy[key] = value
    if args.densities:
        accuracy["n_d"] = floats(args.densities, "--n-d")
    body = {"accuracy": accuracy, "tags": args.tags}
    if base:
        body["base"] = base
    if args.name:
        body["name"] = args.name
    return body


def cmd_accuracy(args, ctx):
    api = ctx.api()
    study = studies.create(api, accuracy_body(args))
    if not args.quiet:
        log(f"created study {study.get('id')}")
    if args.wait:
        study = studies.wait(api, study["id"], args.wait_timeout, None if args.quiet else log)
        show(study, args)
    else:
        print_json(study) if args.json else print(study.get("id"))
    return 0


def build_body(args):
    if args.file:
        if args.base or args.lengths or args.densities:
            raise UsageError("give either a study FILE or --base/--L/--n-d, not both")
        body = jobspec.load_job(args.file)
        return body
    search_options = {"from": args.search_from, "factor": args.factor, "floor": args.floor,
                      "confirm": args.confirm}
    if any(v is not None for v in search_options.values()) and not args.search:
        raise UsageError("--from, --factor, --floor and --confirm need --search")
    if args.search:
        if args.lengths:
            raise UsageError("give either --L or --search, not both")
        base = jobspec.build_job(args.base, args.overrides)
        studies.drop_study_fields(base)
        densities = (floats(args.densities, "--n-d") if args.densities else [10, 20, 40, 80, 160])
        return studies.study_request(base, [], densities, args.name, args.tags,
                                     n_d_max=args.n_d_max,
                                     search={k: v for k, v in search_options.items()
                                             if v is not None})
    if args.n_d_max is not None and not args.convergence:
        raise UsageError("--n-d-max needs --convergence")
    if not args.lengths or not (args.densities or args.convergence):
        raise UsageError("study create needs --L and --n-d (or --convergence, or a study FILE)")
    base = jobspec.build_job(args.base, args.overrides)
    dropped = studies.drop_study_fields(base)
    if dropped and not args.quiet:
        log(f"base: {', '.join(dropped)} removed (the study sets them from --L/--n-d)")
    densities = (floats(args.densities, "--n-d") if args.densities else [10, 20, 40, 80, 160])
    return studies.study_request(base, floats(args.lengths, "--L"), densities, args.name,
                                 args.tags, convergence=args.convergence, n_d_max=args.n_d_max)


def show(study, args):
    if args.json:
        print_json(study)
    else:
        print("\n".join(studies.summary_lines(study)))


def cmd_create(args, ctx):
    api = ctx.api()
    study = studies.create(api, build_body(args))
    study_id = study.get("id")
    if not args.quiet:
        log(f"created study {study_id}")
    if args.wait and study_id:
        study = studies.wait(api, study_id, args.wait_timeout, None if args.quiet else log)
        show(study, args)
    else:
        print_json(study) if args.json else print(study_id)
    return 0


STUDY_COLUMNS = [
    ("id", lambda s: s.get("id")),
    ("status", lambda s: s.get("status")),
    ("kind", lambda s: s.get("kind")),
    ("method", lambda s: s.get("method")),
    ("runs", lambda s: "{}/{}".format((s.get("progress") or {}).get("done", "?"),
                                      (s.get("progress") or {}).get("total", "?"))),
    ("L_c", lambda s: s.get("L_c")),
    ("created_at", lambda s: s.get("created_at")),
    ("name", lambda s: s.get("name")),
]


def cmd_list(args, ctx):
    if args.limit < 0:
        raise UsageError("--limit must be >= 0")
    found = list(ctx.api().list_studies(status=args.status, limit=args.limit or None,
                                        archived=args.archived))
    if args.json:
        print_json(found)
    else:
        print("\n".join(table(found, STUDY_COLUMNS)))
    return 0


def cmd_wait(args, ctx):
    study = studies.wait(ctx.api(), args.id, args.wait_timeout, None if args.quiet else log)
    show(study, args)
    return 0


def cmd_show(args, ctx):
    show(studies.get(ctx.api(), args.id), args)
    return 0


def cmd_cancel(args, ctx):
    try:
        study = ctx.api().cancel_study(args.id)
    except ServerError as e:
        if e.status == 409:
            raise ServerError(f"study {args.id} is not running; nothing to cancel",
                              status=e.status, problem=e.problem) from e
        raise
    if args.json:
        print_json(study)
    else:
        cancelled = study.get("cancelled_jobs", [])
        stopping = study.get("cancel_requested_jobs", [])
        print(f"{study['id']} {study['status']}: {len(cancelled)} queued run(s) cancelled, "
              f"{len(stopping)} running run(s) stopping")
    return 0


def show_kept(study, args):
    if args.json:
        print_json(study)
    else:
        archived = " (archived)" if study.get("archived_at") else ""
        print(f"{study['id']} tags={','.join(study.get('tags') or []) or '-'}{archived}")
        if study.get("note"):
            print(study["note"])
    return 0


def cmd_tag(args, ctx):
    change = commands_keep.tag_change(args)
    api = ctx.api()
    if change is None:  # nothing to change: the tags as they are
        return show_kept(api.study(args.id), args)
    return show_kept(api.patch_study(args.id, change), args)


def cmd_note(args, ctx):
    text = args.text
    if text == "-":
        import sys
        text = sys.stdin.read()
    return show_kept(ctx.api().patch_study(args.id, {"note": text}), args)


def cmd_archive(args, ctx):
    return show_kept(ctx.api().archive_study(args.id, args.archived), args)


def cmd_delete(args, ctx):
    if not args.yes:
        try:
            answer = input(f"delete study {args.id} with its runs and their result files? [y/N] ")
        except EOFError:  # no terminal and no --yes: not deleted
            answer = ""
        if answer.strip().lower() not in ("y", "yes"):
            raise UsageError("not deleted")
    result = ctx.api().delete_study(args.id)
    if args.json:
        print_json(result)
    else:
        print(f"{result['id']} deleted with {len(result['deleted_jobs'])} run(s) and "
              f"{result['results_deleted']} result file(s)")
    return 0


def cmd_export(args, ctx):
    import os
    if os.path.exists(args.output):
        raise UsageError(f"{args.output} exists; choose another --output or remove it")
    partial = args.output + ".part"
    try:
        size = ctx.api().export_study(args.id, partial)
        os.replace(partial, args.output)
    finally:
        if os.path.exists(partial):
            os.remove(partial)
    if not args.quiet:
        log(f"{args.output}: {size} bytes")
    print(args.output)
    return 0

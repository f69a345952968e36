"""Keep, annotate, share (docs/server.md): tag, note, archive, restore, delete, export-runs,
import-runs."""

import os

from .errors import UsageError
from .output import log, print_json


def add_parsers(sub, common):
    p = sub.add_parser("tag", parents=[common],
                       help="add or remove a job's tags (after submission); --set replaces "
                            "them all")
    add_tag_arguments(p)
    p.set_defaults(func=cmd_tag)

    p = sub.add_parser("note", parents=[common], help="set a job's note ('' clears it)")
    p.add_argument("id")
    p.add_argument("text", help="the note; '-' reads it from standard input")
    p.set_defaults(func=cmd_note)

    p = sub.add_parser("archive", parents=[common],
                       help="hide a job from listings and exports (never deleted)")
    p.add_argument("id")
    p.set_defaults(func=cmd_archive, archived=True)

    p = sub.add_parser("restore", parents=[common], help="list an archived job again")
    p.add_argument("id")
    p.set_defaults(func=cmd_archive, archived=False)

    p = sub.add_parser("delete", parents=[common],
                       help="delete a finished job and its result file (owner only)")
    p.add_argument("id")
    p.add_argument("--yes", action="store_true", help="do not ask for confirmation")
    p.set_defaults(func=cmd_delete)

    p = sub.add_parser("export-runs", parents=[common],
                       help="write finished runs as one tar archive (specs, metrics, "
                            "provenance, result files, SHA-256 manifest)")
    p.add_argument("ids", nargs="*", help="job ids (or use the filters below)")
    p.add_argument("--study-id", help="the runs of a study")
    p.add_argument("--tag")
    p.add_argument("--where", action="append", default=[], metavar="CONDITION",
                   help="as for `list --where` (repeatable)")
    p.add_argument("--archived", choices=["exclude", "include", "only"])
    p.add_argument("-o", "--output", required=True, help="the .tar file to write")
    p.set_defaults(func=cmd_export)

    p = sub.add_parser("import-runs", parents=[common],
                       help="store the runs of an export archive on this server (every "
                            "checksum verified first)")
    p.add_argument("archive", help="a .tar file written by export-runs")
    p.add_argument("--again", action="store_true",
                   help="store the runs already on the server too, under new ids (a copy of "
                        "your own); by default they are skipped")
    p.set_defaults(func=cmd_import)


def add_tag_arguments(p):
    """The arguments of `tag` (and `study tag`): ID, tags to add, --add/--remove, --set."""
    p.add_argument("id")
    p.add_argument("tags", nargs="*", help="tags to add (the others are kept)")
    p.add_argument("--add", action="extend", nargs="+", default=[], metavar="TAG",
                   help="tags to add (repeatable)")
    p.add_argument("--remove", action="extend", nargs="+", default=[], metavar="TAG",
                   help="tags to remove (repeatable; one not there is no error)")
    p.add_argument("--set", nargs="*", metavar="TAG",
                   help="replace every tag by these (none: clear them)")


def tag_change(args):
    """The PATCH body's tag members for `tag` (and `study tag`); None when nothing changes."""
    if args.set is not None:
        if args.tags or args.add or args.remove:
            raise UsageError("--set replaces every tag: give the tags after it, without other "
                             "tags, --add or --remove")
        return {"tags": list(args.set)}
    add = list(args.tags) + list(args.add)
    if not add and not args.remove:
        return None
    change = {}
    if add:
        change["tags_add"] = add
    if args.remove:
        change["tags_remove"] = list(args.remove)
    return change


def show(job, args):
    if args.json:
        print_json(job)
    else:
        archived = " (archived)" if job.get("archived_at") else ""
        print(f"{job['id']} tags={','.join(job.get('tags') or []) or '-'}{archived}")
        if job.get("note"):
            print(job["note"])
    return 0


def cmd_tag(args, ctx):
    change = tag_change(args)
    api = ctx.api()
    if change is None:  # nothing to change: the tags as they are
        return show(api.job(args.id), args)
    return show(api.patch_job(args.id, change), args)


def cmd_note(args, ctx):
    text = args.text
    if text == "-":
        import sys
        text = sys.stdin.read()
    return show(ctx.api().annotate(args.id, note=text), args)


def cmd_archive(args, ctx):
    return show(ctx.api().archive(args.id, args.archived), args)


def cmd_delete(args, ctx):
    if not args.yes:
        try:
            answer = input(f"delete job {args.id} and its result file? [y/N] ")
        except EOFError:  # no terminal and no --yes: not deleted
            answer = ""
        if answer.strip().lower() not in ("y", "yes"):
            raise UsageError("not deleted")
    result = ctx.api().delete(args.id)
    if args.json:
        print_json(result)
    else:
        print(f"{result['id']} deleted" + (" with its result file" if result["result_deleted"]
                                            else ""))
    return 0


def cmd_export(args, ctx):
    if os.path.exists(args.output):
        raise UsageError(f"{args.output} exists; choose another --output or remove it")
    filters = {}
    if args.study_id:
        filters["study_id"] = args.study_id
    if args.tag:
        filters["tag"] = args.tag
    if args.where:
        filters["where"] = ";".join(args.where)
    if args.archived:
        filters["archived"] = args.archived
    if bool(args.ids) == bool(filters):
        raise UsageError("give job ids, or filters (--study-id, --tag, --where), not both")
    partial = args.output + ".part"
    try:
        size = ctx.api().export_archive(partial, ids=args.ids, filters=filters)
        os.replace(partial, args.output)
    finally:
        if os.path.exists(partial):
            os.remove(partial)
    if not args.quiet:
        log(f"{args.output}: {size} bytes")
    print(args.output)
    return 0


def cmd_import(args, ctx):
    if not os.path.isfile(args.archive):
        raise UsageError(f"{args.archive}: no such file")
    result = ctx.api().import_archive(args.archive, again=args.again)
    if args.json:
        print_json(result)
    else:
        for run in result["imported"]:
            same = "" if run["id"] == run["original_id"] else f" (was {run['original_id']})"
            print(f"{run['id']}{same}")
        for run in result.get("skipped", []):
            print(f"{run['id']} skipped, already here: {run['detail']}")
        study = result.get("study")
        if study:
            print(f"study {study['id']} " + ("skipped, already here" if study["skipped"]
                                             else "imported with its runs"))
    return 0

"""`compare ID ID ... [--study SID] [--where COND] [--out DIR]`: runs side by side — the table
of their fields with the differences marked (compare.py), and their figures overlaid as PNG
(or --format): |V|(t) at the first run's stations, else its probes (--x1), V_r(x1), the slip fronts and one
parameter against one metric (--x, --y). Drawn from the server's JSON (/front, /fields): no
result file is downloaded."""

import argparse
import importlib
import os

from . import compare, methods
from .errors import UsageError
from .output import log, print_json

MAX_RUNS = 12  # overlaid curves beyond this read as noise (the web view's limit too)
FIGURES = ("velocity", "speed", "front", "scatter")


def add_parsers(sub, common):
    p = sub.add_parser(
        "compare", parents=[common], help="runs side by side: fields, differences, figures",
        description="Compare runs: a table of their run fields, parameters (the spec) and "
                    "metrics with the fields that differ marked '*', and their figures "
                    "overlaid, each run named by its method, law, n_d and every other "
                    "parameter that differs; FE solid lines and circles, BI dashed lines and "
                    "squares. Runs by id, by study, by search (docs/server.md).",
        epilog="examples:\n"
               "  slipfront-client compare 31bbda07... 1650a1e6... --out figs\n"
               "  slipfront-client compare --study STUDY_ID --x friction.L --y arrest_position\n"
               "  slipfront-client compare --where 'friction.L=1e-4' --where n_d=10 --all",
        formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("ids", nargs="*", metavar="ID", help="job ids")
    p.add_argument("--study", action="append", default=[], metavar="SID",
                   help="every run of this study (repeatable)")
    p.add_argument("--where", action="append", default=[], metavar="CONDITION",
                   help="the runs of a search, e.g. method=spectral_bi (repeatable: all must hold)")
    p.add_argument("--all", action="store_true",
                   help="show every field (default: those that differ and the key ones)")
    p.add_argument("-o", "--out", "--output-dir", dest="out", default=".",
                   help="directory for the figures (default .)")
    p.add_argument("--stem", default="compare",
                   help="file names STEM_velocity.png, STEM_speed.png, ... (default compare)")
    p.add_argument("--format", default="png", help="comma-separated: png,pdf,svg (default png)")
    p.add_argument("--force", action="store_true", help="replace figures that exist")
    p.add_argument("--no-figures", action="store_true", help="print the table only")
    p.add_argument("--x1", help="positions of the |V|(t) panels [m] (default: the first run's "
                                "stations, else its probes)")
    p.add_argument("--x", dest="scatter_x", metavar="PARAM",
                   help="the scatter's parameter, a spec field (default: the one that differs)")
    p.add_argument("--y", dest="scatter_y", metavar="METRIC",
                   help="the scatter's metric (default propagation_distance)")
    p.set_defaults(func=cmd_compare)


def _by_scene(job):
    spec = job.get("spec") or {}
    return (job.get("method") or spec.get("method") or methods.default(),
            -((spec.get("friction") or {}).get("L") or 0),
            (spec.get("geometry") or {}).get("nodes_per_meter") or 0)


def pick_jobs(api, ids, studies, where):
    """The jobs named by ids (in that order), then those of the studies and of the search
    (by method, L large to small, n_d), each once."""
    jobs = [api.job(i) for i in ids]
    found = []
    for sid in studies:
        found += api.list_jobs({"study_id": sid}, limit=1000)
    if where:
        found += api.list_jobs({"where": ";".join(where)}, limit=1000)
    jobs += sorted(found, key=_by_scene)
    unique = {}
    for job in jobs:
        unique.setdefault(job["id"], job)
    return list(unique.values())


def _field(rows, name, group, text):
    """The row of the scatter's axis named `name` (with or without its 'spec.'/'metrics.')."""
    key = name.split(".", 1)[1] if name.startswith(f"{group}.") else name
    candidates = compare.plottable(rows, group, text=text)
    for row in candidates:
        if row["key"] == key:
            return row
    known = ", ".join(r["key"] for r in candidates[:12])
    raise UsageError(f"{'--x' if group == 'spec' else '--y'} {name!r}: no "
                     f"{'parameter' if group == 'spec' else 'numeric metric'} of that name in "
                     f"these runs (for example {known})")


def figure_paths(args, formats):
    """The files the figures go to; UsageError naming those that exist (unless --force)."""
    paths = {name: [os.path.join(args.out, f"{args.stem}_{name}.{fmt}") for fmt in formats]
             for name in FIGURES}
    existing = [p for ps in paths.values() for p in ps if os.path.exists(p)]
    if existing and not args.force:
        raise UsageError(f"{len(existing)} figure file(s) exist; --force replaces them, or "
                         f"choose --out or --stem", existing)
    return paths


def draw_figures(api, jobs, labels, axes, args, paths, quiet):
    """The four figures of the runs, written to `paths`; `axes`: the scatter's two rows."""
    common = importlib.import_module(".plots.common", __package__)
    velocity = importlib.import_module(".plots.velocity", __package__)
    speed = importlib.import_module(".plots.speed", __package__)
    compared = importlib.import_module(".plots.compare", __package__)
    results = importlib.import_module(".results", __package__)
    x_row, y_row = axes
    done = [i for i, j in enumerate(jobs) if j.get("status") == "succeeded" and j.get("result")]
    positions = (_floats(args.x1, "--x1") if args.x1 else
                 [x for x, _ in results.job_positions(jobs[done[0]].get("spec") or {})] if done
                 else [])
    if len(done) < len(jobs) and not quiet:
        left = [j["id"][:8] for i, j in enumerate(jobs) if i not in done]
        log(f"no result, so no curves, for: {', '.join(left)}")
    runs = [results.result_from_json(api, jobs[i], positions) for i in done]
    run_labels = [labels[i] for i in done]
    figures = {
        "velocity": velocity.plot_velocity(runs, positions, labels=run_labels)[0],
        "speed": speed.plot_speed(runs, labels=run_labels)[0],
        "front": compared.plot_fronts(runs, run_labels)[0],
        "scatter": compared.plot_scatter(
            jobs, labels,
            [_plain(v) for v in x_row["values"]], [_plain(v) for v in y_row["values"]],
            x_row["key"], f"metrics.{y_row['key']}")[0],
    }
    written = []
    for name, fig in figures.items():
        out_dir = os.path.dirname(paths[name][0]) or "."
        formats = [os.path.splitext(p)[1][1:] for p in paths[name]]
        written += common.save_figure(fig, out_dir, f"{args.stem}_{name}", formats)
    return written


def _plain(value):
    return None if value is compare.MISSING else value


def _floats(text, option):
    try:
        return [float(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise UsageError(f"{option} {text!r}: expected comma-separated numbers") from None


def cmd_compare(args, ctx):
    if not (args.ids or args.study or args.where):
        raise UsageError("compare: give job ids, --study SID or --where CONDITION")
    api = ctx.api()
    jobs = pick_jobs(api, args.ids, args.study, args.where)
    if len(jobs) < 2:
        raise UsageError(f"compare: {len(jobs)} run(s) found; at least two are needed")
    if len(jobs) > MAX_RUNS:
        if not args.quiet:
            log(f"{len(jobs)} runs: comparing the first {MAX_RUNS} (narrow the search for others)")
        jobs = jobs[:MAX_RUNS]
    rows = compare.compare_rows(jobs)
    labels = compare.compare_labels(jobs, rows)
    x_default, y_default = compare.scatter_defaults(rows)
    axes = (_field(rows, args.scatter_x or x_default, "spec", True),
            _field(rows, args.scatter_y or y_default, "metrics", False))
    paths = None
    if not args.no_figures:
        common = importlib.import_module(".plots.common", __package__)
        paths = figure_paths(args, common.parse_formats(args.format))
    written = draw_figures(api, jobs, labels, axes, args, paths, args.quiet) if paths else []
    if args.json:
        print_json({**compare.as_json(jobs, rows, labels), "figures": written})
        return 0
    for line in compare.table_lines(jobs, rows, labels, show_all=args.all):
        print(line)
    if written:
        print()
        for path in written:
            print(f"wrote {path}")
    return 0

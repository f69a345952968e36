"""`plot map|velocity|speed|convergence|filter|cost`: the paper's figures from our runs.

Sources are HDF5 result files or job ids (downloaded into the cache, see results.py);
the convergence map and the cost chart also read JSON files, and can ask the server.
"""

import json
import os

import importlib

from . import analysis, methods
from .errors import UsageError
from .output import log


def plots(name):
    """A plot module, imported on first use (matplotlib and h5py are slow to import and
    the other subcommands do not need them)."""
    return importlib.import_module(f".plots.{name}", __package__)


def results():
    return importlib.import_module(".results", __package__)


def floats(text, option):
    try:
        return [float(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise UsageError(f"{option} {text!r}: expected comma-separated numbers") from None


def add_parsers(sub, common_parent):
    import argparse

    out = argparse.ArgumentParser(add_help=False)
    out.add_argument("-o", "--output-dir", default=".", help="directory for the figures (default .)")
    out.add_argument("--format", default="png", help="comma-separated: png,pdf,svg (default png)")
    out.add_argument("--stem", help="file name without extension (default: the figure's name, "
                                    "and for map the figure's name and each source's: "
                                    "map_SOURCE)")
    out.add_argument("--force", action="store_true",
                     help="replace figure files that exist (default: refuse, naming them)")
    out.add_argument("--title", help="figure title")
    out.add_argument("--cache-dir", help="where job ids are downloaded (default ~/.cache/slipfront)")
    parents = [common_parent, out]

    p = sub.add_parser("plot", parents=[common_parent], help="draw the paper's figures")
    psub = p.add_subparsers(dest="plot_command", required=True,
                            metavar="map|velocity|speed|convergence|filter|cost")

    m = psub.add_parser("map", parents=parents, help="(a) |V| in the x1-t plane with the front")
    m.add_argument("sources", nargs="+", help="HDF5 files or job ids (one figure each)")
    m.add_argument("--probes", help="x1 of the vertical lines (default: each run's stations, "
                                    "else its probes)")
    m.add_argument("--whole", action="store_true",
                   help="the whole domain and run (default: zoom to the event)")
    m.add_argument("--vmax", type=float, help="upper end of the grey scale [m/s]")
    m.add_argument("--scale", choices=["log", "linear"], default="log",
                   help="colour scale: log over four decades below the peak (default), or "
                        "linear clipped at the 99th percentile (or --vmax)")
    m.set_defaults(func=cmd_map)

    v = psub.add_parser("velocity", parents=parents, help="(b) |V| against time at given x1")
    v.add_argument("sources", nargs="+")
    v.add_argument("--x1", help="positions [m] (default: the first run's stations, else its "
                                "probes)")
    v.add_argument("--no-zoom", action="store_true",
                   help="show the whole run (default: zoom each panel to the signal)")
    v.set_defaults(func=cmd_velocity)

    s = psub.add_parser("speed", parents=parents, help="(c) rupture speed against x1")
    s.add_argument("sources", nargs="+")
    s.add_argument("--front-json", action="store_true",
                   help="sources are job ids: read GET /jobs/{id}/front, download nothing")
    s.set_defaults(func=cmd_speed)

    c = psub.add_parser("convergence", parents=parents, help="(d) convergence map in the L-n_d plane")
    c.add_argument("sources", nargs="*", help="HDF5 files or job ids: statuses computed here")
    c.add_argument("--map", dest="map_file", help="JSON: list of {L, n_d, status} or the server's map")
    c.add_argument("--from-server", action="store_true",
                   help="GET /api/v1/convergence-map (with --study ID or --scene HASH)")
    c.add_argument("--study", help="the map of this study's scene (with --from-server; alone: "
                                   "the study's own map, GET /studies/{id})")
    c.add_argument("--scene", help="with --from-server: the map of this scene hash")
    c.add_argument("--tag", help="the server's jobs with this tag: statuses computed here")
    c.add_argument("--critical-length", type=float, help="draw L_c as a horizontal line")
    c.set_defaults(func=cmd_convergence)

    f = psub.add_parser("filter", parents=parents, help="(e) A/A0 against frequency (eq. 6)")
    f.add_argument("sources", nargs="*", help="runs whose L and stable_dt to use")
    f.add_argument("--L", dest="lengths", help="comma-separated L [m] (default: runs' L, or the paper's)")
    f.add_argument("--n-d", dest="densities", help="comma-separated n_d (f_max from dx/c_p)")
    f.add_argument("--v-star", type=float, default=1e-4, help="V* [m/s] (default 1e-4)")
    f.add_argument("--slip-velocity", type=float, default=3e-3,
                   help="|V| in eq. 6 [m/s] (default 3e-3, the paper's peak at x1 = 6 m)")
    f.set_defaults(func=cmd_filter)

    k = psub.add_parser("cost", parents=parents,
                        help="(f) error against wall time and memory, per L and method")
    k.add_argument("sources", nargs="*", help="HDF5 files or job ids (error vs finest n_d per L)")
    k.add_argument("--data", help="JSON list of {L, n_d, wall_time_s, error}")
    k.add_argument("--tag", help="the server's jobs with this tag (error vs finest n_d per L)")
    k.add_argument("--study", action="append", default=[], metavar="ID",
                   help="a study's GET /studies/{id}/speed-accuracy (error: the larger of the "
                        "distance and arrival-time errors vs its L's reference): both methods "
                        "from its across_methods when the server gives it, else the study's own "
                        "runs; repeat (--study FE_ID --study BI_ID) to draw several studies")
    k.set_defaults(func=cmd_cost)


def output_paths(args, stems):
    """The files the figures `stems` will be written to. Without --force, refuses (before any
    work) when one of them exists: a figure is never replaced silently."""
    common = plots("common")
    paths = [os.path.join(args.output_dir, f"{stem}.{fmt}")
             for stem in stems for fmt in common.parse_formats(args.format)]
    existing = [p for p in paths if os.path.exists(p)]
    if existing and not args.force:
        raise UsageError(f"{', '.join(existing)} exist{'s' if len(existing) == 1 else ''}: "
                         "give --force to replace, or choose --stem or --output-dir")
    return paths


def _save(fig, args, stem):
    common = plots("common")
    paths = common.save_figure(fig, args.output_dir, args.stem or stem,
                               common.parse_formats(args.format))
    for path in paths:
        print(path)
    return paths


def _results(args, ctx):
    return results().load_results(args.sources, ctx.api, args.cache_dir,
                                None if args.quiet else log)


def _load_json(path):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except OSError as e:
        raise UsageError(f"cannot read {path}: {e.strerror}") from e
    except json.JSONDecodeError as e:
        raise UsageError(f"{path}: not valid JSON: {e.msg} (line {e.lineno})") from e


def _server_rows(ctx, tag):
    jobs = ctx.api().list_jobs({"tag": tag}, limit=None)
    return [results().row_from_job(j) for j in jobs]


def map_stems(args):
    """One figure per source: map_SOURCE (SOURCE: the file's name without its extension, or
    the job id); --stem names a single figure, or replaces "map" for several."""
    if args.stem and len(args.sources) == 1:
        return [args.stem]
    stems = [f"{args.stem or 'map'}_{os.path.splitext(os.path.basename(s))[0]}"
             for s in args.sources]
    if len(set(stems)) != len(stems):
        raise UsageError("plot map: two sources have the same name; draw them one at a time "
                         "with --stem")
    return stems


def cmd_map(args, ctx):
    common = plots("common")
    formats = common.parse_formats(args.format)
    probes = floats(args.probes, "--probes") if args.probes else None
    stems = map_stems(args)
    output_paths(args, stems)
    for stem, result in zip(stems, _results(args, ctx)):
        fig, _ = plots("slip_map").plot_map(result, probes, args.vmax, args.title, args.scale,
                                            whole=args.whole)
        for path in common.save_figure(fig, args.output_dir, stem, formats):
            print(path)
    return 0


def cmd_velocity(args, ctx):
    output_paths(args, [args.stem or "velocity"])
    positions = floats(args.x1, "--x1") if args.x1 else None
    fig, _ = plots("velocity").plot_velocity(_results(args, ctx), positions, args.title,
                                             zoom=not args.no_zoom)
    _save(fig, args, "velocity")
    return 0


def cmd_speed(args, ctx):
    output_paths(args, [args.stem or "speed"])
    if args.front_json:
        runs = [results().result_from_front(ctx.api(), source) for source in args.sources]
    else:
        runs = _results(args, ctx)
    fig, _ = plots("speed").plot_speed(runs, args.title)
    _save(fig, args, "speed")
    return 0


def convergence_points(args, ctx):
    """[{L, n_d, status}] from whichever input the command line names."""
    inputs = sum(bool(x) for x in (args.sources, args.map_file, args.from_server or args.study,
                                   args.tag))
    if inputs != 1:
        raise UsageError("plot convergence: give exactly one of SOURCES, --map, "
                         "--from-server (--study ID | --scene HASH), --study, --tag")
    convergence = plots("convergence")
    if args.map_file:
        return convergence.points_from_json(_load_json(args.map_file), args.map_file)
    if args.from_server:
        if bool(args.study) == bool(args.scene):
            raise UsageError("plot convergence --from-server: give --study ID or --scene HASH")
        params = {"study": args.study} if args.study else {"scene": args.scene}
        doc = ctx.api().convergence_map(params)
        return convergence.points_from_json(doc.get("convergence_map") or doc,
                                            "server convergence map")
    if args.study:
        study = ctx.api().study(args.study)
        return convergence.points_from_json(study.get("convergence_map") or study,
                                            f"study {args.study}")
    rows = (_server_rows(ctx, args.tag) if args.tag
            else [results().row_from_result(r) for r in _results(args, ctx)])
    return [{"L": r["L"], "n_d": r["n_d"], "status": r["convergence"]}
            for r in analysis.convergence_statuses(rows) if r["L"] is not None]


def cmd_convergence(args, ctx):
    output_paths(args, [args.stem or "convergence"])
    points = convergence_points(args, ctx)
    fig, _ = plots("convergence").plot_convergence(points, args.critical_length, args.title)
    _save(fig, args, "convergence")
    return 0


def cmd_filter(args, ctx):
    output_paths(args, [args.stem or "filter"])
    filter_response = plots("filter_response")
    runs = _results(args, ctx) if args.sources else []
    if args.lengths:
        lengths = floats(args.lengths, "--L")
    else:
        lengths = sorted({r.L for r in runs if r.L is not None and r.law != "coulomb"})
        lengths = lengths or list(filter_response.PAPER_L)
    meshes = {r.n_d: r.metrics.get("stable_dt") for r in runs if r.n_d}
    if args.densities:
        meshes.update({n: meshes.get(n) for n in floats(args.densities, "--n-d")})
    fig, _ = filter_response.plot_filter(lengths, meshes or None, args.v_star, args.slip_velocity,
                                         title=args.title)
    _save(fig, args, "filter")
    return 0


def study_cost_rows(api, study_ids):
    """(rows, reference) of the studies: `across_methods` of the first study whose
    speed-accuracy has it (every run of both methods' scenes), else the runs of every study
    given, each with its study's method (GET /studies/{id}); errors against the server's
    reference runs ("converged"). When no L of the studies converged the server has no
    reference: the errors are then computed here against the finest run of each L
    ("unconverged", labelled so on the chart), with the same definition."""
    docs = [api.get_json(f"/api/v1/studies/{sid}/speed-accuracy") for sid in study_ids]
    rows = None
    for doc in docs:
        if analysis.has_across_methods(doc):
            rows = analysis.rows_from_speed_accuracy(doc)
            break
    if rows is None:
        lists = []
        for sid, doc in zip(study_ids, docs):
            method = (doc.get("method") if isinstance(doc, dict) else None) or api.study(sid).get("method")
            lists.append(analysis.rows_from_speed_accuracy(doc, method))
        rows = analysis.merge_rows(*lists)
    if any(plots("cost").usable(r) for r in rows):
        return rows, "converged"
    finest = []
    for sid in study_ids:
        jobs = list(api.list_jobs({"study_id": sid}, limit=None))
        base = [dict(results().row_from_job(j),
                     method=(j.get("spec") or {}).get("method") or methods.default())
                for j in jobs]
        by_method = {}
        for r in base:
            by_method.setdefault(r["method"], []).append(r)
        for method_rows in by_method.values():
            finest += analysis.errors_against_finest(method_rows)
    return finest, "unconverged"


def cmd_cost(args, ctx):
    output_paths(args, [args.stem or "cost"])
    inputs = sum(bool(x) for x in (args.sources, args.data, args.tag, args.study))
    if inputs != 1:
        raise UsageError("plot cost: give exactly one of SOURCES, --data, --tag, --study")
    reference = "finest"
    if args.study:
        rows, reference = study_cost_rows(ctx.api(), args.study)
    elif args.data:
        reference = "converged"
        rows = _load_json(args.data)
        if isinstance(rows, dict):
            rows = rows.get("runs") or rows.get("points") or []
        if not isinstance(rows, list):
            raise UsageError(f"{args.data}: expected a list of {{L, n_d, wall_time_s, error}}")
    else:
        base = (_server_rows(ctx, args.tag) if args.tag
                else [results().row_from_result(r) for r in _results(args, ctx)])
        rows = analysis.errors_against_finest(base)
    fig, _ = plots("cost").plot_cost(rows, args.title, reference=reference)
    _save(fig, args, "cost")
    return 0

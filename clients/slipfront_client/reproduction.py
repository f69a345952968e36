"""The paper's study through the studies API, and its Markdown report (the library behind
clients/reproduce_paper.py).

Two convergence studies of the same scene, one per method (FE and the spectral boundary
integral, `"base": {"method": "spectral_bi"}`), over the same L, and a BI L search; the report
leads with the answer by each method and the paper's L_c beside ours (reproduction_story.py),
then each method's verdict and the cross-method table (report.py), our numbers beside the
paper's (docs/physics.md), the convergence maps, every figure of the paper
(reproduction_figures.py, slipfront_client.plots) and every run.
With `quick` the scene is small and coarse and `check_shape` asserts the maps' shape.
"""

import datetime
import os
import platform
import tempfile
import time

from . import methods
from . import report as report_mod
from . import results as results_mod
from .local_server import log
from .reproduction_measures import chosen_run, figure2_run, runs_by_L
from .reproduction_plan import (
    BI_LADDER, FE_ONLY, FINAL_JOB, FULL_L, FULL_LADDER, QUICK_BASE, QUICK_BI_LADDER, QUICK_L,
    DAMPED, QUICK_LADDER, QUICK_SEARCH, SEARCH, bi_base, damped_body, search_body, study_body)
from .reproduction_figures import MESH_L, loader, make_paper_figures
from .reproduction_checks import check_search
from .reproduction_report import check_shape, cost_rows, make_figures, write_report
from .plots import common

# What clients/reproduce_paper.py and the tests use (the plan's names are re-exported).
__all__ = ["BI_LADDER", "DAMPED", "FE_ONLY", "FINAL_JOB", "FULL_L", "FULL_LADDER",
           "QUICK_BASE", "QUICK_BI_LADDER", "QUICK_L", "QUICK_LADDER", "QUICK_SEARCH", "SEARCH",
           "bi_base", "cost_rows", "damped_body", "loadavg", "progress_line", "report",
           "search_body", "study_body", "study_wall", "wait_study"]


def progress_line(study):
    p = study.get("progress") or {}
    states = ", ".join(f"L={L}: {r.get('state')}" for L, r in (study.get("refinement") or {}).items())
    method = methods.label(report_mod.method_of(study))
    return (f"{method} study {study.get('status')}: {p.get('done')}/{p.get('total')} runs final"
            f"  [{states}]")


def wait_study(api, study_id, timeout=None):
    last = None
    delay = 1.0
    deadline = None if timeout is None else time.monotonic() + timeout
    while True:
        study = api.study(study_id)
        line = progress_line(study)
        if line != last:
            log(line)
            last = line
            delay = 1.0
        if study.get("status") == "finished":
            return study
        if deadline is not None and time.monotonic() > deadline:
            raise SystemExit(f"reproduce: study {study_id} not finished after {timeout} s")
        time.sleep(delay)
        delay = min(delay * 1.5, 10.0)


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def loadavg():
    try:
        with open("/proc/loadavg") as f:
            return " ".join(f.read().split()[:3])
    except OSError:
        return "unknown"


# -- main ---------------------------------------------------------------------------------


def study_wall(study):
    try:
        t = [datetime.datetime.fromisoformat(str(study[k]).replace("Z", "+00:00"))
             for k in ("created_at", "finished_at")]
        return (t[1] - t[0]).total_seconds()
    except (KeyError, ValueError, TypeError):
        return None


def job_metrics(api, study):
    """{job_id: metrics} of the study's runs (also kept as run["_metrics"])."""
    metrics = {}
    for r in (study or {}).get("runs") or []:
        metrics[r["job_id"]] = api.job(r["job_id"]).get("metrics") or {}
        r["_metrics"] = metrics[r["job_id"]]
    return metrics


def report(args, api, study, speed_acc, wall, server, bi=None, search=None, damped=None):
    """Write the report of the FE `study`, the BI study `bi` = {"study", "speed_acc",
    "wall"}, the BI L search `search` = {"study", "wall"} and the damped FE study `damped` =
    {"study", "wall"} (or None); in quick mode check the maps' shape, the search and the
    figures. Returns the exit code."""
    metrics = job_metrics(api, study)
    bi = dict(bi or {})
    bi["metrics"] = job_metrics(api, bi.get("study"))
    search = dict(search or {})
    search["metrics"] = job_metrics(api, search.get("study"))
    damped = dict(damped or {})
    damped["metrics"] = job_metrics(api, damped.get("study"))
    bi["run_sum"] = sum(float(m.get("wall_time_s") or 0) for m in bi["metrics"].values())
    rows, bi["rows_source"] = cost_rows(speed_acc, bi.get("speed_acc"))
    out = os.path.abspath(args.out)
    out_dir = os.path.dirname(out)
    os.makedirs(out_dir, exist_ok=True)
    fig_dir = os.path.join(out_dir, "figures", "reproduction")
    cache = os.path.join(server.data_dir if server else tempfile.mkdtemp(), "downloads")
    chosen, results = {}, {}
    for L in runs_by_L(study):
        r, conv = chosen_run(study, L)
        chosen[L] = (r, conv)
        if r is None:
            continue
        if (r.get("outcome") or "") == "no_rupture":
            continue  # nothing to draw
        path = results_mod.resolve_source(r["job_id"], lambda: api, cache, log)
        results[L] = results_mod.load_result(path)
        if not conv:
            results[L].note = "not converged"
    extra = []  # the damped FE study's finest run of each L, beside the undamped ones
    for L in runs_by_L(damped.get("study") or {}):
        r, conv = chosen_run(damped["study"], L)
        if r is not None and (r.get("outcome") or "") != "no_rupture":
            extra.append(results_mod.load_result(
                results_mod.resolve_source(r["job_id"], lambda: api, cache, log)))
            extra[-1].note = "" if conv else "not converged"
    fig2_run = figure2_run(study)
    fig2 = (fig2_run, None)
    if fig2_run is not None:
        same = chosen.get(5e-5, (None, False))[0]
        fig2 = (fig2_run, results.get(5e-5) if same and same["job_id"] == fig2_run["job_id"]
                else results_mod.load_result(
                    results_mod.resolve_source(fig2_run["job_id"], lambda: api, cache, log)))
    formats = [f.strip() for f in args.format.split(",") if f.strip()]
    figures = make_figures(study, bi.get("study"), rows, chosen, results, fig_dir, formats, log,
                           fig2[1], extra)
    captions = {}

    def save(fig, stem, caption):
        figures[stem] = common.save_figure(fig, fig_dir, stem, formats)[0]
        captions[stem] = caption
        log(f"figure {figures[stem]}")
    all_metrics = {**metrics, **bi["metrics"], **search["metrics"]}
    notes = make_paper_figures(study, bi.get("study"), search.get("study"), all_metrics,
                               loader(api, cache, log), save,
                               mesh_L=QUICK_L[-1] if args.quick else MESH_L)
    search.update(captions=captions, notes=notes)
    timing_load = getattr(args, "loadavg", loadavg())
    run_sum = sum(float(m.get("wall_time_s") or 0) for m in metrics.values())
    cmd = "/usr/bin/python3 clients/reproduce_paper.py" + (" --quick" if args.quick else "") + (
        f" --n-d-max {args.n_d_max}" if not args.quick and args.n_d_max != 160 else "")
    timing = {"wall": wall, "run_sum": run_sum, "n_runs": len(metrics),
              "n_cached": sum(1 for r in study.get("runs") or [] if r.get("cached_from")),
              "nproc": len(os.sched_getaffinity(0)), "loadavg": timing_load, "cpu": cpu_model(),
              "workers": args.workers if server else "(external server)",
              "finished_utc": datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M"),
              "command": cmd, "script_wall": time.time() - getattr(args, "script_t0", time.time()),
              "load_at_start": getattr(args, "load_at_start", None)}
    write_report(out, args, study, bi, chosen, results, metrics, figures, timing, fig2, search,
                 damped)
    log(f"wrote {out}")
    log(f"study wall {wall:.1f} s; sum of run wall times {run_sum:.1f} s; L_c {study.get('L_c')}; "
        f"spectral {study.get('spectral_critical_length')}")
    for s in (study, bi.get("study")):
        if s:
            log(f"{report_mod.method_of(s)}: {report_mod.verdict_text(s)}")
    s = (search.get("study") or {}).get("search") or {}
    log(f"L search: {s.get('state')}, L_c {s.get('L_c')}: {s.get('reason')}")
    if args.quick:
        fails = check_shape(study, out, figures, bi.get("study"))
        fails += check_search(search.get("study"), out, figures)
        methods = {r["method"] for r in rows if r.get("error") is not None}
        if bi["rows_source"] != "across_methods" or methods != {"fe", "spectral_bi"}:
            fails.append(f"speed-accuracy: rows from {bi['rows_source']} with errors for "
                         f"{sorted(methods)}, expected across_methods with both methods")
        if "cost" not in figures:
            fails.append("figure cost missing")
        if fails:
            for f in fails:
                log("CHECK FAILED: " + f)
            return 1
        log("quick checks passed: the maps have the expected shape")
    return 0


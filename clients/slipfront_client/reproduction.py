"""The paper's study through the studies API, and its Markdown report (the library behind
clients/reproduce_paper.py).

Two convergence studies of the same scene, one per method (FE and the spectral boundary
integral, `"base": {"method": "spectral_bi"}`), over the same L; the report leads with each
method's L_c verdict and the cross-method table (report.py), then our numbers beside the
paper's (SPEC §3), the FE convergence map, figures (slipfront_client.plots) and every run.
With `quick` the scene is small and coarse and `check_shape` asserts the maps' shape.
"""

import datetime
import json
import os
import platform
import tempfile
import time

from . import report as report_mod
from . import results as results_mod
from .analysis import merge_rows, rows_from_speed_accuracy, has_across_methods
from .local_server import log
from .report import converged_n_d, fmt

FULL_L = [1e-3, 1e-4, 5e-5, 1e-5, 5e-6]
FULL_LADDER = [10, 20, 40, 80, 160]
BI_LADDER = [10, 20, 40, 80, 160, 320]
QUICK_L = [1e-3, 5e-5]
QUICK_LADDER = [5, 10]
QUICK_BI_LADDER = [10, 20, 40]
QUICK_BASE = {"geometry": {"width": 20, "x_min": -5, "height": 8}, "time": {"duration": 10}}
# FE-only fields: an error in a spectral_bi spec (docs/spectral-bi.md, Options).
FE_ONLY = {"geometry": ("height", "top_boundary"), "time": ("safety_factor",)}
FINAL_JOB = ("succeeded", "failed", "cancelled")


def bi_base(base):
    """The FE base as a spectral BI base: `"method": "spectral_bi"`, FE-only fields dropped."""
    out = json.loads(json.dumps(base or {}))
    for section, keys in FE_ONLY.items():
        for key in keys:
            (out.get(section) or {}).pop(key, None)
        if section in out and not out[section]:
            del out[section]
    out["method"] = "spectral_bi"
    return out


def study_body(args, method="fe"):
    """The convergence study of one method: FE on `args.ladder` up to `args.n_d_max`, BI
    on `args.bi_ladder` up to `args.bi_n_d_max`, the same L and scene."""
    bi = method == "spectral_bi"
    body = {"name": "reproduction" + (" BI" if bi else "") + (" (quick)" if args.quick else ""),
            "tags": ["reproduction"] + (["quick"] if args.quick else []),
            "convergence": {"L": args.L, "n_d": args.bi_ladder if bi else args.ladder,
                            "n_d_max": args.bi_n_d_max if bi else args.n_d_max}}
    base = bi_base(args.base) if bi else args.base
    if base:
        body["base"] = base
    if args.fresh:
        body["fresh"] = True
    return body


def progress_line(study):
    p = study.get("progress") or {}
    states = ", ".join(f"L={L}: {r.get('state')}" for L, r in (study.get("refinement") or {}).items())
    method = report_mod.SHORT.get(report_mod.method_of(study), "")
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


# -- measurements from runs ---------------------------------------------------------------

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


def key_L(L):
    return float(L)


def runs_by_L(study):
    out = {}
    for r in study.get("runs") or []:
        out.setdefault(float(r["L"]), []).append(r)
    for L in out:
        out[L].sort(key=lambda r: float(r["n_d"]))
    return out


def chosen_run(study, L):
    """The run drawn for L: the coarsest converged one (the paper's triangle); without a
    converged run, the finest succeeded run (labelled as such in the report)."""
    runs = [r for r in runs_by_L(study).get(L, []) if r.get("job_status") == "succeeded"]
    nd = converged_n_d(study, L)
    if nd is not None:
        for r in runs:
            if abs(float(r["n_d"]) - nd) < 1e-9 and not r.get("cached_from_dup"):
                return r, True
    return (runs[-1], False) if runs else (None, False)


def figure2_run(study):
    """The run of the paper's Fig. 2 values (SPEC §3 quotes them at n_d = 40): L = 5e-5 m at
    n_d = 40 when the study has it, else the run drawn for L = 5e-5 m."""
    for r in runs_by_L(study).get(5e-5, []):
        if abs(float(r["n_d"]) - 40) < 1e-9 and r.get("job_status") == "succeeded":
            return r
    return chosen_run(study, 5e-5)[0]


def peak_at(result, x1):
    import numpy as np
    node = int(np.argmin(np.abs(result.x1 - x1)))
    v = np.abs(result.slip_velocity[:, node])
    i = int(np.argmax(v))
    return float(result.x1[node]), float(v[i]), float(result.time[i])


def front_time_at(result, x1):
    import numpy as np
    ok = np.isfinite(result.arrival_time)
    xs, ts = result.front_x1[ok], result.arrival_time[ok]
    if xs.size == 0 or x1 < xs.min() or x1 > xs.max():
        return None
    return float(np.interp(x1, xs, ts))


def speed_summary(result):
    """Rupture speed on the run's front: fraction of x1 > 1 m (past the nucleation
    patch) with c_s < V_r < c_p; median V_r in x1 in [1, 3] m and in the last 2 m
    before arrest (excluding the last 0.5 m)."""
    import numpy as np
    c_s, c_p = result.wave_speeds()
    ok = np.isfinite(result.rupture_speed)
    x, v = result.front_x1[ok], result.rupture_speed[ok]
    out = {"c_s": c_s, "c_p": c_p}
    past = x > 1.0
    if past.any():
        out["supershear_fraction"] = float(np.mean((v[past] > c_s) & (v[past] < c_p)))
        early = (x >= 1.0) & (x <= 3.0)
        out["v_early"] = float(np.median(v[early])) if early.any() else None
        x_end = float(x.max())
        late = (x >= x_end - 2.5) & (x <= x_end - 0.5)
        out["v_late"] = float(np.median(v[late])) if late.any() else None
        out["late_range"] = (x_end - 2.5, x_end - 0.5)
    return out


# -- report -------------------------------------------------------------------------------

def cost_rows(speed_acc, bi_speed_acc=None):
    """The cost chart's rows of both methods and where they come from: the server's
    `across_methods` (every run against the finest converged run of its L by either method)
    when it gives it, else each study's own runs against its own method's reference."""
    for doc in (speed_acc, bi_speed_acc):
        if has_across_methods(doc):
            return rows_from_speed_accuracy(doc), "across_methods"
    return merge_rows(rows_from_speed_accuracy(speed_acc or {}, "fe"),
                      rows_from_speed_accuracy(bi_speed_acc or {}, "spectral_bi")), "runs"


def make_figures(study, bi_study, rows, chosen, results, fig_dir, formats, log_fn):
    from slipfront_client.plots import common, convergence, velocity, speed, filter_response, cost
    from slipfront_client.plots import slip_map
    made = {}

    def save(fig, stem):
        paths = common.save_figure(fig, fig_dir, stem, formats)
        made[stem] = paths[0]
        log_fn(f"figure {paths[0]}")

    points = convergence.points_from_json(study["convergence_map"], "study convergence map")
    lc = study.get("L_c")
    fig, _ = convergence.plot_convergence(points, lc, "Convergence map (study)")
    save(fig, "convergence")
    if bi_study and bi_study.get("convergence_map"):
        points = convergence.points_from_json(bi_study["convergence_map"], "BI convergence map")
        fig, _ = convergence.plot_convergence(points, bi_study.get("L_c"),
                                              "Convergence map, spectral BI (study)")
        save(fig, "convergence_bi")

    drawn = [results[L] for L in sorted(results, reverse=True)]
    if drawn:
        fig, _ = velocity.plot_velocity(drawn, (6.0, 10.0), "Slip velocity, drawn run of each L")
        save(fig, "velocity")
        fig, _ = speed.plot_speed(drawn, "Rupture speed, drawn run of each L")
        save(fig, "speed")
        ref = results.get(5e-5) or drawn[0]
        fig, _ = slip_map.plot_map(ref, [6.0, 10.0], None, f"|V|, {ref.label()}")
        save(fig, "map")

    lengths = sorted({float(r["L"]) for r in study.get("runs") or []})
    meshes = {}
    for r in study.get("runs") or []:
        dt = (r.get("_metrics") or {}).get("stable_dt")
        if dt:
            meshes[float(r["n_d"])] = dt
    fig, _ = filter_response.plot_filter(lengths, meshes or None, title=None)
    save(fig, "filter")

    if any(cost.usable(r) for r in rows):
        fig, _ = cost.plot_cost(rows, "Speed and accuracy, FE and spectral BI (labels: n_d)")
        save(fig, "cost")
    return made


def write_report(path, args, study, bi, chosen, results, metrics, figures, timing,
                 fig2=(None, None)):
    """`bi`: {"study", "metrics", "wall", "rows_source"} of the spectral BI study (or None)."""
    rel = os.path.relpath
    out_dir = os.path.dirname(os.path.abspath(path))
    by_L = runs_by_L(study)
    bi = bi or {}
    bi_study = bi.get("study")
    lines = []
    add = lines.append
    title = "Reproduction of Kammer et al. 2014"
    if args.quick:
        title += " — QUICK RUN (small, coarse scene; not the paper's scene)"
    add(f"# {title}\n")
    add(f"Generated by `clients/reproduce_paper.py` on {timing['finished_utc']} UTC from the FE "
        f"study `{study.get('id')}`"
        + (f" and the spectral BI study `{bi_study.get('id')}`" if bi_study else "")
        + f" of the same scene (FE scene hash `{str(study.get('scene_hash'))[:16]}…`). "
        "Every number below is computed from those studies' runs; the paper's values are SPEC §3.\n")
    if args.quick:
        add("> **This is the CI-short version** (`--quick`): a 20 m × 8 m scene, "
            f"duration {args.base['time']['duration']} s, L ∈ {{{', '.join(f'{L:g}' for L in args.L)}}} m, "
            f"n_d ∈ {{{', '.join(str(n) for n in args.ladder)}}} (BI: {{{', '.join(str(n) for n in args.bi_ladder)}}}). "
            "Its numbers are **not** comparable with the paper's; it checks that the pipeline "
            "works and the maps have the expected shape.\n")

    add("## L_c verdict, by method\n")
    add("- " + "; ".join(f"**{report_mod.SHORT.get(report_mod.method_of(s), '?')}: "
                         f"{report_mod.verdict_text(s)}** (spectral estimate "
                         f"{fmt(s.get('spectral_critical_length'), unit='m')})"
                         for s in (study, bi_study) if s) + ".\n")
    add("The rule (SPEC §2, docs/studies.md): L_c is the largest L whose mesh-converged "
        "reference agrees with that of every smaller L (propagation distance within 0.5 %, "
        "arrival time at the probe within 0.1 %). Each method has its own convergence map "
        "and verdict.\n")
    for s in (study, bi_study):
        if s:
            lines.extend(report_mod.verdict_lines(s))

    add("## Same L, both methods\n")
    lines.extend(report_mod.cross_method_lines(study.get("cross_method")
                                               or (bi_study or {}).get("cross_method")))
    add("")

    add("## How it was made\n")
    add("```sh\n" + timing["command"] + "\n```\n")
    add(f"FE study request: `{json.dumps(study.get('request') or study_body(args))}`\n")
    if bi_study:
        add(f"BI study request: `{json.dumps(bi_study.get('request') or study_body(args, 'spectral_bi'))}`\n")
    add(f"- FE n_d ladder {args.ladder}, cap n_d_max = {args.n_d_max}"
        + (" (the paper's ladder goes to 160; capped here to bound the run time)"
           if not args.quick and args.n_d_max < 160 else "")
        + f"; BI ladder {args.bi_ladder}, cap {args.bi_n_d_max}.")
    add(f"- Wall clock of the FE study (creation to finished): **{timing['wall']:.1f} s**; "
        f"sum of the runs' wall times: **{timing['run_sum']:.1f} s** over {timing['n_runs']} runs "
        f"({timing['n_cached']} reused from earlier jobs, counted with their original time).")
    if bi_study:
        add(f"- Wall clock of the BI study: **{fmt(bi.get('wall'))} s**; sum of its runs' wall "
            f"times: **{bi.get('run_sum', 0):.1f} s** over {len(bi.get('metrics') or {})} runs. "
            "The two studies ran at the same time on the same workers.")
    add(f"- Machine: `nproc` = {timing['nproc']}, CPU {timing['cpu']}; server workers: "
        f"{timing['workers']}; load average (1, 5, 15 min) when the study finished: "
        f"{timing['loadavg']} — other work shared the machine when it exceeds the workers, "
        "and the wall times are then upper bounds.\n")

    # values table
    add("## Our numbers beside the paper's\n")
    add("| quantity | paper (SPEC §3) | ours | run |")
    add("| --- | --- | --- | --- |")
    for row in comparison_rows(study, chosen, results, metrics, fig2):
        add("| " + " | ".join(row) + " |")
    add("")
    add("The Fig. 2 rows (L = 5e-5 m) use the n_d = 40 run when the study has one, as SPEC §3 "
        "quotes them at n_d = 40. "
        "The drawn run of an L is its coarsest mesh-converged run (the paper's triangle); "
        "where an L has no converged run, its finest finished run, marked *(not converged)*. "
        "Rupture speed: the solver's `/front/rupture_speed`; ‘early’ is the median over "
        "x1 ∈ [1, 3] m, ‘late’ the median over the 2 m ending 0.5 m before the arrest; "
        "‘super-shear’ is the fraction of front points past x1 = 1 m with c_s < V_r < c_p.\n")

    findings = differences(study, metrics, chosen)
    if findings:
        add("Where we differ from the paper (computed from the rows above, nothing tuned):\n")
        for f in findings:
            add(f"- {f}")
        add("")
        if not args.quick:
            add("Why the smallest L need finer meshes here, and why L = 5e-6 m moves away at "
                "n_d = 160: [docs/small-l-study.md](small-l-study.md) (the strength update's "
                "time-step error, plain Coulomb friction and the mesh-scale oscillation, "
                "`bench/small_l_study.py`).\n")

    # convergence map table
    add("## Convergence map\n")
    nds = sorted({float(r["n_d"]) for r in study.get("runs") or []})
    add("| L [m] | " + " | ".join(f"n_d = {n:g}" for n in nds) + " | converged from |")
    add("| --- | " + " | ".join("---" for _ in nds) + " | --- |")
    for L in sorted(by_L, reverse=True):
        cells = []
        for n in nds:
            r = next((r for r in by_L[L] if abs(float(r["n_d"]) - n) < 1e-9), None)
            if r is None:
                cells.append("")
            else:
                conv = (r.get("convergence") or {}).get("status", "?")
                cells.append(f"{conv} ({r.get('outcome') or r.get('job_status')})")
        add(f"| {L:g} | " + " | ".join(cells) + f" | {fmt(converged_n_d(study, L))} |")
    add("")
    refinement = study.get("refinement") or {}
    if refinement:
        add("Refinement per L (server): " + "; ".join(
            f"L = {float(k):g}: {v.get('state')}" for k, v in sorted(refinement.items(),
                                                                  key=lambda kv: -float(kv[0]))) + ".\n")
    if "convergence" in figures:
        add(f"![convergence map]({rel(figures['convergence'], out_dir)})\n")
    if "convergence_bi" in figures:
        add("The spectral BI study's map (same symbols; its runs are listed under "
            "“Runs (spectral BI)”):\n")
        add(f"![convergence map, spectral BI]({rel(figures['convergence_bi'], out_dir)})\n")

    add("## Critical length beside the paper's\n")
    add("| method | verdict (SPEC §2) | spectral estimate | from L | paper |")
    add("| --- | --- | --- | --- | --- |")
    for st in (study, bi_study):
        if st:
            cl = st.get("critical_length") or {}
            add(f"| {report_mod.SHORT.get(report_mod.method_of(st), '?')} | "
                f"{report_mod.verdict_text(st)} | {fmt(st.get('spectral_critical_length'), unit='m')} | "
                f"{fmt(cl.get('spectral_from_L'), unit='m')} | L_c ≈ 1e-5 m |")
    add("\nThe reasons, the change per step in L and the n_d per L: the verdicts at the top.\n")

    add("## Figures\n")
    captions = {
        "velocity": "Slip velocity |V| at x1 = 6 and 10 m, the drawn run of each L (paper Fig. 2b, 3a, 4a).",
        "speed": "Rupture speed against x1, the drawn run of each L, with c_s and c_p (paper Fig. 2c, 3b, 4b).",
        "map": "|V| in the x1–t plane with the slip front (paper Fig. 2a).",
        "filter": "Friction filter A/A0 (eq. 6) for the study's L, with the meshes' highest "
                  "eigenfrequencies 1/(π dt_stable) from the runs' `stable_dt` (paper Fig. 5c).",
        "cost": "Error against wall time (left) and against the memory estimate (right), both "
                "methods (FE ● solid, BI ■ dashed, colour = L), labelled by n_d. Error: the larger "
                "relative change of propagation distance and arrival time at the probe against "
                + ("the finest mesh-converged run of the same L by either method (the server's "
                   "`across_methods`)" if bi.get("rows_source") == "across_methods" else
                   "the reference run of the same L by the same method (this server has no "
                   "`across_methods` yet)")
                + "; a reference run (error 0) is not drawn.",
    }
    for stem in ("velocity", "speed", "map", "filter", "cost"):
        if stem in figures:
            add(f"{captions[stem]}\n\n![{stem}]({rel(figures[stem], out_dir)})\n")
    if "cost" not in figures:
        add("No speed–accuracy chart: no run has a reference to be compared with "
            "(an L needs a mesh-converged run).\n")

    add("## Runs\n")
    lines.extend(runs_table(by_L, metrics))
    if bi_study:
        add("## Runs (spectral BI)\n")
        lines.extend(runs_table(runs_by_L(bi_study), bi.get("metrics") or {}))
    add("## Commands\n")
    add("```sh")
    add("cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && cmake --build build -j2 --target slipfront")
    add("/usr/bin/python3 clients/reproduce_paper.py --n-d-max 80     # the paper's ladder capped at n_d = 80")
    add("/usr/bin/python3 clients/reproduce_paper.py                  # the paper's ladder up to n_d = 160")
    add("/usr/bin/python3 clients/reproduce_paper.py --quick          # CI-short, checks the map shape")
    add("ctest --test-dir build -L reproduction --output-on-failure     # the same under ctest")
    add("```\n")
    add("With `--server URL` the script uses a running server (runs it already has are reused, "
        "`--fresh` recomputes them); `--study-id ID` (and `--bi-study-id ID`) write the report "
        "of existing studies; `--bi-n-d-max` caps the BI ladder (default 320).\n")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")


def runs_table(by_L, metrics):
    lines = ["| L [m] | n_d | job | outcome | convergence | propagation distance [m] | "
             "arrival at probe [s] | max V [m/s] | wall [s] | reused |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for L in sorted(by_L, reverse=True):
        for r in by_L[L]:
            m = metrics.get(r["job_id"]) or {}
            lines.append(
                f"| {L:g} | {float(r['n_d']):g} | `{r['job_id'][:8]}` | {r.get('outcome') or '—'} | "
                f"{(r.get('convergence') or {}).get('status', '?')} | "
                f"{fmt(m.get('propagation_distance'), 5)} | {fmt(m.get('arrival_time_at_probe'), 5)} | "
                f"{fmt(m.get('max_slip_velocity'))} | {fmt(m.get('wall_time_s'))} | "
                f"{'yes' if r.get('cached_from') else 'no'} |")
    return lines + [""]


PAPER_CONVERGED_ND = {1e-4: 20, 5e-5: 20, 1e-5: 40}


def differences(study, metrics, chosen):
    """Plain statements where the study disagrees with SPEC §3's qualitative claims."""
    out = []
    by_L = runs_by_L(study)
    for L, paper_nd in PAPER_CONVERGED_ND.items():
        if L not in by_L:
            continue
        nd = converged_n_d(study, L)
        tried = max(float(r["n_d"]) for r in by_L[L])
        if nd is None:
            out.append(f"L = {L:g}: no mesh-converged run up to n_d = {tried:g} "
                       f"(paper: n_d = {paper_nd} suffices).")
        elif nd > paper_nd:
            out.append(f"L = {L:g}: converged from n_d = {nd:g}, the paper from n_d = {paper_nd}.")
    if 1e-3 in by_L and any(r.get("outcome") not in ("no_rupture",) for r in by_L[1e-3]):
        out.append("L = 1e-3: a run ruptured (paper: no rupture).")
    lc = study.get("L_c")
    if lc is None:
        out.append("L_c: not determined by this study (paper: ≈ 1e-5 m); reason: "
                   + str((study.get("critical_length") or {}).get("reason", "—")))
    elif not (5e-6 <= lc <= 5e-5):
        out.append(f"L_c = {lc:g} m (paper: ≈ 1e-5 m).")
    return out


def comparison_rows(study, chosen, results, metrics, fig2=(None, None)):
    """SPEC §3 against our runs. `fig2` = (run, result) of figure2_run(); the Fig. 3 rows use
    the run drawn for each L (the coarsest mesh-converged one, the paper's triangle)."""
    rows = []

    def tag(L):
        r, conv = chosen.get(L, (None, False))
        if r is None:
            return "no finished run"
        return f"n_d = {float(r['n_d']):g}" + ("" if conv else " *(not converged)*")

    run2, res2 = fig2
    if run2 is not None:
        mm = metrics.get(run2["job_id"]) or {}
        # Converged itself, or at least as fine as the coarsest converged mesh of its L (an
        # n_d = 40 run after a converged n_d = 20 has no finer partner: status unknown).
        n2, nd_conv = float(run2["n_d"]), converged_n_d(study, 5e-5)
        settled = ((run2.get("convergence") or {}).get("status") == "converged"
                   or (nd_conv is not None and nd_conv <= n2))
        tag2 = f"n_d = {n2:g}" + ("" if settled else " *(not converged)*")
        rows.append(["L = 5e-5: max slip velocity", "≈ 8 mm/s (early)",
                     fmt((mm.get("max_slip_velocity") or float("nan")) * 1e3, 3, "mm/s"), tag2])
        if res2 is not None:
            s = speed_summary(res2)
            rows.append(["L = 5e-5: super-shear (c_s < V_r < c_p)", "almost everywhere",
                         fmt(100 * s["supershear_fraction"], 3, "% of front past x1 = 1 m")
                         if "supershear_fraction" in s else "—", tag2])
        rows.append(["L = 5e-5: arrest position", "≈ 12.5 m", fmt(mm.get("arrest_position"), 4, "m"),
                     tag2])
        rows.append(["L = 5e-5: outcome", "arrested", str(mm.get("outcome")), tag2])
    for L in (1e-4, 5e-5):
        res = results.get(L)
        if res is None:
            continue
        x, vpk, tpk = peak_at(res, 6.0)
        rows.append([f"L = {L:g}: peak V at x1 = 6 m", "≈ 3 mm/s around t ≈ 4.5 s",
                     f"{vpk * 1e3:.3g} mm/s at t = {tpk:.3g} s (node x1 = {x:g} m)", tag(L)])
        tf = front_time_at(res, 6.0)
        rows.append([f"L = {L:g}: front arrival at x1 = 6 m", "≈ 4.5 s", fmt(tf, 3, "s"), tag(L)])
        s = speed_summary(res)
        if s.get("v_early") is not None or s.get("v_late") is not None:
            lo, hi = s.get("late_range", (float("nan"), float("nan")))
            rows.append([f"L = {L:g}: V_r early → late", "1.6 → 1.0 m/s, then abrupt arrest",
                         f"{fmt(s.get('v_early'))} → {fmt(s.get('v_late'))} m/s "
                         f"(late: x1 ∈ [{lo:.3g}, {hi:.3g}] m)", tag(L)])
    if 1e-3 in chosen or 1e-3 in runs_by_L(study):
        outs = sorted({str(r.get("outcome")) for r in runs_by_L(study).get(1e-3, [])})
        rows.append(["L = 1e-3: rupture", "no rupture at all", "outcomes: " + ", ".join(outs),
                     "every n_d"])
    conv_paper = {1e-3: "(no rupture)", 1e-4: "n_d = 20", 5e-5: "n_d = 20", 1e-5: "n_d = 40",
                  5e-6: "finer than 40"}
    for L in sorted(runs_by_L(study), reverse=True):
        nd = converged_n_d(study, L)
        rows.append([f"L = {L:g}: coarsest converged n_d", conv_paper.get(L, "—"),
                     fmt(nd) if nd is not None else "none up to the cap", "map"])
    rows.append(["critical length L_c", "≈ 1e-5 m", fmt(study.get("L_c"), 3, "m"), "study"])
    rows.append(["spectral estimate of L_c", "(paper: filter argument, §5)",
                 fmt(study.get("spectral_critical_length"), 3, "m"), "study"])
    return rows


# -- quick-mode assertions ----------------------------------------------------------------

def check_bi_shape(bi_study, fe_study):
    """The quick BI study: finished, every run succeeded, L = 1e-3 never ruptures and
    L = 5e-5 always does, at least two meshes per L; the cross-method table has the
    L = 1e-3 row with both sides (both methods converge there at once)."""
    if not bi_study:
        return ["no BI study"]
    fails = []
    if bi_study.get("status") != "finished":
        fails.append(f"BI study status {bi_study.get('status')!r}, expected 'finished'")
    if bi_study.get("method") not in (None, "spectral_bi"):
        fails.append(f"BI study method {bi_study.get('method')!r}")
    by_L = runs_by_L(bi_study)
    for L in QUICK_L:
        runs = by_L.get(L, [])
        if len(runs) < 2:
            fails.append(f"BI L = {L:g}: {len(runs)} run(s), expected at least two meshes")
        for r in runs:
            where = f"BI L = {L:g}, n_d = {float(r['n_d']):g}"
            if r.get("job_status") != "succeeded":
                fails.append(f"{where}: job {r.get('job_status')}, expected succeeded")
            elif (r.get("outcome") == "no_rupture") != (L == 1e-3):
                fails.append(f"{where}: outcome {r.get('outcome')}")
    rows = [row for row in fe_study.get("cross_method") or [] if abs(float(row["L"]) - 1e-3) < 1e-12]
    if not rows or not rows[0].get("fe") or not rows[0].get("spectral_bi"):
        fails.append(f"cross_method: no L = 1e-3 row with both methods ({rows})")
    return fails


def check_shape(study, report_path, figures, bi_study=None):
    """The quick studies' maps must have the expected shape; returns the list of failures."""
    fails = check_bi_shape(bi_study, study)
    by_L = runs_by_L(study)
    nds = [float(n) for n in QUICK_LADDER]
    finest = max(nds)
    if study.get("status") != "finished":
        fails.append(f"study status {study.get('status')!r}, expected 'finished'")
    for L in QUICK_L:
        runs = {float(r["n_d"]): r for r in by_L.get(L, [])}
        missing = [n for n in nds if n not in runs]
        if missing:
            fails.append(f"L = {L:g}: no run at n_d = {missing}")
            continue
        for n in nds:
            r = runs[n]
            status = (r.get("convergence") or {}).get("status")
            if r.get("job_status") != "succeeded":
                fails.append(f"L = {L:g}, n_d = {n:g}: job {r.get('job_status')}, expected succeeded")
            if L == 1e-3:
                if r.get("outcome") != "no_rupture":
                    fails.append(f"L = 1e-3, n_d = {n:g}: outcome {r.get('outcome')}, expected no_rupture")
                want = "unknown" if n == finest else "converged"
                if status != want:
                    fails.append(f"L = 1e-3, n_d = {n:g}: status {status}, expected {want}")
            else:
                if r.get("outcome") in (None, "no_rupture", "diverged"):
                    fails.append(f"L = {L:g}, n_d = {n:g}: outcome {r.get('outcome')}, expected a rupture")
                want = ("unknown",) if n == finest else ("converged", "not_converged")
                if status not in want:
                    fails.append(f"L = {L:g}, n_d = {n:g}: status {status}, expected {' or '.join(want)}")
    if not os.path.isfile(report_path):
        fails.append(f"report {report_path} missing")
    else:
        text = open(report_path, encoding="utf-8").read()
        for needle in ("## Our numbers beside the paper's", "| quantity | paper (SPEC §3) | ours | run |",
                       "## Convergence map", "## Critical length", "Wall clock",
                       "## L_c verdict, by method", "### finite elements", 
                       "### spectral boundary integral", "## Same L, both methods",
                       "| L [m] | n_d FE / BI |", "## Runs (spectral BI)"):
            if needle not in text:
                fails.append(f"report lacks {needle!r}")
        if text.find("## L_c verdict") > text.find("## Same L") or \
                text.find("## Same L") > text.find("## Our numbers"):
            fails.append("report does not lead with the verdicts, then the cross-method table")
        for stem in ("convergence", "velocity", "speed", "filter", "convergence_bi"):
            path = figures.get(stem)
            if not path or not os.path.isfile(path) or os.path.getsize(path) == 0:
                fails.append(f"figure {stem} missing")
            elif os.path.relpath(path, os.path.dirname(os.path.abspath(report_path))) not in text:
                fails.append(f"report does not link figure {stem}")
    return fails


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


def report(args, api, study, speed_acc, wall, server, bi=None):
    """Write the report of the FE `study` and the BI study `bi` = {"study", "speed_acc",
    "wall"}; in quick mode check the maps' shape. Returns the exit code."""
    metrics = job_metrics(api, study)
    bi = dict(bi or {})
    bi["metrics"] = job_metrics(api, bi.get("study"))
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
    fig2_run = figure2_run(study)
    fig2 = (fig2_run, None)
    if fig2_run is not None:
        same = chosen.get(5e-5, (None, False))[0]
        fig2 = (fig2_run, results.get(5e-5) if same and same["job_id"] == fig2_run["job_id"]
                else results_mod.load_result(
                    results_mod.resolve_source(fig2_run["job_id"], lambda: api, cache, log)))
    formats = [f.strip() for f in args.format.split(",") if f.strip()]
    figures = make_figures(study, bi.get("study"), rows, chosen, results, fig_dir, formats, log)
    timing_load = getattr(args, "loadavg", loadavg())
    run_sum = sum(float(m.get("wall_time_s") or 0) for m in metrics.values())
    cmd = "/usr/bin/python3 clients/reproduce_paper.py" + (" --quick" if args.quick else "") + (
        f" --n-d-max {args.n_d_max}" if not args.quick else "")
    timing = {"wall": wall, "run_sum": run_sum, "n_runs": len(metrics),
              "n_cached": sum(1 for r in study.get("runs") or [] if r.get("cached_from")),
              "nproc": len(os.sched_getaffinity(0)), "loadavg": timing_load, "cpu": cpu_model(),
              "workers": args.workers if server else "(external server)",
              "finished_utc": datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M"),
              "command": cmd}
    write_report(out, args, study, bi, chosen, results, metrics, figures, timing, fig2)
    log(f"wrote {out}")
    log(f"study wall {wall:.1f} s; sum of run wall times {run_sum:.1f} s; L_c {study.get('L_c')}; "
        f"spectral {study.get('spectral_critical_length')}")
    for s in (study, bi.get("study")):
        if s:
            log(f"{report_mod.method_of(s)}: {report_mod.verdict_text(s)}")
    if args.quick:
        fails = check_shape(study, out, figures, bi.get("study"))
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

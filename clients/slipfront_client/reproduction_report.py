"""The Markdown report of the paper's study: figures, the report text, and the quick-mode
shape checks (library of clients/reproduce_paper.py)."""

import json
import os

from . import methods
from . import report as report_mod
from .analysis import merge_rows, rows_from_speed_accuracy, has_across_methods
from .report import converged_n_d, fmt
from .reproduction_measures import comparison_rows, differences, runs_by_L, runs_table
from .reproduction_plan import QUICK_L, QUICK_LADDER, study_body
from .reproduction_story import damped_lines, fe_lines, paper_lines, search_lines


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


def make_figures(study, bi_study, rows, chosen, results, fig_dir, formats, log_fn, event=None,
                 extra=()):
    """The maps, the FE drawn runs (and the `extra` Results beside them: the damped FE runs),
    the filter and the cost chart; with `event` (the Result of the paper's Fig. 2 run) its
    x1-t map, |V| at x1 = 6 and 10 m and rupture speed."""
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
        fig, _ = velocity.plot_velocity(drawn + list(extra), (6.0, 10.0),
                                        "Slip velocity, drawn run of each L")
        save(fig, "velocity")
        fig, _ = speed.plot_speed(drawn + list(extra), "Rupture speed, drawn run of each L")
        save(fig, "speed")
        ref = event or results.get(5e-5) or drawn[0]
        fig, _ = slip_map.plot_map(ref, [6.0, 10.0], None, f"|V|, {ref.label()}")
        save(fig, "map")
        fig, _ = velocity.plot_velocity([ref], (6.0, 10.0), f"Slip velocity, {ref.label()}")
        save(fig, "event_velocity")
        fig, _ = speed.plot_speed([ref], f"Rupture speed, {ref.label()}")
        save(fig, "event_speed")

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


def map_table_lines(study):
    """The convergence map as a table: one row per L (largest first), one column per n_d,
    each cell "status (outcome)", and the coarsest converged n_d."""
    by_L = runs_by_L(study)
    nds = sorted({float(r["n_d"]) for r in study.get("runs") or []})
    lines = ["| L [m] | " + " | ".join(f"n_d = {n:g}" for n in nds) + " | converged from |",
             "| --- | " + " | ".join("---" for _ in nds) + " | --- |"]
    for L in sorted(by_L, reverse=True):
        cells = []
        for n in nds:
            r = next((r for r in by_L[L] if abs(float(r["n_d"]) - n) < 1e-9), None)
            if r is None:
                cells.append("")
            else:
                conv = (r.get("convergence") or {}).get("status", "?")
                cells.append(f"{conv} ({r.get('outcome') or r.get('job_status')})")
        lines.append(f"| {L:g} | " + " | ".join(cells) + f" | {fmt(converged_n_d(study, L))} |")
    return lines + [""]


def opening_lines(search_study, fe_study, bi_study):
    """The report's first block (docs/studies.md "The answer"): the answer of the study that
    decides — the BI L search when there is one, else the FE study — with the other studies'
    verdicts and the paper's value among the other numbers, each labelled."""
    main = search_study or fe_study
    extra = []
    for other, what in ((fe_study, "the FE convergence study over the paper's L (docs/reproduction"
                                   ".md \"L_c verdict, by method\")"),
                        (bi_study, "the BI convergence study over the paper's L")):
        if other is not None and other is not main:
            extra.append((what, report_mod.verdict_text(other), None))
    method = methods.label(report_mod.method_of(main))
    kind = "L search" if main.get("search") else f"{main.get('kind', 'convergence')} study"
    lines = ["## The answer\n", f"From the {method} {kind} `{main.get('id')}`:\n"]
    lines += report_mod.answer_lines(main, extra)
    return lines + [""]


def write_report(path, args, study, bi, chosen, results, metrics, figures, timing,
                 fig2=(None, None), search=None, damped=None):
    """`bi`: {"study", "metrics", "wall", "rows_source"} of the spectral BI study (or None);
    `search`: {"study", "metrics", "wall", "captions", "notes"} of the BI L search and the
    paper figures drawn from the studies (or None); `damped`: {"study", "metrics", "wall"} of
    the FE study with the mesh damping (or None)."""
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
    search = search or {}
    lines.extend(opening_lines(search.get("study"), study, bi_study))
    add(f"Generated by `clients/reproduce_paper.py` on {timing['finished_utc']} UTC from the FE "
        f"study `{study.get('id')}`"
        + (f" and the spectral BI study `{bi_study.get('id')}`" if bi_study else "")
        + f" of the same scene (FE scene hash `{str(study.get('scene_hash'))[:16]}…`). "
        "Every number below is computed from those studies' runs; the paper's values are "
        "those of docs/physics.md \"The paper's published values\".\n")
    if args.quick:
        add("> **This is the CI-short version** (`--quick`): a 20 m × 8 m scene, "
            f"duration {args.base['time']['duration']} s, L ∈ {{{', '.join(f'{L:g}' for L in args.L)}}} m, "
            f"n_d ∈ {{{', '.join(str(n) for n in args.ladder)}}} (BI: {{{', '.join(str(n) for n in args.bi_ladder)}}}). "
            "Its numbers are **not** comparable with the paper's; it checks that the pipeline "
            "works and the maps have the expected shape.\n")

    if not args.quick and args.n_d_max < 160:
        add(f"> **FE capped at n_d = {args.n_d_max}** (`--n-d-max {args.n_d_max}`, the paper's "
            f"ladder goes to 120 and ours to 160), BI in full (cap {args.bi_n_d_max}). "
            + (f"Whole script: **{fmt(timing.get('script_wall'))} s** wall on {timing['nproc']} "
               f"cores at load {timing['loadavg']}. " if not args.study_id else
               "Report written from existing studies (their wall times below). ")
            + f"Command: `{timing['command']}`. Run it without "
            "`--n-d-max` on an idle machine for the whole FE ladder.\n")
    add("## The answer, by method\n")
    lines.extend(search_lines(search.get("study"), search.get("wall"),
                              len(search.get("metrics") or {}),
                              sum(float(m.get("wall_time_s") or 0)
                                  for m in (search.get("metrics") or {}).values())))
    lines.extend(fe_lines(study, metrics, args.n_d_max, bi_study))
    damped = damped or {}
    if damped.get("study"):
        lines.extend(damped_lines(damped["study"], damped.get("metrics") or {}, bi_study,
                                  damped.get("wall")))
    if bi_study:
        add(f"- **BI, convergence study over the paper's L: {report_mod.verdict_text(bi_study)}** "
            f"(study `{bi_study.get('id')}`): its L stop at {min(runs_by_L(bi_study)):g} m, above "
            "the L search's answer.\n")
    lines.extend(paper_lines(study, bi_study, search.get("study")))

    add("## L_c verdict, by method\n")
    add("- " + "; ".join(f"**{methods.label(report_mod.method_of(s))}: "
                         f"{report_mod.verdict_text(s)}** (spectral estimate "
                         f"{fmt(s.get('spectral_critical_length'), unit='m')})"
                         for s in (study, bi_study) if s) + ".\n")
    add("The rule (docs/metrics.md \"Critical length\", docs/studies.md): L_c is the largest L "
        "whose mesh-converged reference agrees with that of every smaller L (propagation "
        "distance within 0.5 %, arrival time at the probe within 0.1 %). Each method has its own convergence map "
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
    if not args.study_id:
        add(f"Whole script, start to report: **{fmt(timing.get('script_wall'))} s** wall "
            f"(load average at its start: {timing.get('load_at_start') or 'not recorded'}).\n")
    add(f"FE study request: `{json.dumps(study.get('request') or study_body(args))}`\n")
    if bi_study:
        add(f"BI study request: `{json.dumps(bi_study.get('request') or study_body(args, 'spectral_bi'))}`\n")
    if search.get("study"):
        add(f"BI L search request: `{json.dumps(search['study'].get('request') or {})}`\n")
    if damped.get("study"):
        add(f"FE study with the mesh damping: `{json.dumps(damped['study'].get('request') or {})}`\n")
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
            "The studies (FE, BI, the L search"
            + (" and the damped FE study" if damped.get("study") else "")
            + ") ran at the same time on the same workers.")
    add(f"- Machine: `nproc` = {timing['nproc']}, CPU {timing['cpu']}; server workers: "
        f"{timing['workers']}; load average (1, 5, 15 min) "
        + (f"when the script started: {timing['load_at_start']}, "
           if timing.get("load_at_start") and not args.study_id else "")
        + f"when the study finished: {timing['loadavg']} (the server's own two workers make "
        "about 2) — other work shared the machine when it exceeds the workers, "
        "and the wall times are then upper bounds.\n")

    # values table
    add("## Our numbers beside the paper's\n")
    add("| quantity | paper | ours | run |")
    add("| --- | --- | --- | --- |")
    for row in comparison_rows(study, chosen, results, metrics, fig2):
        add("| " + " | ".join(row) + " |")
    add("")
    add("The Fig. 2 rows (L = 5e-5 m) use the n_d = 40 run when the study has one, as the paper "
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
    lines.extend(map_table_lines(study))
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
    add("| method | verdict | spectral estimate | from L | paper |")
    add("| --- | --- | --- | --- | --- |")
    for st in (study, bi_study):
        if st:
            cl = st.get("critical_length") or {}
            add(f"| {methods.label(report_mod.method_of(st))} | "
                f"{report_mod.verdict_text(st)} | {fmt(st.get('spectral_critical_length'), unit='m')} | "
                f"{fmt(cl.get('spectral_from_L'), unit='m')} | L_c ≈ 1e-5 m |")
    add("\nThe reasons, the change per step in L and the n_d per L: the verdicts at the top.\n")

    add("## Figures\n")
    captions = {
        "velocity": "The FE side of Fig. 4a: |V| at x1 = 6 and 10 m of the FE run drawn for "
                    "each L (its coarsest mesh-converged run, else its finest, not converged).",
        "speed": "The FE side of Fig. 4b: rupture speed against x1 of the same FE runs, with "
                 "c_s and c_p.",
        "map": "Paper Fig. 2a: |V| in the x1–t plane with the slip front, the FE run of "
               "L = 5e-5 m (n_d = 40 where the study has it, as the paper).",
        "event_velocity": "Paper Fig. 2b: |V| at x1 = 6 and 10 m of the same run.",
        "event_speed": "Paper Fig. 2c: its rupture speed against x1, with c_s and c_p.",
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
    captions.update(search.get("captions") or {})
    order = (("Fig. 2: one slip event", ("map", "event_velocity", "event_speed")),
             ("Fig. 3: mesh convergence", ("mesh_convergence",)),
             ("Fig. 4: convergence with L", ("length_convergence", "velocity", "speed")),
             ("Fig. 5: the frictional strength and the friction filter",
              ("strength_spectrum", "filter")),
             ("Fig. 6: the critical length against the event's frequency",
              ("critical_frequency",)),
             ("Cost", ("cost",)))
    for heading, stems in order:
        drawn = [stem for stem in stems if stem in figures]
        if drawn:
            add(f"### {heading}\n")
        for stem in drawn:
            add(f"{captions[stem]}\n\n![{stem}]({rel(figures[stem], out_dir)})\n")
    for note in search.get("notes") or []:
        add(f"Not drawn: {note}\n")
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
        "`--fresh` recomputes them); `--study-id ID` (and `--bi-study-id ID`, "
        "`--search-study-id ID`) write the report of existing studies; `--bi-n-d-max` caps "
        "the BI ladder (default 320).\n")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")


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
        for needle in ("## Our numbers beside the paper's", "| quantity | paper | ours | run |",
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




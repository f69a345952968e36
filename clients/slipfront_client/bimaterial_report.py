"""The Markdown report of the bimaterial study (library of clients/bimaterial_study.py):
figures, the verdict on L_c and on plain Coulomb friction, the tables, and the quick-mode
shape checks. Every number comes from the runs; the rules are the server's (docs/studies.md)
and, for the Coulomb runs, the client's copy of them (analysis.py)."""

import datetime
import os
import tempfile

from . import bimaterial as bm
from . import report as report_mod
from . import results as results_mod
from .local_server import log
from . import analysis
from .report import converged_n_d, fmt, percent
from .reproduction import cpu_model
from .reproduction_measures import chosen_run, runs_by_L, runs_table
from .reproduction_report import map_table_lines

PROBES = (-20.0, 20.0, 40.0)  # x1 [m] of the V(t) panels: both directions, and the probe
ILL_POSED = "ill-posed"
COULOMB_WINDOW = 0.025  # s: the Coulomb slip-rate figure's time axis


def load(api, job_id, cache):
    return results_mod.load_result(results_mod.resolve_source(job_id, lambda: api, cache, log))


def reference_runs(study):
    """{L: (run, converged)}: the run drawn for each L (the coarsest converged one, else the
    finest succeeded one)."""
    return {L: chosen_run(study, L) for L in runs_by_L(study)}


def zoom_to_front(ax, result, margin=30.0):
    """Limit a map to where the front went (± `margin` m, from t = 0 to 1.5 × its last
    time): an arrested event fills a small part of the 600 m, 0.1 s plane."""
    import numpy as np
    known = np.isfinite(result.arrival_time)
    if not known.any():
        return
    x, t = result.front_x1[known], result.arrival_time[known]
    lo, hi = max(float(result.x1.min()), x.min() - margin), min(float(result.x1.max()), x.max() + margin)
    ax.set_xlim(lo, hi)
    ax.set_ylim(0.0, min(float(result.time.max()), 1.5 * float(t.max())))


def make_figures(study, drawn, coulomb_results, crow, fig_dir, formats):
    from .plots import common, convergence, mesh_growth, slip_map, station_rates
    from .stations import load_stations
    made = {}

    def save(fig, stem):
        made[stem] = common.save_figure(fig, fig_dir, stem, formats)[0]
        log(f"figure {made[stem]}")

    points = convergence.points_from_json(study["convergence_map"], "bimaterial study map")
    fig, _ = convergence.plot_convergence(points, study.get("L_c"),
                                          "Convergence map, bimaterial Prakash–Clifton (BI)")
    save(fig, "convergence")
    ordered = [drawn[L] for L in sorted(drawn, reverse=True)]
    # The arrested mesh-converged L on a linear scale; the others apart (not mesh-converged,
    # or slipping over the whole interface at the end): their peaks, up to 100 times higher,
    # would flatten the arrested curves.
    calm = [r for r in ordered if converged_n_d(study, r.L) is not None
            and r.metrics.get("outcome") == "arrested"]
    if calm:
        fig, _ = station_rates.plot_station_rates(
            [(r.label(), load_stations(r.path)) for r in calm], PROBES,
            "Slip rate at the stations, mesh-converged arrested L (BI)")
        save(fig, "velocity_by_L")
    others = [r for r in ordered if r not in calm]
    if others:
        fig, _ = station_rates.plot_station_rates(
            [(r.label(), load_stations(r.path)) for r in others], PROBES,
            "Slip rate at the stations, the other L (BI; log scale)", log_scale=True)
        save(fig, "velocity_unconverged")
    for L in sorted(drawn, reverse=True):  # every L's map, converged or not
        fig, _ = slip_map.plot_map(drawn[L], PROBES, None, f"|V|, {drawn[L].label()}")
        zoom_to_front(fig.axes[0], drawn[L])
        save(fig, f"map_L{L:g}")
    if coulomb_results:
        default = [c for c, r in zip(coulomb_results, crow) if r["beta"] == 0.5] or coulomb_results
        # the first 25 ms (later every run flickers at every step), the finest mesh first
        # so that the coarser ones stay visible on top of it
        fig, _ = station_rates.plot_station_rates(
            [(r.label(), load_stations(r.path)) for r in reversed(default)], PROBES,
            "Slip rate at the stations, plain Coulomb under refinement (BI, β = 0.5)",
            log_scale=True, t_max=COULOMB_WINDOW)
        save(fig, "velocity_coulomb")
        finest = default[-1]
        fig, _ = slip_map.plot_map(finest, PROBES, None, f"|V|, {finest.label()}")
        save(fig, "map_coulomb")
    series = [(f"Coulomb (μ = 0.7), β = {beta:g}",
               [(r["n_d"], r.get("max_slip_velocity")) for r in crow if r["beta"] == beta], "line")
              for beta in sorted({r["beta"] for r in crow}, reverse=True)]
    for L, runs in sorted(runs_by_L(study).items(), reverse=True):
        series.append((f"Prakash–Clifton L = {L:g} m",
                       [(float(r["n_d"]), (r.get("_metrics") or {}).get("max_slip_velocity"))
                        for r in runs], "flat"))
    fig, _ = mesh_growth.plot_growth(series, "max |V| over the run [m/s]",
                                     "Peak slip rate against the mesh (BI)")
    save(fig, "peak_rate_growth")
    return made


def coulomb_lines(crow):
    lines = ["| β | n_d | dx [m] | outcome | convergence (client, same rule, same β) | "
             "propagation distance [m] | arrival at 40 m [s] | max \\|V\\| [m/s] | "
             "rupture time at −20 / +20 / +40 m [ms] | wall [s] | flagged ill-posed |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in crow:
        st = {float(s["x1"]): s.get("rupture_time") for s in r.get("stations") or []}
        times = " / ".join(fmt(st.get(x) * 1e3 if st.get(x) is not None else None, 4)
                           for x in PROBES)
        flagged = any(ILL_POSED in w for w in r.get("warnings") or [])
        lines.append(f"| {r['beta']:g} | {r['n_d']:g} | {r['dx']:g} | "
                     f"{r.get('outcome') or r.get('status')} | {r.get('convergence')} | "
                     f"{fmt(r.get('propagation_distance'), 5)} | "
                     f"{fmt(r.get('arrival_time_at_probe'), 5)} | "
                     f"{fmt(r.get('max_slip_velocity'), 4)} | {times} | "
                     f"{fmt(r.get('wall_time_s'))} | {'yes' if flagged else 'no'} |")
    lines.append("")
    for beta, steps in bm.peak_ratios(crow).items():
        lines.append(f"- β = {beta:g}: max |V| grows by "
                     + ", ".join(f"× {fmt(q, 3)} from n_d = {a:g} to {b:g}" for a, b, q in steps)
                     + " (a mesh-independent answer would give × 1).")
    warnings = sorted({w for r in crow for w in r.get("warnings") or []})
    if warnings:
        lines += ["", "The runs' own warnings (the ill-posedness warning on every Coulomb run, "
                  "the others where they apply):", ""]
        lines += [f"- {w}" for w in warnings]
    return lines + [""]


def pc_peak_lines(study):
    """max |V| of every Prakash-Clifton run, per L and n_d: bounded under refinement."""
    by_L = runs_by_L(study)
    nds = sorted({float(r["n_d"]) for r in study.get("runs") or []})
    lines = ["| L [m] | " + " | ".join(f"max \\|V\\| at n_d = {n:g} [m/s]" for n in nds) + " |",
             "| --- | " + " | ".join("---" for _ in nds) + " |"]
    for L in sorted(by_L, reverse=True):
        cells = []
        for n in nds:
            r = next((r for r in by_L[L] if abs(float(r["n_d"]) - n) < 1e-9), None)
            cells.append(fmt((r or {}).get("_metrics", {}).get("max_slip_velocity"), 4) if r else "")
        lines.append(f"| {L:g} | " + " | ".join(cells) + " |")
    return lines + [""]


def pc_growth(study):
    """Largest ratio of max |V| between successive meshes of one L (the regularised runs)."""
    worst = None
    for runs in runs_by_L(study).values():
        peaks = [(r.get("_metrics") or {}).get("max_slip_velocity") for r in runs]
        for a, b in zip(peaks, peaks[1:]):
            if a and b:
                worst = max(worst or 0.0, b / a)
    return worst


def last_peak_ratio(study, L):
    """(coarse n_d, fine n_d, ratio) of max |V| between the two finest runs of one L."""
    runs = [r for r in runs_by_L(study).get(L, [])
            if (r.get("_metrics") or {}).get("max_slip_velocity")]
    if len(runs) < 2:
        return None
    a, b = runs[-2], runs[-1]
    return (float(a["n_d"]), float(b["n_d"]),
            b["_metrics"]["max_slip_velocity"] / a["_metrics"]["max_slip_velocity"])


def saturated_lines(study, rows):
    """A mesh-converged L whose run slipped over the whole interface: the rule's metrics (the
    distance, the arrival at the probe) saturate there, so say what the peak does."""
    out = []
    for L, row in sorted(rows.items(), reverse=True):
        last = last_peak_ratio(study, L)
        if not row["converged"] or row["outcome"] != "running_at_end" or not last:
            continue
        out.append(f"L = {L:g} m is mesh-converged by the paper's rule, but its event is of "
                   "another kind: the whole periodic interface slips by the end (propagation "
                   "distance = the width), which the rule's distance cannot resolve, and its "
                   f"peak |V| still changes × {fmt(last[2], 3)} from n_d = {last[0]:g} to "
                   f"{last[1]:g}: read its answer as the distance and arrival time only.")
    return out


def finest_rows(study):
    """{L: row} of each L's finest succeeded run (analysis.py row keys, plus max |V|,
    whether the L is mesh-converged and the n_d)."""
    out = {}
    for L, runs in runs_by_L(study).items():
        done = [r for r in runs if r.get("job_status") == "succeeded"]
        if not done:
            continue
        r = done[-1]
        m = r.get("_metrics") or {}
        out[L] = {"L": L, "n_d": float(r["n_d"]), "outcome": m.get("outcome"),
                  "propagation_distance": m.get("propagation_distance"),
                  "arrival_time_at_probe": m.get("arrival_time_at_probe"),
                  "arrest_position": m.get("arrest_position"),
                  "max_slip_velocity": m.get("max_slip_velocity"),
                  "converged": converged_n_d(study, L) is not None}
    return out


def change(value, reference):
    """|value − reference| / |reference|, None when either is missing or the reference 0."""
    if not isinstance(value, (int, float)) or not isinstance(reference, (int, float)) \
            or reference == 0:
        return None
    return abs(value - reference) / abs(reference)


def steps_lines(study):
    """Each L's finest run against the next smaller L's, converged or not: the same rule
    as L_c, shown for every step so that the reader sees where the behaviour changes."""
    rows = finest_rows(study)
    lengths = sorted(rows, reverse=True)
    lines = ["| L [m] (n_d) | outcome | mesh-converged | propagation [m] | arrest [m] | "
             "arrival at 40 m [ms] | max \\|V\\| [m/s] | against the next smaller L |",
             "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for big, small in zip(lengths, lengths[1:] + [None]):
        a = rows[big]
        if small is None:
            against = "—"
        else:
            b = rows[small]
            d = change(a.get("propagation_distance"), b.get("propagation_distance"))
            t = change(a.get("arrival_time_at_probe"), b.get("arrival_time_at_probe"))
            against = (f"L = {small:g}: distance {percent(d)}, arrival {percent(t)}: "
                       + ("agree" if analysis.results_agree(a, b) else "disagree"))
        arrival = a.get("arrival_time_at_probe")
        lines.append(f"| {big:g} ({a['n_d']:g}) | {a.get('outcome')} | "
                     f"{'yes' if a['converged'] else 'no'} | {fmt(a.get('propagation_distance'), 5)} | "
                     f"{fmt(a.get('arrest_position'), 4)} | "
                     f"{fmt(arrival * 1e3 if arrival is not None else None, 5)} | "
                     f"{fmt(a.get('max_slip_velocity'), 4)} | {against} |")
    return lines + [""]


def reading(study, crow):
    """What the comparisons say, from the finest run of each L: the largest L's that agree
    pairwise, where agreement breaks, and how the smallest L compares with Coulomb."""
    rows = finest_rows(study)
    lengths = sorted(rows, reverse=True)
    if len(lengths) < 2:
        return []
    top = [lengths[0]]
    for big, small in zip(lengths, lengths[1:]):
        if not (rows[big]["converged"] and rows[small]["converged"]
                and analysis.results_agree(rows[big], rows[small])):
            break
        top.append(small)
    out = []
    if len(top) > 1:
        out.append(f"The large L's agree with each other: L = {', '.join(f'{L:g}' for L in top)} m "
                   "(mesh-converged, same result within 0.5 % / 0.1 %): a plateau at the "
                   "**large**-L end (presumably where the regularisation filters the normal-stress "
                   "changes out of the event: not checked here); below it the result depends on L.")
    below = [L for L in lengths if L < top[-1]]
    if below:
        out.append("Below L = " + f"{top[-1]:g} m the result moves with L: "
                   + "; ".join(f"L = {L:g} m ({rows[L]['outcome']}, propagation "
                               f"{fmt(rows[L]['propagation_distance'], 4)} m, max |V| "
                               f"{fmt(rows[L]['max_slip_velocity'], 3)} m/s, "
                               + ("mesh-converged" if rows[L]["converged"] else
                                  f"not mesh-converged up to n_d = {rows[L]['n_d']:g}") + ")"
                               for L in below) + ".")
    smallest = rows[lengths[-1]]
    same_mesh = [r for r in crow if r["beta"] == 0.5 and abs(r["n_d"] - smallest["n_d"]) < 1e-9]
    if same_mesh and not smallest["converged"]:
        c = same_mesh[0]
        out.append(f"At the smallest L ({lengths[-1]:g} m) the regularised run behaves like plain "
                   f"Coulomb at the same mesh (n_d = {c['n_d']:g}: {smallest['outcome']} vs "
                   f"{c.get('outcome')}, propagation {fmt(smallest['propagation_distance'], 4)} vs "
                   f"{fmt(c.get('propagation_distance'), 4)} m, max |V| "
                   f"{fmt(smallest['max_slip_velocity'], 3)} vs {fmt(c.get('max_slip_velocity'), 3)} m/s) "
                   "and does not converge: as L decreases the answer approaches the ill-posed "
                   "Coulomb problem, which has no mesh-independent limit. **No critical length in "
                   "the paper's sense** (an L below which every L gives the same, converged "
                   "answer) exists on this grid.")
    return out


def verdict(study, crow):
    """The sentences the report leads with, from the runs."""
    v = report_mod.verdict_text(study)
    cl = study.get("critical_length") or {}
    out = []
    if v.startswith("L_c ="):
        nxt = cl.get("next_larger_L")
        out.append(f"**A critical length exists at this bimaterial interface: {v}** (the "
                   "paper's rules on mesh-converged BI runs); the true threshold lies between "
                   f"{fmt(study.get('L_c'))} m and "
                   + (f"{fmt(nxt)} m, the next larger L of the study, which breaks agreement."
                      if nxt is not None else "the largest L studied: it is only a lower bound."))
    else:
        out.append(f"**Critical length: {v}** ({cl.get('reason') or 'see below'}).")
    for beta, steps in bm.peak_ratios(crow).items():
        group = [r for r in crow if r["beta"] == beta]
        converged = [r["n_d"] for r in group if r.get("convergence") == "converged"]
        out.append(f"**Plain Coulomb (β = {beta:g})**: "
                   + ("no mesh agrees with the next finer one by the paper's rule"
                      if not converged else f"n_d = {converged} agree with the next finer mesh")
                   + "; max |V| " + ", ".join(f"× {fmt(q, 3)} ({a:g} → {b:g})"
                                            for a, b, q in steps)
                   + f"; flagged ill-posed by the solver in "
                   f"{sum(any(ILL_POSED in w for w in r['warnings']) for r in group)}"
                   f" of {len(group)} runs.")
    out += reading(study, crow)
    out += saturated_lines(study, finest_rows(study))
    worst = pc_growth(study)
    out.append(f"Prakash–Clifton, for comparison: max |V| changes by at most × {fmt(worst, 3)} "
               "between successive meshes of one L.")
    return out


def report(args, api, study, run):
    """Write the report; in quick mode check its shape. Returns the exit code."""
    metrics = bm.study_metrics(api, study)
    crow = bm.coulomb_rows(run["coulomb_jobs"])
    out = os.path.abspath(args.out)
    out_dir = os.path.dirname(out)
    os.makedirs(out_dir, exist_ok=True)
    fig_dir = os.path.join(out_dir, "figures", "bimaterial")
    server = run.get("server")
    cache = os.path.join(server.data_dir if server else tempfile.mkdtemp(), "downloads")
    chosen = reference_runs(study)
    drawn = {L: load(api, r["job_id"], cache) for L, (r, _) in chosen.items()
             if r is not None and r.get("outcome") != "no_rupture"}
    coulomb_results = [load(api, r["id"], cache) for r in crow if r.get("status") == "succeeded"]
    formats = [f.strip() for f in args.format.split(",") if f.strip()]
    figures = make_figures(study, drawn, coulomb_results, crow, fig_dir, formats)
    run_sum = sum(float(m.get("wall_time_s") or 0) for m in metrics.values()) + sum(
        float(r.get("wall_time_s") or 0) for r in crow)
    run["span"] = bm.computation_span(api, [r["job_id"] for r in study.get("runs") or []]
                                      + [r["id"] for r in crow])
    write(out, args, study, run, crow, chosen, metrics, figures, run_sum)
    log(f"wrote {out}; wall {run['wall']:.1f} s, sum of run wall times {run_sum:.1f} s; "
        f"{report_mod.verdict_text(study)}; Coulomb peak ratios {bm.peak_ratios(crow)}")
    if not args.quick:
        return 0
    fails = check_shape(args, study, crow, out, figures)
    for f in fails:
        log("CHECK FAILED: " + f)
    if not fails:
        log("quick checks passed")
    return 1 if fails else 0


def write(path, args, study, run, crow, chosen, metrics, figures, run_sum):
    out_dir = os.path.dirname(os.path.abspath(path))

    def img(stem, alt):
        return f"![{alt}]({os.path.relpath(figures[stem], out_dir)})\n" if stem in figures else ""

    lines = []
    add = lines.append
    add("# The paper's question at a bimaterial interface"
        + (" — QUICK RUN (200 m, 30 ms, coarse; not the scene's answer)" if args.quick else "")
        + "\n")
    add("Does the critical length of Kammer et al. (2014) exist when the interface lies "
        "between **two different elastic solids**, where plain Coulomb friction is ill-posed "
        "(Adams 1995; Ranjith & Rice 2001; docs/physics.md)? The scene is the "
        f"`{bm.PRESET}` preset (docs/presets.md: upper ρ 2730.834, c_s 2620, c_p 4537.973; "
        "lower ρ 2745.739, c_s 3091.6, c_p 5354.808; σ −130 MPa; τ 89.18 MPa, 100.1 MPa on "
        "|x1| ≤ 10 m; μ = 0.7, V* = 0.26 m/s; 600 m periodic, 0.1 s) by the spectral "
        "boundary-integral method, L varied, and the same scene with plain Coulomb friction "
        "(μ = 0.7, no regularisation) under mesh refinement. "
        f"Generated by `clients/bimaterial_study.py` on "
        f"{datetime.datetime.utcnow().strftime('%Y-%m-%d %H:%M')} UTC from study "
        f"`{study.get('id')}` and {len(crow)} Coulomb jobs.\n")
    add("## Verdict\n")
    for sentence in verdict(study, crow):
        add(f"- {sentence}")
    add("")
    lines.extend(report_mod.verdict_lines(study))
    add("The rules (docs/metrics.md, docs/studies.md): a run is mesh-converged when the next "
        "finer mesh changes the propagation distance by < 0.5 % and the arrival time at the "
        "probe (x1 = 40 m here) by < 0.1 %; L_c is the largest L whose mesh-converged "
        "reference agrees, by the same tolerances, with that of every smaller L.\n")
    add("## Every L against the next smaller one\n")
    add("Each L's finest run (mesh-converged or not), compared with the next smaller L's by the "
        "same rule (distance < 0.5 %, arrival < 0.1 %); the server's L_c uses only the "
        "mesh-converged ones.\n")
    lines.extend(steps_lines(study))
    add("## How it was made\n")
    add("```sh\n/usr/bin/python3 clients/bimaterial_study.py" + (" --quick" if args.quick else "")
        + "\n```\n")
    add(f"- L = {', '.join(f'{L:g}' for L in args.L)} m; n_d ladder {args.ladder} (cap "
        f"{max(args.ladder)}), refined by the server until two successive meshes agree; "
        "Coulomb at (n_d, β) = " + ", ".join(f"({n:g}, {b:g})" for n, b in args.coulomb)
        + ", β the BI time-step factor (dt = β dx / c_s of the faster solid). Every run: "
        "one solver thread; the Prakash–Clifton runs at the BI defaults (β = 0.5, 1 corrector "
        "pass).")
    add(f"- Wall clock of the computation (first run submitted to last run finished, reused "
        f"runs by their original jobs): **{fmt(run.get('span'), 4)} s**; this invocation "
        f"took {run['wall']:.0f} s; "
        f"sum of the runs' own wall times: **{run_sum:.0f} s** over "
        f"{len(metrics) + len(crow)} runs ({sum(1 for r in study.get('runs') or [] if r.get('cached_from'))} "
        "reused from earlier jobs, counted with their original time).")
    add(f"- Machine: `nproc` = {len(os.sched_getaffinity(0))}, CPU {cpu_model()}; server workers "
        f"{args.workers if run.get('server') else '(external server)'}, niced; load average "
        f"(1, 5, 15 min) at the end: {run['loadavg']}. "
        "Other work shared the machine when the load exceeds the cores: the wall times are then "
        "upper bounds.\n")
    if getattr(args, "study_id", None):
        add(f"- Written from the finished study `{study.get('id')}` and its Coulomb jobs "
            "(`--study-id`, `--coulomb-ids`) after they ran: the load average above is the "
            "report's, not the computation's.\n")
    add("## Convergence map (Prakash–Clifton, BI)\n")
    lines.extend(map_table_lines(study))
    add(img("convergence", "convergence map"))
    add("Peak slip rate of every regularised run, per mesh:\n")
    lines.extend(pc_peak_lines(study))
    add("## Plain Coulomb under refinement\n")
    lines.extend(coulomb_lines(crow))
    add(img("peak_rate_growth", "peak slip rate against n_d"))
    add("## Figures\n")
    add("Slip rate |V| at x1 = −20 m (the negative direction), +20 m and +40 m (the "
        "preferred direction and the probe), the drawn run of each mesh-converged L that "
        "arrested (its coarsest mesh-converged run):\n")
    add(img("velocity_by_L", "slip rate by L"))
    if "velocity_unconverged" in figures:
        add("The other L (log scale): not mesh-converged (their finest run), or still slipping "
            "over the whole interface at the end (their coarsest mesh-converged run):\n")
        add(img("velocity_unconverged", "slip rate, the other L"))
    for L in sorted(chosen, reverse=True):
        r, conv = chosen[L]
        stem = f"map_L{L:g}"
        if stem in figures:
            add(f"|V| in the x1–t plane, L = {L:g} m (n_d = {float(r['n_d']):g}"
                + ("" if conv else ", not mesh-converged") + "):\n")
            add(img(stem, f"slip-rate map L = {L:g}"))
    add("Plain Coulomb, slip rate at the same points under refinement (first "
        f"{COULOMB_WINDOW * 1e3:g} ms; later every run flickers between stick and slip at "
        "every step), and its finest run's map:\n")
    add(img("velocity_coulomb", "Coulomb slip rate"))
    add(img("map_coulomb", "Coulomb slip-rate map"))
    add("## Runs (Prakash–Clifton)\n")
    lines.extend(runs_table(runs_by_L(study), metrics))
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")


def check_shape(args, study, crow, path, figures):
    """The quick run's shape: the study finished with every run succeeded and two meshes per
    L, the Coulomb runs succeeded and are flagged ill-posed with a peak rate growing with
    n_d, and the report holds its sections and figures."""
    fails = []
    if study.get("status") != "finished":
        fails.append(f"study status {study.get('status')!r}")
    by_L = runs_by_L(study)
    for L in args.L:
        runs = by_L.get(float(L), [])
        if len(runs) < 2 or any(r.get("job_status") != "succeeded" for r in runs):
            fails.append(f"L = {L:g}: {[(r['n_d'], r.get('job_status')) for r in runs]}")
    if sorted((r["n_d"], r["beta"]) for r in crow) != sorted((float(n), b) for n, b in args.coulomb):
        fails.append(f"Coulomb runs at {[(r['n_d'], r['beta']) for r in crow]}")
    for r in crow:
        if r.get("status") != "succeeded" or not any(ILL_POSED in w for w in r["warnings"]):
            fails.append(f"Coulomb n_d = {r['n_d']:g}: {r.get('status')}, not flagged ill-posed")
    for beta, steps in bm.peak_ratios(crow).items():
        if not steps or any(q <= 1 for _, _, q in steps):
            fails.append(f"Coulomb β = {beta:g}: max |V| does not grow with n_d: {steps}")
    text = open(path, encoding="utf-8").read() if os.path.isfile(path) else ""
    for needle in ("## Verdict", "## Convergence map", "## Plain Coulomb under refinement",
                   "Wall clock", "load average"):
        if needle not in text:
            fails.append(f"report lacks {needle!r}")
    linked = {stem for stem, fig in figures.items()
              if os.path.relpath(fig, os.path.dirname(path)) in text}
    for stems in (("convergence",), ("velocity_by_L", "velocity_unconverged"),
                  ("velocity_coulomb",), ("peak_rate_growth",)):
        if not linked.intersection(stems):
            fails.append(f"figure {' or '.join(stems)} missing or not linked")
    return fails



"""Measurements of the paper's study from its runs: the run chosen per L, Fig. 2 values
(peak slip velocity, front times, rupture speed), the cost rows of the speed-accuracy chart
and the comparison with the paper's published values (docs/physics.md; library of clients/reproduce_paper.py)."""

from .report import converged_n_d, fmt


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
    """The run of the paper's Fig. 2 values (the paper quotes them at n_d = 40): L = 5e-5 m at
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
    """Plain statements where the study disagrees with the paper's qualitative claims
    (docs/physics.md "The paper's published values")."""
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
    """The paper's published values (docs/physics.md) against our runs. `fig2` = (run, result) of figure2_run(); the Fig. 3 rows use
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



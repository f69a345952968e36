"""The opening of the reproduction report: the answer by each method (BI from the L search, FE
from its convergence study, said plainly where FE stops at the mesh cap and what its last mesh
cost) and the paper's L_c beside ours with the measured reason they differ (library of
clients/reproduce_paper.py). Every number comes from the studies' answers."""

from .report import converged_n_d, fmt, percent, verdict_text
from .reproduction_measures import runs_by_L

PAPER_L_C = 1e-5
V_STAR = 1e-4  # the paper scene's V* [m/s] (docs/physics.md)
PAPER_TOLERANCES = "0.5 % on the propagation distance, 0.1 % on the arrival time at x1 = 11 m"


CHANGE_KEYS = ("propagation_distance", "arrival_time_at_probe")


def relative_changes(new, old):
    """|new - old| / |new| of each of CHANGE_KEYS between two runs' metrics (None where either
    lacks it); rounding noise (equal node positions) is 0."""
    out = []
    for k in CHANGE_KEYS:
        if not (new.get(k) and old.get(k)):
            out.append(None)
            continue
        change = abs(float(new[k]) - float(old[k])) / abs(float(new[k]))
        out.append(0.0 if change < 1e-12 else change)
    return out


def _same(a, b):
    return a is not None and b is not None and abs(float(a) - float(b)) <= 1e-9 * abs(float(b))


def search_step_rows(search):
    rows = ["| L [m] → next smaller L [m] | change of propagation distance | change of arrival "
            "time | agree (0.5 % / 0.1 %) |", "| --- | --- | --- | --- |"]
    for s in search.get("steps") or []:
        ch = s.get("changes") or {}
        rows.append(f"| {fmt(s.get('L'))} → {fmt(s.get('smaller_L'))} | "
                    f"{percent(ch.get('propagation_distance'))} | "
                    f"{percent(ch.get('arrival_time'))} | {fmt(s.get('agree'))} |")
    return rows + [""]


def coulomb_rows(coulomb):
    rows = ["| L [m] | propagation distance against Coulomb | arrival time against Coulomb | "
            "meets Coulomb |", "| --- | --- | --- | --- |"]
    for s in coulomb.get("steps") or []:
        ch = s.get("changes") or {}
        rows.append(f"| {fmt(s.get('L'))} | {percent(ch.get('propagation_distance'))} | "
                    f"{percent(ch.get('arrival_time'))} | {fmt(s.get('agree'))} |")
    return rows + [""]


def search_lines(search_study, wall, n_runs, run_sum=None):
    """The BI answer: the L search's verdict, its steps and the comparison with Coulomb."""
    s = (search_study or {}).get("search") or {}
    if not s:
        return ["- **BI (L search)**: no L search in this report.", ""]
    L_c = s.get("L_c", search_study.get("L_c"))
    lines = [f"- **BI, L search: {'L_c = ' + fmt(L_c) + ' m' if L_c else 'no L_c'}** "
             f"(state `{s.get('state')}`), from L = {fmt(s.get('from'))} m by a factor "
             f"{fmt(s.get('factor'))}, L tried: {', '.join(fmt(L) for L in s.get('searched_L') or [])}; "
             f"{n_runs} runs in {fmt(wall)} s wall, {fmt(run_sum)} s summed over its runs (study "
             f"`{search_study.get('id')}`; it shared the two workers with the FE and BI studies, "
             "so its wall time is mostly waiting for FE runs; alone on the idle machine the "
             "same search takes 19.7 s, docs/studies-api.md \"L search\").",
             f"  Server's reason: {s.get('reason')}", ""]
    if s.get("steps"):
        lines += ["Each searched L against the next smaller one (the rule of docs/metrics.md "
                  "\"Critical length\"):", ""] + search_step_rows(s)
    c = s.get("coulomb") or {}
    if c:
        lines.append(f"Plain Coulomb beside the L (status `{c.get('status')}`): each L's "
                     "mesh-converged answer against the mesh-converged Coulomb answer of the "
                     "same scene.\n")
        if c.get("steps"):
            lines += coulomb_rows(c)
    return lines


def fe_lines(study, metrics, n_d_max, bi_study=None):
    """The FE answer from its convergence study: where FE converges, how it agrees with BI
    (the server's cross-method rows); where it stops, each L without a mesh-converged run,
    its last refinement's change and what that run cost."""
    lines = [f"- **FE, convergence study: {verdict_text(study)}** (study `{study.get('id')}`; "
             f"mesh cap n_d_max = {n_d_max})."]
    rows = [r for r in study.get("cross_method") or (bi_study or {}).get("cross_method") or []
            if (r.get("fe") or {}).get("propagation_distance")
            and (r.get("spectral_bi") or {}).get("propagation_distance")
            and converged_n_d(study, float(r["L"])) is not None]
    if rows:
        agree = [r for r in rows if r.get("agree")]
        diffs = [r.get("differences") or {} for r in rows]
        lines.append(
            "  - Where FE converges it agrees with BI: L = "
            + ", ".join(f"{fmt(r['L'])}" for r in sorted(rows, key=lambda r: -float(r["L"])))
            + f" m, {len(agree)} of {len(rows)} within the rule (propagation distance at most "
            f"{percent(max(float(d.get('propagation_distance') or 0) for d in diffs))} apart, "
            f"arrival time at most {percent(max(float(d.get('arrival_time_at_probe') or 0) for d in diffs))}; "
            "table \"Same L, both methods\").")
    for L, runs in sorted(runs_by_L(study).items(), reverse=True):
        ok = [r for r in runs if r.get("job_status") == "succeeded" and not r.get("regime")]
        if converged_n_d(study, L) is not None or len(ok) < 2:
            continue
        a, b = ok[-2], ok[-1]
        ma, mb = (metrics.get(r["job_id"]) or {} for r in (a, b))
        change = relative_changes(mb, ma)
        lines.append(f"  - L = {fmt(L)} m: **not mesh-converged up to the cap** n_d = "
                     f"{fmt(float(b['n_d']))}: the last refinement n_d = {fmt(float(a['n_d']))} → "
                     f"{fmt(float(b['n_d']))} still changed the propagation distance by "
                     f"{percent(change[0])} and the arrival time by {percent(change[1])}; that "
                     f"n_d = {fmt(float(b['n_d']))} run took {fmt(mb.get('wall_time_s'))} s "
                     "(the next mesh has 4× the nodes and twice the steps). Why: the "
                     "undamped lattice with nodal friction has a growing interface mode (rate "
                     "≈ 0.14 c_s/dx, faster on finer meshes) that Prakash–Clifton at this L "
                     "does not damp (docs/small-l-study.md); the BI method has no such mode.")
    lines.append("")
    return lines


def bi_study_step(bi_study, larger, smaller):
    for s in (bi_study.get("critical_length") or {}).get("steps_in_L") or []:
        if _same(s.get("from_L"), smaller) and _same(s.get("to_L"), larger):
            return s
    return None


def paper_lines(study, bi_study, search_study):
    """The paper's L_c beside ours, and the reason they differ, from the studies' numbers."""
    s = (search_study or {}).get("search") or {}
    L_c = s.get("L_c", (search_study or {}).get("L_c"))
    lines = ["## The paper's L_c beside ours\n",
             "| | L_c [m] | how |", "| --- | --- | --- |",
             f"| paper (§3.2, Fig. 4) | ≈ {PAPER_L_C:g} | FE, n_d 10 to 120; five L (1e-3 to "
             "5e-6 m); L_c read from the overlap of the two smallest L's curves |",
             f"| ours, BI L search | {fmt(L_c)} | the paper's mesh tolerances ({PAPER_TOLERANCES}) "
             f"applied between successive mesh-converged L, L divided by {fmt(s.get('factor'))} each step |",
             f"| ours, FE | {verdict_text(study)} | the same rule over the paper's L, FE meshes "
             "up to the cap |", ""]
    reasons = []
    if bi_study:
        step = bi_study_step(bi_study, 1e-5, 5e-6)
        if step:
            ch = step.get("changes") or {}
            reasons.append(
                f"From L = 1e-5 to 5e-6 m the mesh-converged BI runs still differ by "
                f"{percent(ch.get('propagation_distance'))} in propagation distance and "
                f"{percent(ch.get('arrival_time'))} in arrival time — above the tolerances the "
                "paper itself used for mesh convergence, so by its own numbers 1e-5 m is not "
                "yet the L below which nothing changes. The paper judged these two L \"nearly "
                "indiscernible\" on its Fig. 4; on ours (below) they nearly overlap too.")
    stuck = [L for L in (1e-5, 5e-6)
             if L in runs_by_L(study) and converged_n_d(study, L) is None]
    if stuck:
        tried = max(float(r["n_d"]) for L in stuck for r in runs_by_L(study)[L])
        reasons.append(
            f"FE: L = {' and '.join(f'{L:g}' for L in stuck)} m have no mesh-converged run up "
            f"to n_d = {tried:g} here (the paper reports n_d = 40 for 1e-5 m, finer for 5e-6 m, "
            "with the same tolerances), so our FE study cannot compare these L by the rule; BI "
            "converges there from n_d = "
            + ", ".join(f"{fmt(converged_n_d(bi_study, L))} (L = {L:g} m)" for L in stuck
                        if bi_study) + ".")
    if s.get("steps"):
        changes = [((st.get("changes") or {}).get("propagation_distance"), st.get("L"))
                   for st in s["steps"]]
        reasons.append("The L search's change of propagation distance from each L to the next "
                       "smaller: " + ", ".join(f"{percent(c)} at L = {fmt(L)} m" for c, L in changes)
                       + f"; its verdict: L_c = {fmt(L_c)} m (state `{s.get('state')}`).")
    rule = filter_rule_line(study, search_study, L_c)
    if rule:
        reasons.append(rule)
    coul = s.get("coulomb") or {}
    agree = [st for st in coul.get("steps") or [] if st.get("agree")]
    if agree:
        reasons.append(f"Against plain Coulomb (paper §5: below L_c the event is Coulomb's) "
                       f"the first L that meets it is {fmt(agree[0].get('L'))} m.")
    lines.append("Why they differ (measured, not tuned):\n")
    lines += [f"- {r}" for r in reasons] or ["- (no runs at the paper's L to compare)"]
    lines.append("")
    return lines


def filter_rule_line(study, search_study, L_c):
    """Both L_c read through the filter rule (paper §5, eq. 6 at A/A0 = 0.98; Fig. 6): the
    frequency each needs, with |V| of the search's smallest-L run, beside the FE n_d = 20
    mesh's highest frequency that the paper used."""
    from .plots.critical_frequency import frequency_of
    from .plots.filter_response import highest_frequency
    own = [r for r in (search_study or {}).get("runs") or [] if not r.get("regime")
           and (r.get("_metrics") or {}).get("spectral_velocity") is not None]
    if not own or not L_c:
        return None
    v = float(min(own, key=lambda r: float(r["L"]))["_metrics"]["spectral_velocity"])
    f20 = [highest_frequency(r["_metrics"]["stable_dt"]) for r in study.get("runs") or []
           if abs(float(r["n_d"]) - 20) < 1e-9 and (r.get("_metrics") or {}).get("stable_dt")]
    return (f"Through the filter rule (eq. 6 at A/A0 = 0.98, |V| = {v:.3g} m/s; Fig. 6), "
            f"L_c = {PAPER_L_C:g} m is the critical length of an event whose frequencies stop "
            f"at {frequency_of(PAPER_L_C, V_STAR, v):.3g} Hz — the paper took the highest "
            "frequency of its n_d = 20 mesh (§5"
            + (f"; ours: {f20[0]:.3g} Hz" if f20 else "") + ") — and our "
            f"L_c = {fmt(L_c)} m that of an event with content up to "
            f"{frequency_of(L_c, V_STAR, v):.3g} Hz.")


def damped_lines(damped_study, metrics, bi_study, wall):
    """FE with the vanishing mesh-scale damping where the undamped lattice stops: its verdict
    per L (converged from which mesh, or the last refinement's change) and its finest run
    against BI's reference run of the same L."""
    runs = runs_by_L(damped_study)
    zeta = ((damped_study.get("request") or {}).get("base") or {}).get("fe", {}).get("mesh_damping")
    lines = [f"- **FE with the mesh damping** (`fe.mesh_damping` = {fmt(zeta)}: a damping force "
             "∝ dx that vanishes under refinement and removes the undamped lattice's growing "
             "interface mode, docs/small-l-study.md; study "
             f"`{damped_study.get('id')}`, {fmt(wall)} s wall):"]
    bi_ref = {}
    for r in sorted((bi_study or {}).get("runs") or [], key=lambda r: float(r["n_d"])):
        m = r.get("_metrics") or {}
        if (not r.get("regime") and m and converged_n_d(bi_study, float(r["L"])) is not None
                and float(r["n_d"]) >= converged_n_d(bi_study, float(r["L"]))):
            bi_ref[float(r["L"])] = m  # the finest (last) run of each L
    for L, rs in sorted(runs.items(), reverse=True):
        ok = [r for r in rs if r.get("job_status") == "succeeded"]
        if not ok:
            continue
        nd = converged_n_d(damped_study, L)
        finest = metrics.get(ok[-1]["job_id"]) or {}
        text = (f"mesh-converged from n_d = {fmt(nd)}" if nd is not None else
                "not mesh-converged up to n_d = " + fmt(float(ok[-1]["n_d"])))
        if nd is None and len(ok) >= 2:
            prev = metrics.get(ok[-2]["job_id"]) or {}
            ch = relative_changes(finest, prev)
            text += (f" (the last refinement still changed the propagation distance by "
                     f"{percent(ch[0])} and the arrival time by {percent(ch[1])})")
        ref = bi_ref.get(L)
        against = ""
        if ref and finest.get("propagation_distance") and ref.get("propagation_distance"):
            d = relative_changes(ref, finest)  # against BI: relative to BI's value
            against = (f"; its n_d = {fmt(float(ok[-1]['n_d']))} run against BI's "
                       f"mesh-converged run of the same L: propagation distance "
                       f"{fmt(finest.get('propagation_distance'), 5)} / "
                       f"{fmt(ref.get('propagation_distance'), 5)} m ({percent(d[0])}), arrival "
                       f"time {fmt(finest.get('arrival_time_at_probe'), 6)} / "
                       f"{fmt(ref.get('arrival_time_at_probe'), 6)} s ({percent(d[1])}); "
                       f"that run took {fmt(finest.get('wall_time_s'))} s")
        lines.append(f"  - L = {fmt(L)} m: {text}{against}.")
    lines.append("")
    return lines

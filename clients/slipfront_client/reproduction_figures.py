"""The paper's Fig. 3a/b, 4, 5 and 6 from the reproduction's studies (library of
clients/reproduce_paper.py): which runs each figure draws, their result files, the figures.

Fig. 3a/b draws every FE run of the mesh-convergence L (the paper's 5e-6 m); Fig. 4 and 5 the
mesh-converged run (the coarsest converged mesh, the paper's triangle) of every L of the BI
study and of the BI L search, with the search's Coulomb run; Fig. 6 every such run's spectral
frequency and estimate (docs/metrics.md "Spectral estimate") with the search's L_c.
"""

import numpy as np

from . import methods
from . import results as results_mod
from .report import fmt
from .reproduction_story import V_STAR

MESH_L = 5e-6  # the paper's Fig. 3


def succeeded(runs):
    return [r for r in runs if r.get("job_status") == "succeeded"]


def reference_run(runs):
    """The coarsest mesh-converged run of one L (the paper's triangle), else None."""
    ok = [r for r in succeeded(runs) if (r.get("convergence") or {}).get("status") == "converged"]
    return min(ok, key=lambda r: float(r["n_d"])) if ok else None


def converged_by_L(*studies):
    """{L: run}: the reference run of each L over the studies (Coulomb runs left out; the
    first study that has a converged run of an L wins), and the Coulomb reference or None."""
    out, coulomb = {}, None
    for study in studies:
        runs = (study or {}).get("runs") or []
        by_L = {}
        for r in runs:
            if not r.get("regime"):
                by_L.setdefault(float(r["L"]), []).append(r)
        for L, rs in by_L.items():
            ref = reference_run(rs)
            if ref is not None and ref.get("outcome") == "no_rupture":
                continue  # no event to draw or analyse (the paper's Fig. 4 leaves it out too)
            if ref is not None and not any(abs(L - k) <= 1e-9 * L for k in out):
                out[L] = ref
        coulomb = coulomb or reference_run([r for r in runs if r.get("regime") == "coulomb"])
    return out, coulomb


def mesh_runs(study, L):
    """Every succeeded run of `L` in the study, coarse to fine."""
    rs = [r for r in succeeded(study.get("runs") or []) if not r.get("regime")
          and abs(float(r["L"]) - L) <= 1e-9 * L]
    return sorted(rs, key=lambda r: float(r["n_d"]))


def spectral_points(refs, metrics):
    """[(label, L, f, spectral L_c, |V|)] of the reference runs that have the estimate."""
    points = []
    for L in sorted(refs, reverse=True):
        m = metrics.get(refs[L]["job_id"]) or {}
        f, lc, v = (m.get(k) for k in ("spectral_frequency", "spectral_critical_length",
                                       "spectral_velocity"))
        if f and lc and v is not None:
            points.append((f"run L = {L:g} m, n_d = {float(refs[L]['n_d']):g}", L, float(f),
                           float(lc), float(v)))
    return points


def mesh_frequencies(studies, metrics):
    """{"FE n_d = 20": 1/(pi stable_dt)} of every mesh in the studies whose method has a stable
    step (FE's; the spectral BI method has none: null) (paper Fig. 5c)."""
    from .plots.filter_response import highest_frequency
    out = {}
    for study in studies:
        for r in (study or {}).get("runs") or []:
            m = metrics.get(r["job_id"]) or r.get("_metrics") or {}
            if m.get("stable_dt"):
                label = methods.label(m.get("method"))
                out[f"{label} $\\bar f_{{{float(r['n_d']):g}}}$"] = highest_frequency(m["stable_dt"])
    return out


def make_paper_figures(study, bi_study, search_study, metrics, load, save, mesh_L=MESH_L):
    """Fig. 3a/b, 4, 5, 6; `load(run)` gives a run's Result, `save(fig, stem, caption)` writes
    a figure. Returns notes on what could not be drawn."""
    from .plots import critical_frequency, length_convergence, mesh_convergence
    from .plots import strength_spectrum
    notes = []
    runs = mesh_runs(study, mesh_L)
    if len(runs) >= 2:
        fig, _ = mesh_convergence.plot_mesh_convergence(
            [load(r) for r in runs], title=f"FE mesh convergence at L = {mesh_L:g} m")
        save(fig, "mesh_convergence",
             f"Paper Fig. 3a, 3b: the FE runs of L = {mesh_L:g} m on every mesh "
             f"(n_d = {', '.join(fmt(float(r['n_d'])) for r in runs)}; darker is finer): "
             "|V| at x1 = 6 and 10 m and the rupture speed. Fig. 3c is the convergence map "
             "above.")
    else:
        notes.append(f"Fig. 3a/b: fewer than two FE runs of L = {mesh_L:g} m.")
    refs, coulomb = converged_by_L(bi_study, search_study)
    L_c = (search_study or {}).get("L_c") or ((search_study or {}).get("search") or {}).get("L_c")
    if refs:
        loaded = {L: load(r) for L, r in refs.items()}
        fig, _ = length_convergence.plot_length_convergence(
            loaded, L_c, load(coulomb) if coulomb else None,
            title="Mesh-converged run of each L (spectral BI)")
        save(fig, "length_convergence",
             "Paper Fig. 4a, 4b: the mesh-converged BI run of each L (the BI study's L and the "
             "L search's; darker is smaller L), |V| at x1 = 6 and 10 m and the rupture speed; "
             + (f"the run at the L search's L_c = {fmt(L_c)} m is drawn thick" if L_c else
                "the L search found no L_c")
             + ("; plain Coulomb dotted black" if coulomb else "") + ".")
        meshes = mesh_frequencies((study,), metrics)
        fig, _ = strength_spectrum.plot_strength_spectrum(loaded, meshes)
        save(fig, "strength_spectrum",
             "Paper Fig. 5: (a) the frictional strength τ_s at x1 = 6 m of the same runs, "
             "(b) its power spectrum (end-point line removed, Hann window, as "
             "docs/metrics.md \"Spectral estimate\"), (c) the friction filter A/A0 (eq. 6) for "
             "each L, with the FE meshes' highest eigenfrequencies 1/(π dt_stable) from the "
             "runs' `stable_dt` (dashed).")
        points = spectral_points(refs, metrics)
        halves, nyquist = [], None
        if coulomb:
            reference = load(coulomb)
            for L in sorted(loaded, reverse=True):
                f, ratio = strength_spectrum.amplitude_against(loaded[L], reference)
                halves.append((f"L = {L:g} m", L,
                               strength_spectrum.half_amplitude_frequency(f, ratio)))
                nyquist = float(f[-1])
        fig, _ = critical_frequency.plot_critical_frequency(points, L_c, halves=halves,
                                                            nyquist=nyquist)
        v = float(np.median([p[4] for p in points])) if points else None
        save(fig, "critical_frequency", critical_frequency_caption(halves, nyquist, v))
    else:
        notes.append("Fig. 4-6: no mesh-converged BI run.")
    return notes


def critical_frequency_caption(halves, nyquist, slip_velocity=None):
    """The caption of Fig. 6, with the measured half-amplitude frequencies when there are."""
    text = ("Paper Fig. 6 from our runs: each mesh-converged BI run's highest frequency (99 % "
            "of the τ_s power at x1 = 6 m, `spectral_frequency`) and its spectral estimate "
            "`spectral_critical_length` (dots), on the filter rule L_c(f) (A/A0 = 0.98); "
            "the L search's L_c and the paper's 1e-5 m as horizontal lines, each with a star "
            "at the frequency the rule needs for it (L_c ∝ 1/f, paper §5)")
    if not halves:
        return text + "."
    found = [h for h in halves if h[2]]
    text += ("; × the filter measured on the runs: the frequency above which each run's τ_s "
             "amplitude at x1 = 6 m stays below half that of the plain-Coulomb run (the same "
             "window, resampled on the coarser output step), beside eq. 6 at A/A0 = ½ (dotted): "
             + ", ".join(f"{fmt(h[2])} Hz at L = {fmt(h[1])} m" for h in found))
    if len(found) < len(halves):
        text += f"; the smaller L stay above ½ up to the records' Nyquist {fmt(nyquist)} Hz"
    text += (". The dots' measure (99 % of the power) sits at the event's low-frequency content "
             "near 1 Hz for every L and does not separate them; the × do")
    if slip_velocity:
        from .plots.critical_frequency import critical_length
        between = [h for h in found
                   if critical_length(1.0, V_STAR, slip_velocity) / h[1] <= h[2]
                   <= critical_length(1.0, V_STAR, slip_velocity, 0.5) / h[1]]
        text += (f": {len(between)} of {len(found)} lie between eq. 6's onset (A/A0 = 0.98, "
                 "solid) and its half point (½, dotted) at the event's slip rate — the event "
                 "loses half its amplitude at lower frequencies than one harmonic perturbation "
                 "at a fixed slip rate (eq. 6's model) would")
    return text + "."


def loader(api, cache, log):
    """load(run) -> Result, each file downloaded once."""
    seen = {}

    def load(run):
        if run["job_id"] not in seen:
            seen[run["job_id"]] = results_mod.load_result(
                results_mod.resolve_source(run["job_id"], lambda: api, cache, log))
        return seen[run["job_id"]]
    return load

"""Client-side convergence and error estimates from run summaries (rows of
`results.run_row`: L, n_d, status, outcome, propagation_distance, arrival_time_at_probe,
wall_time_s).

Convergence (SPEC §2, the paper's criterion): a run is `converged` when the next finer n_d
with the same L changes `propagation_distance` by < 0.5 % and `arrival_time_at_probe` by
< 0.1 %; `not_converged` otherwise; `unknown` without a finer partner; `pending` while the
job is queued or running; `diverged` when it diverged. Runs are grouped by L only: give it
runs that differ in nothing else.
"""

import math

DISTANCE_TOL = 0.005
ARRIVAL_TOL = 0.001
STATUSES = ("converged", "not_converged", "diverged", "pending", "unknown")


def _relative_change(value, reference):
    """|value - reference| / |reference|; 0 when both are missing; inf when one is."""
    missing = [v is None or (isinstance(v, float) and math.isnan(v)) for v in (value, reference)]
    if all(missing):
        return 0.0
    if any(missing):
        return math.inf
    if reference == 0:
        return 0.0 if value == 0 else math.inf
    return abs(value - reference) / abs(reference)


def _finished(row):
    return row.get("status") in (None, "succeeded") and row.get("outcome") != "diverged"


def own_status(row):
    """The status a run has on its own: pending, diverged, or None (needs a partner)."""
    status = row.get("status")
    if status in ("queued", "running"):
        return "pending"
    if row.get("outcome") == "diverged" or status == "failed":
        return "diverged"
    if status == "cancelled":
        return "unknown"
    return None


def convergence_statuses(rows):
    """A copy of `rows`, each with `convergence` set (see the module docstring)."""
    out = [dict(r) for r in rows]
    by_L = {}
    for r in out:
        by_L.setdefault(r.get("L"), []).append(r)
    for runs in by_L.values():
        finished = sorted((r for r in runs if _finished(r) and r.get("n_d") is not None),
                          key=lambda r: r["n_d"])
        for r in runs:
            status = own_status(r)
            if status is None:
                finer = [p for p in finished if p["n_d"] > r["n_d"]]
                if not finer:
                    status = "unknown"
                else:
                    p = finer[0]
                    ok = (_relative_change(r.get("propagation_distance"),
                                           p.get("propagation_distance")) < DISTANCE_TOL and
                          _relative_change(r.get("arrival_time_at_probe"),
                                           p.get("arrival_time_at_probe")) < ARRIVAL_TOL)
                    status = "converged" if ok else "not_converged"
            r["convergence"] = status
    return out


def errors_against_finest(rows):
    """Rows with `error`: the larger relative difference of propagation_distance and
    arrival_time_at_probe from the finest finished run of the same L. The finest run
    (the reference) is left out."""
    out = []
    by_L = {}
    for r in rows:
        if _finished(r) and r.get("n_d") is not None:
            by_L.setdefault(r.get("L"), []).append(r)
    for L, runs in by_L.items():
        runs.sort(key=lambda r: r["n_d"])
        ref = runs[-1]
        for r in runs[:-1]:
            error = max(_relative_change(r.get("propagation_distance"), ref.get("propagation_distance")),
                        _relative_change(r.get("arrival_time_at_probe"), ref.get("arrival_time_at_probe")))
            out.append({**r, "error": error, "reference_n_d": ref["n_d"]})
    return out


def rows_from_speed_accuracy(doc, method=None):
    """Cost-chart rows {L, n_d, method, wall_time_s, memory_bytes, error} from the server's
    GET /studies/{id}/speed-accuracy: error = the larger of the propagation-distance and
    arrival-time errors against the reference run of the same L (null: left out).

    `across_methods.runs` (every run of both methods' scenes, each against the finest
    converged run of its L by either method) is used when the server gives it; otherwise
    `runs` (the study's own method: `method`, else the document's, else "fe")."""
    across = doc.get("across_methods") if isinstance(doc, dict) else None
    if isinstance(across, dict) and across.get("runs") is not None:
        runs, default = across["runs"], method or "fe"
    else:
        runs = doc.get("runs") if isinstance(doc, dict) else doc
        default = method or (doc.get("method") if isinstance(doc, dict) else None) or "fe"
    rows = []
    for r in runs or []:
        errors = r.get("errors") or {}
        values = [errors.get("propagation_distance"), errors.get("arrival_time")]
        values = [v for v in values if isinstance(v, (int, float)) and math.isfinite(v)]
        rows.append({"L": r.get("L"), "n_d": r.get("n_d"), "wall_time_s": r.get("wall_time_s"),
                     "memory_bytes": r.get("memory_bytes"), "method": r.get("method") or default,
                     "id": r.get("id") or r.get("job_id"),
                     "error": max(values) if values else None})
    return rows


def has_across_methods(doc):
    return isinstance(doc, dict) and isinstance(doc.get("across_methods"), dict)


def merge_rows(*row_lists):
    """Rows of several studies in one list, each run once (by id; rows without one kept)."""
    out, seen = [], set()
    for rows in row_lists:
        for r in rows:
            key = (r.get("id"), r.get("method"))
            if r.get("id") is not None and key in seen:
                continue
            seen.add(key)
            out.append(r)
    return out

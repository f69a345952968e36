"""Client-side convergence and error estimates from run summaries (rows of
`results.run_row`: id, L, n_d, status, outcome, propagation_distance,
arrival_time_at_probe, steps, simulated_time, wall_time_s).

Convergence: the server's rules, one for one (docs/studies.md, "Mesh-convergence status of a
run"; api/study/convergence.cpp), so that a local plot colours a run as the server's
map does. Both are tested against the same cases (tests/study/convergence_cases.json).
A row without a status (a local result file) counts as succeeded. Runs are grouped by
L only: give it runs that differ in nothing else. Where the server has a study or a
scene, ask it instead (`plot convergence --from-server`, `--study`).
"""

import math

from . import methods

DISTANCE_TOL = 0.005
ARRIVAL_TOL = 0.001
STATUSES = ("converged", "not_converged", "diverged", "pending", "unknown", "failed")

# What a run contributes, in the order a cell prefers them (a result first).
_MEASURED, _DIVERGED, _PENDING, _VOID = range(4)


def _same(a, b):
    """L and n_d come from JSON numbers: equal up to round-off means the same value."""
    return abs(a - b) <= 1e-9 * max(abs(a), abs(b))


def _finer(n_d, than):
    return n_d > than and not _same(n_d, than)


def _metric(row, key):
    """A metric as a float; NaN when absent, null or not a number."""
    value = row.get(key)
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return math.nan
    return float(value)


def _outcome(row):
    outcome = row.get("outcome")
    return outcome if isinstance(outcome, str) else ""


def _simulated_nothing(row):
    """The metrics say the run took 0 steps or simulated no time: it measured nothing,
    whatever its status and outcome."""
    return any(not math.isnan(_metric(row, key)) and _metric(row, key) <= 0
               for key in ("steps", "simulated_time"))


def _state(row):
    status = row.get("status") or "succeeded"
    if status in ("queued", "running"):
        return _PENDING
    if status == "cancelled" or _simulated_nothing(row):
        return _VOID
    if _outcome(row) == "diverged":
        return _DIVERGED  # the server keeps a diverged run as job status "failed"
    if status == "succeeded" and _outcome(row):
        return _MEASURED
    return _VOID


def _relative_change(value, reference):
    """|value - reference| / |reference|; NaN if either is undefined."""
    if not (math.isfinite(value) and math.isfinite(reference)):
        return math.nan
    if reference == 0:
        return 0.0 if value == 0 else math.inf
    return abs(value - reference) / abs(reference)


def _common_station(row, ref):
    """(x1, time, reference time) at the station both fronts reached that the reference's
    front reached last, or None (docs/metrics.md "Convergence status")."""
    def times(r):
        out = {}
        for s in ((r.get("metrics") or r).get("stations") or []):
            t, x = s.get("rupture_time"), s.get("x1")
            if isinstance(t, (int, float)) and isinstance(x, (int, float)) and math.isfinite(t):
                out[x] = t
        return out
    mine, theirs = times(row), times(ref)
    best = None
    for x, t_ref in theirs.items():
        t = next((t for y, t in mine.items() if _same(y, x)), None)
        if t is not None and (best is None or t_ref > best[2]):
            best = (x, t, t_ref)
    return best


def _agree(row, ref):
    """The convergence criterion (docs/metrics.md "Convergence status") between a run and its
    partner (the next finer mesh): the arrival time at the probe when both fronts reached it,
    else at the station both reached last, else distance alone (if neither reached the probe)."""
    mine, theirs = _outcome(row), _outcome(ref)
    if theirs == "diverged" or mine != theirs:
        return False
    if mine == "no_rupture":
        return True
    distance = _relative_change(_metric(row, "propagation_distance"),
                                _metric(ref, "propagation_distance"))
    if math.isnan(distance):
        return False
    arrived = math.isfinite(_metric(row, "arrival_time_at_probe"))
    ref_arrived = math.isfinite(_metric(ref, "arrival_time_at_probe"))
    if arrived and ref_arrived:
        arrival = _relative_change(_metric(row, "arrival_time_at_probe"),
                                   _metric(ref, "arrival_time_at_probe"))
        return distance < DISTANCE_TOL and arrival < ARRIVAL_TOL
    station = _common_station(row, ref)
    if station is not None:
        return distance < DISTANCE_TOL and _relative_change(station[1], station[2]) < ARRIVAL_TOL
    return arrived == ref_arrived and distance < DISTANCE_TOL


def results_agree(row, ref):
    """Whether two run summaries agree by the convergence criterion (also the rule between
    two L's, docs/studies.md "Mesh-convergence status of a run"), `ref` the finer mesh or the
    smaller L."""
    return _agree(row, ref)


def _pick(rows, L, n_d):
    """The run that stands for an (L, n_d) cell: a result before a pending run before a
    void one; among equals the smallest id."""
    cell = [r for r in rows if _same(r["L"], L) and _same(r["n_d"], n_d)]
    return min(cell, key=lambda r: (_state(r), str(r.get("id") or "")), default=None)


def _partner(rows, row):
    """The run of the same L at the next finer n_d present; meshes whose runs all failed
    or were cancelled are skipped."""
    finer = [r["n_d"] for r in rows if _same(r["L"], row["L"]) and
             _finer(r["n_d"], row["n_d"]) and _state(r) != _VOID]
    return _pick(rows, row["L"], min(finer)) if finer else None


def convergence_status(rows, row):
    """The convergence status of `row` among `rows` (see the module docstring)."""
    state = _state(row)
    if state == _PENDING:
        return "pending"
    if state == _VOID:
        return "failed"
    if state == _DIVERGED:
        return "diverged"
    partner = _partner(rows, row)
    if partner is None or _state(partner) == _PENDING:
        return "unknown"
    return "converged" if _agree(row, partner) else "not_converged"


def convergence_statuses(rows):
    """A copy of `rows`, each with `convergence` set (see the module docstring); rows
    without L or n_d get "unknown"."""
    out = [dict(r) for r in rows]
    def placed(r):
        return all(isinstance(r.get(k), (int, float)) and not isinstance(r.get(k), bool)
                   for k in ("L", "n_d"))
    runs = [r for r in out if placed(r)]
    for r in out:
        r["convergence"] = convergence_status(runs, r) if placed(r) else "unknown"
    return out


def _finished(row):
    return (row.get("status") in (None, "succeeded") and row.get("outcome") != "diverged"
            and not _simulated_nothing(row))


def _error_change(value, reference):
    """|value - reference| / |reference|; 0 when both are missing; inf when one is."""
    missing = [v is None or (isinstance(v, float) and math.isnan(v)) for v in (value, reference)]
    if all(missing):
        return 0.0
    if any(missing):
        return math.inf
    if reference == 0:
        return 0.0 if value == 0 else math.inf
    return abs(value - reference) / abs(reference)


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
            error = max(_error_change(r.get("propagation_distance"), ref.get("propagation_distance")),
                        _error_change(r.get("arrival_time_at_probe"), ref.get("arrival_time_at_probe")))
            out.append({**r, "error": error, "reference_n_d": ref["n_d"]})
    return out


def rows_from_speed_accuracy(doc, method=None):
    """Cost-chart rows {L, n_d, method, wall_time_s, memory_bytes, error} from the server's
    GET /studies/{id}/speed-accuracy: error = the larger of the propagation-distance and
    arrival-time errors against the reference run of the same L (null: left out).

    `across_methods.runs` (every run of both methods' scenes, each against the finest
    converged run of its L by either method) is used when the server gives it; otherwise
    `runs` (the study's own method: `method`, else the document's, else the default)."""
    across = doc.get("across_methods") if isinstance(doc, dict) else None
    if isinstance(across, dict) and across.get("runs") is not None:
        runs, default = across["runs"], method or methods.default()
    else:
        runs = doc.get("runs") if isinstance(doc, dict) else doc
        default = (method or (doc.get("method") if isinstance(doc, dict) else None)
                   or methods.default())
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

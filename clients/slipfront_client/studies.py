"""Studies (POST /studies, GET /studies/{id}; docs/studies-api.md): a grid of runs over L × n_d of one
base job, from which the server derives convergence statuses and the critical length L_c.

The request the client sends (docs/studies-api.md): {"name", "tags", "base": job spec,
"grid": {"L": [...], "n_d": [...]}}, or with `convergence` instead of `grid`
({"L", "n_d": ladder, "n_d_max"}: the server refines each L until two meshes agree).
Runs are read from `runs` (job_id, L, n_d, job_status, outcome, convergence.status); the
study's `L_c` and `spectral_critical_length` are top-level numbers, `critical_length` the
server's table. A server without the API is reported as "server has no studies API (404)".
"""

import time

from . import report
from .errors import ServerError
from .waiting import Backoff

FINAL_STUDY = ("succeeded", "failed", "cancelled", "complete", "completed", "done", "finished")
FINAL_JOB = ("succeeded", "failed", "cancelled")


def _no_api(error):
    return (isinstance(error, ServerError) and error.status == 404 and
            "no such resource" in str(error.problem.get("detail", "")))


def _guard(call):
    try:
        return call()
    except ServerError as e:
        if e.status in (404, 405) and (e.status == 405 or _no_api(e)):
            raise ServerError(f"server has no studies API ({e.status})", status=e.status) from e
        raise


def study_request(base, lengths, densities, name=None, tags=None, convergence=False,
                  n_d_max=None, search=None):
    """A grid study (every L x n_d), or with `convergence` a refinement study over the
    n_d ladder `densities` (capped at `n_d_max`); with `search` (a dict of from, factor,
    floor, confirm, each optional) an L search instead of the L list."""
    if search is not None:
        plan = {"search": dict(search), "n_d": list(densities)}
        if n_d_max is not None:
            plan["n_d_max"] = n_d_max
        body = {"convergence": plan}
    elif convergence:
        plan = {"L": list(lengths), "n_d": list(densities)}
        if n_d_max is not None:
            plan["n_d_max"] = n_d_max
        body = {"convergence": plan}
    else:
        body = {"grid": {"L": list(lengths), "n_d": list(densities)}}
    if base:
        body["base"] = base
    if name:
        body["name"] = name
    if tags:
        body["tags"] = list(tags)
    return body


STUDY_FIELDS = (("friction", "L"), ("geometry", "nodes_per_meter"))


def drop_study_fields(base):
    """Remove friction.L and geometry.nodes_per_meter from a base job (the server refuses
    them: the study sets them); return the dotted names removed."""
    dropped = []
    for section, key in STUDY_FIELDS:
        part = base.get(section)
        if isinstance(part, dict) and key in part:
            del part[key]
            dropped.append(f"{section}.{key}")
            if not part:
                del base[section]
    return dropped


def create(api, body):
    return _guard(lambda: api.create_study(body))


def get(api, study_id):
    return _guard(lambda: api.study(study_id))


def runs_of(study):
    runs = study.get("runs") or study.get("jobs") or []
    return [r for r in runs if isinstance(r, dict)]


def run_status(run):
    """The job status of a study run (`job_status` in the server's answer)."""
    return run.get("job_status", run.get("status"))


def is_final(study):
    return study.get("status") in FINAL_STUDY


def wait(api, study_id, timeout=None, log=None, sleep=time.sleep):
    backoff = Backoff(first=0.5, cap=10.0)
    deadline = None if timeout is None else time.monotonic() + timeout
    last = None
    while True:
        study = get(api, study_id)
        if is_final(study):
            return study
        if log:
            progress = study.get("progress") or {}
            runs = runs_of(study)
            done = progress.get("done", sum(run_status(r) in FINAL_JOB for r in runs))
            total = progress.get("total", len(runs))
            line = f"study {study_id}: {done}/{total} runs finished"
            if line != last:
                log(line)
                last = line
        delay = backoff.next()
        if deadline is not None and time.monotonic() + delay > deadline:
            raise ServerError(f"study {study_id} not finished after {timeout} s")
        sleep(delay)


def _value(run, key, spec_path):
    if key in run:
        return run[key]
    node = run.get("spec") or {}
    for part in spec_path:
        node = node.get(part) if isinstance(node, dict) else None
    return node


def summary_lines(study):
    """A readable table of the study's runs and its critical length."""
    lines = [f"study {study.get('id', '?')}  {study.get('name') or ''}  status "
             f"{study.get('status', '?')}"]
    progress = study.get("progress") or {}
    if progress:
        lines[0] += f"  ({progress.get('done')}/{progress.get('total')} runs final)"
    if study.get("method"):
        lines[0] += f"  method {study['method']}"
    # The headline answer first (docs/studies.md "The answer"), then the runs and the rest.
    if study.get("answer"):
        lines += ["", "the answer: " + report.answer_lines(study, markdown=False)[0]]
        lines += ["  " + line for line in report.answer_lines(study, markdown=False)[1:]]
        lines.append("")
    lines.append(f"{'L [m]':>10} {'n_d':>6} {'status':>10} {'outcome':>15} {'d_dist':>10} "
                 f"{'d_t_probe':>10} {'convergence':>14}  id")
    for r in runs_of(study):
        m = r.get("metrics") or {}
        ch = (r.get("convergence") or {}).get("changes") or {} if isinstance(r.get("convergence"), dict) else {}
        # An L search's plain-Coulomb runs have no L of their own (their spec keeps the base's).
        L = "coulomb" if r.get("regime") == "coulomb" else _value(r, "L", ("friction", "L"))
        n_d = _value(r, "n_d", ("geometry", "nodes_per_meter"))
        conv = r.get("convergence")
        if isinstance(conv, dict):
            conv = conv.get("status")
        lines.append(f"{_fmt(L):>10} {_fmt(n_d):>6} {str(run_status(r) or '?'):>10} "
                     f"{str(m.get('outcome', r.get('outcome')) or '-'):>15} "
                     f"{_fmt(ch.get('propagation_distance')):>10} "
                     f"{_fmt(ch.get('arrival_time')):>10} "
                     f"{str(conv or '-'):>14}  {r.get('job_id', r.get('id', ''))}")
    lines.append("(d_dist, d_t_probe: relative changes of propagation_distance and "
                 "arrival_time_at_probe against the next finer n_d)")
    if study.get("kind") == "accuracy":  # one L: no critical length, no cross-method table
        return lines + accuracy_summary(study.get("accuracy"))
    converged = (study.get("convergence_map") or {}).get("converged_n_d") or {}
    for L, n_d in converged.items():
        if n_d is not None:
            lines.append(f"L = {L}: converged from n_d = {_fmt(n_d)}")
            continue
        tried = [_value(r, "n_d", ("geometry", "nodes_per_meter")) for r in runs_of(study)
                 if r.get("regime") != "coulomb" and _same_L(r.get("L"), L)]
        finest = max((n for n in tried if n is not None), default=None)
        lines.append(f"L = {L}: not converged" + (f" (no two successive meshes agree up to "
                                                  f"n_d = {_fmt(finest)})" if finest else ""))
    labels = {"L_c": "L_c by the rule over every L run",
              "spectral_critical_length": "spectral estimate (an order of magnitude from the "
                                          "filter law, not the rule's answer)"}
    for key, label in labels.items():
        if key in study:
            lines.append(f"{label}: {_fmt(study[key])}")
    reason = (study.get("critical_length") or {}).get("reason") if isinstance(
        study.get("critical_length"), dict) else None
    if reason:
        lines.append(f"L_c reason: {reason}")
    if "critical_length" in study:
        lines.append(f"verdict: {report.verdict_text(study)}")
    lines += search_summary(study.get("search"))
    lines += cross_method_summary(study.get("cross_method") or [])
    return lines


def search_summary(search):
    """The L search's state, the L it tried and each step's comparison."""
    if not search:
        return []
    lines = [f"L search ({search.get('state')}): {search.get('reason')}",
             "  tried L = " + ", ".join(_fmt(L) for L in search.get("searched_L") or [])]
    for step in search.get("steps") or []:
        lines.append(f"  {_fmt(step.get('L'))} vs {_fmt(step.get('smaller_L'))}: "
                     f"{'agree' if step.get('agree') else 'differ'} ({step.get('reason')})")
    return lines


def accuracy_summary(answer):
    """An accuracy study's answer: the value with its error, how it was estimated, the meshes
    and what they cost (docs/studies-api.md "Accuracy target")."""
    if not answer:
        return []
    target = answer.get("target") or {}
    value, error = answer.get("value"), answer.get("error")
    lines = [f"accuracy target: {target.get('metric')} within "
             f"{report.percent(target.get('tolerance'))} at L = {_fmt(target.get('L'))} m",
             f"  answer ({answer.get('state')}): {_fmt(value)} ± {_fmt(error)} "
             f"({report.percent(answer.get('relative_error'))}, {answer.get('estimate') or '-'}) "
             f"at n_d = {_fmt(answer.get('n_d'))}"]
    if answer.get("extrapolated") is not None:
        lines.append(f"  Richardson: observed order {_fmt(answer.get('observed_order'))}, "
                     f"extrapolated {_fmt(answer['extrapolated'])}")
    method = answer.get("method") or {}
    lines.append(f"  method {method.get('name')}: {method.get('reason')}")
    start = answer.get("start") or {}
    if start:
        lines.append(f"  first mesh n_d = {_fmt(start.get('n_d'))}: {start.get('reason')}")
    for step in answer.get("steps") or []:
        lines.append(f"  n_d = {_fmt(step.get('n_d')):>6}: {_fmt(step.get('value'))}"
                     + (f"  ± {_fmt(step.get('error'))} ({step.get('estimate')})"
                        if step.get("error") is not None else "")
                     + f"  [{_fmt(step.get('wall_time_s'))} s]")
    cost = answer.get("cost") or {}
    lines.append(f"  cost: {cost.get('runs')} run(s), {_fmt(cost.get('wall_time_s'))} s of "
                 f"run wall time; {answer.get('reason')}")
    return lines


def cross_method_summary(rows):
    """One line per L of the cross-method table: n_d, distance, arrival, agreement."""
    if not rows:
        return []
    lines = ["cross-method (FE / BI, |FE - BI| / BI):"]
    for row in sorted(rows, key=lambda r: -float(r.get("L") or 0)):
        fe, bi = row.get("fe") or {}, row.get("spectral_bi") or {}
        diff = row.get("differences") or {}
        text = f"  L = {_fmt(row.get('L'))}: n_d {_fmt(fe.get('n_d'))} / {_fmt(bi.get('n_d'))}"
        for key, name in (("propagation_distance", "distance"), ("arrival_time_at_probe", "arrival")):
            text += (f", {name} {_fmt(fe.get(key))} / {_fmt(bi.get(key))}"
                     f" ({report.percent(diff.get(key))})")
        agree = row.get("agree")
        text += (f", agree {'yes' if agree else 'no'}" if agree is not None
                 else f" ({row.get('reason') or 'one side missing'})")
        lines.append(text)
    return lines


def _same_L(value, key):
    """Whether a run's L is the map's key (its text, as the server writes it)."""
    try:
        return value is not None and abs(float(value) - float(key)) <= 1e-12 * abs(float(key))
    except (TypeError, ValueError):
        return False


def _fmt(value):
    if value is None:
        return "-"
    if isinstance(value, float):
        return f"{value:.4g}"
    return str(value)

"""Markdown pieces of a study report (used by clients/reproduce_paper.py): the L_c verdict
of one method's study, the changes of the metrics per step in L, the n_d each L needed,
and the cross-method table (the same L by FE and by spectral BI).

Inputs are the server's answers, unchanged: GET /api/v1/studies/{id} (`method`, `L_c`,
`spectral_critical_length`, `critical_length` with `steps_in_L`, `reason`, `references`,
`convergence_map.converged_n_d`, `refinement`, `runs`, `cross_method`). Every function
returns a list of lines and tolerates missing keys (an older server), saying "—".
"""

import math

from . import methods

NO_L_MEETS = "no L meets the rule"


def fmt(value, digits=3, unit=""):
    """A number with `digits` significant digits (and a unit), "—" when missing."""
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "—"
    if isinstance(value, bool):
        text = "yes" if value else "no"
    elif isinstance(value, (int, float)):
        text = f"{value:.{digits}g}"
    else:
        text = str(value)
    return text + (f" {unit}" if unit else "")


def percent(value, digits=3):
    """0.0213 -> "2.13 %", 1.0 -> "100 %"; "—" when missing."""
    if value is None or not isinstance(value, (int, float)) or not math.isfinite(value):
        return "—"
    p = 100 * value
    return f"{p:.0f} %" if abs(p) >= 10 ** digits else f"{p:.{digits}g} %"


def method_of(study):
    return study.get("method") or (study.get("base") or {}).get("method") or methods.default()


def method_name(method):
    """'finite elements (`fe`)': a method in words and by its name."""
    return f"{methods.title(method)} (`{method}`)"


def same_L(a, b):
    return abs(float(a) - float(b)) <= 1e-9 * abs(float(b))


def converged_n_d(study, L):
    table = (study.get("convergence_map") or {}).get("converged_n_d") or {}
    for k, v in table.items():
        if same_L(k, L):
            return v
    return None


def _lookup(mapping, L):
    for k, v in (mapping or {}).items():
        if same_L(k, L):
            return v
    return None


def answer_lines(study, extra=(), markdown=True):
    """The headline answer block of a study (docs/studies.md "The answer"; the server's
    `answer`): the verdict, what it means, how sure it is, then the other numbers, each with
    what it is. `extra`: more (label, value, unit) to list among the others. Without the
    server's block (an older server), the verdict alone."""
    answer = study.get("answer") or {}
    verdict = answer.get("verdict") or verdict_text(study)
    bold = (lambda t: f"**{t}**") if markdown else (lambda t: t)
    gap = [""] if markdown else []  # Markdown: one paragraph each
    lines = [bold(verdict) + "."]
    if answer.get("meaning"):
        lines += gap + [f"What it means: {answer['meaning']}."]
    if answer.get("certainty"):
        lines += gap + [f"How sure: {answer['certainty']}."]
    others = [(o.get("label"), o.get("value"), o.get("unit")) for o in answer.get("others") or []]
    others += list(extra)
    if others:
        lines += gap + ["Other numbers, each for what it is:"] + gap
        lines += [f"- {fmt(value, unit=unit or '') if isinstance(value, (int, float)) else value}: "
                  f"{label}" for label, value, unit in others]
    return lines


def verdict_text(study):
    """One line: "L_c = 1e-05 m" / "no L meets the rule" / "L_c undetermined"."""
    cl = study.get("critical_length") or {}
    lc = study.get("L_c", cl.get("L_c"))
    if lc is not None:
        return f"L_c = {fmt(lc)} m"
    steps = cl.get("steps_in_L") or []
    reason = str(cl.get("reason") or "")
    if reason.startswith(NO_L_MEETS) or (steps and not any(s.get("agree") for s in steps)):
        return NO_L_MEETS
    return "L_c undetermined"


def steps_table(study):
    """The change of the metrics from each mesh-converged L to the next larger one."""
    steps = (study.get("critical_length") or {}).get("steps_in_L") or []
    if not steps:
        return []
    lines = ["| step in L [m] | change of propagation distance | change of arrival time at probe | "
             "within 0.5 % / 0.1 % |", "| --- | --- | --- | --- |"]
    for s in steps:
        ch = s.get("changes") or {}
        lines.append(f"| {fmt(s.get('from_L'))} → {fmt(s.get('to_L'))} | "
                     f"{percent(ch.get('propagation_distance'))} | {percent(ch.get('arrival_time'))} | "
                     f"{fmt(s.get('agree'))} |")
    return lines


def n_d_table(study):
    """Per L: the coarsest converged n_d (what the L needed), the finest tried, the state."""
    own = [r for r in study.get("runs") or [] if not r.get("regime")]  # not a search's Coulomb
    lengths = sorted({float(r["L"]) for r in own if r.get("L") is not None}, reverse=True)
    if not lengths:
        return []
    refinement = study.get("refinement") or {}
    lines = ["| L [m] | n_d needed (converged from) | finest n_d run | refinement |",
             "| --- | --- | --- | --- |"]
    for L in lengths:
        tried = [float(r["n_d"]) for r in own
                 if r.get("L") is not None and same_L(r["L"], L) and r.get("n_d") is not None]
        nd = converged_n_d(study, L)
        state = (_lookup(refinement, L) or {}).get("state", "—")
        lines.append(f"| {fmt(L)} | {fmt(nd) if nd is not None else 'none up to the cap'} | "
                     f"{fmt(max(tried)) if tried else '—'} | {state} |")
    return lines


def verdict_lines(study, heading="###"):
    """The L_c verdict of one method's study: the verdict, the spectral estimate beside it,
    the server's reason, the steps in L and the n_d each L needed."""
    method = method_of(study)
    cl = study.get("critical_length") or {}
    verdict = verdict_text(study)
    lines = [f"{heading} {method_name(method)}: {verdict}\n"]
    lines.append(f"Study `{study.get('id')}`, {study.get('status', '?')}.")
    if verdict.startswith("L_c ="):
        nxt = cl.get("next_larger_L")
        lines.append(f"- **{verdict}**" + (f"; the next larger L, {fmt(nxt)} m, breaks agreement"
                                           if nxt is not None else "") + ".")
    elif verdict == NO_L_MEETS:
        lines.append(f"- **{NO_L_MEETS}**: no step from one mesh-converged L to the next "
                     "changes the propagation distance by < 0.5 % and the arrival time at the "
                     "probe by < 0.1 % (table below).")
    else:
        lines.append("- **L_c undetermined** (reason below).")
    spectral = study.get("spectral_critical_length", cl.get("spectral_critical_length"))
    lines.append(f"- Spectral estimate beside it: **{fmt(spectral, unit='m')}**"
                 + (f" (from the reference run of L = {fmt(cl.get('spectral_from_L'))} m, the "
                    "smallest mesh-converged L)." if spectral is not None else "."))
    if cl.get("reason"):
        lines.append(f"- Server's reason: {cl['reason']}")
    lines.append("")
    for table in (steps_table(study), n_d_table(study)):
        if table:
            lines += table + [""]
    return lines


CROSS_KEYS = (("propagation_distance", "propagation distance [m]", 5),
              ("arrival_time_at_probe", "arrival at probe [s]", 5),
              ("arrest_position", "arrest position [m]", 4),
              ("max_slip_velocity", "max \\|V\\| [m/s]", 3),
              ("spectral_velocity", "peak \\|V\\| at spectrum probe [m/s]", 3))


def cross_method_lines(rows):
    """The cross-method table: one row per L, each metric as "FE / BI (|FE − BI| / BI)"."""
    if not rows:
        return ["No cross-method rows (the server gave none: an older server, or no run of "
                "either scene)."]
    head = ["L [m]", "n_d FE / BI"] + [label for _, label, _ in CROSS_KEYS] + [
        "wall FE / BI [s]", "agree (0.5 % / 0.1 %)"]
    lines = ["| " + " | ".join(head) + " |", "| " + " | ".join("---" for _ in head) + " |"]
    for row in sorted(rows, key=lambda r: -float(r.get("L") or 0)):
        fe, bi = row.get("fe") or {}, row.get("spectral_bi") or {}
        diff = row.get("differences") or {}
        cells = [fmt(row.get("L")), f"{fmt(fe.get('n_d'))} / {fmt(bi.get('n_d'))}"]
        for key, _, digits in CROSS_KEYS:
            cell = f"{fmt(fe.get(key), digits)} / {fmt(bi.get(key), digits)}"
            if key in diff:
                cell += f" ({percent(diff.get(key))})"
            cells.append(cell)
        cells.append(f"{fmt(fe.get('wall_time_s'))} / {fmt(bi.get('wall_time_s'))}")
        agree = row.get("agree")
        cells.append(fmt(agree) if agree is not None else "— " + str(row.get("reason") or ""))
        lines.append("| " + " | ".join(cells) + " |")
    lines.append("")
    lines.append("Each side is that method's reference run of the L (its finest run, where the L "
                 "is mesh-converged by that method); the percentage is |FE − BI| / BI; "
                 "‘agree’ applies the convergence rule (propagation distance within 0.5 %, "
                 "arrival time within 0.1 %) between the two methods.")
    return lines

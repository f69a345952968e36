"""Printing: JSON for scripts, short tables and summaries for people, messages on stderr."""

import json
import sys


def log(message):
    print(message, file=sys.stderr, flush=True)


def print_json(value):
    print(json.dumps(value, indent=2, sort_keys=True))


def fmt(value):
    if value is None:
        return "-"
    if isinstance(value, float):
        return f"{value:.4g}"
    if isinstance(value, (list, dict)):
        return json.dumps(value, separators=(",", ":"))
    return str(value)


def warning_lines(warnings, indent="  warning     "):
    """The validation's warnings ({pointer, message}) one a line: `pointer: message`."""
    return [f"{indent}{w.get('pointer')}: {w.get('message')}" for w in warnings or []]


def provenance_lines(provenance, indent="  "):
    """The numbers with a unit a job takes that it did not give: `pointer = value unit (source)`."""
    return [f"{indent}{v.get('pointer')} = {fmt(v.get('value'))} {v.get('unit')}  ({v.get('source')})"
            for v in provenance or [] if v.get("source") != "given"
            and not str(v.get("source")).startswith("preset")]


def job_summary(job):
    """Lines describing a job: identity, status, progress, key metrics, cost, result."""
    spec = job.get("spec") or {}
    L = (spec.get("friction") or {}).get("L")
    n_d = (spec.get("geometry") or {}).get("nodes_per_meter")
    lines = [f"job {job.get('id')}  {job.get('name') or ''}".rstrip(),
             f"  status      {job.get('status')}"
             + (f"  (cache hit of {job['cached_from']})" if job.get("cached_from") else "")]
    if spec:
        lines.append(f"  L = {fmt(L)} m, n_d = {fmt(n_d)}, tags {fmt(job.get('tags'))}")
    lines += warning_lines(job.get("warnings"))
    p = job.get("progress") or {}
    if job.get("status") in ("queued", "running"):
        lines.append(f"  progress    {100 * float(p.get('fraction') or 0):.1f}%  "
                     f"t = {fmt(p.get('time'))}/{fmt(p.get('duration'))} s  ETA {fmt(p.get('eta_s'))} s")
    m = job.get("metrics") or {}
    if m:
        rs = m.get("rupture_speed") or {}
        lines.append(f"  outcome     {m.get('outcome')}  arrest {fmt(m.get('arrest_position'))} m  "
                     f"distance {fmt(m.get('propagation_distance'))} m  "
                     f"t_probe {fmt(m.get('arrival_time_at_probe'))} s")
        lines.append(f"  max |V|     {fmt(m.get('max_slip_velocity'))} m/s  "
                     f"V_r max {fmt(rs.get('max'))} mean {fmt(rs.get('mean'))} m/s  "
                     f"energy error {fmt(m.get('energy_error'))}")
        lines.append(f"  cost        {fmt(m.get('wall_time_s', job.get('wall_time_s')))} s wall, "
                     f"{fmt(m.get('steps'))} steps of {fmt(m.get('dt'))} s")
        for w in m.get("warnings") or []:
            lines.append(f"  warning     {w}")
    if job.get("error"):
        lines.append(f"  error       {job['error']}")
    if job.get("result"):
        r = job["result"]
        lines.append(f"  result      {r.get('url')} ({r.get('size')} bytes, sha256 {r.get('sha256')})")
    return lines


def table(rows, columns):
    """Rows (dicts) as aligned text columns; `columns` are (header, function(row))."""
    cells = [[h for h, _ in columns]] + [[fmt(f(r)) for _, f in columns] for r in rows]
    widths = [max(len(c[i]) for c in cells) for i in range(len(columns))]
    return ["  ".join(c.ljust(w) for c, w in zip(line, widths)).rstrip() for line in cells]

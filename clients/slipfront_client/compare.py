"""Runs side by side (`slipfront-client compare`, docs/client.md "compare"): their run
fields, spec and metrics flattened into one table with the fields that differ marked, and the
legend texts of their overlaid curves — each run's label (results.run_label: method, what is
below the interface, the friction law by its scale parameter, n_d) followed by every other spec
field that differs. The web view's compare page (web/app/run_labels.js) follows the same rules.
"""

import json
import math

# The job fields shown beside the spec and the metrics.
RUN_FIELDS = ("name", "status", "study_id", "submitted_by", "code_version", "scene_hash",
              "cached_from", "wall_time_s")
# Spec fields that are not the physics (the job's own name and tags are run fields).
NOT_PHYSICS = {"name", "tags"}
# The spec fields the run label already says.
IN_RUN_LABEL = {"method", "geometry.nodes_per_meter", "friction.law", "friction.regularization",
                "friction.L", "friction.t_star", "friction.D_c"}
# Rows shown even when every run has the same value (`--all` shows every row).
KEY_ROWS = {"run.name", "run.status", "spec.method", "spec.friction.L",
            "spec.geometry.nodes_per_meter", "metrics.outcome", "metrics.arrest_position",
            "metrics.propagation_distance", "metrics.rupture_speed.max",
            "metrics.rupture_speed.mean", "metrics.arrival_time_at_probe",
            "metrics.max_slip_velocity", "metrics.wall_time_s"}
GROUPS = {"run": "run", "spec": "parameters (the job spec, defaults filled)",
          "metrics": "metrics (docs/metrics.md)"}
MISSING = object()  # a field a run does not have (another method's, no metrics yet)


def flatten(value, prefix="", out=None):
    """{'friction.L': 1e-4, ...}: a nested dict's leaves by their dotted path; lists are
    leaves."""
    out = {} if out is None else out
    if isinstance(value, dict):
        for key, v in value.items():
            flatten(v, f"{prefix}.{key}" if prefix else key, out)
    elif prefix:
        out[prefix] = value
    return out


def _same(a, b):
    def canon(v):
        return None if v is MISSING else v
    return json.dumps(canon(a), sort_keys=True) == json.dumps(canon(b), sort_keys=True)


def spread(values):
    """(max - min) / max |v| of a row's numbers when every run has a number and they are not
    all zero; else None."""
    if not values or not all(isinstance(v, (int, float)) and not isinstance(v, bool)
                             and math.isfinite(v) for v in values):
        return None
    top = max(abs(v) for v in values)
    return (max(values) - min(values)) / top if top > 0 else None


def compare_rows(jobs):
    """[{group, key, values (one per job; MISSING where a job has no such field), differs,
    partial (some job has no such field), spread}]: the run fields, the spec fields, the
    metrics; in each group the fields every job has and that differ first, then those only
    some jobs have (a method's own settings), then the identical ones, each in the order the
    jobs first have them."""
    rows = []

    def add(group, keys, maps):
        made = []
        for key in keys:
            values = [m.get(key, MISSING) for m in maps]
            differs = any(not _same(v, values[0]) for v in values)
            made.append({"group": group, "key": key, "values": values, "differs": differs,
                         "partial": any(v is MISSING for v in values), "spread": spread(values)})
        rows.extend(sorted(made, key=lambda r: 0 if r["differs"] and not r["partial"]
                           else 1 if r["differs"] else 2))

    def keys_of(maps):
        return list(dict.fromkeys(k for m in maps for k in m))

    runs = [{k: j[k] for k in RUN_FIELDS if j.get(k) is not None} for j in jobs]
    specs = [flatten(j.get("spec") or {}) for j in jobs]
    metrics = [flatten(j.get("metrics") or {}) for j in jobs]
    add("run", RUN_FIELDS, runs)
    add("spec", [k for k in keys_of(specs) if k not in NOT_PHYSICS], specs)
    add("metrics", keys_of(metrics), metrics)
    return rows


def cell(value):
    """A value as the table shows it: numbers with six digits (integers as integers), lists
    and dicts as JSON, '-' for a field the run does not have (or null)."""
    if value is MISSING or value is None:
        return "-"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return str(int(value)) if value.is_integer() and abs(value) < 1e15 else f"{value:.6g}"
    if isinstance(value, (list, dict)):
        return json.dumps(value, separators=(",", ":"))
    return str(value)


def compare_labels(jobs, rows=None):
    """The legend text of each job: its run label, then every other spec field that every job
    has and that differs ('time.duration = 3'); a text still shared by two jobs gets the short
    id, so that no two legend entries read the same."""
    from .results import run_label  # numpy on first use: the command line starts without it
    rows = compare_rows(jobs) if rows is None else rows
    extra = [r for r in rows if r["group"] == "spec" and r["differs"] and not r["partial"]
             and r["key"] not in IN_RUN_LABEL]
    labels = [", ".join([run_label(j.get("spec") or {}, j.get("metrics"))]
                        + [f"{r['key']} = {cell(r['values'][i])}" for r in extra])
              for i, j in enumerate(jobs)]
    return [f"{text} ({jobs[i]['id'][:8]})" if labels.count(text) > 1 else text
            for i, text in enumerate(labels)]


def table_lines(jobs, rows, labels, show_all=False, width=28):
    """The comparison as text: a key of the runs (number, id, legend text), then one line per
    field, '*' before the fields that differ, and the spread of the numbers that differ;
    identical fields other than the key ones are counted, not shown, unless `show_all`."""
    lines = [f"run {i + 1}: {j['id']}  {label}" for i, (j, label) in enumerate(zip(jobs, labels))]
    differing = sum(r["differs"] and not r["partial"] for r in rows)
    partial = sum(r["partial"] for r in rows)
    lines.append(f"{differing} field{'s' if differing != 1 else ''} differ (marked *)"
                 + (f", {partial} more only some runs have (marked * too)" if partial else ""))

    def clip(text):
        return text if len(text) <= width else text[:width - 3] + "..."

    for group, title in GROUPS.items():
        in_group = [r for r in rows if r["group"] == group]
        shown = [r for r in in_group
                 if show_all or r["differs"] or f"{group}.{r['key']}" in KEY_ROWS]
        hidden = len(in_group) - len(shown)
        note = f" ({hidden} identical not shown; --all shows them)" if hidden else ""
        cells = [[("* " if r["differs"] else "  ") + r["key"]]
                 + [clip(cell(v)) for v in r["values"]] + [_spread_text(r, group)]
                 for r in shown]
        head = ["  field"] + [f"run {i + 1}" for i in range(len(jobs))] + ["spread"]
        widths = [max(len(c[k]) for c in cells + [head]) for k in range(len(head))]
        lines += ["", title + note]
        lines.extend("  ".join(c.ljust(w) for c, w in zip(c_row, widths)).rstrip()
                     for c_row in [head] + cells)
    return lines


def _spread_text(row, group):
    """'2.6 %' for a row of numbers that differ (not the run's own fields), else ''."""
    if group == "run" or not row["differs"] or row["spread"] is None:
        return ""
    return f"{100 * row['spread']:.3g} %"


def as_json(jobs, rows, labels):
    """The comparison for scripts: the runs with their labels, every field with its values
    (null where a run has none) and whether it differs."""
    def plain(v):
        return None if v is MISSING else v
    return {"runs": [{"id": j["id"], "label": label} for j, label in zip(jobs, labels)],
            "fields": [{"group": r["group"], "field": r["key"], "differs": r["differs"],
                        "values": [plain(v) for v in r["values"]], "spread": r["spread"]}
                       for r in rows]}


def plottable(rows, group, text=False):
    """The rows of `group` whose values (where a run has one) are all numbers (or with
    `text`, all text): what the scatter can put on an axis."""
    kinds = (str,) if text else ()
    out = []
    for r in rows:
        if r["group"] != group:
            continue
        present = [v for v in r["values"] if v is not MISSING and v is not None]
        numbers = all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in present)
        texts = bool(kinds) and all(isinstance(v, kinds) for v in present)
        if present and (numbers or texts):
            out.append(r)
    return out


def scatter_defaults(rows):
    """(parameter, metric): the parameter that differs and every run has (L, n_d, the method
    first), and the propagation distance."""
    params = plottable(rows, "spec", text=True)
    common = [r["key"] for r in params
              if r["differs"] and all(v is not MISSING and v is not None for v in r["values"])]
    x = next((k for k in ("friction.L", "geometry.nodes_per_meter", "method") if k in common),
             common[0] if common else "friction.L")
    return x, "propagation_distance"

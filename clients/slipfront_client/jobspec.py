"""Job files and inline overrides (`--set friction.L=1e-5`).

The job JSON is that of docs/api-job-spec.md; the server validates it. The client only checks what it
must to build the document: the file parses, it is an object, and every override is
`dotted.path=value` where the value is JSON (a number, true, "text", [1, 2]) or, if it
does not parse as JSON, a plain string.
"""

import json
import sys

from .errors import UsageError


def load_job(source, stdin=None):
    """The job document from a file path, or from stdin when `source` is "-"."""
    try:
        if source == "-":
            text = (stdin or sys.stdin).read()
            where = "stdin"
        else:
            with open(source, encoding="utf-8") as f:
                text = f.read()
            where = source
    except OSError as e:
        raise UsageError(f"cannot read job file {source}: {e.strerror}") from e
    try:
        doc = json.loads(text) if text.strip() else {}
    except json.JSONDecodeError as e:
        raise UsageError(f"{where}: not valid JSON: {e.msg} (line {e.lineno}, column {e.colno})") from e
    if not isinstance(doc, dict):
        raise UsageError(f"{where}: a job must be a JSON object, got {type(doc).__name__}")
    return doc


def parse_value(text):
    """A JSON value, or the text itself when it is not JSON."""
    try:
        return json.loads(text)
    except json.JSONDecodeError:
        return text


def apply_override(doc, assignment):
    """Apply one `a.b.c=value` to `doc` (in place), creating objects on the way."""
    key, sep, raw = assignment.partition("=")
    key = key.strip()
    if not sep or not key:
        raise UsageError(f"--set {assignment!r}: expected PATH=VALUE, e.g. friction.L=1e-5")
    parts = key.split(".")
    if any(not p for p in parts):
        raise UsageError(f"--set {assignment!r}: empty name in path {key!r}")
    node = doc
    for i, part in enumerate(parts[:-1]):
        child = node.get(part)
        if child is None:
            child = node[part] = {}
        if not isinstance(child, dict):
            where = ".".join(parts[: i + 1])
            raise UsageError(f"--set {assignment!r}: {where} is not an object")
        node = child
    node[parts[-1]] = parse_value(raw)
    return doc


def build_job(source=None, overrides=(), name=None, tags=None, stdin=None, preset=None):
    """The job document: the file (or an empty job = the paper's scene) plus overrides.

    With `preset`, the document names it ({"preset": NAME, ...}): the server expands it, the
    preset's spec with the document's members merged over it (docs/presets.md)."""
    doc = load_job(source, stdin) if source else {}
    if preset is not None:
        doc["preset"] = preset
    for assignment in overrides:
        apply_override(doc, assignment)
    if name is not None:
        doc["name"] = name
    if tags:
        doc["tags"] = list(doc.get("tags") or []) + list(tags)
    return doc


def pointer_lookup(doc, path, default=None):
    """The value at a dotted path (`friction.L`) of a nested dict, or `default`."""
    node = doc
    for part in path.split("."):
        if not isinstance(node, dict) or part not in node:
            return default
        node = node[part]
    return node

"""A run's friction in words, from the labels the friction laws give themselves (the job
schema's x-labels of friction.law and friction.regularization, docs/api-job-spec.md): the same
rule as the web view's friction_labels.js. The labels of the server this package was built
with are in friction_labels.json (scripts/update_job_docs.py writes it from `slipfront
schema`, and its --check keeps it equal); `labels_of(schema)` reads another server's."""

import json
import os

_PACKAGED = os.path.join(os.path.dirname(os.path.abspath(__file__)), "friction_labels.json")
_labels = None


def labels_of(schema):
    """The labels of a job schema (GET /api/v1/schema/job.json, or `slipfront schema`)."""
    f = ((schema or {}).get("properties") or {}).get("friction", {}).get("properties", {})
    return {
        "law": (f.get("law") or {}).get("x-labels", {}),
        "regularization": (f.get("regularization") or {}).get("x-labels", {}),
        "fixed": (f.get("law") or {}).get("x-fixed-regularization", {}),
        "defaults": {name: sub["default"] for name, sub in f.items() if "default" in sub},
    }


def packaged_labels():
    global _labels
    if _labels is None:
        with open(_PACKAGED) as fh:
            _labels = json.load(fh)
    return _labels


def _number(value, unit=""):
    return "?" if value is None else f"{value:g}{unit}"


def _fill(template, friction):
    """{name} of a label with the friction's value ('?' when the spec does not hold it)."""
    out = template or ""
    for name in set(part.split("}")[0] for part in out.split("{")[1:]):
        value = friction.get(name)
        out = out.replace("{" + name + "}", value if isinstance(value, str) else _number(value))
    return out


def friction_label(friction, labels=None):
    """The friction law of a job's `friction` by the parameter that sets its scale: 'L = 5e-05
    m' (slip-scale regularisation: the paper's Prakash–Clifton), 't* = 0.00035 s' (time
    scale), 'Coulomb' (constant μ, none), 'slip weakening D_c = 0.000744 m' followed by its
    regularisation's parameter."""
    labels = labels or packaged_labels()
    friction = friction or {}
    defaults = labels["defaults"]
    law = friction.get("law", defaults.get("law"))
    regularization = (labels["fixed"].get(law) or friction.get("regularization")
                      or defaults.get("regularization") or "none")
    own = labels["law"].get(law, {})
    its = labels["regularization"].get(regularization, {})
    parts = [p for p in (_fill(own.get("label"), friction), _fill(its.get("label"), friction))
             if p]
    if not parts:
        parts.append(own.get("alone") or its.get("alone") or str(law))
    return ", ".join(parts)

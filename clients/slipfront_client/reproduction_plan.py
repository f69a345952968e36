"""The paper's study as requests: the L and n_d ladders of each mode and the study body per
method (library of clients/reproduce_paper.py)."""

import json


FULL_L = [1e-3, 1e-4, 5e-5, 1e-5, 5e-6]
FULL_LADDER = [10, 20, 40, 80, 160]
BI_LADDER = [10, 20, 40, 80, 160, 320]
QUICK_L = [1e-3, 5e-5]
QUICK_LADDER = [5, 10]
QUICK_BI_LADDER = [10, 20, 40]
QUICK_BASE = {"geometry": {"width": 20, "x_min": -5, "height": 8}, "time": {"duration": 10}}
# The BI L search (docs/studies-api.md "L search"): from below the paper's smallest L, halving;
# quick: the small scene from 5e-5 m by 4 down to a floor, a few seconds.
SEARCH = {"from": 3.2e-6, "factor": 2}
QUICK_SEARCH = {"from": 5e-5, "factor": 4, "floor": 1e-6}
# Where the undamped FE lattice does not converge (the paper's smallest L, docs/small-l-study.md):
# the same scene by FE with the vanishing mesh-scale damping, a short ladder.
DAMPED = {"L": [5e-6], "n_d": [20, 40, 80], "n_d_max": 80, "mesh_damping": 0.1}
# FE-only fields: an error in a spectral_bi spec (docs/spectral-bi.md, Options).
FE_ONLY = {"geometry": ("height", "top_boundary"), "time": ("safety_factor",)}
FINAL_JOB = ("succeeded", "failed", "cancelled")


def bi_base(base):
    """The FE base as a spectral BI base: `"method": "spectral_bi"`, FE-only fields dropped."""
    out = json.loads(json.dumps(base or {}))
    for section, keys in FE_ONLY.items():
        for key in keys:
            (out.get(section) or {}).pop(key, None)
        if section in out and not out[section]:
            del out[section]
    out["method"] = "spectral_bi"
    return out


def study_body(args, method="fe"):
    """The convergence study of one method: FE on `args.ladder` up to `args.n_d_max`, BI
    on `args.bi_ladder` up to `args.bi_n_d_max`, the same L and scene."""
    bi = method == "spectral_bi"
    body = {"name": "reproduction" + (" BI" if bi else "") + (" (quick)" if args.quick else ""),
            "tags": ["reproduction"] + (["quick"] if args.quick else []),
            "convergence": {"L": args.L, "n_d": args.bi_ladder if bi else args.ladder,
                            "n_d_max": args.bi_n_d_max if bi else args.n_d_max}}
    base = bi_base(args.base) if bi else args.base
    if base:
        body["base"] = base
    if args.fresh:
        body["fresh"] = True
    return body


def search_body(args):
    """The BI L search of the same scene: no L list, `args.search` (from, factor, floor), the
    BI ladder and cap."""
    body = {"name": "reproduction L search" + (" (quick)" if args.quick else ""),
            "tags": ["reproduction"] + (["quick"] if args.quick else []),
            "base": bi_base(args.base),
            "convergence": {"search": dict(args.search), "n_d": args.bi_ladder,
                            "n_d_max": args.bi_n_d_max}}
    if args.fresh:
        body["fresh"] = True
    return body


def damped_body(args):
    """The FE study with the mesh-scale damping (`args.damped`: L, n_d, n_d_max, mesh_damping)
    on the same scene: FE's answer where the undamped lattice does not converge."""
    d = args.damped
    base = json.loads(json.dumps(args.base or {}))
    base.setdefault("fe", {})["mesh_damping"] = d["mesh_damping"]
    body = {"name": "reproduction FE, mesh damping" + (" (quick)" if args.quick else ""),
            "tags": ["reproduction"] + (["quick"] if args.quick else []),
            "base": base,
            "convergence": {"L": d["L"], "n_d": d["n_d"], "n_d_max": d["n_d_max"]}}
    if args.fresh:
        body["fresh"] = True
    return body

"""The rupture methods and their labels, in one place for the client: the server's list (its job
schema's `method`: the enum, the default and `x-labels`; GET /api/v1/schema/job.json) once
`load(api)` has read it (or, after `use(api)`, when a label is first asked for), else the two
built-in methods. A method's line style goes by its
place in the list (the first solid lines and filled circles, the second dashed lines and open
squares, ...), as in the web view (web/app/methods.js).

    methods.use(api)             # the server's methods, read when first needed
    methods.load(api)            # ... or now (the list stays as it was if it cannot say)
    methods.label("spectral_bi") # 'BI'; methods.title(...): 'spectral boundary integral'
"""

import copy

BUILT_IN = {
    "names": ["fe", "spectral_bi"],
    "default": "fe",
    "labels": {
        "fe": {"label": "FE", "heading": "FE", "title": "finite elements",
               "run_cost": "minutes per run at fine meshes", "cost_rank": 1},
        "spectral_bi": {"label": "BI", "heading": "spectral BI",
                        "title": "spectral boundary integral", "run_cost": "seconds per run",
                        "cost_rank": 0},
    },
}
_known = copy.deepcopy(BUILT_IN)
_source = None  # an Api whose job schema is read when a method is first asked about

# Line style, marker, open marker and the offset of point labels, by a method's place.
STYLES = [{"ls": "-", "marker": "o", "open": False, "offset": (4, 3)},
          {"ls": "--", "marker": "s", "open": True, "offset": (4, -9)},
          {"ls": ":", "marker": "D", "open": True, "offset": (-12, 3)},
          {"ls": "-.", "marker": "v", "open": True, "offset": (-12, -9)}]


def learn(schema):
    """Takes the methods of a job schema (a dict); returns whether it listed any."""
    method = ((schema or {}).get("properties") or {}).get("method") or {}
    names = method.get("enum")
    if not isinstance(names, list) or not names:
        return False
    _known["names"] = list(names)
    _known["default"] = method.get("default", names[0])
    _known["labels"] = dict(method.get("x-labels") or {})
    return True


def load(api):
    """The server's methods (api: slipfront_client.api.Api); the list stays as it was when
    the server cannot say (an older server, no connection)."""
    try:
        return learn(api.job_schema())
    except Exception:  # noqa: BLE001 - labels never stop a command
        return False


def use(api):
    """Reads the server's methods from `api` when a method is first asked about (no request
    until then: the CLI and workflow.connect call it for every API client they make)."""
    global _source
    _source = api


def _current():
    global _source
    if _source is not None:
        api, _source = _source, None
        load(api)
    return _known


def reset():
    """Back to the built-in methods (for tests)."""
    global _source
    _source = None
    _known.clear()
    _known.update(copy.deepcopy(BUILT_IN))


def names():
    return list(_current()["names"])


def default():
    """The method of a job that names none: 'fe'."""
    return _current()["default"]


def known(method):
    return (method or default()) in _current()["names"]


def _labels(method):
    return _current()["labels"].get(method or default()) or {}


def label(method):
    """'FE', 'BI': legends and table cells (a method without labels: its name)."""
    return _labels(method).get("label", method)


def heading(method):
    """'FE', 'spectral BI'."""
    return _labels(method).get("heading", method)


def title(method):
    """'finite elements', 'spectral boundary integral'."""
    return _labels(method).get("title", method)


def style(method):
    """{ls, marker, open, offset} of a method's runs; None for a method not in the list."""
    method = method or default()
    listed = _current()["names"]
    if method not in listed:
        return None
    index = listed.index(method)
    return STYLES[index] if index < len(STYLES) else STYLES[-1]

"""slipfront-client: a command-line and Python client of the slipfront simulation service
(submit and follow jobs, download verified results, studies, search and export of runs) and
the paper's figures from result files. Needs only Debian's python3-requests, -h5py, -numpy
and -matplotlib (python3-pandas for DataFrames). The notebook functions: docs/python-api.md.
"""

import importlib

# The server's version (project VERSION in CMakeLists.txt); tests/clients/test_package.py
# fails when they differ.
__version__ = "0.1.0"

# The public functions, imported on first use so that the command line starts without
# numpy and h5py.
_PUBLIC = {
    "Api": "api", "ClientError": "errors", "JobCancelled": "errors", "JobFailed": "errors",
    "ServerError": "errors", "UsageError": "errors", "Result": "results",
    "load_result": "results", "connect": "workflow", "download": "workflow",
    "list_runs": "workflow", "load_job_result": "workflow", "run_study": "workflow",
    "runs_dataframe": "workflow", "submit": "workflow", "wait_job": "workflow",
    "Stations": "stations", "job_stations": "stations", "load_stations": "stations",
    "parse_stations_csv": "stations",
}

__all__ = sorted(_PUBLIC) + ["__version__"]


def __getattr__(name):
    if name in _PUBLIC:
        return getattr(importlib.import_module(f".{_PUBLIC[name]}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return __all__

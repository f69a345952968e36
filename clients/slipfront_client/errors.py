"""Exceptions of the client, each carrying the process exit code it maps to.

Exit codes (docs/client.md): 0 ok, 1 server or network error, 2 usage or validation error,
3 job failed or diverged, 4 job cancelled, 130 interrupted (Ctrl-C).
"""

import sys

EXIT_OK = 0
EXIT_SERVER = 1
EXIT_USAGE = 2
EXIT_JOB_FAILED = 3
EXIT_CANCELLED = 4
EXIT_INTERRUPTED = 130


class ClientError(Exception):
    """Base class: a message for stderr and an exit code."""

    exit_code = EXIT_SERVER

    def __init__(self, message, details=()):
        super().__init__(message)
        self.message = message
        self.details = list(details)  # extra lines, e.g. "/pointer: reason"

    def lines(self):
        """The message and its details, ready to print one per line."""
        return [self.message] + ["  " + d for d in self.details]


class UsageError(ClientError):
    """Bad command line, bad job file or a job the server rejected (4xx validation)."""

    exit_code = EXIT_USAGE


class MissingDependency(UsageError):
    """A command needs a Python package this interpreter cannot import (the package installs
    without numpy, h5py, matplotlib and requests; docs/python-api.md "Install")."""

    DEBIAN = {"requests": "python3-requests", "numpy": "python3-numpy", "h5py": "python3-h5py",
              "matplotlib": "python3-matplotlib", "pandas": "python3-pandas"}

    def __init__(self, module, purpose=None):
        why = f" to {purpose}" if purpose else ""
        super().__init__(
            f"this needs the Python package {module}{why}, which {sys.executable} cannot "
            f"import",
            [f"Debian: apt install {self.DEBIAN.get(module, 'python3-' + module)}, and make the "
             f"venv with --system-site-packages",
             f"elsewhere, with a package index: pip install {module} (or pip install "
             f"'./clients[full]' for all of them)"])
        self.module = module


class ServerError(ClientError):
    """The server answered with an error, or could not be reached."""

    exit_code = EXIT_SERVER

    def __init__(self, message, details=(), status=None, problem=None):
        super().__init__(message, details)
        self.status = status
        self.problem = problem or {}


class JobFailed(ClientError):
    """The job ended as failed, or its outcome is `diverged`."""

    exit_code = EXIT_JOB_FAILED


class JobCancelled(ClientError):
    """The job ended as cancelled."""

    exit_code = EXIT_CANCELLED

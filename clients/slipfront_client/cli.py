"""Command line of slipfront-client: options, subcommands, errors and exit codes."""

import argparse
import os
import sys

from . import commands_jobs, commands_plot, commands_study
from .api import Api
from .errors import EXIT_INTERRUPTED, EXIT_SERVER, ClientError

DEFAULT_SERVER = "http://127.0.0.1:8080"

EPILOG = """environment:
  SLIPFRONT_SERVER  server URL (default http://127.0.0.1:8080)
  SLIPFRONT_TOKEN   bearer token for submit/cancel on servers with --token-file

exit codes:
  0 ok, 1 server or network error, 2 usage or validation error,
  3 job failed or diverged, 4 job cancelled, 130 interrupted
"""


class Context:
    """What every command needs: the API client, created on first use."""

    def __init__(self, args):
        self.args = args
        self._api = None

    def api(self):
        if self._api is None:
            server = self.args.server or os.environ.get("SLIPFRONT_SERVER") or DEFAULT_SERVER
            token = self.args.token or os.environ.get("SLIPFRONT_TOKEN") or None
            self._api = Api(server, token=token, timeout=self.args.http_timeout)
        return self._api

    def close(self):
        if self._api is not None:
            self._api.close()


def common_options():
    """Options accepted before or after the subcommand."""
    p = argparse.ArgumentParser(add_help=False)
    s = argparse.SUPPRESS
    p.add_argument("--server", default=s, help="server URL (env SLIPFRONT_SERVER)")
    p.add_argument("--token", default=s, help="bearer token (env SLIPFRONT_TOKEN)")
    p.add_argument("--json", action="store_true", default=s, help="print JSON on stdout")
    p.add_argument("-q", "--quiet", action="store_true", default=s, help="no messages on stderr")
    p.add_argument("--http-timeout", type=float, default=s, help="seconds per request (30)")
    return p


def build_parser():
    common = common_options()
    parser = argparse.ArgumentParser(
        prog="slipfront-client", parents=[common], epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Submit, follow and fetch slipfront rupture simulations; draw the paper's "
                    "figures from the results.")
    sub = parser.add_subparsers(dest="command", required=True,
                                metavar="submit|status|list|cancel|download|study|plot")
    commands_jobs.add_parsers(sub, common)
    commands_study.add_parsers(sub, common)
    commands_plot.add_parsers(sub, common)
    return parser


def parse_args(argv):
    args = build_parser().parse_args(argv)
    for name, default in (("server", None), ("token", None), ("json", False), ("quiet", False),
                          ("http_timeout", 30.0)):
        if not hasattr(args, name):
            setattr(args, name, default)
    return args


def report(error):
    prefix = "slipfront-client: error: "
    for i, line in enumerate(error.lines()):
        print((prefix if i == 0 else "") + line, file=sys.stderr)


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    ctx = Context(args)
    try:
        return args.func(args, ctx)
    except ClientError as e:
        report(e)
        return e.exit_code
    except OSError as e:  # a local file or directory the command could not use
        report(ClientError(f"{e.filename or ''}: {e.strerror or e}".lstrip(": ")))
        return EXIT_SERVER
    except KeyboardInterrupt:
        print("\nslipfront-client: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except BrokenPipeError:
        return 0
    finally:
        ctx.close()

"""Command line of slipfront-client: options, subcommands, errors and exit codes."""

import argparse
import sys

from . import (__version__, commands_compare, commands_fit, commands_jobs, commands_keep,
               commands_plot, commands_study, config, methods)
from .api import Api
from .errors import EXIT_INTERRUPTED, EXIT_SERVER, ClientError, MissingDependency

EPILOG = """server URL (and token), first found:
  --server (--token), SLIPFRONT_SERVER (SLIPFRONT_TOKEN), server = "..." (token = "...") in
  ~/.config/slipfront/client.toml (or $SLIPFRONT_CONFIG), else http://127.0.0.1:8080

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
            server, source = config.server_url(self.args.server)
            self._api = Api(server, token=config.token(self.args.token),
                            timeout=self.args.http_timeout, url_source=source)
            methods.use(self._api)  # the server's methods and labels, read when first needed
        return self._api

    def close(self):
        if self._api is not None:
            self._api.close()


def common_options():
    """Options accepted before or after the subcommand."""
    p = argparse.ArgumentParser(add_help=False)
    s = argparse.SUPPRESS
    p.add_argument("--server", default=s,
                   help="server URL (else SLIPFRONT_SERVER, the config file, 127.0.0.1:8080)")
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
    parser.add_argument("--version", action="version",
                        version=f"slipfront-client {__version__}")
    sub = parser.add_subparsers(dest="command", required=True,
                                metavar="submit|status|list|cancel|download|stations|tag|note|"
                                        "archive|restore|delete|export-runs|import-runs|"
                                        "fit-length|study|compare|plot")
    commands_jobs.add_parsers(sub, common)
    commands_keep.add_parsers(sub, common)
    commands_fit.add_parsers(sub, common)
    commands_study.add_parsers(sub, common)
    commands_study.add_accuracy_parser(sub, common)
    commands_compare.add_parsers(sub, common)
    commands_plot.add_parsers(sub, common)
    return parser


def join_sort_values(argv):
    """`--sort -friction.L` as `--sort=-friction.L`: argparse would take a value starting
    with '-' for an option."""
    out, it = [], iter(argv)
    for arg in it:
        if arg == "--sort":
            value = next(it, None)
            out.append(arg if value is None else f"--sort={value}")
        else:
            out.append(arg)
    return out


def parse_args(argv):
    args = build_parser().parse_args(join_sort_values(list(argv)))
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
    except ModuleNotFoundError as e:
        module = (e.name or "").split(".")[0]
        if module not in MissingDependency.DEBIAN:
            raise
        error = MissingDependency(module)
        report(error)
        return error.exit_code
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

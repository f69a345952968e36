"""`fit-length RECORD`: the experimentalist's procedure of paper Sec. 6 on one record, by the
server (POST /api/v1/length-fits; docs/length-fit.md)."""

from . import length_fit
from .output import log, print_json


def add_parsers(sub, common):
    p = sub.add_parser(
        "fit-length", parents=[common], help="fit L to a record (paper Sec. 6)",
        description="Fit the simplified Prakash-Clifton law to the record of one interface "
                    "point (CSV with time, slip_rate, contact_pressure, frictional_stress; a "
                    "stations CSV as it is; or JSON columns): the measured length L_m with its "
                    "95 % interval, f_m, the contact pressure's power above f_m, and whether "
                    "L_m is the interface's physical length or the event only bounds it.")
    p.add_argument("record", help="CSV or JSON file ('-': standard input)")
    p.add_argument("--fit-v-star", action="store_true", help="fit V* too")
    p.add_argument("--v-star", type=float, help="V* [m/s] (default 1e-4, the paper's)")
    p.add_argument("--mu", type=float, help="friction coefficient (default: fitted)")
    p.add_argument("--station", type=float, help="the station of a stations CSV [m]")
    p.add_argument("--slip-threshold", type=float,
                   help="|V| [m/s] from which a sample slips (default 1 %% of the peak)")
    p.add_argument("--plot", metavar="FILE",
                   help="also draw the fit and the spectrum with f_m to FILE (png, pdf, svg)")
    p.set_defaults(func=cmd_fit_length)


def cmd_fit_length(args, ctx):
    record = length_fit.read_record(args.record, args.station)
    body = length_fit.request_body(record, args.v_star, args.fit_v_star, args.mu, args.station,
                                   args.slip_threshold)
    answer = ctx.api().fit_length(body)
    if args.plot:
        from .plots.length_fit import plot_length_fit

        fig, _ = plot_length_fit(answer)
        fig.savefig(args.plot, dpi=150)
        if not args.quiet:
            log(f"figure written to {args.plot}")
    if args.json:
        print_json(answer)
    else:
        print("\n".join(length_fit.report_lines(answer)))
    return 0

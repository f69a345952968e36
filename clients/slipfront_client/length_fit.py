"""The length fit of paper Sec. 6 from the client (docs/length-fit.md): a record file read
for POST /api/v1/length-fits, and the answer as a short report.

A record is CSV (a header naming time, slip_rate, contact_pressure, frictional_stress; or the
stations CSV of `slipfront stations --csv` / `slipfront-client stations ID --csv` as it is)
or JSON ({"time": [...], ...}). Of a stations CSV with several stations only the chosen
station's rows are sent, the others as empty lines: the server's body limit (1 MiB by default)
then holds one station, and the line numbers of its errors are those of the file.
"""

import json

from .errors import UsageError


def stations_rows_only(text, station):
    """`text` with the data rows of every other station blanked (comments, header and the
    line count kept). Unchanged when the header does not start with station_x1."""
    lines = text.split("\n")
    header = next((i for i, line in enumerate(lines)
                   if line.strip() and not line.lstrip().startswith("#")), None)
    if header is None or not lines[header].strip().startswith("station_x1"):
        return text
    kept = []
    for i, line in enumerate(lines):
        if i <= header or not line.strip() or line.lstrip().startswith("#"):
            kept.append(line)
            continue
        try:
            same = float(line.split(",", 1)[0]) == station
        except ValueError:
            same = True  # the server names the bad cell
        kept.append(line if same else "")
    return "\n".join(kept)


def read_record(path, station=None):
    """The request's "record" from a file ("-" is standard input): a dict of columns for
    JSON, else the CSV text (one station of it when `station` is given)."""
    import sys

    if path == "-":
        text = sys.stdin.read()
    else:
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
    if text.lstrip().startswith("{"):
        try:
            return json.loads(text)
        except ValueError as e:
            raise UsageError(f"{path}: not valid JSON: {e}") from None
    return stations_rows_only(text, station) if station is not None else text


def request_body(record, v_star=None, fit_v_star=False, mu=None, station_x1=None,
                 slip_threshold=None):
    """The JSON body of POST /length-fits (the options left out when not given)."""
    body = {"record": record}
    for name, value in (("v_star", v_star), ("mu", mu), ("station_x1", station_x1),
                        ("slip_threshold", slip_threshold)):
        if value is not None:
            body[name] = value
    if fit_v_star:
        body["fit_v_star"] = True
    return body


def _interval(pair):
    lo, hi = pair
    return f"[{lo:.3g}, {'inf' if hi is None else f'{hi:.3g}'}]"


def report_lines(answer):
    """The answer as the lines `slipfront fit-length` prints."""
    rec, fit, fm = answer["record"], answer["fit"], answer["critical_frequency"]
    spectrum, verdict = answer["spectrum"], answer["verdict"]
    where = f" (station x1 = {rec['station_x1']:g} m)" if rec.get("station_x1") is not None else ""
    lines = [
        f"record: {rec['samples']} samples over {rec['duration']:.4g} s{where}; "
        f"{rec['slipping_samples']} slip (|V| >= {rec['slip_threshold']:.3g} m/s), "
        f"peak |V| = {rec['peak_slip_rate']:.3g} m/s",
        "fit of the simplified Prakash-Clifton law (paper eq. 1) where it slips:",
        f"  L_m = {fit['L']:.4g} m, 95 % interval {_interval(fit['L_interval_95'])} m",
        f"  V*  = {fit['v_star']:.4g} m/s"
        + (f", 95 % interval {_interval(fit['v_star_interval_95'])} m/s"
           if fit["v_star_fitted"] else " (given)"),
        f"  mu  = {fit['mu']:.6g}" + (f" +- {fit['mu_standard_error']:.2g}"
                                      if fit["mu_fitted"] else " (given)"),
        f"measured critical frequency f_m = {fm['f_m']:.4g} Hz (L_c(f_m) = L_m: A/A0 = "
        f"{fm['attenuation_ratio']:g} at |V| = {fm['slip_rate']:.3g} m/s)",
        f"contact pressure spectrum: 99 % of the power below {spectrum['frequency_99']:.4g} Hz; "
        f"{100 * spectrum['power_above_f_m']:.3g} % above f_m",
        f"verdict: {verdict['text']}",
        f"  ({verdict['reason']})",
    ]
    return lines

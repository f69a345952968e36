#!/usr/bin/python3
"""The paper's question asked of rate-and-state friction: is there a critical length L_c?

    /usr/bin/python3 clients/rsf_study.py                  # own server, writes docs/rsf-study.md
    /usr/bin/python3 clients/rsf_study.py --server http://127.0.0.1:8080
    /usr/bin/python3 clients/rsf_study.py --study-id ID    # report on a finished study

The `bimaterial_rate_state_pc` preset (two different solids, rate-and-state friction with the
slip-scale Prakash-Clifton regularisation of the normal stress) by the spectral BI method: an
L search through the studies API (POST /api/v1/studies, `convergence.search`, the server's
mesh-convergence and critical-length rules, docs/studies-api.md "L search"), with the
unregularised companion (the same law, `regularization: "none"`) run beside it under the
same mesh refinement. Starts `slipfront serve` (niced) in a temporary data dir unless
--server is given, waits, and writes the report with its figure under docs/figures/rsf-study/.
"""

import argparse
import copy
import os
import shutil
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
REPO = os.path.dirname(HERE)

from slipfront_client import report as report_mod  # noqa: E402
from slipfront_client.api import Api  # noqa: E402
from slipfront_client.local_server import Server, default_binary, log  # noqa: E402
from slipfront_client.reproduction import loadavg, study_wall, wait_study  # noqa: E402
from slipfront_client.reproduction_plan import FE_ONLY  # noqa: E402

PRESET = "bimaterial_rate_state_pc"
SEARCH = {"from": 2e-2, "factor": 2, "floor": 5e-4, "confirm": 2, "coulomb": True}
LADDER = [2.5, 5, 10]
fmt = report_mod.fmt


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--server", help="use this server instead of starting one")
    p.add_argument("--token", default=os.environ.get("SLIPFRONT_TOKEN"))
    p.add_argument("--binary", default=None, help="slipfront executable (default build/slipfront)")
    p.add_argument("--workers", type=int, default=min(2, os.cpu_count() or 1))
    p.add_argument("--out", default=os.path.join(REPO, "docs", "rsf-study.md"),
                   help="report path (default docs/rsf-study.md)")
    p.add_argument("--data-dir", help="server data dir when starting one (kept; default: "
                   "temporary): a second run reuses the runs it holds")
    p.add_argument("--timeout", type=float, help="give up waiting after this many seconds")
    p.add_argument("--study-id", help="report on this existing study instead of creating one")
    p.add_argument("--no-wait", action="store_true", help="with --study-id and --server: "
                   "report the study as it stands now, even if it is still running (the report "
                   "says so)")
    return p.parse_args(argv)


def bi_base(api):
    """The preset's job by BI as the server expands it, one thread, without the study's
    variables (friction.L, geometry.nodes_per_meter) and its name."""
    preset = next((p for p in api.presets() if p.get("name") == PRESET), None)
    if preset is None:
        raise SystemExit(f"rsf study: the server has no preset {PRESET!r}")
    spec = copy.deepcopy((preset.get("specs") or {}).get("spectral_bi") or preset["spec"])
    for section, keys in FE_ONLY.items():
        for key in keys:
            (spec.get(section) or {}).pop(key, None)
    spec["method"] = "spectral_bi"
    spec["threads"] = 1
    spec.pop("name", None)
    spec["friction"].pop("L", None)
    spec["geometry"].pop("nodes_per_meter", None)
    return spec


def study_body(base):
    return {"name": "rate-and-state with Prakash-Clifton: L search", "tags": ["rsf-study"],
            "base": base,
            "convergence": {"search": SEARCH, "n_d": LADDER, "n_d_max": max(LADDER)}}


def run_rows(api, study):
    """One row per run of the study, with its metrics; the companion's L is None."""
    rows = []
    for r in study.get("runs") or []:
        m = api.job(r["job_id"]).get("metrics") or {}
        rows.append({"id": r["job_id"], "L": None if r.get("regime") else r.get("L"),
                     "n_d": r.get("n_d"), "status": r.get("status"),
                     "outcome": m.get("outcome"),
                     "distance": m.get("propagation_distance"),
                     "arrival": m.get("arrival_time_at_probe"),
                     "peak": m.get("max_slip_velocity"), "wall": m.get("wall_time_s")})
    return sorted(rows, key=lambda r: (r["L"] is None, -(r["L"] or 0), r["n_d"] or 0))


def statement(study):
    """The answer in one plain paragraph, from the search's state."""
    search = study.get("search") or {}
    state, reason = search.get("state"), search.get("reason") or ""
    if state == "found" or state == "meets_coulomb":
        return (f"**Yes: a critical length exists for this rate-and-state scene, L_c = "
                f"{fmt(search.get('L_c'))} m.** Below it the mesh-converged answers no longer "
                f"change with L ({reason}).")
    if state == "floor":
        return ("**No critical length was found above the floor of the search.** Every step in L "
                f"down to {fmt(SEARCH['floor'])} m still changed the answer ({reason}).")
    if state == "all_agree":
        return ("**Every mesh-converged L agrees with every smaller one**: the answer does not "
                f"depend on L in the range searched, so L_c is at least {fmt(SEARCH['from'])} m "
                f"({reason}).")
    if state == "mesh_cap":
        return ("**Undecided at these meshes**: the smallest L tried have no mesh-converged run "
                f"up to n_d = {fmt(max(LADDER))} ({reason}).")
    if state in (None, "refining", "next_L"):
        return f"**The search is still going** ({state or 'no state yet'}): {reason}."
    return f"**The search ended {state}**: {reason}"


def companion_lines(rows):
    companion = [r for r in rows if r["L"] is None]
    if not companion:
        return ["The unregularised companion did not run."]
    lines = ["| n_d | outcome | propagation distance [m] | arrival at probe [s] | peak slip "
             "rate [m/s] | wall [s] |", "| --- | --- | --- | --- | --- | --- |"]
    for r in companion:
        lines.append(f"| {fmt(r['n_d'])} | {r['outcome'] or r['status']} | {fmt(r['distance'])} | "
                     f"{fmt(r['arrival'])} | {fmt(r['peak'])} | {fmt(r['wall'])} |")
    peaks = [r["peak"] for r in companion if r["peak"]]
    if len(peaks) >= 2:
        ratios = ", ".join(f"{b / a:.2f}" for a, b in zip(peaks, peaks[1:]))
        lines += ["", f"Peak slip rate, each mesh over the one before: {ratios} (a well-posed "
                  "problem's ratios tend to 1 as the mesh is refined)."]
    return lines


def runs_table(rows):
    lines = ["| L [m] | n_d | outcome | propagation distance [m] | arrival at probe [s] | peak slip "
             "rate [m/s] | wall [s] |", "| --- | --- | --- | --- | --- | --- | --- |"]
    for r in rows:
        if r["L"] is None:
            continue
        lines.append(f"| {fmt(r['L'])} | {fmt(r['n_d'])} | {r['outcome'] or r['status']} | "
                     f"{fmt(r['distance'])} | {fmt(r['arrival'])} | {fmt(r['peak'])} | "
                     f"{fmt(r['wall'])} |")
    return lines


def search_steps(study):
    steps = (study.get("search") or {}).get("steps") or []
    if not steps:
        return []
    lines = ["| L [m] against the next smaller | agree | change of distance | change of "
             "arrival time | why |", "| --- | --- | --- | --- | --- |"]
    for s in steps:
        ch = s.get("changes") or {}
        lines.append(f"| {fmt(s.get('L'))} → {fmt(s.get('smaller_L'))} | {fmt(s.get('agree'))} | "
                     f"{report_mod.percent(ch.get('propagation_distance'))} | "
                     f"{report_mod.percent(ch.get('arrival_time'))} | {s.get('reason', '')} |")
    return lines


def figure(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4), constrained_layout=True)
    for n_d in sorted({r["n_d"] for r in rows if r["n_d"]}):
        own = [r for r in rows if r["L"] is not None and r["n_d"] == n_d and r["distance"]]
        if own:
            a.semilogx([r["L"] for r in own], [r["distance"] for r in own], "o-",
                       label=f"n_d = {n_d:g} /m")
            b.loglog([r["L"] for r in own], [r["peak"] for r in own], "o-", label=f"n_d = {n_d:g} /m")
    for r in rows:
        if r["L"] is None and r["peak"]:
            b.axhline(r["peak"], ls=":", color="grey")
            b.annotate(f"no regularisation, n_d {r['n_d']:g}", (0.55, r["peak"]),
                       xycoords=("axes fraction", "data"), fontsize=7, color="grey")
    a.set(xlabel="L [m]", ylabel="propagation distance [m]",
          title="how far the rupture ran in 0.1 s")
    b.set(xlabel="L [m]", ylabel="peak slip rate [m/s]", title="peak slip rate")
    from matplotlib.ticker import NullFormatter
    for ax in (a, b):
        ax.xaxis.set_minor_formatter(NullFormatter())  # decade labels only: no overlap
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def wall_text(study, wall):
    if study.get("status") == "finished":
        return f"{wall:.0f} s wall"
    return f"started {study.get('created_at')}, still running"


def write_report(args, api, study, wall, server):
    rows = run_rows(api, study)
    fig_dir = os.path.join(os.path.dirname(os.path.abspath(args.out)), "figures", "rsf-study")
    os.makedirs(fig_dir, exist_ok=True)
    fig_path = os.path.join(fig_dir, "l_search.png")
    figure(rows, fig_path)
    rel = os.path.relpath(fig_path, os.path.dirname(os.path.abspath(args.out)))
    lines = [
        "# Does a critical length exist under rate-and-state friction?",
        "",
        "Generated by `/usr/bin/python3 clients/rsf_study.py` (do not edit by hand): the L search "
        f"of the studies API on the `{PRESET}` preset (docs/presets.md) by the spectral BI method, "
        f"search {SEARCH}, meshes n_d = {LADDER} per metre. Study `{study.get('id')}`, "
        f"{len(rows)} runs, {wall_text(study, wall)} on this machine (load {loadavg()}).",
        "",
        "## The answer",
        "",
        statement(study),
        "",
    ]
    if study.get("status") != "finished":
        progress = study.get("progress") or {}
        lines += [f"**The search had not finished when this report was written** (status "
                  f"{study.get('status')}, {progress.get('done')} of {progress.get('total')} runs "
                  "final): what follows is its state then, not its answer.", ""]
    lines += report_mod.answer_lines(study)
    lines += ["", "## Each step in L", ""] + (search_steps(study) or ["(no steps)"])
    lines += ["", "## What each L needed", ""] + report_mod.n_d_table(study)
    lines += ["", f"![propagation distance and peak slip rate against L]({rel})", "",
              "Left: how far the rupture ran in the scene's 0.1 s, against L, per mesh. Right: the "
              "peak slip rate, with the unregularised companion's as dotted lines.", "",
              "## Without regularisation", "",
              "The same law and scene with `regularization: \"none\"` (the search's companion, "
              "run under the same mesh refinement): between two different solids rate-and-state "
              "friction alone does not regularise the response to a change of normal stress "
              "(Rice, Lapusta & Ranjith 2001; Rubin & Ampuero 2007).", ""]
    lines += companion_lines(rows)
    lines += ["", "## Every run", ""] + runs_table(rows) + [""]
    with open(args.out, "w") as f:
        f.write("\n".join(lines))
    log(f"wrote {args.out} and {fig_path}")
    return 0


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    server, tmp = None, None
    t_start = time.time()
    try:
        if args.server:
            url = args.server
        else:
            data_dir = args.data_dir or tempfile.mkdtemp(prefix="slipfront-rsfstudy-data-")
            tmp = None if args.data_dir else data_dir
            os.makedirs(data_dir, exist_ok=True)
            server = Server(args.binary or default_binary(), data_dir,
                            ["--workers", str(args.workers)], startup_timeout=30,
                            preexec_fn=lambda: os.nice(10)).start()
            url = server.url
            log(f"server {url} (pid {server.proc.pid}, data {data_dir}, niced)")
        api = Api(url, token=args.token, timeout=60)
        if args.study_id:
            study = api.study(args.study_id)
        else:
            study = api.create_study(study_body(bi_base(api)))
            log(f"created study {study['id']}")
        if args.no_wait and args.study_id:
            study = api.study(study["id"])
        else:
            study = wait_study(api, study["id"], args.timeout)
        wall = study_wall(study) or (time.time() - t_start)
        return write_report(args, api, study, wall, server)
    finally:
        if server:
            server.stop()
        if tmp:
            shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())

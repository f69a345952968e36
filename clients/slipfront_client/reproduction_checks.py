"""The quick-mode checks of the L search and the paper's figures (library of
clients/reproduce_paper.py --quick; the maps' checks are reproduction_report.check_shape)."""

import os


PAPER_FIGURES = ("mesh_convergence", "length_convergence", "strength_spectrum",
                 "critical_frequency", "event_velocity", "event_speed")
SEARCH_STATES = ("found", "meets_coulomb", "mesh_cap", "floor", "all_agree")


def figure_is_blank(path):
    """True when the PNG has a single colour (nothing drawn)."""
    import matplotlib.image as mpimg
    pixels = mpimg.imread(path)
    return float(pixels.std()) == 0.0


def check_search(search_study, report_path, figures):
    """The quick L search: finished with a final state, a reason and its steps; the report
    leads with the answer by method and the paper's L_c beside ours; every new figure of the
    paper is written, non-blank and linked."""
    fails = []
    s = (search_study or {}).get("search") or {}
    if (search_study or {}).get("status") != "finished":
        fails.append(f"L search status {(search_study or {}).get('status')!r}, expected finished")
    if s.get("state") not in SEARCH_STATES or not s.get("reason"):
        fails.append(f"L search state {s.get('state')!r} / reason {s.get('reason')!r}")
    if len(s.get("searched_L") or []) < 2 or not s.get("steps"):
        fails.append(f"L search tried {s.get('searched_L')} with steps {s.get('steps')}")
    text = open(report_path, encoding="utf-8").read() if os.path.isfile(report_path) else ""
    for needle in ("## The answer, by method", "**BI, L search:", "**FE, convergence study:",
                   "## The paper's L_c beside ours", "Why they differ"):
        if needle not in text:
            fails.append(f"report lacks {needle!r}")
    if not (0 <= text.find("## The answer, by method") < text.find("## L_c verdict")):
        fails.append("report does not lead with the answer by method")
    for stem in PAPER_FIGURES:
        path = figures.get(stem)
        if not path or not os.path.isfile(path):
            fails.append(f"figure {stem} missing")
        elif figure_is_blank(path):
            fails.append(f"figure {stem} is blank")
        elif os.path.relpath(path, os.path.dirname(os.path.abspath(report_path))) not in text:
            fails.append(f"report does not link figure {stem}")
    return fails

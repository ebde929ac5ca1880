"""The papers with no figure to quote (published files with "no_figures"): what the run measures
of their ports instead."""

from .. import data, groups
from ..markdown import NOT_MEASURED, pct, ratio, table

LEVEL = 3
NUMBERED = False


def unquoted(run):
    """[(folder, published document)] of the run's papers that have no figure to quote."""
    return [(folder, doc) for folder, doc in run.published.items() if doc.get("no_figures")]


def TITLE(run):  # noqa: N802  (a section's TITLE may be a function of the run)
    papers = [doc["paper"] for _, doc in unquoted(run)]
    return "%s: what can be compared" % (" and ".join(papers) or "Papers with no figure to quote")


def render(run, part):
    docs = unquoted(run)
    sw = run.d.get("sweeps")
    rows = []
    for folder, doc in docs:
        for a in run.ports(folder):
            sing = data.totals(run.check, a, predicate=lambda f: f not in data.SINGULAR_EXCLUDED)
            exact = groups.sweep_totals(sw, a, "exact", "identity") if sw else None
            r = run.ratio_range(a, run.reference)
            rows.append([a, pct(sing.overlap_error_rate()),
                         pct(exact.overlap_error_rate()) if exact and exact.cases else "-",
                         ratio(r[0]) if r else "-", doc.get("notes", {}).get(a, "")])
    if not rows:
        part.add("%s.\n" % NOT_MEASURED)
        return
    reasons = sorted({d["no_figures"] for _, d in docs})
    why = ("for each, " + reasons[0]) if len(reasons) == 1 else "; ".join(
        "%s: %s" % (d["paper"], d["no_figures"]) for _, d in docs)
    part.add("No figure of %s can be quoted (%s), so there is no number to set ours against; what the run "
             "does measure:\n" % (" or ".join(d["paper"] for _, d in docs), why))
    part.add(table(["algorithm", "error rate, singular families", "error rate, exact input",
                    "time ÷ %s at R = 0.5" % run.reference, "note"], rows, align=["l", "r", "r", "r", "l"]))
    part.add("Sources: %s.\n" % "; ".join(doc["source"] for _, doc in docs))

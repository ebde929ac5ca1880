"""Part 5: the papers' published figures beside ours. Each paper with figures to compare has its
own subsection after this one (moller97.py, ...); the figures are read from
algorithms/<folder>/published.json (published.py)."""

from ..markdown import NOT_MEASURED, table

TITLE = "The papers' tables"

# Where each paper's own subsection stands (sections/__init__.py): LEVEL 3, under this part,
# NUMBERED False.
SUBSECTION = 3, False


def render(run, part):
    part.add("Published figures (quoted from the papers, cited below each table) beside ours, with a verdict "
             "and the reason for any difference. Our times are CPU time per pair on this machine, in C++, "
             "on pools of distinct shuffled pairs; no paper measured that way, so only ratios measured "
             "in the same run are compared, never absolute times across machines.\n")


def claim_table(part, rows):
    """The claim | published | ours | verdict | reason table every paper section uses."""
    part.add(table(["claim", "published", "ours", "verdict", "reason"], rows, align=["l"] * 5))


def cite(part, doc):
    part.add("Published: %s.\n" % doc["source"])


def subsection(folder, compare, needs_bench=False):
    """The render function of a paper's subsection: compare(run, part, doc) with the paper's
    published file (algorithms/FOLDER/published.json), then its citation; without that file (or,
    with needs_bench, without a bench result) the subsection says so instead."""
    def render(run, part):
        doc = run.published.get(folder)
        if not doc or (needs_bench and not run.bench):
            part.add("%s.\n" % NOT_MEASURED)
            return
        compare(run, part, doc)
        cite(part, doc)
    return render

"""Part 5: the papers' published figures beside ours. Each paper with figures to compare has its
own subsection after this one (moller97.py, ...); the figures are read from
algorithms/<folder>/published.json (published.py)."""

from ..markdown import table

TITLE = "The papers' tables"


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

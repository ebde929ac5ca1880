"""Part 6: each algorithm's worst listed failures, drawn in three views, with their case lines."""

from .. import analysis, data, figures
from ..markdown import NOT_MEASURED

TITLE = "Failure gallery"


def render(run, part):
    if not run.check:
        part.add("%s.\n" % NOT_MEASURED)
        return
    failures = run.check.get("failures", [])
    total = 0
    for a in run.algorithms():
        t = data.totals(run.check, a)
        total += t.fp + t.fn + (t.misclassified or 0)
    part.add("For each algorithm, its worst listed failures in three orthographic views (front x–z, top x–y, "
             "side y–z, as Yu–He draw theirs; T1 blue, T2 orange). Worst: a wrong yes/no before a wrong "
             "relation, exactly singular input before rounded or perturbed input, then one per family. "
             "The check lists %d of the %d disagreements (`--json-max-failures` keeps the first ones of each "
             "algorithm × family × level). Near-singular failures look like their exact neighbours: the "
             "coordinates are the evidence.\n" % (len(failures), total))
    drawn = [draw(part, a, failures) for a in run.algorithms()]
    if not any(drawn):
        part.add("No failure listed: every algorithm agrees with the oracle on every case.\n")


def draw(part, algorithm, failures):
    """The algorithm's figure and case lines; False when it has no listed failure."""
    chosen = analysis.gallery_choice(failures, algorithm)
    if not chosen:
        return False
    rows = []
    for k, f in enumerate(chosen, 1):
        t1, t2 = analysis.case_triangles(f["line"])
        rows.append(("(%d) %s" % (k, f["case"]), t1, t2))
    fig = part.figure("gallery-%s.png" % algorithm, figures.gallery, rows, title=algorithm)
    part.add("### %s\n" % algorithm)
    part.add("![failures of %s](%s)\n" % (algorithm, fig))
    for k, f in enumerate(chosen, 1):
        what = ("overlap: answered %s, oracle %s" % (f["answer"], f["oracle"]) if f["level"] == "overlap"
                else "%s: answered %s, oracle %s" % (f["level"], f["answer"], f["oracle"]))
        part.add("(%d) `%s`, family %s — %s (oracle relation %s).\n\n```\n%s\n```\n" % (
            k, f["case"], f["family"], what, f.get("oracle_relation", "?"), f["line"]))
    return True

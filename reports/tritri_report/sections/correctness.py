"""Part 1: every algorithm against the oracle on the corpus (check.json), per algorithm, per
family, relations and segments. The symmetric variants and the baselines follow as their own
subsections (asymmetry.py, baseline.py)."""

from collections import OrderedDict

from .. import data, figures
from ..markdown import NOT_MEASURED, count, pct, sci, table

TITLE = "Correctness"


def render(run, part):
    c = run.check
    if not c:
        part.add("The corpus check (`check.json`): %s.\n" % NOT_MEASURED)
        return
    part.add("Every algorithm against the oracle on the corpus (%d cases, %d families), from `check.json`. "
             "FP: said they meet, they do not; FN: the reverse; relation: misclassified (algorithms "
             "that answer the relation level); unsupported: declined, or degenerate input the algorithm "
             "does not accept; crash and timeout: the case killed or hung the algorithm (each runs "
             "isolated).\n" % (c.get("case_count", 0), len(c.get("families", []))))
    part.add(judged(c))
    per_algorithm(run, part)
    per_family(run, part)
    relations(run, part)
    segments(run, part)


def judged(check):
    """Which judge decided how many cases (tritri-check/3; a version-2 file was judged by the
    oracle alone)."""
    j = check.get("judge")
    if not j:
        return "Judged by the oracle alone (CGAL), every case.\n"
    if j["kind"] == "oracle":
        return "Judged by the oracle alone (CGAL, `--judge oracle`): %d cases.\n" % j["oracle"]
    return ("Judged exact-first: %d cases decided by `exact` (%d of them cross-checked by the oracle, "
            "one in %d, seed %d), %d by the oracle (what `exact` declined, and the exact "
            "intersection for the segment level).\n"
            % (j["exact"], j["cross_checked"], j["sample"]["one_in"], j["sample"]["seed"], j["oracle"]))


def per_algorithm(run, part):
    part.heading("Per algorithm")
    rows = []
    for a in run.algorithms():
        t = data.totals(run.check, a)
        rows.append([a, t.cases, t.fp, t.fn, count(t.misclassified), t.unsupported, t.crashes, t.timeouts,
                     pct(t.overlap_error_rate())])
    part.add(table(["algorithm", "cases", "FP", "FN", "relation", "unsupported", "crash", "timeout",
                    "overlap error rate"], rows))


def per_family(run, part):
    """The heatmap and the FP/FN counts per algorithm x family."""
    fams, algos = run.check.get("families", []), run.algorithms()
    tb = data.tallies_by(run.check)
    values, counts, cells = [], [], []
    for a in algos:
        vr, cr, row = [], [], [a]
        for f in fams:
            t = tb.get((a, f))
            if t is None:
                vr.append(None)
                cr.append(None)
                row.append("-")
                continue
            tot = data.Totals().add(t)
            vr.append(tot.overlap_error_rate())
            cr.append(tot.overlap_errors)
            row.append("0" if tot.overlap_errors == 0 else "%d/%d" % (tot.fp, tot.fn))
        values.append(vr)
        counts.append(cr)
        cells.append(row)
    fig = part.figure("correctness-heatmap.png", figures.heatmap, algos, fams, values, counts,
                      title="Overlap error rate per algorithm × family (cell: FP+FN count)")
    part.heading("Overlap errors per family")
    part.add("![overlap error rate per algorithm and family](%s)\n" % fig)
    part.add("Cells: FP/FN counts (0 when neither).\n")
    part.add(table(["algorithm"] + fams, cells))


def top_wrong_cells(tb, algorithm, fams, limit=5):
    """The most frequent (answered, oracle) cells off the confusion's diagonal, all families."""
    cells = OrderedDict()
    for f in fams:
        for cell in (tb.get((algorithm, f), {}).get("confusion") or []):
            if cell["answer"] != cell["oracle"]:
                key = (cell["answer"], cell["oracle"])
                cells[key] = cells.get(key, 0) + cell["count"]
    return sorted(cells.items(), key=lambda kv: -kv[1])[:limit]


def relations(run, part):
    fams, c = run.check.get("families", []), run.check
    tb = data.tallies_by(c)
    rel_algos = [a for a in run.algorithms() if data.totals(c, a).misclassified is not None]
    part.heading("Misclassified relations per family")
    if not rel_algos:
        part.add("No algorithm in this run answers the relation level.\n")
        return
    rows = [[a] + [count(tb[(a, f)].get("misclassified")) if (a, f) in tb else "-" for f in fams]
            for a in rel_algos]
    part.add(table(["algorithm"] + fams, rows))
    part.add("The most frequent wrong cells of the relation confusion (answered → oracle), all "
             "families together:\n")
    rows = [[a, "; ".join("%s → %s: %d" % (k[0], k[1], v) for k, v in top_wrong_cells(tb, a, fams)) or "none"]
            for a in rel_algos]
    part.add(table(["algorithm", "top wrong cells"], rows, align=["l", "l"]))


def segments(run, part):
    fams, c = run.check.get("families", []), run.check
    tb = data.tallies_by(c)
    part.heading("Segment error")
    seg_algos = [a for a in run.algorithms() if data.totals(c, a).has_segment]
    if not seg_algos:
        part.add("No algorithm in this run answers the segment level.\n")
        return
    part.add("For algorithms that return the intersection: the Hausdorff distance between the answered "
             "and the exact point or segment, over the pair's bounding-box diagonal. Medians are per "
             "family (the JSON has no corpus-wide median); kind mismatch: the answer's dimension is "
             "not the exact one's; not computed: coplanar contact found, no geometry given.\n")
    rows = []
    for a in seg_algos:
        t = data.totals(c, a)
        meds = [tb[(a, f)]["segment"].get("median_error") for f in fams
                if (a, f) in tb and tb[(a, f)].get("segment")]
        meds = [m for m in meds if m is not None]
        rows.append([a, t.segment_answered, t.segment_measured,
                     "%s … %s" % (sci(min(meds)), sci(max(meds))) if meds else "-",
                     sci(t.segment_max), t.kind_mismatches, t.not_computed])
    part.add(table(["algorithm", "answered", "measured", "family medians (min … max)", "max",
                    "kind mismatch", "not computed"], rows))
    rows = []
    for a in seg_algos:
        row = [a]
        for f in fams:
            s = tb.get((a, f), {}).get("segment")
            row.append("%s / %s" % (sci(s.get("median_error")), sci(s.get("max_error"))) if s else "-")
        rows.append(row)
    part.add("Median / max per family:\n")
    part.add(table(["algorithm"] + fams, rows))

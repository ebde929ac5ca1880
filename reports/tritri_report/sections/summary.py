"""One row per algorithm: errors, asymmetry, time, and time over the bench's reference."""

from .. import data, groups
from ..markdown import NOT_MEASURED, count, ns, pct, ratio, table

TITLE = "Summary"
NUMBERED = False


def relative_cell(run, algorithm):
    """The time over the reference's on `ratio:0.50`, as the bench file gives it."""
    if not run.bench:
        return "-"
    level = data.primary_levels(run.bench).get(algorithm)
    rel = data.relative_to_reference(data.bench_entry(run.bench, algorithm, level, "ratio:0.50"))
    return ratio(rel) if rel else "-"


def render(run, part):
    if not run.check:
        part.add("Correctness: %s.\n" % NOT_MEASURED)
        return
    asym = groups.asymmetry(run.d["symmetry"], run.floors) if "symmetry" in run.d else None
    rows = []
    for a in run.algorithms():
        sing = data.totals(run.check, a, predicate=lambda f: f not in data.SINGULAR_EXCLUDED)
        rnd = data.totals(run.check, a, families=data.SINGULAR_EXCLUDED)
        allt = data.totals(run.check, a)
        t, level = run.timed_ns(a)
        asym_cell = "-"
        if asym is not None and a in asym:
            asym_cell = "%d / %d" % (sum(v[0] for v in asym[a].values()), sum(v[1] for v in asym[a].values()))
        rows.append([a, allt.fp + allt.fn, pct(sing.overlap_error_rate()),
                     pct(rnd.overlap_error_rate()) if rnd.cases else "-",
                     count(allt.misclassified), asym_cell,
                     ns(t) + ("" if level in (None, "overlap") else " (%s)" % level),
                     relative_cell(run, a)])
    part.add("Overlap errors are false positives plus false negatives over the whole corpus; the rates "
             "are over the cases each algorithm accepts. Time: median ns per pair on the `ratio:0.50` "
             "pool at the algorithm's first level (overlap, else relation).\n")
    part.add(table(["algorithm", "overlap errors", "error rate, singular families", "error rate, random",
                    "misclassified relations", "asymmetric base cases", "ns/pair", "× " + run.reference], rows))

"""One row per algorithm: errors, asymmetry, and its time in each mode the bench timed (one pair
per call, and in batches), absolute and over the bench's reference in the same mode."""

from .. import data, groups
from ..markdown import NOT_MEASURED, count, ns, pct, ratio, table

TITLE = "Summary"
NUMBERED = False


def relative_cell(run, algorithm, mode):
    """The time over the reference's on `ratio:0.50` in `mode`, as the bench file gives it."""
    if not run.bench:
        return "-"
    level = data.primary_levels(run.bench).get(algorithm)
    rel = data.relative_to_reference(data.bench_entry(run.bench, algorithm, level, "ratio:0.50", mode))
    return ratio(rel) if rel else "-"


def time_cells(run, a, modes):
    cells = []
    for mode in modes:
        t, level = run.timed_ns(a, mode=mode)
        cells.append(ns(t) + ("" if level in (None, "overlap") else " (%s)" % level))
    return cells + [relative_cell(run, a, mode) for mode in modes]


def render(run, part):
    if not run.check:
        part.add("Correctness: %s.\n" % NOT_MEASURED)
        return
    asym = groups.asymmetry(run.d["symmetry"], run.floors) if "symmetry" in run.d else None
    modes = run.modes or [None]
    rows = []
    for a in run.algorithms():
        sing = data.totals(run.check, a, predicate=lambda f: f not in data.SINGULAR_EXCLUDED)
        rnd = data.totals(run.check, a, families=data.SINGULAR_EXCLUDED)
        allt = data.totals(run.check, a)
        asym_cell = "-"
        if asym is not None and a in asym:
            asym_cell = "%d / %d" % (sum(v[0] for v in asym[a].values()), sum(v[1] for v in asym[a].values()))
        rows.append([a, allt.fp + allt.fn, pct(sing.overlap_error_rate()),
                     pct(rnd.overlap_error_rate()) if rnd.cases else "-",
                     count(allt.misclassified), asym_cell] + time_cells(run, a, modes))
    part.add("Overlap errors are false positives plus false negatives over the whole corpus; the rates "
             "are over the cases each algorithm accepts. Time: median ns per pair on the `ratio:0.50` "
             "pool at the algorithm's first level (overlap, else relation), %s, on %s with the lane "
             "algorithms (`exact`) on %s; ×: over %s's time in the same mode.\n"
             % (mode_words(run.modes), run.cpu, run.isa, run.reference))
    suffix = (lambda m: " " + m) if len(run.modes) > 1 else (lambda m: "")
    part.add(table(["algorithm", "overlap errors", "error rate, singular families", "error rate, random",
                    "misclassified relations", "asymmetric base cases"] +
                   ["ns/pair" + suffix(m) for m in run.modes or [""]] +
                   ["× " + run.reference + suffix(m) for m in run.modes or [""]], rows))


MODE_WORDS = {"call": "in call mode (one pair per out-of-line call, as a BVH calls its narrow phase)",
              "batch": "in batch mode (the pool handed over in batches of 256, where `exact` decides several "
                       "pairs per SIMD instruction: 4 with AVX2, 8 with AVX-512)"}


def mode_words(modes):
    """The modes as a sentence names them."""
    words = [MODE_WORDS.get(m, "in %s mode" % m) for m in modes]
    return " and ".join(words) if words else "in no mode (no bench)"

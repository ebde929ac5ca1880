"""Möller 1997, section 3: brute force against Möller's test, and Möller's test against ERIT
(held97): the ratio of times, and where the two cross over R."""

from .. import analysis
from ..markdown import NOT_MEASURED
from . import papers

TITLE = "Möller 1997"
LEVEL, NUMBERED = papers.SUBSECTION
FOLDER = "moller97"


def compare(run, part, doc):
    claims = doc["claims"]
    rows = [brute_force(run, claims["brute_force"]), faster_than_erit(run, claims["faster_than_erit"]),
            break_even(run, claims["break_even_with_erit"])]
    papers.claim_table(part, rows)


def brute_force(run, claim):
    lo, hi = claim["range"]
    published = "%.1f–%.1f ×" % (lo, hi)
    br = run.ratio_range(claim["algorithm"], claim["against"])
    if not br:
        return [claim["claim"], published, NOT_MEASURED, "-", "-"]
    mid, mn, mx, _ = br
    inside = lo <= mid <= hi
    if inside and lo <= mn and mx <= hi:
        verdict = "holds"
    elif inside:
        verdict = "holds at R = 0.5; outside the range at other R"
    elif mx >= lo and mn <= hi:
        verdict = "partly: inside the range at some R only"
    else:
        verdict = "differs"
    return [claim["claim"], published, "%.2f × at R = 0.5; %.2f–%.2f × over R = 0…1" % (mid, mn, mx), verdict,
            "Möller timed \"several different scenarios\" inside RAPID on 1997 SGI machines and did "
            "not publish his brute force: ours (six edge–triangle tests) is a reconstruction, timed "
            "per pair on shuffled pools. The ratio moves with R because the two tests exit early "
            "on different pairs, so a scenario's collision ratio decides where in (or out of) the "
            "range it falls."]


def faster_than_erit(run, claim):
    published = "≈ %.0f%%" % (100 * claim["value"])
    hr = run.ratio_range(claim["algorithm"], claim["against"])
    if not hr:
        return [claim["claim"], published, NOT_MEASURED, "-", "-"]
    mid, mn, mx, _ = hr
    faster = mid - 1
    if faster < 0:
        verdict = "differs: Möller's test is the slower one here"
    elif faster <= 0.15:
        verdict = "holds"
    else:
        verdict = "holds in direction; the gap is larger"
    return [claim["claim"], published,
            "%s takes %.2f × Möller's time at R = 0.5; %.2f–%.2f × over R" % (claim["algorithm"], mid, mn, mx),
            verdict,
            "ERIT's code was never published: %s is reconstructed from Möller's and Tropp's "
            "descriptions (normalised normals, tolerance 1e-10), so its cost is ours, not Held's; "
            "different machine and compiler." % claim["algorithm"]]


def break_even(run, claim):
    published = "≈ %.0f%%" % (100 * claim["value"])
    series, spreads = run.ratio_series()
    a, b = claim["against"], claim["algorithm"]
    if a not in series or b not in series:
        return [claim["claim"], published, NOT_MEASURED, "-", "-"]
    cr = analysis.crossings(series[a], series[b], spreads.get(a), spreads.get(b))
    if cr:
        ours = "; ".join("R = %.2f%s" % (r, " (within noise)" if n else "") for r, _, n in cr)
        close = any(abs(r - claim["value"]) <= 0.1 and not n for r, _, n in cr)
        verdict = "holds" if close else "differs"
    else:
        ta, tb = dict(series[a]), dict(series[b])
        faster = a if all(ta[r] < tb[r] for r in ta if r in tb) else b
        ours = "no crossing: %s is faster at every R" % faster
        verdict = "differs"
    return [claim["claim"], published, ours, verdict,
            "the break-even point depends on what each early exit costs on the machine: Möller saw it "
            "on the O2 and not on the Impact, so it is machine-dependent even in his measurements; "
            "and our ERIT is a reconstruction."]


render = papers.subsection(FOLDER, compare)

"""Tropp, Tal & Shimshoni 2006: faster than the earlier tests, with fewer operations. Both are
measured over the ratio pools, against the earlier tests its published file names."""

from .. import data
from ..markdown import NOT_MEASURED, ns, table
from . import papers

TITLE = "Tropp, Tal & Shimshoni 2006"
LEVEL, NUMBERED = papers.SUBSECTION
FOLDER = "tropp06"


def means_over_ratio_pools(bench, algorithm, mode):
    """(operations per pair, ns per pair), each the mean over the ratio pools, at the overlap level."""
    ops, times = [], []
    for _, w in data.ratio_workloads(bench):
        e = data.bench_entry(bench, algorithm, "overlap", w, mode)
        if e:
            o = data.ops_total(e)
            if o is not None:
                ops.append(o)
            if e.get("ns_per_pair_median") is not None:
                times.append(e["ns_per_pair_median"])
    return (sum(ops) / len(ops) if ops else None), (sum(times) / len(times) if times else None)


def compare(run, part, doc):
    faster, fewer = doc["claims"]["faster"], doc["claims"]["fewer_operations"]
    ours = faster["algorithm"]
    levels = data.primary_levels(run.bench)
    earlier = [a for a in doc["earlier_tests"] if levels.get(a) == "overlap"]
    ports = run.ports(FOLDER) or [ours]
    measured = {a: means_over_ratio_pools(run.bench, a, run.mode) for a in ports + earlier}
    ops_t = {a: m[0] for a, m in measured.items()}
    time_t = {a: m[1] for a, m in measured.items()}
    rows = [row for row in (speed_row(faster, ours, earlier, time_t, run.reference),
                            operations_row(fewer, ours, earlier, ops_t)) if row]
    if rows:
        papers.claim_table(part, rows)
    else:
        part.add("%s or the earlier tests were not timed: %s.\n" % (ours, NOT_MEASURED))
    part.add("Operations and time per pair, mean over the ratio pools:\n")
    part.add(table(["algorithm", "operations/pair", "ns/pair"],
                   [[a, "%.1f" % ops_t[a] if ops_t[a] is not None else "-", ns(time_t[a])] for a in measured]))


def speed_row(claim, ours, earlier, time_t, reference):
    timed = [a for a in earlier if time_t.get(a)]
    if not time_t.get(ours) or not timed:
        return None
    fastest = min(timed, key=lambda a: time_t[a])
    gain = 1 - time_t[ours] / time_t[fastest]
    verdict = "holds" if abs(gain - claim["value"]) <= 0.08 else ("differs: slower" if gain < 0 else "differs in size")
    text = "%+.1f%% against %s, the fastest earlier test here (mean over R = 0…1)" % (100 * gain, fastest)
    if fastest != reference and time_t.get(reference):
        text += "; %+.1f%% against %s" % (100 * (1 - time_t[ours] / time_t[reference]), reference)
    return [claim["claim"], "%.1f%%" % (100 * claim["value"]), text, verdict,
            "Tropp timed a Pentium 4 on their collision scenarios, with the edge vectors supplied by "
            "the caller; our harness times their computation too, on shuffled pools, against "
            "earlier tests that include Guigue–Devillers 2003."]


def operations_row(claim, ours, earlier, ops_t):
    published = "≈ %.0f%%" % (100 * claim["value"])
    if not ops_t.get(ours):
        return [claim["claim"], published,
                "%s: %s registers no operation-counting instantiation, so `tritri bench` counts nothing "
                "for it" % (NOT_MEASURED, ours), "-", "-"]
    counted = [a for a in earlier if ops_t.get(a)]
    if not counted:
        return None
    fewest = min(counted, key=lambda a: ops_t[a])
    fewer = 1 - ops_t[ours] / ops_t[fewest]
    verdict = "holds" if abs(fewer - claim["value"]) <= 0.08 else (
        "differs: more operations" if fewer < 0 else "differs in size")
    return [claim["claim"], published,
            "%+.1f%% against %s (add+mul+div+cmp per pair, mean over R)" % (100 * fewer, fewest), verdict,
            "we count every addition, multiplication, division and comparison executed, set-up "
            "included, averaged over the pools' mix of exits; the paper's count is per full test."]


render = papers.subsection(FOLDER, compare, needs_bench=True)

"""The exact test of this project (algorithms/exact): per pool, what share of the pairs its SIMD
filter could not decide and its exact engine had to, and its time per pair in each mode: one pair
per call (its one-pair entry is the scalar path alone) and in batches (the SIMD lanes), beside
the fast inexact tests and the exact peer on the same pools in the same mode.

Read from the bench JSON: each batch-mode `exact` result carries `path_counters` (the algorithm's
PathCounters: pairs, undecided_by_simd, to_scalar, grid, filtered, declined, one_pair_route,
isa:NAME). The batch may send chunks straight to its one-pair path (its route choice,
algorithms/exact/README.md): the SIMD shares are of the pairs that went through the lanes, and
the pairs sent straight are a column of their own. A file from before the modes has batch mode
only; its `exact-scalar` stood for the scalar path.
"""

from .. import data, figures
from ..markdown import NOT_MEASURED, ns, pct, ratio, table
from . import summary

TITLE = "The exact test: where its time goes"
LEVEL = 3
EXACT = "exact"
PEERS = ("moller97", "guigue03", "cgal")
LEVEL_TIMED = "overlap"


def pools_of(bench):
    """The pools exact was timed on, ratio pools first (by R), then the rest in bench order."""
    pools = []
    for r in data.bench_results(bench):
        if r["algorithm"] == EXACT and r["level"] == LEVEL_TIMED and r["workload"] not in pools:
            pools.append(r["workload"])
    ratios = [w for _, w in data.ratio_workloads(bench) if w in pools]
    return ratios + [w for w in pools if w not in ratios]


def isa_of(counters):
    names = [k.split(":", 1)[1] for k in counters if k.startswith("isa:")]
    return names[0] if names else "?"


def share(counters, key, lanes=False):
    """counters[key] as a share of the batch's pairs; with `lanes`, of those it ran through its SIMD
    lanes (not sent straight to its one-pair path by the route choice; files from before it have no
    such pairs)."""
    pairs = (counters.get("pairs") or 0) - (counters.get("one_pair_route", 0) if lanes else 0)
    return counters.get(key, 0) / pairs if pairs > 0 else None


def time_over(bench, workload, exact_ns, other, mode):
    e = data.bench_entry(bench, other, LEVEL_TIMED, workload, mode)
    t = e.get("ns_per_pair_median") if e else None
    return exact_ns / t if exact_ns and t else None


def batch_counters(bench, workload):
    """The path counters of exact's batch on the pool (counted through the batch entry)."""
    return (data.bench_entry(bench, EXACT, LEVEL_TIMED, workload, "batch") or {}).get("path_counters") or {}


def row(bench, workload, modes):
    times = [data.bench_median(bench, EXACT, LEVEL_TIMED, workload, m) for m in modes]
    c = batch_counters(bench, workload)
    return [workload] + [ns(t) for t in times] + \
        [ratio(time_over(bench, workload, t, p, m)) for p in PEERS for m, t in zip(modes, times)] + \
        [pct(share(c, "undecided_by_simd", lanes=True)), pct(share(c, "to_scalar", lanes=True)), pct(share(c, "filtered", lanes=True)),
         pct(share(c, "one_pair_route")), isa_of(c)]


def render(run, part):
    pools = pools_of(run.bench)
    if not pools:
        part.add("The exact test on the bench's pools: %s.\n" % NOT_MEASURED)
        return
    modes = run.modes
    part.add("`exact` (algorithms/exact, this project) answers every pair as the oracle does. Its batch "
             "decides each pair from orientation signs in SIMD lanes, each sign certain when it exceeds a "
             "semi-static error bound; a pair the lanes cannot decide goes to a second SIMD pass on small "
             "integer grids, and what is left to the exact scalar classification, whose filtered "
             "predicates fall back to an integer engine. Called one pair at a time (call mode) it runs that "
             "scalar classification alone: what a user calling it from a BVH traversal gets. Per pool: ns "
             "per pair (median) %s, on %s with its lanes on %s; exact's time over each peer's on the same "
             "pool in the same mode; and, in its batch, of the pairs it ran through its lanes, the share left "
             "undecided by the first SIMD pass, sent to the scalar path, and decided by filtered predicates "
             "there (the rest of those on the grid); last, the share its route choice sent straight to the "
             "one-pair path (where that was the faster).\n" % (summary.mode_words(modes), run.cpu, run.isa))
    rows = [row(run.bench, w, modes) for w in pools]
    part.add(table(["pool"] + ["exact ns " + m for m in modes] + ["÷ %s %s" % (p, m) for p in PEERS for m in modes] +
                   ["undecided by SIMD", "to scalar path", "filtered predicates", "one-pair route", "SIMD width"], rows))
    families = [w for w in pools if w.startswith("family:")]
    if families:
        left = [share(batch_counters(run.bench, w), "undecided_by_simd", lanes=True) for w in families]
        right = [share(batch_counters(run.bench, w), "to_scalar", lanes=True) for w in families]
        fig = part.figure("exact-fallback.png", figures.paired_bars, [w.split(":", 1)[1] for w in families],
                          left, right, ("undecided by the SIMD filter", "sent to the exact scalar path"),
                          ylabel="share of the family's pairs", title="exact: the fallback share per family")
        part.add("![exact: fallback share per family](%s)\n" % fig)

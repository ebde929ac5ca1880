"""The exact test of this project (algorithms/exact): per pool, what share of the pairs its SIMD
filter could not decide and its exact engine had to, and the time per pair of its SIMD batch
(`exact`) and of its scalar path alone (`exact-scalar`), beside the fast inexact tests and the
exact peer on the same pools.

Read from the bench JSON: each `exact` result carries `path_counters` (the algorithm's
PathCounters: pairs, undecided_by_simd, to_scalar, grid, filtered, declined, isa:NAME).
"""

from .. import data, figures
from ..markdown import NOT_MEASURED, ns, pct, ratio, table

TITLE = "The exact test: where its time goes"
LEVEL = 3
EXACT, SCALAR = "exact", "exact-scalar"
PEERS = ("moller97", "guigue03", "cgal")
LEVEL_TIMED = "overlap"


def pools_of(bench):
    """The pools exact was timed on, ratio pools first (by R), then the rest in bench order."""
    pools = [r["workload"] for r in data.bench_results(bench)
             if r["algorithm"] == EXACT and r["level"] == LEVEL_TIMED]
    ratios = [w for _, w in data.ratio_workloads(bench) if w in pools]
    return ratios + [w for w in pools if w not in ratios]


def isa_of(counters):
    names = [k.split(":", 1)[1] for k in counters if k.startswith("isa:")]
    return names[0] if names else "?"


def share(counters, key):
    pairs = counters.get("pairs") or 0
    return counters.get(key, 0) / pairs if pairs else None


def time_over(bench, workload, exact_ns, other):
    e = data.bench_entry(bench, other, LEVEL_TIMED, workload)
    t = e.get("ns_per_pair_median") if e else None
    return exact_ns / t if exact_ns and t else None


def row(bench, workload):
    e = data.bench_entry(bench, EXACT, LEVEL_TIMED, workload)
    s = data.bench_entry(bench, SCALAR, LEVEL_TIMED, workload)
    t = e.get("ns_per_pair_median")
    c = e.get("path_counters") or {}
    return [workload, ns(t), ns(s.get("ns_per_pair_median") if s else None)] + \
        [ratio(time_over(bench, workload, t, p)) for p in PEERS] + \
        [pct(share(c, "undecided_by_simd")), pct(share(c, "to_scalar")), pct(share(c, "filtered")), isa_of(c)]


def render(run, part):
    pools = pools_of(run.bench)
    if not pools:
        part.add("The exact test on the bench's pools: %s.\n" % NOT_MEASURED)
        return
    part.add("`exact` (algorithms/exact, this project) answers every pair as the oracle does. Its batch "
             "decides each pair from orientation signs in SIMD lanes, each sign certain when it exceeds a "
             "semi-static error bound; a pair the lanes cannot decide goes to a second SIMD pass on small "
             "integer grids, and what is left to the exact scalar classification, whose filtered "
             "predicates fall back to an integer engine. `exact-scalar` runs every pair through that "
             "scalar path alone. Per pool: ns per pair (median), exact's time over each peer's on the same "
             "pool, and the share of pairs left undecided by the first SIMD pass, sent to the scalar "
             "path, and decided by filtered predicates there (the rest of those on the grid).\n")
    rows = [row(run.bench, w) for w in pools]
    part.add(table(["pool", "exact ns", "exact-scalar ns"] + ["÷ " + p for p in PEERS] +
                   ["undecided by SIMD", "to scalar path", "filtered predicates", "SIMD width"], rows))
    families = [w for w in pools if w.startswith("family:")]
    if families:
        left = [share(data.bench_entry(run.bench, EXACT, LEVEL_TIMED, w).get("path_counters") or {},
                      "undecided_by_simd") for w in families]
        right = [share(data.bench_entry(run.bench, EXACT, LEVEL_TIMED, w).get("path_counters") or {},
                       "to_scalar") for w in families]
        fig = part.figure("exact-fallback.png", figures.paired_bars, [w.split(":", 1)[1] for w in families],
                          left, right, ("undecided by the SIMD filter", "sent to the exact scalar path"),
                          ylabel="share of the family's pairs", title="exact: the fallback share per family")
        part.add("![exact: fallback share per family](%s)\n" % fig)

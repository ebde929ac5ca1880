"""The tests the web ships (three-mesh-bvh, fast-triangle-triangle-intersection, Rapier's
WebAssembly build), run as process plug-ins in Node.js and timed in their own runtime: each times
its own loop over the pool on its runtime's clock ('#time' in harness/run/process_plugin.hpp), so
no pipe is inside their times. Beside them, moller97 and null timed the same way by a C++ process
plug-in (what this way of timing gives for a known test, and its floor), and moller97 timed in
process by Google Benchmark. Reads bench-peers.json (`tritri bench --exec ...` in scripts/run)
and, for their answers, check.json."""

from .. import data
from ..markdown import NOT_MEASURED, count, ns, pct, ratio, table

TITLE = "The tests the web ships, in their own runtime"
POOLS = ("ratio:0.00", "ratio:0.50", "ratio:1.00")
# The C++ process plug-ins scripts/run times beside the peers (build/plugins/process-peer).
PROTOCOL_REFERENCE = "moller97-process"
PROTOCOL_FLOOR = "null-process"


def self_timed(bench):
    """{algorithm: {workload: ns per pair}} of the results the plug-ins timed themselves."""
    out = {}
    for r in bench.get("tritri", {}).get("self_timed", []):
        out.setdefault(r["algorithm"], {})[r["workload"]] = r.get("ns_per_pair_median")
    return out


def render(run, part):
    bench = run.d.get("peers_bench")
    if bench is None:
        part.add("%s: no bench-peers.json (scripts/run times the process peers when Node.js and their "
                 "packages are installed: scripts/setup).\n" % NOT_MEASURED)
        return
    timed = self_timed(bench)
    peers = [a for a in timed if a not in (PROTOCOL_REFERENCE, PROTOCOL_FLOOR)]
    if not peers:
        part.add("%s: bench-peers.json holds no self-timed peer.\n" % NOT_MEASURED)
        return
    reference = timed.get(PROTOCOL_REFERENCE, {})
    rows = []
    for a in [PROTOCOL_REFERENCE, PROTOCOL_FLOOR] + peers:
        if a not in timed:
            continue
        cells = []
        for w in POOLS:
            t, m = timed[a].get(w), reference.get(w)
            cells.append("%s (%s)" % (ns(t), ratio(t / m)) if t and m else ns(t))
        rows.append([a, "its own loop"] + cells)
    for a in ("moller97", "null"):
        cells = [ns(data.bench_median(bench, a, "overlap", w, "call")) for w in POOLS]
        if any(c != ns(None) for c in cells):
            rows.append([a, "Google Benchmark, in process"] + cells)
    part.add("ns per pair, one pair per call of the test, medians of one run (%s); in brackets ÷ %s, "
             "the same test this report times in process, timed the same way as the peers: a C++ process "
             "plug-in looping over the pool on its own clock. %s is that loop with a test that answers at "
             "once: what the protocol's way of timing adds to every row.\n"
             % (data.platform(bench)[0], PROTOCOL_REFERENCE, PROTOCOL_FLOOR))
    part.add(table(["test", "timed by"] + list(POOLS), rows))
    check = run.d.get("check")
    if check is None:
        return
    listed = set(data.algorithm_names(check))
    rows = []
    for a in peers:
        if a not in listed:
            continue
        t = data.totals(check, a)
        rows.append([a, count(t.cases), count(t.fp), count(t.fn), count(t.unsupported),
                     count(t.crashes + t.timeouts), pct(t.overlap_errors / t.scored if t.scored else None)])
    if rows:
        part.add("Their answers on the corpus (check.json, overlap level, every family): the per-family "
                 "counts are in the correctness tables above, their findings and witnesses in "
                 "`algorithms/<name>/README.md`.\n")
        part.add(table(["test", "cases", "false positives", "false negatives", "declined", "crashes or hangs",
                        "wrong"], rows))

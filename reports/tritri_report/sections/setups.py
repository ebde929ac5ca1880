"""The papers' own timing drivers, rerun: what the papers' sections read from papers-bench.json
(`scripts/papers-bench`, in the main job with --authors-code: one `tritri bench` run of the
`paper:` workloads, harness/bench/workloads/paper.hpp) and float-bench.json (every port beside its
float instantiation on three ratio pools). Not a section: the helpers the papers' sections share.

Each driver's pool is the paper's set-up; each `paper:NAME/MODIFIER` pool changes one thing of it
(the order, the pool size, the ratio, the distribution), the `@float` entries change the scalar
type, and tropp06's stage edges-given hands it the edge vectors precomputed. All in one run, so
every ratio below is of times measured side by side.
"""

from .. import data
from ..markdown import NOT_MEASURED

FLOAT = "@float"  # the suffix of a float instantiation (and of an original built in float)
EDGES = "edges-given"  # tropp06's stage: the published interface, edges precomputed by the caller
NOT_RUN = ("%s: no papers-bench.json (`./scripts/run --authors-code PATH`, or `scripts/papers-bench "
           "PATH`, reruns the papers' drivers; paper:shen03 reads the authors' data files)" % NOT_MEASURED)


def papers_bench(run):
    return run.d.get("papers_bench")


def ns_of(bench, algorithm, workload, stage=None):
    """The median ns per pair of an algorithm on a pool: its primary level, or the stage named."""
    for r in data.bench_results(bench):
        if r["algorithm"] != algorithm or r["workload"] != workload:
            continue
        if stage is not None and r.get("stage") == stage:
            return r.get("ns_per_pair_median")
        if stage is None and r.get("level") == data.primary_levels(bench).get(algorithm):
            return r.get("ns_per_pair_median")
    return None


def over(a, b):
    return a / b if a and b else None


def pools(bench):
    """The workloads of the run, in run order."""
    seen = []
    for r in data.bench_results(bench):
        if r["workload"] not in seen:
            seen.append(r["workload"])
    return seen


def skipped(bench, workload):
    """Why a paper pool was not built ("" when it was): the bench's context key "paper VALUE"."""
    note = ((bench or {}).get("context") or {}).get("paper " + workload.split(":", 1)[-1], "")
    return note[len("skipped: "):] if note.startswith("skipped: ") else ""


def pool_note(bench, workload):
    """The driver's own description of a paper pool (pairs, intersecting, order), or ""."""
    return ((bench or {}).get("context") or {}).get("paper " + workload.split(":", 1)[-1], "")


def moves_text(changes, target, fmt, target_name):
    """Which change alone accounts for the difference between the paper's set-up and ours.
    changes: [(what, before, after)], each one difference from the paper's set-up varied alone
    (before: the result without it, after: with it); target: our pools' result. Names the change
    that brings the result closest to ours, and the one that moves it most, when another."""
    changes = [c for c in changes if c[1] is not None and c[2] is not None]
    if not changes or target is None:
        return "-"
    closest = min(changes, key=lambda c: abs(c[2] - target))
    largest = max(changes, key=lambda c: abs(c[2] - c[1]))
    text = "toward ours (%s %s): %s alone, %s → %s" % (target_name, fmt(target), closest[0], fmt(closest[1]),
                                                       fmt(closest[2]))
    if largest is not closest:
        text += "; the largest move: %s, %s → %s" % (largest[0], fmt(largest[1]), fmt(largest[2]))
    return text + " (table below)"


def float_times(bench, workload):
    """{port: (double ns, float ns)} of the ports timed beside their float instantiation."""
    out = {}
    levels = data.primary_levels(bench)
    for a, level in levels.items():
        if a.endswith(FLOAT) or a + FLOAT not in levels or a in data.floors(bench):
            continue
        out[a] = (data.bench_median(bench, a, level, workload), data.bench_median(bench, a + FLOAT, level, workload))
    return out

"""Ports against the authors' code: per port, the cases where it answers differently from the
published routine it follows, and its time over the original's on the same pools in the same run.

Read from two files that `./scripts/run --authors-code PATH` writes (scripts/authors-code builds
the originals as plug-ins named orig-PORT): authors-diff.json (`tritri diff --json`, schema
tritri-diff/1) and authors-bench.json (`tritri bench` with the plug-ins). Without them the
section says that nothing was measured, and why.
"""

import os

from .. import data
from ..markdown import count, ns, ratio, table

TITLE = "Ports against the authors' code"
LEVEL = 3
NUMBERED = False
DIFF = "authors-diff.json"
BENCH = "authors-bench.json"
EXAMPLES_PER_PORT = 2


def render(run, part):
    diff = data.load_json(os.path.join(run.results_dir, DIFF), "diff")
    bench = data.load_json(os.path.join(run.results_dir, BENCH), "bench")
    if diff is None and bench is None:
        part.add("Not measured: no --authors-code given. `./scripts/run --authors-code PATH [--tropp FILE]` "
                 "builds the authors' published routines from a jgt-code checkout (scripts/authors-code) "
                 "and sets each port beside its original here.\n")
        return
    part.add("Each port follows one published routine, operation for operation; the original is built "
             "from the authors' file (float changed to double, nothing else) with the same compiler flags "
             "and loaded as a plug-in named orig-PORT.\n")
    if diff is not None:
        differences(part, diff)
    if bench is not None:
        speed(part, bench)


def differences(part, diff):
    part.add("Answers, port against original, on %s cases (%d case files), from `%s`:\n"
             % (count(diff.get("case_count", 0)), len(diff.get("inputs", [])), DIFF))
    rows = []
    for p in diff.get("pairs", []):
        where = ", ".join("%s %s" % (f["family"], count(f["differ"]))
                          for f in sorted(p["families"], key=lambda f: -f["differ"]) if f["differ"])
        rows.append([p["a"], p["b"], count(p["differ"]), count(p["overlap_differ"]),
                     count(p["segment_differ"]) if p.get("segment_compared") else "-",
                     count(p["fate_differ"]), where or "-"])
    part.add(table(["port", "original", "differ", "overlap", "segment", "crash/timeout", "families"], rows))
    part.add("A difference where the original reads unset memory (the undefined paths each port's "
             "README names) is the original's, not the port's.\n")
    shown = [(p, e) for p in diff.get("pairs", []) for e in p.get("examples", [])[:EXAMPLES_PER_PORT]]
    if shown:
        part.add("First differing cases (paste-ready: `tritri show` or a case file takes them):\n")
        text = "\n".join("# %s vs %s, %s: %s %s=%s %s=%s\n%s" % (p["a"], p["b"], e["family"], e["level"], p["a"],
                                                               e["a"], p["b"], e["b"], e["case"].rstrip())
                         for p, e in shown)
        part.add("```\n%s\n```\n" % text)


def speed(part, bench):
    """Port ÷ original per ratio pool, from one bench run that timed both."""
    levels = data.primary_levels(bench)
    pools = [w for _, w in data.ratio_workloads(bench)]
    for r in data.bench_results(bench):  # then the other workloads (singular families), in run order
        if r["level"] == "overlap" and r["workload"] not in pools:
            pools.append(r["workload"])
    originals = [a for a in levels if a.startswith("orig-")]
    rows = []
    for original in originals:
        port = original[len("orig-"):]
        if port not in levels:
            continue
        cells = []
        for w in pools:
            t_port = data.bench_median(bench, port, "overlap", w)
            t_orig = data.bench_median(bench, original, "overlap", w)
            cells.append("%s / %s (%s)" % (ns(t_port), ns(t_orig), ratio(t_port / t_orig) if t_port and t_orig else "-"))
        rows.append([port] + cells)
    if not rows:
        part.add("Speed: the bench file has no port timed beside its original.\n")
        return
    part.add("Time per pair at the overlap level, port / original (port ÷ original), medians of the "
             "same `tritri bench` run on the same pools:\n")
    part.add(table(["port"] + pools, rows))

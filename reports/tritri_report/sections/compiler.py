"""What the compiler changes: every port tritri compiles from source, built a second time for
x86-64-v3 with FMA contraction allowed (`-march=x86-64-v3 -ffp-contract=fast`, registered as
NAME@v3fma: algorithms/api/builds.hpp), set beside its baseline build (`-ffp-contract=off`).

Read from two files the main job writes: compiler-diff.json (`tritri diff --oracle --pair
NAME=NAME@v3fma ...` on the corpus, schema tritri-diff/1 with the oracle's judgement per family)
and compiler-bench.json (`tritri bench` of both builds on the ratio pools). Without them (the CPU
cannot run the v3fma build, so tritri registers none) the part says that nothing was measured.
"""

from .. import data
from ..markdown import NOT_MEASURED, count, ns, ratio, table

TITLE = "What the compiler changes"
SUFFIX = "@v3fma"  # the name build_variants.hpp gives each port's x86-64-v3 build
EXAMPLES = 2  # changed cases shown per port, paste-ready, for the three ports with most changes


def render(run, part):
    diff, bench = run.d.get("compiler_diff"), run.d.get("compiler_bench")
    if diff is None and bench is None:
        part.add("The x86-64-v3 builds (`%s`, `%s`): %s (tritri loads NAME%s only on a CPU with AVX2 "
                 "and FMA).\n" % (data.FILES["compiler_diff"], data.FILES["compiler_bench"], NOT_MEASURED,
                                  SUFFIX))
        return
    part.add("Every timing and answer elsewhere in this report is of one build: baseline x86-64 with "
             "`-ffp-contract=off`. The same ports as users ship them, compiled with `-march=x86-64-v3 "
             "-ffp-contract=fast` (AVX2, and the compiler free to fuse `a*b+c` into one rounding), are "
             "registered as NAME%s; the library peers are prebuilt and not rebuilt. A fused "
             "multiply-add rounds once where the source rounds twice: it moves a nearly-zero "
             "determinant's sign, exactly where these tests are judged.\n" % SUFFIX)
    if diff is not None:
        answers(part, diff)
    else:
        part.add("Answers (`%s`): %s.\n" % (data.FILES["compiler_diff"], NOT_MEASURED))
    if bench is not None:
        speed(part, bench)
    else:
        part.add("Speed (`%s`): %s.\n" % (data.FILES["compiler_bench"], NOT_MEASURED))
    if diff is not None:
        examples(part, diff)


def build_pairs(diff):
    """The diff's pairs that set a port beside its own v3fma build."""
    return [p for p in diff.get("pairs", []) if p["b"] == p["a"] + SUFFIX]


def family_sum(pair, key):
    return sum(f.get(key, 0) for f in pair["families"])


def answers(part, diff):
    pairs = build_pairs(diff)
    part.add("Answers, baseline build against NAME%s, on the same %s cases (`tritri diff --oracle`). "
             "Where the two builds' overlap answers differ, one of them is wrong: the columns say which, "
             "and by a false positive (FP) or a false negative (FN) against the exact oracle. A segment "
             "change is the same overlap answer with other bits in the segment's ends.\n"
             % (SUFFIX, count(diff.get("case_count", 0))))
    rows = []
    for p in pairs:
        judged = p.get("oracle", False)
        cell = (lambda key: count(family_sum(p, key)) if judged else "-")  # noqa: E731
        rows.append([p["a"], count(p["overlap_differ"]), cell("b_fp"), cell("b_fn"), cell("a_fp"), cell("a_fn"),
                     count(p["segment_differ"]) if p.get("segment_compared") else "-", count(p["fate_differ"])])
    part.add(table(["port", "overlap changed", "v3fma wrong: FP", "v3fma wrong: FN", "baseline wrong: FP",
                    "baseline wrong: FN", "segment changed", "crash/timeout"], rows))
    by_family = []
    for p in pairs:
        for f in sorted(p["families"], key=lambda f: (-f.get("overlap_differ", 0), f["family"])):
            if f.get("overlap_differ", 0):
                by_family.append([p["a"], f["family"], count(f["cases"]), count(f["overlap_differ"]),
                                  "%s / %s" % (count(f.get("b_fp")), count(f.get("b_fn"))),
                                  "%s / %s" % (count(f.get("a_fp")), count(f.get("a_fn")))])
    if by_family:
        part.add("Per family, the cases whose overlap answer changes:\n")
        part.add(table(["port", "family", "cases", "changed", "v3fma wrong (FP / FN)", "baseline wrong (FP / FN)"],
                       by_family))
    else:
        part.add("No overlap answer changes between the two builds on this corpus.\n")


def speed(part, bench):
    """NAME@v3fma ÷ NAME per ratio pool, at the port's primary level, from one bench run."""
    levels = data.primary_levels(bench)
    pools = data.ratio_workloads(bench)
    rows = []
    for port, level in levels.items():
        if port.endswith(SUFFIX) or port + SUFFIX not in levels:
            continue
        cells = []
        for _, w in pools:
            base = data.bench_median(bench, port, level, w)
            built = data.bench_median(bench, port + SUFFIX, level, w)
            cells.append(ratio(built / base) if base and built else "-")
        at_half = [data.bench_median(bench, port, level, w) for r, w in pools if r == 0.5]
        rows.append([port, level, ns(at_half[0]) if at_half else "-"] + cells)
    if not rows:
        part.add("Speed: the bench file has no port timed beside its v3fma build.\n")
        return
    part.add("Time per pair, NAME%s ÷ NAME (below 1: the x86-64-v3 build is faster), medians of the same "
             "`tritri bench` run on the same pools, at each intersection ratio R; the baseline's ns per pair "
             "at R = 0.5 for scale:\n" % SUFFIX)
    part.add(table(["port", "level", "baseline ns, R=0.5"] + ["R=%g" % r for r, _ in pools], rows))


def examples(part, diff):
    """The first changed overlap answers of the ports with most changes, paste-ready."""
    top = sorted(build_pairs(diff), key=lambda p: -p["overlap_differ"])[:3]
    shown = [(p, e) for p in top for e in [e for e in p.get("examples", []) if e["level"] == "overlap"][:EXAMPLES]]
    if not shown:
        return
    part.add("First cases whose overlap answer changes (paste-ready: `tritri show` or a case file takes them):\n")
    text = "\n".join("# %s: %s=%s %s=%s\n%s" % (e["family"], p["a"], e["a"], p["b"], e["b"], e["case"].rstrip())
                      for p, e in shown)
    part.add("```\n%s\n```\n" % text)

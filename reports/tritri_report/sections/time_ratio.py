"""Part 3: time per pair against the share of intersecting pairs, break-even points, and the
pools of one intersection type or one corpus family."""

from .. import analysis, data, figures
from ..markdown import NOT_MEASURED, ns, table

TITLE = "Time against intersection ratio"


def published_marks(run, series):
    """Crossings a paper published a break-even for: ([(R, ns, label)], the sentence naming them)."""
    marks, names = [], []
    for a, b, what in run.published_crossings():
        if a not in series or b not in series:
            continue
        names.append("%s and %s%s" % (a, b, " (%s)" % what if what else ""))
        for r, t, _ in analysis.crossings(series[a], series[b]):
            marks.append((r, t, "%s=%s @%.2f" % (a, b, r)))
    return marks, "".join(", and where %s cross" % n for n in names)


def reference_crossings(run, series, spreads):
    ref = run.reference
    rows = []
    if ref not in series:
        return rows
    for a in series:
        if a == ref or a in run.floors:
            continue
        for r, t, noisy in analysis.crossings(series[ref], series[a], spreads.get(ref), spreads.get(a)):
            rows.append([ref + " / " + a, "%.2f" % r, ns(t), "within noise" if noisy else ""])
    return rows


def render(run, part):
    if not run.bench or not data.ratio_workloads(run.bench):
        part.add("The ratio workloads of `tritri bench`: %s.\n" % NOT_MEASURED)
        return
    series, spreads = run.ratio_series()
    env = analysis.envelope_changes({a: p for a, p in series.items() if a not in run.floors})
    marks, also = published_marks(run, series)
    marks = [(r, t, "%s→%s @%.2f" % (a, b, r)) for r, t, a, b in env] + marks
    fig = part.figure("time-ratio.png", figures.ratio_lines, series, marks,
                      xlabel="intersection ratio R (share of the pool's pairs that intersect)",
                      ylabel="ns per pair (median, log scale)")
    pool = (run.bench.get("context", {}) or {}).get("pool_size", "?")
    part.add("Median ns per pair on pools of %s distinct pairs of which exactly R intersect, each algorithm "
             "at its first level. Red circles: break-even points where the fastest algorithm changes%s.\n"
             % (pool, also))
    part.add("![time against intersection ratio](%s)\n" % fig)
    rs = [r for r, _ in data.ratio_workloads(run.bench)]
    rows = [[a] + [ns(dict(pts).get(r)) for r in rs] for a, pts in series.items()]
    part.add(table(["algorithm"] + ["%.1f" % r for r in rs], rows))
    part.add("Break-even points where the fastest algorithm changes:\n")
    if env:
        part.add(table(["R", "ns/pair", "fastest before", "fastest after"],
                       [["%.2f" % r, ns(t), a, b] for r, t, a, b in env]))
    else:
        part.add("None: one algorithm is fastest at every R.\n")
    part.add("Every crossing with %s (linear between measured R; \"within noise\": the gap at both "
             "ends is smaller than the repetitions' spread):\n" % run.reference)
    pair_rows = reference_crossings(run, series, spreads)
    part.add(table(["pair", "R", "ns/pair", "note"], pair_rows) if pair_rows else "None.\n")
    other_workloads(run, part)


OTHER_WORKLOADS = (
    ("type:", "Time per intersection type",
     "Pools of only disjoint, point, segment or area pairs (the oracle's dimension), "
     "median ns per pair at each algorithm's first level:"),
    ("family:", "Time on the corpus families",
     "One pool per corpus family (%s): what singular and near-singular input costs, median ns per "
     "pair; `!` marks a time measured on a pool where the algorithm answers some pairs wrongly."),
)


def other_workloads(run, part):
    """The type and family pools: what each kind of contact, and singular input, costs."""
    levels = data.primary_levels(run.bench)
    for prefix, title, intro in OTHER_WORKLOADS:
        workloads = []
        for r in data.bench_results(run.bench):
            if r["workload"].startswith(prefix) and r["workload"] not in workloads:
                workloads.append(r["workload"])
        part.heading(title)
        if not workloads:
            part.add("%s.\n" % NOT_MEASURED)
            continue
        if "%s" in intro:
            intro = intro % ((run.bench.get("context") or {}).get("family_source", "the corpus generator's"))
        rows = []
        for a, level in levels.items():
            if a == data.HARNESS_FLOOR:
                continue
            row = [a]
            for w in workloads:
                e = data.bench_entry(run.bench, a, level, w)
                cell = ns(e.get("ns_per_pair_median")) if e else "-"
                if e and prefix == "family:" and e.get("wrong") and a not in run.floors:
                    cell += " !"
                row.append(cell)
            rows.append(row)
        part.add(intro + "\n")
        part.add(table(["algorithm"] + [w.split(":", 1)[1] for w in workloads], rows))

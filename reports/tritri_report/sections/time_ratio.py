"""Part 3: time per pair against the share of intersecting pairs, break-even points, and the
pools of one intersection type or one corpus family."""

from collections import OrderedDict

from .. import analysis, data, figures, kinds
from ..markdown import NOT_MEASURED, ns, table
from . import summary

TITLE = "Time against intersection ratio"


def published_marks(run, series):
    """Crossings a paper published a break-even for: ([(R, ns, label, {a, b})], the sentence naming them)."""
    marks, names = [], []
    for a, b, what in run.published_crossings():
        if a not in series or b not in series:
            continue
        names.append("%s and %s%s" % (a, b, " (%s)" % what if what else ""))
        for r, t, _ in analysis.crossings(series[a], series[b]):
            marks.append((r, t, "%s=%s @%.2f" % (a, b, r), {a, b}))
    return marks, "".join(", and where %s cross" % n for n in names)


def reference_crossings(run, series, spreads, mode):
    ref = run.reference
    rows = []
    if ref not in series:
        return rows
    for a in series:
        if a == ref or a in run.floors:
            continue
        for r, t, noisy in analysis.crossings(series[ref], series[a], spreads.get(ref), spreads.get(a)):
            rows.append([ref + " / " + a, mode, "%.2f" % r, ns(t), "within noise" if noisy else ""])
    return rows


def render(run, part):
    if not run.bench or not data.ratio_workloads(run.bench):
        part.add("The ratio workloads of `tritri bench`: %s.\n" % NOT_MEASURED)
        return
    per_mode = OrderedDict((m, run.ratio_series(m)) for m in run.modes)
    envs, panels, also = OrderedDict(), [], ""
    for mode, (series, spreads) in per_mode.items():
        envs[mode] = analysis.envelope_changes({a: p for a, p in series.items() if a not in run.floors})
        marks, also = published_marks(run, series)
        marks = [(r, t, "%s→%s @%.2f" % (a, b, r), {a, b}) for r, t, a, b in envs[mode]] + marks
        panels.append((mode, group_panels(run, series, marks)))
    fig = part.figure("time-ratio.png", figures.ratio_panels, panels,
                      xlabel="intersection ratio R (share of the pool's pairs that intersect)",
                      ylabel="ns per pair (median, log scale)")
    pool = (run.bench.get("context", {}) or {}).get("pool_size", "?")
    part.add("Median ns per pair on pools of %s distinct pairs of which exactly R intersect, each algorithm "
             "at its first level, %s, on %s (lane algorithms on %s); one panel per group of algorithms and "
             "mode, each line named at its end. Red circles: break-even points where the fastest algorithm "
             "changes%s (listed below).\n"
             % (pool, summary.mode_words(run.modes), run.cpu, run.isa, also))
    part.add("![time against intersection ratio](%s)\n" % fig)
    part.add(spread_sentence(run.bench))
    rs = [r for r, _ in data.ratio_workloads(run.bench)]
    rows = []
    for a in all_names(per_mode):
        for mode, (series, _) in per_mode.items():
            if a in series:
                rows.append([a, mode] + [ns(dict(series[a]).get(r)) for r in rs])
    part.add(table(["algorithm", "mode"] + ["%.1f" % r for r in rs], rows))
    part.add("Break-even points where the fastest algorithm changes, per mode:\n")
    env_rows = [["%.2f" % r, mode, ns(t), a, b] for mode, env in envs.items() for r, t, a, b in env]
    if env_rows:
        part.add(table(["R", "mode", "ns/pair", "fastest before", "fastest after"], env_rows))
    else:
        part.add("None: one algorithm is fastest at every R, in every mode.\n")
    part.add("Every crossing with %s in the same mode (linear between measured R; \"within noise\": the gap "
             "at both ends is smaller than the repetitions' spread):\n" % run.reference)
    pair_rows = [row for mode, (series, spreads) in per_mode.items()
                 for row in reference_crossings(run, series, spreads, mode)]
    part.add(table(["pair", "mode", "R", "ns/pair", "note"], pair_rows) if pair_rows else "None.\n")
    other_workloads(run, part)


def spread_sentence(bench):
    """How far a median here can be trusted: the repetitions behind it and how much they differ."""
    reps, median, worst = data.repetition_spread(bench)
    if median is None:
        return "The repetitions' spread: not recorded.\n"
    count = ("" if not reps else " of %d" % reps[0] if len(reps) == 1 else " of %d to %d" % (reps[0], reps[-1]))
    return ("Each time is the median%s repetitions; their spread (slowest over fastest, minus one) is "
            "%.0f%% at the median benchmark and %.0f%% at the worst: differences smaller than the spread "
            "are not measured here.\n" % (count, 100 * median, 100 * (worst or median)))


def group_panels(run, series, marks):
    """[(group, its series, the marks of its algorithms)] (kinds.py); the floor `null` beside
    the published ports, as the line every other lies above."""
    out = []
    for group, names in kinds.split(run, [a for a in series if a not in run.floors]):
        shown = names + ([f for f in series if f in run.floors] if group == kinds.GROUPS[0] else [])
        out.append((group, OrderedDict((a, series[a]) for a in shown),
                    [(r, t, text) for r, t, text, who in marks if who & set(names)]))
    return out


def all_names(per_mode):
    """The algorithms of every mode's series, in first-seen order."""
    names = []
    for series, _ in per_mode.values():
        names += [a for a in series if a not in names]
    return names


OTHER_WORKLOADS = (
    ("type:", "Time per intersection type",
     "Pools of only disjoint, point, segment or area pairs (the oracle's dimension), "
     "median ns per pair at each algorithm's first level, per mode:"),
    ("family:", "Time on the corpus families",
     "One pool per corpus family (%s): what singular and near-singular input costs, median ns per "
     "pair per mode; `!` marks a time measured on a pool where the algorithm answers some pairs wrongly."),
)


def other_workloads(run, part):
    """The type and family pools: what each kind of contact, and singular input, costs."""
    levels = data.primary_levels(run.bench)
    for prefix, title, intro in OTHER_WORKLOADS:
        workloads, timed_modes = [], set()
        for r in data.bench_results(run.bench):
            if r["workload"].startswith(prefix):
                timed_modes.add(data.mode_of(r))
                if r["workload"] not in workloads:
                    workloads.append(r["workload"])
        # The main job's default plan times these pools in one mode only (scripts/run): no rows of dashes.
        modes = [m for m in run.modes if m in timed_modes]
        part.heading(title)
        if not workloads:
            part.add("%s.\n" % NOT_MEASURED)
            continue
        if "%s" in intro:
            intro = intro % ((run.bench.get("context") or {}).get("family_source", "the corpus generator's"))
        rows = [[a, mode] + [workload_cell(run, a, level, w, mode, prefix) for w in workloads]
                for a, level in levels.items() if a != data.HARNESS_FLOOR for mode in modes]
        if len(modes) < len(run.modes):
            intro += " Timed in %s only in this run." % " and ".join("%s mode" % m for m in modes)
        part.add(intro + "\n")
        part.add(table(["algorithm", "mode"] + [w.split(":", 1)[1] for w in workloads], rows))


def workload_cell(run, a, level, w, mode, prefix):
    e = data.bench_entry(run.bench, a, level, w, mode)
    cell = ns(e.get("ns_per_pair_median")) if e else "-"
    if e and prefix == "family:" and e.get("wrong") and a not in run.floors:
        cell += " !"
    return cell

"""Part 2: each algorithm's time against its error rate, and the Pareto frontier, per mode."""

from .. import analysis, data, figures, kinds
from ..markdown import NOT_MEASURED, ns, pct, table
from . import summary

TITLE = "Speed against error"


def points_in(run, mode, levels):
    """[(algorithm, ns on ratio:0.50 in `mode`, error rate on the singular families)]."""
    points = []
    for a in run.algorithms():
        t, levels[a] = run.timed_ns(a, mode=mode)
        if t is None:
            continue
        rate = data.totals(run.check, a, predicate=lambda f: f not in data.SINGULAR_EXCLUDED).overlap_error_rate()
        if rate is not None:
            points.append((a, t, rate))
    return points


def render(run, part):
    if not run.check or not run.bench:
        part.add("Needs both the check and the bench results: %s.\n" % NOT_MEASURED)
        return
    levels, per_mode = {}, {}
    for mode in run.modes:
        points = points_in(run, mode, levels)
        per_mode[mode] = (points, analysis.pareto_frontier(points))
    panels = [(m, [(g, [p for p in pts if p[0] in names]) for g, names in kinds.split(run, [p[0] for p in pts])],
               pts, front) for m, (pts, front) in per_mode.items()]
    fig = part.figure("speed-error.png", figures.pareto_panels, panels,
                      xlabel="ns per pair on ratio:0.50 (median, log scale)",
                      ylabel="overlap error rate, singular families (log)")
    part.add("One point per algorithm and per tolerance setting (each variant is registered on its own), "
             "one panel per group of algorithms and mode: x is the median time per pair on the `ratio:0.50` pool %s, on %s (lane "
             "algorithms on %s); y the overlap error rate (FP + FN + crashes + timeouts over the cases it "
             "accepts) on every corpus family but `random`. Points with no error sit on the \"no errors\" "
             "line. The dashed line is the Pareto frontier of the mode over every group (its algorithms ringed in "
             "red): no other algorithm is both faster and more accurate in it.\n" % (summary.mode_words(run.modes), run.cpu, run.isa))
    part.add("![speed against error](%s)\n" % fig)
    first = per_mode[run.modes[0]][0] if run.modes else []
    times = {m: {a: t for a, t, _ in pts} for m, (pts, _) in per_mode.items()}
    rows = [[a, levels[a]] + [ns(times[m].get(a)) for m in run.modes] + [pct(rate, 3)] +
            ["yes" if a in per_mode[m][1] else "" for m in run.modes]
            for a, _, rate in sorted(first, key=lambda p: p[1])]
    part.add(table(["algorithm", "level timed"] + ["ns/pair " + m for m in run.modes] + ["error rate"] +
                   ["on the frontier, " + m for m in run.modes], rows))

"""Part 2: each algorithm's time against its error rate, and the Pareto frontier."""

from .. import analysis, data, figures
from ..markdown import NOT_MEASURED, ns, pct, table

TITLE = "Speed against error"


def render(run, part):
    if not run.check or not run.bench:
        part.add("Needs both the check and the bench results: %s.\n" % NOT_MEASURED)
        return
    points, levels = [], {}
    for a in run.algorithms():
        t, levels[a] = run.timed_ns(a)
        if t is None:
            continue
        rate = data.totals(run.check, a, predicate=lambda f: f not in data.SINGULAR_EXCLUDED).overlap_error_rate()
        if rate is None:
            continue
        points.append((a, t, rate))
    front = analysis.pareto_frontier(points)
    rows = [[a, levels[a], ns(t), pct(rate, 3), "yes" if a in front else ""]
            for a, t, rate in sorted(points, key=lambda p: p[1])]
    fig = part.figure("speed-error.png", figures.pareto, points, front,
                      xlabel="ns per pair on ratio:0.50 (median, log scale)",
                      ylabel="overlap error rate, singular families (log)")
    part.add("One point per algorithm and per tolerance setting (each variant is registered on its own): "
             "x is the median time per pair on the `ratio:0.50` pool, y the overlap error rate "
             "(FP + FN + crashes + timeouts over the cases it accepts) on every corpus family but "
             "`random`. Points with no error sit on the \"no errors\" line. The dashed line is the Pareto "
             "frontier: no other algorithm is both faster and more accurate.\n")
    part.add("![speed against error](%s)\n" % fig)
    part.add(table(["algorithm", "level timed", "ns/pair", "error rate", "on the frontier"], rows))

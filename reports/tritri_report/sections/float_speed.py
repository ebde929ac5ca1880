"""Float against double, in time: every port's float instantiation (NAME@float) beside its double
one on the ratio pools R = 0, 0.5 and 1, from one `tritri bench --float` run (float-bench.json,
batch mode). Möller's and Shen's originals were written in float, the others in double; the
ports are timed in double everywhere else in this report."""

from .. import data
from ..markdown import NOT_MEASURED, ns, ratio, table
from . import papers, setups

TITLE = "Float and double: time per pair"
LEVEL, NUMBERED = papers.SUBSECTION
POOLS = ("ratio:0.00", "ratio:0.50", "ratio:1.00")


def render(run, part):
    bench = run.d.get("float_bench")
    if bench is None:
        part.add("%s: no float-bench.json (the main job's `tritri bench --float` on R = 0, 0.5, 1).\n"
                 % NOT_MEASURED)
        return
    per_pool = {w: setups.float_times(bench, w) for w in POOLS}
    ports = [a for a in data.primary_levels(bench) if any(a in per_pool[w] for w in POOLS)]
    rows = []
    for a in ports:
        cells = []
        for w in POOLS:
            d, f = per_pool[w].get(a, (None, None))
            cells.append("%s / %s (%s)" % (ns(d), ns(f), ratio(f / d) if d and f else "-"))
        rows.append([a] + cells)
    part.add("Each port in double and in float, ns per pair: double / float (float ÷ double), medians of one "
             "run in batch mode. The float instantiation rounds each pair to float inside the call (18 "
             "conversions, part of its time, as a caller holding double coordinates pays them); the "
             "authors' float originals in papers-bench.json are called the same way.\n")
    part.add(table(["port"] + list(POOLS), rows))
    rounding = [(w, data.bench_median(bench, "null" + setups.FLOAT, "overlap", w), data.bench_median(bench, "null", "overlap", w))
                for w in POOLS]
    shown = ["%s %s ns" % (w, ns(f - d)) for w, f, d in rounding if f and d]
    if shown:
        part.add("The rounding alone, null@float − null (the floor reading every coordinate, in float and in "
                 "double): %s. A float time above its double one by less than that is the rounding, not "
                 "the test.\n" % ", ".join(shown))

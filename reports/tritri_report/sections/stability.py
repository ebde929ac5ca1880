"""Part 4: error rates along the sweeps (check-sweeps.json: the corpus grouped by the quantity
swept, groups.py): exact against rounded input, then one subsection per sweep."""

from collections import OrderedDict

from .. import analysis, data, figures, groups
from ..markdown import NOT_MEASURED, pct, table

TITLE = "Stability"


def render(run, part):
    sw = run.d.get("sweeps")
    if not sw:
        part.add("The sweeps (`check-sweeps.json`): %s.\n" % NOT_MEASURED)
        return
    part.add("From `check-sweeps.json`: the corpus cases grouped by the quantity swept (the "
             "construction's label, or the transformation applied), each group checked like a family. "
             "Only exactly transformed variants carry a construction's label (symmetry, scaling, "
             "translation); rotated and perturbed copies are grouped by their own transformation. "
             "Error rate: FP + FN + crashes + timeouts over the cases accepted.\n")
    exact = []
    for a in data.algorithm_names(sw, run.floors):
        exact.append([a] + [pct(groups.sweep_totals(sw, a, *s).overlap_error_rate())
                            for s in (("exact", "identity"), ("rotate",), ("perturb",))])
    part.heading("Exact input against rounded input")
    part.add("Every base construction as built (exactly singular, unpermuted), the same rotated by a random "
             "rotation rounded to double, and perturbed by ±δ:\n")
    part.add(table(["algorithm", "exact (identity variant)", "rotated (rounded)", "perturbed (all δ)"], exact))
    names = groups.sweep_names(sw)
    for sweep in analysis.SWEEPS:
        part.heading(analysis.SWEEPS[sweep][0])
        text = sweep_table_and_figure(part, sweep, sw, run.floors) if sweep in names else None
        part.add(text or NOT_MEASURED + ".\n")


def sweep_table_and_figure(part, sweep, check, floors):
    title, xlabel = analysis.SWEEPS[sweep][:2]
    algos = data.algorithm_names(check, floors)
    series, zero, rows, xs = OrderedDict(), [], [], None
    for a in algos:
        bins = analysis.sweep_bins(sweep, groups.sweep_series(check, sweep, a))
        if not bins:
            continue
        if xs is None:
            xs = [(x, label) for x, label, _ in bins]
        rates = [(x, t.overlap_error_rate()) for x, _, t in bins]
        if any(r for _, r in rates):
            series[a] = rates
        else:
            zero.append(a)
        rows.append([a] + [pct(t.overlap_error_rate()) for _, _, t in bins])
    if not rows:
        return None
    n_cases = sum(t.cases for _, _, t in analysis.sweep_bins(sweep, groups.sweep_series(check, sweep, algos[0])))
    fig = part.figure("stability-%s.png" % sweep, figures.sweep_lines, series,
                      xlabel=xlabel, title=title, xscale="log")
    text = "![%s](%s)\n\n" % (title, fig)
    worst = max(((rate, a, x) for a, pts in series.items() for x, rate in pts if rate), default=None)
    if worst:
        text += "Highest error rate: %s, %s at %s.\n\n" % (worst[1], pct(worst[0]), dict(xs).get(worst[2], "?"))
    if zero:
        text += "No overlap error at any value: %s.\n\n" % ", ".join(zero)
    header = ["algorithm"] + [label for _, label in xs]
    return text + "%d cases. Overlap error rate per value:\n\n" % n_cases + table(header, rows)

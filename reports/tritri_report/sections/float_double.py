"""4.10: the float instantiations (`tritri check --float`, NAME@float) against double."""

from collections import OrderedDict

from .. import analysis, data, figures, groups
from ..markdown import NOT_MEASURED, pct, ratio, table

TITLE = "Float against double"
LEVEL = 3
FLOAT = "@float"  # the suffix `tritri check --float` names each float instantiation with


def render(run, part):
    cf = run.d.get("check_float")
    if not cf or not run.check:
        part.add("The float instantiations (`check-float.json`, from `tritri check --float`): %s.\n"
                 % NOT_MEASURED)
        return
    without = [a for a in run.algorithms() if a + FLOAT not in data.algorithm_names(cf)]
    part.add("Every port that has a float instantiation, run through it (`tritri check --float`: each pair "
             "rounded to float inside the call, judged against the oracle's answer for the double input) "
             "on the same corpus. Ports calling a library on double have none%s. Part of what float gets "
             "wrong is the rounding of the input itself: two triangles a double ulp apart may touch once "
             "rounded to float, and the float answer is judged against the double input: what a caller who "
             "converts double data to float gets.\n" % (" (here: %s)" % ", ".join(without) if without else ""))
    names = corpus_table(run, part, cf)
    swf, sw = run.d.get("sweeps_float"), run.d.get("sweeps")
    if swf and sw:
        for sweep in ("perturb", "scale"):
            sweep_panels(part, sweep, names, sw, swf)
    else:
        part.add("Float sweeps (`check-sweeps-float.json`): %s.\n" % NOT_MEASURED)


def corpus_table(run, part, cf):
    """Error rates in double and float on the corpus; the names compared."""
    names, dbl, flt, rows = [], [], [], []
    float_names = set(data.algorithm_names(cf))
    singular = lambda f: f not in data.SINGULAR_EXCLUDED  # noqa: E731
    for a in run.algorithms():
        if a + FLOAT not in float_names:
            continue
        d_s = data.totals(run.check, a, predicate=singular)
        f_s = data.totals(cf, a + FLOAT, predicate=singular)
        d_r = data.totals(run.check, a, families=data.SINGULAR_EXCLUDED)
        f_r = data.totals(cf, a + FLOAT, families=data.SINGULAR_EXCLUDED)
        names.append(a)
        dbl.append(d_s.overlap_error_rate())
        flt.append(f_s.overlap_error_rate())
        ratio_ = (f_s.overlap_error_rate() / d_s.overlap_error_rate() if d_s.overlap_error_rate() else None)
        rows.append([a, pct(d_s.overlap_error_rate()), pct(f_s.overlap_error_rate()),
                     pct(d_r.overlap_error_rate()) if d_r.cases else "-",
                     pct(f_r.overlap_error_rate()) if f_r.cases else "-",
                     ratio(ratio_) if ratio_ is not None else "-"])
    if names:
        fig = part.figure("float-double.png", figures.paired_bars, names, dbl, flt, ("double", "float"),
                          ylabel="overlap error rate, singular families",
                          title="The same ports in double and in float")
        part.add("![float against double](%s)\n" % fig)
        part.add(table(["algorithm", "double, singular", "float, singular", "double, random",
                        "float, random", "float / double"], rows))
    return names


def sweep_panels(part, sweep, names, sw, swf):
    panels = []
    for a in names:
        s = OrderedDict()
        for label, chk, nm in (("double", sw, a), ("float", swf, a + FLOAT)):
            bins = analysis.sweep_bins(sweep, groups.sweep_series(chk, sweep, nm))
            s[label] = [(x, t.overlap_error_rate()) for x, _, t in bins]
        if any(s.values()):
            panels.append((a, s))
    if panels:
        title, xlabel = analysis.SWEEPS[sweep][:2]
        fig = part.figure("float-double-%s.png" % sweep, figures.small_multiples, panels,
                          xlabel=xlabel, title="float against double: " + title)
        part.add("![float against double, %s](%s)\n" % (sweep, fig))

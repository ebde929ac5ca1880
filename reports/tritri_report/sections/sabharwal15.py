"""Sabharwal & Leopold 2015, Table 1: time per intersection type, relative to disjoint pairs,
and our check of the suite of pairs of the Table 1 types."""

from collections import OrderedDict

from .. import data, figures, groups
from ..markdown import NOT_MEASURED, count, ns, ratio, table
from . import papers

TITLE = "Sabharwal & Leopold 2015, Table 1"
LEVEL, NUMBERED = papers.SUBSECTION
FOLDER = "sabharwal15"


def compare(run, part, doc):
    t1 = doc["table1"]
    pub = t1["seconds_per_pair"]
    ours = our_times(run, t1)
    published_and_ours(part, t1, ours)
    if all(ours.get(k) for k in pub):
        verdict(part, t1, ours)
    else:
        part.add("Our times per type: %s.\n" % NOT_MEASURED)
    w = t1["pairs"]
    weighted = sum(pub[k] * w[k] for k in pub) / sum(w.values())
    part.add("The published overall time (%.3f ms) matches neither the plain mean of the four rows "
             "(%.3f ms) nor their mean weighted by the %s pairs (%.3f ms); the paper does not say how "
             "it was formed, so it is not compared.\n" % (
                 1000 * t1["overall"], 1000 * sum(pub.values()) / len(pub), "/".join(str(w[k]) for k in pub),
                 1000 * weighted))
    suite_table(run, part, doc)


def our_times(run, t1):
    """{type: our median ns per pair on the pool of that type}, at the port's first level."""
    if not run.bench:
        return {}
    level = data.primary_levels(run.bench).get(t1["algorithm"])
    return {k: data.bench_median(run.bench, t1["algorithm"], level, t1["workload_prefix"] + k, run.mode)
            if level else None
            for k in t1["seconds_per_pair"]}


def published_and_ours(part, t1, ours):
    pub = t1["seconds_per_pair"]
    none = next(iter(pub))  # the first row, disjoint pairs: what the other rows are relative to
    rows = []
    for k in pub:
        o, ob = ours.get(k), ours.get(none)
        rows.append([k, "%.3f ms" % (1000 * pub[k]), "%.2f" % (pub[k] / pub[none]), ns(o),
                     ratio(o / ob) if o and ob else "-"])
    rows.append(["overall", "%.3f ms" % (1000 * t1["overall"]), "%.2f" % (t1["overall"] / pub[none]), "-", "-"])
    part.add(table(["intersection type", "published (Python)", "published ÷ none", "ours ns/pair",
                    "ours ÷ none"], rows))


def verdict(part, t1, ours):
    pub = t1["seconds_per_pair"]
    none = next(iter(pub))
    pub_r = [pub[k] / pub[none] for k in pub]
    our_r = [ours[k] / ours[none] for k in pub]
    order = list(range(len(pub)))
    order_same = sorted(order, key=lambda i: pub_r[i]) == sorted(order, key=lambda i: our_r[i])
    pairs = t1["pairs"]
    part.add("Verdict: the ratios between types %s (ours ÷ none: %s against %s). Reason: the paper times "
             "a Python implementation over %d pairs (%s) repeated %d times: in an interpreter every executed "
             "statement costs about the same, so the time follows the amount of classification work, which "
             "grows with the type. In our C++ port the extra work of a point, segment or area answer is small "
             "beside the part every pair goes through, on pools of 65,536 pairs per type.\n" % (
                 "keep their order" if order_same else "do not keep their order",
                 ", ".join("%.1f" % r for r in our_r[1:]), ", ".join("%.1f" % r for r in pub_r[1:]),
                 sum(pairs.values()), ", ".join("%d %s" % (pairs[k], k) for k in pub), t1["repetitions"]))
    fig = part.figure("sabharwal-types.png", figures.grouped_ratio_bars, list(pub.keys()),
                      OrderedDict([("published (Python, Table 1)", pub_r), ("ours (C++ port)", our_r)]),
                      ylabel="time ÷ time of disjoint pairs",
                      title="Sabharwal–Leopold: time per intersection type, relative to disjoint")
    part.add("![Sabharwal types](%s)\n" % fig)


def suite_table(run, part, doc):
    suite = doc["suite"]
    chk = run.suites.get(FOLDER)
    if not chk:
        return
    names = data.algorithm_names(chk)
    rows = []
    for a in [a for a in run.ports(FOLDER) or [doc["table1"]["algorithm"]] if a in names]:
        for f in chk.get("families", []):
            t = data.totals(chk, a, families=[f])
            rows.append([a, groups.labels_of(f).get(suite["group_by"], f), t.cases, t.fp + t.fn,
                         count(t.misclassified)])
    part.add("On %s (`%s`; %s), from `%s`:\n" % (suite["what"], suite["cases"], suite["why"], suite["results"]))
    part.add(table(["algorithm", "type", "pairs", "overlap errors", "misclassified"], rows))


render = papers.subsection(FOLDER, compare)

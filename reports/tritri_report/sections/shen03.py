"""Shen, Heng & Tang 2003: faster than Möller's test. Measured under the authors' own benchmark
(their test package's Performance.cpp and data files, paper:shen03) with ports and originals, in
double and in float, under our pools, and under each difference between the two set-ups alone
(setups.py says where the numbers come from)."""

from ..markdown import ratio, table
from .. import figures, published
from . import papers, setups

TITLE = "Shen, Heng & Tang 2003"
LEVEL, NUMBERED = papers.SUBSECTION
FOLDER = "shen03"
PAPER = "paper:shen03"
DRAWN = "paper:shen03-drawn"
FIGURE = "shen03-setups.png"

# The set-ups, in the order of the factor table: (workload, what it changes from the paper's).
FACTORS = [
    (PAPER, "none: the authors' data files, 500 intersecting pairs then 4,500 disjoint, float values"),
    (DRAWN, "the pairs drawn again from Generation.cpp's distribution (our RNG): checks the rebuild"),
    (DRAWN + "/shuffled", "order: the same pairs shuffled (the driver's are sorted by outcome)"),
    (DRAWN + "/n:65536", "pool size: 65,536 pairs in place of 5,000"),
    (DRAWN + "/r:0.50", "ratio: half intersecting in place of 10%"),
    (DRAWN + "/ours", "distribution: our ratio pools' pairs, in the driver's order and ratio"),
    ("ratio:0.10", "ours: a ratio pool at the driver's ratio (65,536 pairs, mixed sizes, shuffled)"),
    ("ratio:0.50", "ours: the ratio pool at R = 0.5"),
    ("ratio:1.00", "ours: the ratio pool at R = 1"),
]


def compare(run, part, doc):
    bench = setups.papers_bench(run)
    claim = doc["claims"]["faster"]
    if bench is None:
        papers.claim_table(part, [[claim["claim"], claim["quote"], setups.NOT_RUN, "-", "-"]])
        return
    ours, against = claim["algorithm"], claim["against"]
    ratios = {w: ratios_on(bench, ours, against, w) for w, _ in FACTORS}
    base = PAPER if ratios[PAPER][0] else DRAWN
    part.add(table(["claim", "the paper's set-up (%s)" % base, "our pools", "which difference moves the result"],
                   [[claim["claim"], setup_cell(ratios[base]), ours_cell(ratios), moves(ratios, base)]],
                   align=["l"] * 4))
    if base != PAPER:
        part.add("%s was not built (%s): the paper's set-up is its rebuild, %s.\n"
                 % (PAPER, setups.skipped(bench, PAPER) or "not in the run", DRAWN))
    part.add("%s ÷ %s time per pair (below 1: Shen's test is faster), each set-up changing one thing of "
             "the paper's, all from one `tritri bench` run (papers-bench.json, batch mode, medians):\n"
             % (ours, against))
    rows = [[w, what] + [ratio(v) if v else "-" for v in ratios[w]] for w, what in FACTORS]
    part.add(table(["set-up", "what changes", "ports, double", "ports, float", "originals, as published (float)",
                    "originals, double copies"], rows, align=["l", "l", "r", "r", "r", "r"]))
    labels = ["ports, double", "ports, float", "originals, float"]
    shown = [w for w, _ in FACTORS if any(ratios[w][:3])]
    if shown:
        fig = part.figure(FIGURE, figures.grouped_ratio_bars, [w.replace("paper:", "") for w in shown],
                          {label: [ratios[w][i] for w in shown] for i, label in enumerate(labels)},
                          ylabel="%s ÷ %s (time per pair)" % (ours, against),
                          title="Shen's claim under each set-up (below 1: Shen faster)", rotation=30)
        part.add("![Shen against Möller under each set-up](%s)\n" % fig)


def ratios_on(bench, ours, against, workload):
    """shen03 ÷ moller97 on one pool: (ports double, ports float, originals float, originals double)."""
    t = lambda a: setups.ns_of(bench, a, workload)  # noqa: E731
    f = setups.FLOAT
    return (setups.over(t(ours), t(against)), setups.over(t(ours + f), t(against + f)),
            setups.over(t("orig-" + ours + f), t("orig-" + against + f)),
            setups.over(t("orig-" + ours), t("orig-" + against)))


def setup_cell(r):
    parts = [("ports", r[0]), ("ports in float", r[1]), ("originals as published (float)", r[2]),
             ("originals in double", r[3])]
    return "; ".join("%s %s" % (name, ratio(v)) for name, v in parts if v)


def ours_cell(ratios):
    return "; ".join("%s %s" % (w, ratio(ratios[w][0])) for w in ("ratio:0.10", "ratio:0.50", "ratio:1.00")
                     if ratios[w][0])


def moves(ratios, base):
    """Order, size, ratio and distribution changed alone from the rebuilt set-up (the same pairs'
    generator), the scalar type on the paper's own; set against our ratio pool at its ratio."""
    drawn = ratios[DRAWN][0]
    changes = [(dict(FACTORS)[w].split(":")[0] + " (" + w.replace("paper:", "") + ")", drawn, ratios[w][0])
               for w, _ in FACTORS[2:6]] + [("scalar type (float)", ratios[base][0], ratios[base][1])]
    return setups.moves_text(changes, ratios["ratio:0.10"][0], ratio, "ratio:0.10")


def render(run, part):
    # Read whether or not the run's check named shen03 (the papers' drivers can run without it).
    if FOLDER not in run.published:
        run.published.update(published.load([FOLDER]))
    papers.subsection(FOLDER, compare)(run, part)

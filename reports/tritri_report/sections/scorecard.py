"""The robustness scorecard per algorithm (check.json's "scorecards", written by
`tritri check --scorecard`): invariance under exact symmetries, touching and degenerate probes,
float against double."""

from .. import figures
from ..markdown import NOT_MEASURED, table

TITLE = "Robustness scorecard"
LEVEL = 3

INVARIANCE = ["swap", "vertex_order", "axis_permutation", "scale", "translation"]


def _pct(entry):
    return None if not entry or not entry.get("bases") else entry["share"]


def _fmt(x):
    return "-" if x is None else "%.1f" % (100 * x)


def render(run, part):
    cards = (run.d.get("check") or {}).get("scorecards")
    if not cards:
        part.add("The scorecard (`tritri check --scorecard`, in `check.json`): %s.\n" % NOT_MEASURED)
        return
    part.add("Per algorithm, the share (%) of base cases whose overlap answer changes under each exact "
             "transformation (the truth cannot change: every one is a defect); the touching probes "
             "(shared vertex, shared edge, vertex on face, coplanar shared edge, each in 72 symmetric "
             "forms) that do not give what the declared boundary implies; the degenerate probes' "
             "verdicts (yes/no/mixed/declined/crash, called even where the algorithm does not accept "
             "them); float against double where a float instantiation exists. To sort by any column, "
             "use the CSV written beside this report (`figures/scorecard.csv`).\n")
    header = ["algorithm"] + INVARIANCE + ["touching off", "degenerate", "float %"]
    rows, values = [], []
    for c in cards:
        inv = [_pct(c["invariance"].get(k)) for k in INVARIANCE]
        off = [t["probe"] + ":" + t["verdict"] for t in c["touching"] if not t.get("as_declared", True)]
        degen = " ".join(d["verdict"] for d in c["degenerate"])
        flt = _fmt(c["float"]["share"]) if c.get("float") else "-"
        rows.append([c["algorithm"]] + [_fmt(x) for x in inv] + [", ".join(off) or "none", degen, flt])
        values.append(inv + [len(off) / max(1, len(c["touching"]))])
    part.add(table(header, rows))
    part.add("Degenerate probes, in order: zero-area piercing (truth yes), zero-area apart (no), repeated "
             "vertex on the face (yes), single point on the face (yes).\n")
    _write_csv(part, header, rows)
    names = [c["algorithm"] for c in cards]
    cols = INVARIANCE + ["touching off"]
    counts = [["%.0f" % (100 * v) if v else None for v in r] for r in values]
    fig = part.figure("scorecard.png", figures.heatmap, names, cols, values, counts,
                      title="Scorecard: share of bases changed by each exact transformation (%)",
                      colorbar_label="share")
    part.add("![scorecard](%s)\n" % fig)


def _write_csv(part, header, rows):
    import csv
    import os
    os.makedirs(part.fig_dir, exist_ok=True)
    with open(os.path.join(part.fig_dir, "scorecard.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)

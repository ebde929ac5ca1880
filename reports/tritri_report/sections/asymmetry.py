"""1.5: whether an algorithm's answers change across the symmetric variants of one base case
(check-symmetry.json, grouped by `subsuite=symmetry,@base`)."""

from .. import groups
from ..markdown import NOT_MEASURED, table

TITLE = "Asymmetry across the symmetric variants"
LEVEL = 3


def render(run, part):
    sym = run.d.get("symmetry")
    if not sym:
        part.add("The symmetry check (`check-symmetry.json`): %s.\n" % NOT_MEASURED)
        return
    asym = groups.asymmetry(sym, run.floors)
    per = groups.variants_per_base(sym)
    part.add("Each base case is checked under its symmetry variants (%s per base case in this run: the 6 "
             "vertex orders of each triangle × both argument orders, 72 in all). The exact answer "
             "cannot change, so an algorithm whose answers (overlap, or relation) differ between the "
             "variants of one base case has an order-dependent defect. Cells: asymmetric base cases / "
             "base cases.\n" % ("/".join(str(k) for k in sorted(per)) or "?"))
    fams_sym = []
    for per_f in asym.values():
        for f in per_f:
            if f not in fams_sym:
                fams_sym.append(f)
    rows = []
    for a, per_f in asym.items():
        bad = sum(v[0] for v in per_f.values())
        base = sum(v[1] for v in per_f.values())
        rows.append([a, "%d / %d" % (bad, base)] +
                    ["%d / %d" % tuple(per_f[f][:2]) if f in per_f else "-" for f in fams_sym])
    part.add(table(["algorithm", "all"] + fams_sym, rows))
    part.add("The segment level is not compared across variants: its endpoints legitimately differ by "
             "rounding.\n")

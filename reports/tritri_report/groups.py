"""Reading checks tallied by label groups (`tritri check --group-by`) instead of by family.

A group is named by its labels as a case file writes them, "subsuite=scale tilt=2^-30"; a case
is in one group of each grouping it carries the labels of. scripts/run asks for these groupings:

  check-symmetry.json   subsuite=symmetry,@base     the symmetric variants of each base case
  check-sweeps*.json    subsuite,transform          exact identity, scale, translation, rotation,
                                                   perturbation (the transformation applied)
                        subsuite,KEY for each KEY   a construction's swept label (analysis.SWEEPS)
  named suites          the label the paper's published file names

This module turns those groups into what the report counts: sweep values, base cases.
"""

import re
from collections import Counter, OrderedDict

from . import analysis
from .data import Totals

SYMMETRY_GROUPING = "subsuite=symmetry,@base"
IDENTITY = "sym-012-012-ab"  # the symmetry variant that leaves a base case as built
# Only exactly transformed variants keep a construction label's meaning: rotation and
# perturbation move the vertices.
EXACT_VARIANTS = {"symmetry", "scale", "translate"}
_POW2 = re.compile(r"2\^(-?\d+)")


def sweep_groupings():
    """The --group-by specs of the sweeps' checks: the transformation, and each label swept."""
    return ["subsuite,transform"] + ["subsuite," + s[3] for s in analysis.SWEEPS.values() if s[3]]


def labels_of(group):
    """"subsuite=scale tilt=2^-30" -> {"subsuite": "scale", "tilt": "2^-30"}"""
    return dict(field.partition("=")[::2] for field in group.split(" "))


def in_grouping(group, spec):
    """Whether `tritri check --group-by spec` names `group`: the same keys in the same order, and
    the value each KEY=VALUE item asks for."""
    fields = [f.partition("=") for f in group.split(" ")]
    items = [i.partition("=") for i in spec.split(",")]
    return len(fields) == len(items) and all(
        f[0] == i[0] and (not i[1] or f[2] == i[2]) for f, i in zip(fields, items))


def split_groupings(check, specs):
    """The part of a grouped check's JSON that `specs` name: the same document, as if the check had
    been asked for those groupings alone (one pass over the corpus can then serve several files)."""
    missing = [s for s in specs if s not in check.get("group_by", [])]
    if missing:
        raise ValueError("the check was not grouped by %s (it was by %s)"
                         % (", ".join(missing), ", ".join(check.get("group_by", [])) or "family"))
    if check.get("failures"):
        raise ValueError("a check with failures listed cannot be split by grouping (run it with --json-max-failures 0)")
    keep = lambda group: any(in_grouping(group, s) for s in specs)  # noqa: E731
    out = dict(check)
    out["group_by"] = [s for s in check["group_by"] if s in specs]
    out["families"] = [f for f in check.get("families", []) if keep(f)]
    out["tallies"] = [dict(t) for t in check.get("tallies", []) if keep(t["family"])]
    if specs == [FAMILY_GROUPING]:
        _as_ungrouped(out)
    return out


FAMILY_GROUPING = "family"  # grouped by the family= label: an ungrouped check's tallies, when every case has one


def _as_ungrouped(out):
    """Groups "family=F" named "F", as a check without --group-by names them; refused unless every
    case is in one (a case without the label is tallied by its file's name there)."""
    out["group_by"] = []
    out["families"] = [labels_of(f)["family"] for f in out["families"]]
    cases = Counter()
    for t in out["tallies"]:
        t["family"] = labels_of(t["family"])["family"]
        cases[t["algorithm"]] += t["cases"]
    short = {a: n for a, n in cases.items() if n != out.get("case_count")}
    if short:
        raise ValueError("not every case has a family= label (%s: %d of %s cases)"
                         % (next(iter(short)), next(iter(short.values())), out.get("case_count")))


def _transform_sweep(subsuite, transform):
    if subsuite == "symmetry" and transform == IDENTITY:
        return "exact", "identity"
    if subsuite == "scale":
        m = _POW2.fullmatch(transform)
        return ("scale", m.group(1)) if m else None
    if subsuite == "translate":
        m = re.match(r"2\^(-?\d+)\*", transform)
        return ("translate", m.group(1)) if m else None
    if subsuite == "perturb":
        return "perturb", transform
    if subsuite == "rotate":
        return "rotate", "random"
    return None


def sweep_of(group):
    """(sweep, value) a group of check-sweeps.json counts for, or None."""
    lab = labels_of(group)
    subsuite = lab.get("subsuite")
    if "transform" in lab:
        return _transform_sweep(subsuite, lab["transform"])
    if subsuite not in EXACT_VARIANTS:
        return None
    for sweep, (_, _, _, key) in analysis.SWEEPS.items():
        if key in lab:
            m = _POW2.fullmatch(lab[key])
            return (sweep, m.group(1)) if m else None
    return None


def sweep_series(sweeps_check, sweep, algorithm):
    """[(value string, Totals)] for one sweep, in the check's order of first appearance."""
    out = OrderedDict()
    for t in sweeps_check.get("tallies", []):
        if t["algorithm"] != algorithm:
            continue
        sv = sweep_of(t["family"])
        if sv and sv[0] == sweep:
            out.setdefault(sv[1], Totals()).add(t)
    return list(out.items())


def sweep_totals(sweeps_check, algorithm, sweep, value=None):
    """Totals of one sweep (one value of it, when given) for one algorithm."""
    tot = Totals()
    for t in sweeps_check.get("tallies", []):
        if t["algorithm"] != algorithm:
            continue
        sv = sweep_of(t["family"])
        if sv and sv[0] == sweep and (value is None or sv[1] == value):
            tot.add(t)
    return tot


def sweep_names(sweeps_check):
    names = []
    for f in sweeps_check.get("families", []):
        sv = sweep_of(f)
        if sv and sv[0] not in names:
            names.append(sv[0])
    return names


# ---- asymmetry (check-symmetry.json: one group per base case) ----

def group_is_asymmetric(t):
    """The answers to the variants of one base case are not all the same.

    The oracle's answer is the same for every variant (the transformations are exact), so a
    group's overlap answers differ exactly when some but not all scored variants are wrong;
    relations differ when the confusion cells name more than one answer.
    """
    cases = t["cases"]
    lost = t["crashes"] + t["timeouts"]
    scored = cases - t["unsupported"] - lost
    wrong = t["false_positives"] + t["false_negatives"]
    if 0 < lost < cases - t["unsupported"]:
        return True
    if 0 < wrong < scored:
        return True
    confusion = t.get("confusion")
    if confusion:
        answers = {c["answer"] for c in confusion if c.get("count", 0) > 0}
        if len(answers) > 1:
            return True
    return False


def base_case(group):
    """"subsuite=symmetry @base=near-coplanar.through.0" -> "near-coplanar.through.0" """
    return labels_of(group).get("@base", group)


def base_family(group):
    """The corpus family of a base case: near-coplanar.through.0 -> near-coplanar"""
    return base_case(group).split(".", 1)[0]


def asymmetry(symmetry_check, floors=()):
    """{algorithm: {family: [asymmetric base cases, base cases, variants in them]}}"""
    out = OrderedDict()
    for t in symmetry_check.get("tallies", []):
        a = t["algorithm"]
        if a in floors:
            continue
        fam = base_family(t["family"])
        row = out.setdefault(a, OrderedDict()).setdefault(fam, [0, 0, 0])
        row[1] += 1
        row[2] += t["cases"]
        if group_is_asymmetric(t):
            row[0] += 1
    return out


def variants_per_base(symmetry_check):
    """Counter {symmetric variants of a base case: base cases with that many}."""
    first = (symmetry_check.get("algorithms") or [{}])[0].get("name")
    return Counter(t["cases"] for t in symmetry_check.get("tallies", []) if t["algorithm"] == first)

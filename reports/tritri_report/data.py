"""Reading a results directory and the arithmetic on its JSON that every section shares.

Every file is optional: a run may stop early, or a component may not exist yet, and a section
whose input is missing says "not measured in this run" instead of failing.
"""

import json
import math
import os
from collections import OrderedDict

# The results directory's files, by role. scripts/run writes them; see its --help.
FILES = {
    "provenance": "provenance.json",
    "manifest": "corpus.json",
    "steps": "steps.json",
    "check": "check.json",
    "check_float": "check-float.json",
    "symmetry": "check-symmetry.json",
    "sweeps": "check-sweeps.json",
    "sweeps_float": "check-sweeps-float.json",
    "builtin": "check-builtin.json",
    "yuhe13": "check-yuhe13.json",
    "sabharwal15": "check-sabharwal15.json",
    "bench": "bench.json",
}

# Algorithms that are not tests: timing floors.
FLOORS = {"null", "floor"}
SINGULAR_EXCLUDED = {"random"}  # the one generic family; all others are singular or near it


def load_results(results_dir):
    data = {}
    for role, name in FILES.items():
        path = os.path.join(results_dir, name)
        if os.path.exists(path):
            with open(path, encoding="utf-8") as f:
                data[role] = json.load(f)
    return data


def _int(x):
    return int(x) if x is not None else 0


class Totals:
    """Counts summed over tallies (families or groups) of one algorithm."""

    def __init__(self):
        self.cases = self.fp = self.fn = self.unsupported = self.crashes = self.timeouts = 0
        self.misclassified = None
        self.segment_answered = self.segment_measured = self.kind_mismatches = self.not_computed = 0
        self.segment_max = None
        self.has_segment = False

    def add(self, t):
        self.cases += _int(t.get("cases"))
        self.fp += _int(t.get("false_positives"))
        self.fn += _int(t.get("false_negatives"))
        self.unsupported += _int(t.get("unsupported"))
        self.crashes += _int(t.get("crashes"))
        self.timeouts += _int(t.get("timeouts"))
        if t.get("misclassified") is not None:
            self.misclassified = (self.misclassified or 0) + t["misclassified"]
        seg = t.get("segment")
        if seg:
            self.has_segment = True
            self.segment_answered += _int(seg.get("answered"))
            self.segment_measured += _int(seg.get("measured"))
            self.kind_mismatches += _int(seg.get("kind_mismatches"))
            self.not_computed += _int(seg.get("not_computed"))
            m = seg.get("max_error")
            if m is not None:
                self.segment_max = m if self.segment_max is None else max(self.segment_max, m)
        return self

    @property
    def scored(self):
        """Cases with an answer to judge: neither declined nor lost to a crash or hang."""
        return self.cases - self.unsupported - self.crashes - self.timeouts

    @property
    def overlap_errors(self):
        return self.fp + self.fn

    @property
    def judged(self):
        """Cases judged for overlap: everything but the declined ones. A crash is an error."""
        return self.cases - self.unsupported

    def overlap_error_rate(self):
        n = self.judged
        if n <= 0:
            return None
        return (self.fp + self.fn + self.crashes + self.timeouts) / n

    def relation_error_rate(self):
        if self.misclassified is None or self.scored <= 0:
            return None
        return self.misclassified / self.scored


def algorithm_names(check):
    return [a["name"] for a in check.get("algorithms", []) if a["name"] not in FLOORS]


def algorithm_info(check):
    return OrderedDict((a["name"], a) for a in check.get("algorithms", []))


def tallies_by(check):
    """{(algorithm, family): tally}"""
    return {(t["algorithm"], t["family"]): t for t in check.get("tallies", [])}


def totals(check, algorithm, families=None, predicate=None):
    tot = Totals()
    for t in check.get("tallies", []):
        if t["algorithm"] != algorithm:
            continue
        if families is not None and t["family"] not in families:
            continue
        if predicate is not None and not predicate(t["family"]):
            continue
        tot.add(t)
    return tot


def singular_families(check):
    return [f for f in check.get("families", []) if f not in SINGULAR_EXCLUDED]


# ---- asymmetry (check-symmetry.json: one group per base case, family "sym:<base>") ----

def group_is_asymmetric(t):
    """The answers to the variants of one base case are not all the same.

    The oracle's answer is the same for every variant (the transformations are exact), so a
    group's overlap answers differ exactly when some but not all scored variants are wrong;
    relations differ when the confusion cells name more than one answer.
    """
    cases = _int(t.get("cases"))
    lost = _int(t.get("crashes")) + _int(t.get("timeouts"))
    scored = cases - _int(t.get("unsupported")) - lost
    wrong = _int(t.get("false_positives")) + _int(t.get("false_negatives"))
    if 0 < lost < cases - _int(t.get("unsupported")):
        return True
    if 0 < wrong < scored:
        return True
    confusion = t.get("confusion")
    if confusion:
        answers = {c["answer"] for c in confusion if c.get("count", 0) > 0}
        if len(answers) > 1:
            return True
    return False


def base_family(group):
    """sym:near-coplanar.through.0 -> near-coplanar"""
    base = group.split(":", 1)[1] if ":" in group else group
    return base.split(".", 1)[0]


def asymmetry(symmetry_check):
    """{algorithm: {family: [asymmetric base cases, base cases, variants in them]}}"""
    out = OrderedDict()
    for t in symmetry_check.get("tallies", []):
        a = t["algorithm"]
        if a in FLOORS:
            continue
        fam = base_family(t["family"])
        row = out.setdefault(a, OrderedDict()).setdefault(fam, [0, 0, 0])
        row[1] += 1
        row[2] += _int(t.get("cases"))
        if group_is_asymmetric(t):
            row[0] += 1
    return out


# ---- sweeps (check-sweeps.json: families "sweep:value") ----

def sweep_series(sweeps_check, sweep, algorithm):
    """[(value string, Totals)] for one sweep, in the check's order of first appearance."""
    out = OrderedDict()
    for t in sweeps_check.get("tallies", []):
        if t["algorithm"] != algorithm:
            continue
        name, _, value = t["family"].partition(":")
        if name != sweep:
            continue
        out.setdefault(value, Totals()).add(t)
    return list(out.items())


def sweep_names(sweeps_check):
    names = []
    for f in sweeps_check.get("families", []):
        n = f.partition(":")[0]
        if n not in names:
            names.append(n)
    return names


# ---- bench ----

def bench_results(bench):
    return (bench or {}).get("tritri", {}).get("results", [])


def bench_median(bench, algorithm, level, workload):
    for r in bench_results(bench):
        if r["algorithm"] == algorithm and r["level"] == level and r["workload"] == workload:
            return r.get("ns_per_pair_median")
    return None


def bench_entry(bench, algorithm, level, workload):
    for r in bench_results(bench):
        if r["algorithm"] == algorithm and r["level"] == level and r["workload"] == workload:
            return r
    return None


def primary_levels(bench):
    """{algorithm: the level it is timed at in the comparisons}: overlap where it answers that,
    else relation, else segment (an algorithm answering only relations is timed on those)."""
    levels = OrderedDict()
    order = {"overlap": 0, "relation": 1, "segment": 2}
    for r in bench_results(bench):
        lv = r["level"]
        if lv not in order:
            continue
        a = r["algorithm"]
        if a not in levels or order[lv] < order[levels[a]]:
            levels[a] = lv
    return levels


def ratio_workloads(bench):
    """[(R as float, workload name)] sorted by R."""
    seen = {}
    for r in bench_results(bench):
        w = r["workload"]
        if w.startswith("ratio:"):
            try:
                seen[w] = float(w.split(":", 1)[1])
            except ValueError:
                pass
    return sorted(((v, k) for k, v in seen.items()))


def stage_results(bench):
    """{algorithm: {stage: ns}} from benchmarks named algo/stage:NAME/workload."""
    out = OrderedDict()
    for r in bench_results(bench):
        lv = r["level"]
        if lv.startswith("stage:") and r.get("ns_per_pair_median") is not None:
            out.setdefault(r["algorithm"], OrderedDict())[lv.split(":", 1)[1]] = r["ns_per_pair_median"]
    return out


def ops_total(entry):
    ops = (entry or {}).get("ops_per_pair")
    if not ops:
        return None
    return sum(ops.get(k, 0.0) for k in ("add", "mul", "div", "cmp"))


def finite(x):
    return x is not None and isinstance(x, (int, float)) and math.isfinite(x)

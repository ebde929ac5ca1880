"""Reading a results directory and the arithmetic on its JSON that every section shares.

Every file is optional: a run may stop early, or a component may not exist yet, and a section
whose input is missing says "not measured in this run" instead of failing. A file that is there
is checked as it is read (schema.py): a version the report does not read, or a missing key, is
an error naming the file and the key.
"""

import json
import math
import os
from collections import OrderedDict

from . import schema

# The results directory's files, by role. scripts/run writes them; see its --help.
# A role's kind of file (schema.KINDS) is its name's first word: check_float is a check.
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
    "bench": "bench.json",
    "compiler_diff": "compiler-diff.json",
    "compiler_bench": "compiler-bench.json",
    "hunt": "hunt.json",
    "mutants": "mutants.json",
    "float_bench": "float-bench.json",
    "papers_bench": "papers-bench.json",
    "peers_bench": "bench-peers.json",
}
# The named suites' checks (check-yuhe13.json, ...) are named by the papers' published files.

SINGULAR_EXCLUDED = {"random"}  # the one generic family; all others are singular or near it

# `tritri bench` times its own floor under this name beside the registered `null` algorithm
# (harness/bench); the tables show the registered one only.
HARNESS_FLOOR = "floor"
# The reference of bench files written before `tritri bench` named its reference.
OLD_REFERENCE = "moller97"
# How a bench result handed pairs to the test (`tritri bench --mode`), in the order the report
# shows them; files written before the mode was an axis (no "schema" in their "tritri" section)
# timed every result in batch mode.
MODES = ("call", "batch")
OLD_MODE = "batch"


# The kind of the roles whose name does not start with it.
_KIND_OF_ROLE = {"symmetry": "check", "sweeps": "check", "sweeps_float": "check", "builtin": "check",
                 "compiler_diff": "diff", "compiler_bench": "bench", "float_bench": "bench", "papers_bench": "bench",
                 "peers_bench": "bench"}


def load_json(path, kind):
    """The document at `path`, checked as a `kind` of file (schema.KINDS), or None when there is
    no such file."""
    if not os.path.exists(path):
        return None
    with open(path, encoding="utf-8") as f:
        try:
            doc = json.load(f)
        except ValueError as e:
            raise schema.SchemaError("%s: not valid JSON (%s)" % (path, e)) from None
    return schema.check(doc, kind, path)


def load_results(results_dir):
    data = {}
    for role, name in FILES.items():
        doc = load_json(os.path.join(results_dir, name), _KIND_OF_ROLE.get(role, role.split("_")[0]))
        if doc is not None:
            data[role] = doc
    return data


class Totals:
    """Counts summed over tallies (families or groups) of one algorithm."""

    def __init__(self):
        self.cases = self.fp = self.fn = self.unsupported = self.crashes = self.timeouts = 0
        self.misclassified = None
        self.segment_answered = self.segment_measured = self.kind_mismatches = self.not_computed = 0
        self.segment_max = None
        self.has_segment = False

    def add(self, t):
        # Every key is there: load_json checked them (schema.KINDS["check"]).
        self.cases += t["cases"]
        self.fp += t["false_positives"]
        self.fn += t["false_negatives"]
        self.unsupported += t["unsupported"]
        self.crashes += t["crashes"]
        self.timeouts += t["timeouts"]
        if t["misclassified"] is not None:
            self.misclassified = (self.misclassified or 0) + t["misclassified"]
        seg = t["segment"]
        if seg:
            self.has_segment = True
            self.segment_answered += seg["answered"]
            self.segment_measured += seg["measured"]
            self.kind_mismatches += seg["kind_mismatches"]
            self.not_computed += seg["not_computed"]
            m = seg["max_error"]
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


def algorithm_names(check, floors=()):
    return [a["name"] for a in check.get("algorithms", []) if a["name"] not in floors]


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


# ---- bench ----

def bench_results(bench):
    return (bench or {}).get("tritri", {}).get("results", [])


def floors(bench):
    """The timing floors `tritri bench` measured (its own and the `null` algorithm): not tests."""
    harness = (bench or {}).get("tritri", {}).get("harness", {})
    return set(harness.get("floors") or harness.get("floor_share_of_fastest") or {})


def mode_of(result):
    return result.get("mode") or OLD_MODE


def bench_modes(bench):
    """The modes the bench timed, in MODES' order."""
    seen = {mode_of(r) for r in bench_results(bench)}
    return [m for m in MODES if m in seen]


def platform(bench):
    """(CPU model, the ISA the lane algorithms ran on) as the bench recorded them, or "?"."""
    t = (bench or {}).get("tritri", {})
    ctx = (bench or {}).get("context", {}) or {}
    return t.get("cpu_model") or ctx.get("cpu_model") or "?", t.get("isa") or ctx.get("isa") or "?"


def reference(bench):
    """The algorithm every bench time is also given relative to."""
    b = bench or {}
    return b.get("tritri", {}).get("reference") or b.get("context", {}).get("reference") or OLD_REFERENCE


def relative_to_reference(entry):
    """A bench result's time over the reference's on the same pool, as `tritri bench` wrote it."""
    if not entry:
        return None
    if "relative_to_reference" in entry:
        return entry["relative_to_reference"]
    return entry.get("relative_to_" + OLD_REFERENCE)


def bench_entry(bench, algorithm, level, workload, mode=None):
    """The result of algorithm x level x workload in `mode`; None when there is none. Without a
    mode the file must hold one: a lookup that matches two results (two modes) fails loudly
    rather than return the first."""
    found = [r for r in bench_results(bench)
             if r["algorithm"] == algorithm and r["level"] == level and r["workload"] == workload
             and (mode is None or mode_of(r) == mode)]
    if len(found) > 1:
        raise ValueError("bench lookup %s/%s/%s matches %d results (modes %s): name the mode"
                         % (algorithm, level, workload, len(found), ", ".join(mode_of(r) for r in found)))
    return found[0] if found else None


def repetition_spread(bench):
    """(repetitions per benchmark, their spread at the median benchmark, at the worst): the spread
    is the slowest repetition over the fastest, minus one, as `tritri bench` records it."""
    reps = sorted({b.get("repetitions") for b in bench.get("benchmarks", []) if b.get("repetitions")})
    harness = (bench.get("tritri") or {}).get("harness") or {}
    return reps, harness.get("spread_median"), harness.get("spread_worst")


def bench_median(bench, algorithm, level, workload, mode=None):
    e = bench_entry(bench, algorithm, level, workload, mode)
    return e.get("ns_per_pair_median") if e else None


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
    """{algorithm: {stage: ns}}: each result's `stage` (before it had one, its level "stage:NAME")."""
    out = OrderedDict()
    for r in bench_results(bench):
        lv = r.get("level") or ""
        stage = r.get("stage") or (lv.split(":", 1)[1] if lv.startswith("stage:") else None)
        if stage and r.get("ns_per_pair_median") is not None:
            out.setdefault(r["algorithm"], OrderedDict())[stage] = r["ns_per_pair_median"]
    return out


def ops_total(entry):
    ops = (entry or {}).get("ops_per_pair")
    if not ops:
        return None
    return sum(ops.get(k, 0.0) for k in ("add", "mul", "div", "cmp"))


def finite(x):
    return x is not None and isinstance(x, (int, float)) and math.isfinite(x)

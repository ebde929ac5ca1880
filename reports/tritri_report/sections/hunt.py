"""What the hunt finds (`tritri hunt`, harness/hunt): per algorithm, the failures found beyond the
corpus, grouped by signature, one shrunk witness each, and the time to the first; then, when a
mutation run is in the results (scripts/mutants), the share of single-operator mutants of the
ports each case set catches as a new failure.

Read from hunt.json (schema tritri-hunt/1) and mutants.json (schema tritri-mutants/1).
"""

from .. import data
from ..markdown import NOT_MEASURED, count, pct, table

TITLE = "What the hunt finds"
LEVEL = 3
WITNESSES = 3  # groups shown per algorithm, paste-ready: the largest
SET_NAMES = {"random": "random pairs", "builtin": "built-in cases", "quick": "quick corpus",
             "default": "default corpus", "hunt": "hunt"}


def render(run, part):
    hunt, mutants = run.d.get("hunt"), run.d.get("mutants")
    if hunt is None:
        part.add("The hunt (`%s`): %s.\n" % (data.FILES["hunt"], NOT_MEASURED))
    else:
        findings(part, hunt)
    if mutants is None:
        part.add("Mutants (`%s`, scripts/mutants): %s.\n" % (data.FILES["mutants"], NOT_MEASURED))
    else:
        mutation_table(part, mutants)


def seconds(x):
    return "-" if x is None else "%.2f" % x


def budget(hunt):
    b = hunt["budget"]
    return "%s pairs" % b["pairs"] if b.get("pairs") is not None else "%g s" % b["seconds"]


def findings(part, hunt):
    part.add("`tritri hunt` searched each algorithm for %s (seed %s) beyond the corpus: corpus "
             "constructions drawn afresh, random shapes, integer and dyadic grids, perturbed singular "
             "pairs, walks bisected to the last double on each side of a decision, each also under an "
             "exact transformation or rounded to float; judged by `exact`, every failure confirmed by "
             "the oracle, grouped by signature (answer, oracle's relation, plane, shared vertices, "
             "scale, the transformation that broke it), one witness per group shrunk toward small "
             "integers. *bits*: the median over groups of a witness's most significant bits in one "
             "coordinate.\n" % (budget(hunt), hunt["seed"]))
    rows = []
    for a in hunt["algorithms"]:
        groups = a["groups"]
        small = sum(1 for g in groups if g["witness"]["small"])
        rows.append([a["name"], count(a["pairs"]), count(a["pairs_per_second"]), count(a["failures"]),
                     count(len(groups)), seconds(a["first_failure_seconds"]),
                     "-" if a.get("median_witness_bits") is None else "%g" % a["median_witness_bits"],
                     "%d/%d" % (small, len(groups))])
    part.add(table(["algorithm", "pairs", "pairs/s", "failures", "groups", "first failure (s)", "bits",
                    "small witnesses"], rows))
    lines = []
    for a in hunt["algorithms"]:
        largest = sorted(a["groups"], key=lambda g: -g["count"])[:WITNESSES]
        lines += [g["line"] for g in largest]  # a case line: its labels say algorithm, answer and count
    if lines:
        part.add("The largest groups' witnesses (%d per algorithm), paste-ready (`expect=` is the "
                 "oracle's relation, `answered=` the algorithm's):\n\n```\n%s\n```\n" % (WITNESSES, "\n".join(lines)))
    disagreements = hunt.get("exact_oracle_disagreements") or []
    part.add("`exact` and the oracle disagreed on %d pair(s) the hunt met.\n" % len(disagreements))


def mutation_table(part, mutants):
    sets = mutants["sets"]
    part.add("Single-operator mutants of the ports (scripts/mutants: a comparison made strict or "
             "non-strict or flipped, == and != swapped, && and || swapped, + and - swapped, a minus or a "
             "term dropped), each built as a plug-in; a mutant is caught by a case set when it fails "
             "there where the unmutated build does not. Mutants whose machine code is the unmutated "
             "build's are not drawn. Share caught per case set:\n")
    rows = []
    for port, s in sorted(mutants["summary"].items()):
        rows.append([port, count(s["mutants"])] + [pct(s[k]["share"], 0) for k in sets])
    part.add(table(["port", "mutants"] + [SET_NAMES.get(k, k) for k in sets], rows))
    by_name = {m["name"]: m for m in mutants["mutants"]}
    uncaught = [by_name[n] for n in mutants["uncaught"]]
    if uncaught:
        part.add("Caught by no set (equivalent, or a gap in every set):\n\n" + "\n".join(
            "- `%s` (%s, line %d): `%s` → `%s`" % (m["name"], m["operator"], m["line"], m["original"], m["mutated"])
            for m in uncaught) + "\n")
    else:
        part.add("Every mutant is caught by at least one set.\n")

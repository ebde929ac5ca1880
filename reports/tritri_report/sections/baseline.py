"""1.6: the checked-in cases against the baselines each algorithm folder records (steps.json)."""

from ..markdown import NOT_MEASURED

TITLE = "The checked-in cases against the recorded baselines"
LEVEL = 3


def render(run, part):
    gate = run.d.get("steps", {}).get("baseline")
    if gate:
        part.add("`tritri check --baseline algorithms/*/expected-failures.tsv` on %s: %s.\n" % (
            gate.get("inputs", "?"), gate.get("verdict", "?")))
    else:
        part.add("Baseline comparison: %s.\n" % NOT_MEASURED)

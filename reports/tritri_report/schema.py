"""What the report reads, checked as it is read: each JSON's schema version, and the keys the
report relies on.

A file of a version the report does not read, or one whose key was renamed, is refused with the
file's name and the key's path, instead of being read as zeros or as "not measured". An absent
file is not an error: the part that needs it says "not measured in this run" (data.load_json).

A key path is dotted; `name[]` means every element of the list `name`. A key whose value is
null is present: where the writer puts null (an algorithm without the relation level has
`misclassified: null`), the keys below it are not required.
"""

# Per kind of file: (where its version is written, the versions this report reads, the keys it
# needs). Where each is written: `tritri check --json` (harness/check/check_output.cpp),
# `tritri bench --json` (harness/bench/json_output.cpp), `tritri diff --json`
# (harness/cli/cmd_diff.cpp), reports/prepare.py, and the papers' files beside each port.
KINDS = {
    "check": ("schema", {"tritri-check/2", "tritri-check/3"}, [
        "case_count", "families", "algorithms[].name", "algorithms[].folder",
        "tallies[].algorithm", "tallies[].family", "tallies[].cases", "tallies[].false_positives",
        "tallies[].false_negatives", "tallies[].misclassified", "tallies[].unsupported",
        "tallies[].crashes", "tallies[].timeouts", "tallies[].confusion", "tallies[].segment",
        "tallies[].segment.answered", "tallies[].segment.measured", "tallies[].segment.max_error",
        "tallies[].segment.median_error", "tallies[].segment.kind_mismatches",
        "tallies[].segment.not_computed", "failures"]),
    # Version 1 timed every benchmark in batch mode (a result without `mode` is read as batch);
    # version 2 has the mode as an axis of every result.
    "bench": ("tritri.schema", {"tritri-bench/1", "tritri-bench/2"}, [
        "tritri.reference", "tritri.results[].algorithm", "tritri.results[].level",
        "tritri.results[].workload"]),
    "bench/tritri-bench/2": ("tritri.schema", {"tritri-bench/2"}, [
        "tritri.modes", "tritri.cpu_model", "tritri.isa", "tritri.results[].stage",
        "tritri.results[].mode", "tritri.harness.floors", "tritri.harness.floor_share"]),
    "diff": ("schema", {"tritri-diff/1"}, [
        "case_count", "inputs", "pairs[].a", "pairs[].b", "pairs[].differ", "pairs[].overlap_differ",
        "pairs[].fate_differ", "pairs[].families[].family", "pairs[].families[].differ", "pairs[].examples"]),
    # `tritri hunt` (harness/hunt/output.cpp) and scripts/mutants.
    "hunt": ("schema", {"tritri-hunt/1"}, [
        "seed", "budget", "algorithms[].name", "algorithms[].pairs", "algorithms[].pairs_per_second",
        "algorithms[].failures", "algorithms[].first_failure_seconds", "algorithms[].groups[].signature",
        "algorithms[].groups[].count", "algorithms[].groups[].line", "algorithms[].groups[].witness.small"]),
    "mutants": ("schema", {"tritri-mutants/1"}, [
        "sets", "summary", "mutants[].name", "mutants[].port", "mutants[].operator", "mutants[].line",
        "mutants[].caught", "uncaught"]),
    "manifest": ("schema", {"tritri-corpus-manifest/2"}, ["seed", "files", "sha256"]),
    "provenance": ("schema", {"tritri-provenance/1"}, ["machine_name", "git_sha", "git_dirty", "command"]),
    "steps": ("schema", {"tritri-steps/1"}, ["steps[].name", "steps[].seconds", "steps[].status"]),
    "published": ("schema", {"tritri-published/1"}, ["paper", "source"]),
    # `tritri scene --picture` writes no version (harness/cli/cmd_scene.cpp): its keys alone.
    "picture": (None, None, ["scene", "frame", "bodies"]),
}


class SchemaError(ValueError):
    """A file the report cannot read as what it claims to be; the message names file and key."""


def _missing(doc, parts, where):
    """The first required key path under `doc` that is absent, as written out, or None."""
    if not parts or doc is None:
        return None
    head, rest = parts[0], parts[1:]
    each = head.endswith("[]")
    key = head[:-2] if each else head
    if not isinstance(doc, dict) or key not in doc:
        return where + key
    value = doc[key]
    if not each:
        return _missing(value, rest, where + key + ".")
    if value is None:
        return None
    if not isinstance(value, list):
        return where + key + " (not a list)"
    for i, element in enumerate(value):
        found = _missing(element, rest, "%s%s[%d]." % (where, key, i))
        if found:
            return found
    return None


def _get(doc, dotted):
    for part in dotted.split("."):
        if not isinstance(doc, dict) or part not in doc:
            return None
        doc = doc[part]
    return doc


def check(doc, kind, path):
    """Raises SchemaError unless `doc` is a version of `kind` the report reads, with every key
    it needs; returns `doc`."""
    version_key, versions, required = KINDS[kind]
    if version_key is not None:
        version = _get(doc, version_key)
        if version not in versions:
            found = "no %s" % version_key if version is None else "%s %r" % (version_key, version)
            raise SchemaError("%s: %s; the report reads %s" % (path, found, ", ".join(sorted(versions))))
    for key_path in required:
        found = _missing(doc, key_path.split("."), "")
        if found:
            raise SchemaError("%s: missing required key %s" % (path, found))
    if version_key is not None and "%s/%s" % (kind, version) in KINDS:
        return check(doc, "%s/%s" % (kind, version), path)  # the keys of that version alone
    return doc

"""Part 7: where the numbers come from: machine, build, libraries, corpus, bench settings, and
the steps of the run."""

from ..markdown import NOT_MEASURED, table

TITLE = "Provenance"


# The rows of the table: a label and the places its value is read from, the first that has one
# (a place is SOURCE.KEY, the sources as in sources() below). A value that is a table (the
# packages) gives one row per entry, labelled "LABEL ENTRY".
ROWS = [
    ("machine", "provenance.machine_name"),
    ("CPU", "provenance.cpu"),
    ("cores", "provenance.cores"),
    ("memory", "provenance.memory"),
    ("OS", "provenance.os"),
    ("kernel", "provenance.kernel"),
    ("compiler", "provenance.compiler context.compiler"),
    ("build type and flags", "provenance.build_flags context.compiler_flags"),
    ("FMA contraction", "context.fp_contract"),
    ("package", "provenance.packages"),
    ("oracle", "check.oracle context.oracle"),
    ("CGAL (bench context)", "context.cgal_version"),
    ("FCL", "context.fcl_version"),
    ("Eigen", "context.eigen_version"),
    ("Google Benchmark", "context.google_benchmark"),
    ("Google Benchmark library build", "context.library_build_type"),
    ("python / matplotlib", "provenance.python"),
    ("git SHA", "provenance.git_sha context.git_sha"),
    ("uncommitted changes", "run.git_dirty"),
    ("corpus command", "manifest.command"),
    ("corpus seed", "manifest.seed"),
    ("corpus SHA-256 (its files' names and bytes)", "manifest.sha256"),
    ("corpus cases", "run.case_count"),
    ("bench reference", "run.reference"),
    ("bench seed", "context.seed"),
    ("bench pool size", "context.pool_size"),
    ("bench repetitions", "context.repetitions"),
    ("bench pools hash", "context.corpus_hash"),
    ("bench family pools from", "context.family_source"),
    ("bench timing", "context.timing"),
    ("load average at bench start", "context.load_avg"),
    ("CPU frequency scaling", "context.cpu_scaling_enabled"),
]

EMPTY = (None, "", [])


def sources(run):
    """The places ROWS reads: the run's provenance, corpus manifest, bench context and check
    result, and what is derived from more than one of them (run)."""
    prov = run.d.get("provenance", {})
    man = run.d.get("manifest", {})
    ctx = (run.bench or {}).get("context", {})
    check = run.check or {}
    derived = {"git_dirty": str(prov.get("git_dirty", ctx.get("git_dirty"))),
               "case_count": check.get("case_count", man.get("case_count")),
               "reference": run.reference if run.bench else None}
    return {"provenance": prov, "manifest": man, "context": ctx, "check": check, "run": derived}


def rows_of(run):
    src = sources(run)
    rows = []
    for label, places in ROWS:
        values = [src[s].get(k) for s, k in (place.split(".", 1) for place in places.split())]
        v = next((x for x in values if x not in EMPTY), None)
        if isinstance(v, dict):
            rows += [[label + " " + k, x] for k, x in v.items() if x not in EMPTY]
        elif v not in EMPTY:
            rows.append([label, v])
    return rows


def render(run, part):
    rows = rows_of(run)
    if rows:
        part.add(table(["what", "value"], [[k, str(v)] for k, v in rows], align=["l", "l"]))
    else:
        part.add("%s.\n" % NOT_MEASURED)
    steps = run.d.get("steps", {}).get("steps", [])
    if steps:
        part.add("Steps of the run (wall-clock seconds):\n")
        part.add(table(["step", "seconds", "status", "command"],
                       [[s["name"], "%.1f" % s["seconds"], s.get("status", ""), "`%s`" % s.get("command", "")]
                        for s in steps], align=["l", "r", "l", "l"]))

"""Part 7: where the numbers come from: machine, build, libraries, corpus, bench settings, and
the steps of the run."""

from ..markdown import NOT_MEASURED, table

TITLE = "Provenance"


def rows_of(run):
    prov = run.d.get("provenance", {})
    man = run.d.get("manifest", {})
    ctx = (run.bench or {}).get("context", {})
    rows = []

    def put(k, v):
        if v not in (None, "", []):
            rows.append([k, v])
    put("machine", prov.get("machine_name"))
    put("CPU", prov.get("cpu"))
    put("cores", prov.get("cores"))
    put("memory", prov.get("memory"))
    put("OS", prov.get("os"))
    put("kernel", prov.get("kernel"))
    put("compiler", prov.get("compiler") or ctx.get("compiler"))
    put("build type and flags", prov.get("build_flags") or ctx.get("compiler_flags"))
    put("FMA contraction", ctx.get("fp_contract"))
    for k, v in (prov.get("packages") or {}).items():
        put("package " + k, v)
    put("oracle", (run.check or {}).get("oracle") or ctx.get("oracle"))
    put("CGAL (bench context)", ctx.get("cgal_version"))
    put("FCL", ctx.get("fcl_version"))
    put("Eigen", ctx.get("eigen_version"))
    put("Google Benchmark", ctx.get("google_benchmark"))
    put("Google Benchmark library build", ctx.get("library_build_type"))
    put("python / matplotlib", prov.get("python"))
    put("git SHA", prov.get("git_sha") or ctx.get("git_sha"))
    put("uncommitted changes", str(prov.get("git_dirty", ctx.get("git_dirty"))))
    put("corpus command", man.get("command"))
    put("corpus seed", man.get("seed"))
    put("corpus SHA-256 (its files' names and bytes)", man.get("sha256"))
    put("corpus cases", (run.check or {}).get("case_count", man.get("case_count")))
    put("bench reference", run.reference if run.bench else None)
    put("bench seed", ctx.get("seed"))
    put("bench pool size", ctx.get("pool_size"))
    put("bench repetitions", ctx.get("repetitions"))
    put("bench pools hash", ctx.get("corpus_hash"))
    put("bench family pools from", ctx.get("family_source"))
    put("bench timing", ctx.get("timing"))
    put("load average at bench start", ctx.get("load_avg"))
    put("CPU frequency scaling", ctx.get("cpu_scaling_enabled"))
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

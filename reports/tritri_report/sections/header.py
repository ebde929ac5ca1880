"""The title block: machine, source, corpus, oracle, the files read, and the contents."""

from .. import groups
from ..markdown import anchor
from . import papers

TITLE = "tritri report"
LEVEL = 1


def corpus_line(run):
    """The corpus's size from the checks; its seed from the manifest."""
    man = run.d.get("manifest", {})
    cases = (run.check or {}).get("case_count", man.get("case_count"))
    if cases is None:
        return None
    sym = run.d.get("symmetry")
    per_base = groups.variants_per_base(sym) if sym else {}
    if not per_base:
        return "Corpus: %d cases, seed %s." % (cases, man.get("seed", "?"))
    return ("Corpus: %d cases (%d base constructions, each under %s symmetry variants, plus scaled, "
            "translated, rotated and perturbed copies), seed %s." % (
                cases, sum(per_base.values()), "/".join(str(k) for k in sorted(per_base)), man.get("seed", "?")))


def render(run, part):
    prov = run.d.get("provenance", {})
    lines = []
    if prov:
        lines.append("Machine: **%s**. Run: `%s`, %s to %s." % (
            prov.get("machine_name", "unknown"), prov.get("command", "?"),
            prov.get("started", "?"), prov.get("finished", "?")))
        lines.append("Source: git %s%s." % (prov.get("git_sha", "unknown")[:12],
                                              " (with uncommitted changes)" if prov.get("git_dirty") else ""))
    corpus = corpus_line(run)
    if corpus:
        lines.append(corpus)
    if run.check:
        lines.append("Judged by the exact oracle: %s." % run.check.get("oracle", "?"))
    papers_part = next((n for n, t in run.contents if t == papers.TITLE), "?")
    lines.append("Every number below is read from the run's JSON files (`%s`); the papers' published "
                 "figures are quoted with their source in part %s." % (", ".join(run.files_read), papers_part))
    part.add("\n".join(lines) + "\n")
    part.add("Contents: %s\n" % " · ".join("[%d %s](#%s)" % (n, t, anchor("%d %s" % (n, t)))
                                           for n, t in run.contents))

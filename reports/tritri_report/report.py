"""The report: Markdown and PNG figures from a results directory's JSON, nothing else.

`Run` is what every section reads: the loaded JSON, the papers' published files, and the
arithmetic several sections share. `Part` is what a section writes into: its Markdown and the
figures it draws. The sections, in order, are listed in sections/__init__.py; a part whose JSON
is missing says so ("not measured in this run") and the rest is still built.
"""

import os
from collections import OrderedDict

from . import data, published
from .markdown import ns, pct
from .sections import SECTIONS


class Run:
    """A results directory, loaded: what the sections render from."""

    def __init__(self, results_dir):
        self.results_dir = results_dir
        self.d = data.load_results(results_dir)
        self.check = self.d.get("check")
        self.bench = self.d.get("bench")
        self.floors = data.floors(self.bench)
        self.reference = data.reference(self.bench)
        self.modes = data.bench_modes(self.bench)
        # The mode of a part that shows one: call (every test called the same way, one pair at a
        # time) when it was timed.
        self.mode = "call" if "call" in self.modes else (self.modes[0] if self.modes else None)
        self.cpu, self.isa = data.platform(self.bench)
        self.folders = published.folders_of(self.check, self.bench)
        self.published = published.load(self.folders.values())
        self.files_read = [name for role, name in data.FILES.items() if role in self.d]
        self.suites = OrderedDict()  # folder: the check of its named suite
        for folder, doc in self.published.items():
            name = (doc.get("suite") or {}).get("results")
            suite = data.load_json(os.path.join(results_dir, name), "check") if name else None
            if suite is not None:
                self.suites[folder] = suite
                self.files_read.append(name)
        self.contents = []  # (number, title) of the numbered parts: set by build_report

    def algorithms(self):
        """The checked algorithms, floors left out, in the check's order."""
        return data.algorithm_names(self.check, self.floors) if self.check else []

    def ports(self, folder):
        """The checked algorithms registered from one folder (a port and its variants)."""
        return [a for a in self.algorithms() if self.folders.get(a) == folder]

    def machine(self):
        return self.d.get("provenance", {}).get("machine_name", "this machine")

    def terms(self, mode=None):
        """What a time was measured in: "call mode, Intel(R) Xeon(R) ..., lane ISA avx512"."""
        return "%s mode, %s, lane ISA %s" % (mode or self.mode, self.cpu, self.isa)

    def timed_ns(self, algorithm, workload="ratio:0.50", mode=None):
        """(median ns per pair on `workload` at the algorithm's first level in `mode` (default
        self.mode), that level)."""
        if not self.bench:
            return None, None
        level = data.primary_levels(self.bench).get(algorithm)
        if level is None:
            return None, None
        return data.bench_median(self.bench, algorithm, level, workload, mode or self.mode), level

    def ratio_range(self, a, b, mode=None):
        """t(a)/t(b) over the ratio pools in `mode`: (at R = 0.5, min, max, mean), or None."""
        if not self.bench:
            return None
        levels = data.primary_levels(self.bench)
        vals, mid = [], None
        for r, w in data.ratio_workloads(self.bench):
            ta = data.bench_median(self.bench, a, levels.get(a), w, mode or self.mode)
            tb = data.bench_median(self.bench, b, levels.get(b), w, mode or self.mode)
            if ta and tb:
                vals.append(ta / tb)
                if abs(r - 0.5) < 1e-9:
                    mid = ta / tb
        if not vals:
            return None
        return mid, min(vals), max(vals), sum(vals) / len(vals)

    def ratio_series(self, mode=None):
        """({algorithm: [(R, ns)]}, {algorithm: {R: spread}}) at each one's first level, in `mode`."""
        series, spreads = OrderedDict(), {}
        if not self.bench:
            return series, spreads
        for a, level in data.primary_levels(self.bench).items():
            if a == data.HARNESS_FLOOR:
                continue
            pts, sp = [], {}
            for r, w in data.ratio_workloads(self.bench):
                e = data.bench_entry(self.bench, a, level, w, mode or self.mode)
                if e and e.get("ns_per_pair_median") is not None:
                    pts.append((r, e["ns_per_pair_median"]))
                    sp[r] = e.get("spread")
            if pts:
                series[a] = pts
                spreads[a] = sp
        return series, spreads

    def published_crossings(self):
        """[(a, b, what)]: pairs whose crossing over R a paper published (claims of kind break-even)."""
        out = []
        for doc in self.published.values():
            for claim in (doc.get("claims") or {}).values():
                if claim.get("kind") == "break-even":
                    out.append((claim["against"], claim["algorithm"], claim.get("figure_label", "")))
        return out


class Part:
    """One section's output: Markdown paragraphs and the figures drawn for them."""

    def __init__(self, fig_dir, number=None):
        self.fig_dir = fig_dir
        self.number = number  # [part, subsection] of a numbered part, shared with its subsections
        self.paragraphs = []
        self.figures = []  # paths written, relative to the report

    def add(self, text):
        self.paragraphs.append(text)

    def heading(self, title):
        """A '###' subheading, numbered on from the part's last one when the part is numbered."""
        self.add(heading(3, title, self.number))

    def figure(self, name, draw, *args, **kwargs):
        os.makedirs(self.fig_dir, exist_ok=True)
        draw(*args, path=os.path.join(self.fig_dir, name), **kwargs)
        rel = "figures/" + name
        self.figures.append(rel)
        return rel


def title_of(section, run):
    return section.TITLE(run) if callable(section.TITLE) else section.TITLE


def number_parts(sections):
    """[part, subsection] counters for the numbered parts, None for the others, in order."""
    numbers, n = [], 0
    for s in sections:
        if getattr(s, "LEVEL", 2) == 2 and getattr(s, "NUMBERED", True):
            n += 1
            numbers.append([n, 0])
        else:
            numbers.append(None)
    return numbers


def heading(level, title, number):
    """The section's heading: '## 3 Title', '### 3.2 Title' (a numbered subsection), or unnumbered."""
    if number is None:
        return "%s %s\n" % ("#" * level, title)
    if level == 2:
        return "## %d %s\n" % (number[0], title)
    number[1] += 1
    return "### %d.%d %s\n" % (number[0], number[1], title)


class Report:
    def __init__(self, run, out_dir):
        self.run = run
        self.out_dir = out_dir
        self.figures = []
        self.text = ""

    def build(self, sections=SECTIONS):
        numbers = number_parts(sections)
        self.run.contents = [(n[0], title_of(s, self.run)) for s, n in zip(sections, numbers) if n]
        parts, current = [], None
        for s, number in zip(sections, numbers):
            level = getattr(s, "LEVEL", 2)
            if level <= 2:
                current = number  # a subsection belongs to the part before it, if that is numbered
            numbered = current if getattr(s, "NUMBERED", True) else None
            part = Part(os.path.join(self.out_dir, "figures"), numbered)
            part.add(heading(level, title_of(s, self.run), numbered))
            s.render(self.run, part)
            parts.extend(part.paragraphs)
            self.figures.extend(part.figures)
        self.text = "\n".join(parts)
        self._write()
        return self.text

    def _write(self):
        os.makedirs(self.out_dir, exist_ok=True)
        tmp = os.path.join(self.out_dir, "README.md.tmp.%d" % os.getpid())
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(self.text)
        os.replace(tmp, os.path.join(self.out_dir, "README.md"))


def build_report(results_dir, out_dir):
    r = Report(Run(results_dir), out_dir)
    r.build()
    return r


def summary_rows(results_dir):
    """A short table for the terminal: the timing modes of the run, then per algorithm its overlap
    errors, error rate (singular) and ns/pair in each mode."""
    run = Run(results_dir)
    modes = run.modes or [None]
    rows = []
    for a in run.algorithms():
        sing = data.totals(run.check, a, predicate=lambda f: f not in data.SINGULAR_EXCLUDED)
        allt = data.totals(run.check, a)
        rows.append((a, allt.fp + allt.fn, pct(sing.overlap_error_rate()), [ns(run.timed_ns(a, mode=m)[0]) for m in modes]))
    return modes, rows

"""The report: Markdown and PNG figures from a results directory's JSON, nothing else.

Seven parts, as issue 7 lists them: correctness, speed against error, time against intersection
ratio, stability, the papers' tables, the failure gallery, provenance. A part whose JSON is
missing says so ("not measured in this run") and the rest is still built.
"""

import os
from collections import OrderedDict

from . import analysis, data, figures, papers
from .markdown import NOT_MEASURED, count, ns, pct, ratio, sci, table

REFERENCE = "moller97"


class Report:
    def __init__(self, results_dir, out_dir):
        self.results_dir = results_dir
        self.out_dir = out_dir
        self.fig_dir = os.path.join(out_dir, "figures")
        self.d = data.load_results(results_dir)
        self.figures = []  # paths written, relative to out_dir
        self.parts = []

    # ---- helpers ----
    def figure(self, name, draw, *args, **kwargs):
        os.makedirs(self.fig_dir, exist_ok=True)
        path = os.path.join(self.fig_dir, name)
        draw(*args, path=path, **kwargs)
        rel = "figures/" + name
        self.figures.append(rel)
        return rel

    def add(self, text):
        self.parts.append(text)

    @property
    def check(self):
        return self.d.get("check")

    @property
    def bench(self):
        return self.d.get("bench")

    def algorithms(self):
        return data.algorithm_names(self.check) if self.check else []

    def timed_ns(self, algorithm, workload="ratio:0.50"):
        if not self.bench:
            return None, None
        level = data.primary_levels(self.bench).get(algorithm)
        if level is None:
            return None, None
        return data.bench_median(self.bench, algorithm, level, workload), level

    # ---- the document ----
    def build(self):
        self.header()
        self.summary()
        self.correctness()
        self.speed_error()
        self.time_ratio()
        self.stability()
        self.papers()
        self.gallery()
        self.provenance()
        os.makedirs(self.out_dir, exist_ok=True)
        text = "\n".join(self.parts)
        tmp = os.path.join(self.out_dir, "README.md.tmp.%d" % os.getpid())
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(tmp, os.path.join(self.out_dir, "README.md"))
        return text

    def header(self):
        prov = self.d.get("provenance", {})
        man = self.d.get("manifest", {})
        self.add("# tritri report\n")
        lines = []
        if prov:
            lines.append("Machine: **%s**. Run: `%s`, %s to %s." % (
                prov.get("machine_name", "unknown"), prov.get("command", "?"),
                prov.get("started", "?"), prov.get("finished", "?")))
            lines.append("Source: git %s%s." % (prov.get("git_sha", "unknown")[:12],
                                                  " (with uncommitted changes)" if prov.get("git_dirty") else ""))
        if man:
            lines.append("Corpus: %d cases (%d base constructions, each under %s symmetry variants, "
                         "plus scaled, translated, rotated and perturbed copies), seed %s." % (
                             man.get("case_count", 0), man.get("base_cases", 0),
                             "/".join(man.get("symmetry_variants_per_base", {}).keys()) or "?",
                             man.get("seed", "?")))
        if self.check:
            lines.append("Judged by the exact oracle: %s." % self.check.get("oracle", "?"))
        lines.append("Every number below is read from the run's JSON files (`%s`); the papers' published "
                     "figures are quoted with their source in part 5." % ", ".join(
                         data.FILES[k] for k in data.FILES if k in self.d))
        self.add("\n".join(lines) + "\n")
        self.add("Contents: [1 Correctness](#1-correctness) · [2 Speed against error](#2-speed-against-error) · "
                 "[3 Time against intersection ratio](#3-time-against-intersection-ratio) · "
                 "[4 Stability](#4-stability) · [5 The papers' tables](#5-the-papers-tables) · "
                 "[6 Failure gallery](#6-failure-gallery) · [7 Provenance](#7-provenance)\n")

    def summary(self):
        self.add("## Summary\n")
        if not self.check:
            self.add("Correctness: %s.\n" % NOT_MEASURED)
            return
        asym = data.asymmetry(self.d["symmetry"]) if "symmetry" in self.d else None
        rows = []
        for a in self.algorithms():
            sing = data.totals(self.check, a, predicate=lambda f: f not in data.SINGULAR_EXCLUDED)
            rnd = data.totals(self.check, a, families=data.SINGULAR_EXCLUDED)
            allt = data.totals(self.check, a)
            t, level = self.timed_ns(a)
            ref, _ = self.timed_ns(REFERENCE)
            asym_cell = "-"
            if asym is not None and a in asym:
                bad = sum(v[0] for v in asym[a].values())
                base = sum(v[1] for v in asym[a].values())
                asym_cell = "%d / %d" % (bad, base)
            rows.append([a, allt.fp + allt.fn, pct(sing.overlap_error_rate()),
                         pct(rnd.overlap_error_rate()) if rnd.cases else "-",
                         count(allt.misclassified), asym_cell,
                         ns(t) + ("" if level in (None, "overlap") else " (%s)" % level),
                         ratio(t / ref) if t and ref else "-"])
        self.add("Overlap errors are false positives plus false negatives over the whole corpus; the rates "
                 "are over the cases each algorithm accepts. Time: median ns per pair on the `ratio:0.50` "
                 "pool at the algorithm's first level (overlap, else relation).\n")
        self.add(table(["algorithm", "overlap errors", "error rate, singular families", "error rate, random",
                        "misclassified relations", "asymmetric base cases", "ns/pair", "× moller97"], rows))

    # ---- 1 ----
    def correctness(self):
        self.add("## 1 Correctness\n")
        c = self.check
        if not c:
            self.add("The corpus check (`check.json`): %s.\n" % NOT_MEASURED)
            return
        fams = c.get("families", [])
        algos = self.algorithms()
        self.add("Every algorithm against the oracle on the corpus (%d cases, %d families), from `check.json`. "
                 "FP: said they meet, they do not; FN: the reverse; relation: misclassified (algorithms "
                 "that answer the relation level); unsupported: declined, or degenerate input the algorithm "
                 "does not accept; crash and timeout: the case killed or hung the algorithm (each runs "
                 "isolated).\n" % (c.get("case_count", 0), len(fams)))
        self.add("### 1.1 Per algorithm\n")
        rows = []
        for a in algos:
            t = data.totals(c, a)
            rows.append([a, t.cases, t.fp, t.fn, count(t.misclassified), t.unsupported, t.crashes, t.timeouts,
                         pct(t.overlap_error_rate())])
        self.add(table(["algorithm", "cases", "FP", "FN", "relation", "unsupported", "crash", "timeout",
                        "overlap error rate"], rows))

        # Heatmap and per-family counts.
        tb = data.tallies_by(c)
        values, counts, cells = [], [], []
        for a in algos:
            vr, cr, row = [], [], [a]
            for f in fams:
                t = tb.get((a, f))
                if t is None:
                    vr.append(None)
                    cr.append(None)
                    row.append("-")
                    continue
                tot = data.Totals().add(t)
                vr.append(tot.overlap_error_rate())
                cr.append(tot.overlap_errors)
                row.append("0" if tot.overlap_errors == 0 else "%d/%d" % (tot.fp, tot.fn))
            values.append(vr)
            counts.append(cr)
            cells.append(row)
        fig = self.figure("correctness-heatmap.png", figures.heatmap, algos, fams, values, counts,
                          title="Overlap error rate per algorithm × family (cell: FP+FN count)")
        self.add("### 1.2 Overlap errors per family\n")
        self.add("![overlap error rate per algorithm and family](%s)\n" % fig)
        self.add("Cells: FP/FN counts (0 when neither).\n")
        self.add(table(["algorithm"] + fams, cells))

        rel_algos = [a for a in algos if data.totals(c, a).misclassified is not None]
        self.add("### 1.3 Misclassified relations per family\n")
        if rel_algos:
            rows = []
            for a in rel_algos:
                rows.append([a] + [count(tb[(a, f)].get("misclassified")) if (a, f) in tb else "-" for f in fams])
            self.add(table(["algorithm"] + fams, rows))
            self.add("The most frequent wrong cells of the relation confusion (answered → oracle), all "
                     "families together:\n")
            rows = []
            for a in rel_algos:
                cells_ = OrderedDict()
                for f in fams:
                    for cell in (tb.get((a, f), {}).get("confusion") or []):
                        if cell["answer"] != cell["oracle"]:
                            key = (cell["answer"], cell["oracle"])
                            cells_[key] = cells_.get(key, 0) + cell["count"]
                top = sorted(cells_.items(), key=lambda kv: -kv[1])[:5]
                rows.append([a, "; ".join("%s → %s: %d" % (k[0], k[1], v) for k, v in top) or "none"])
            self.add(table(["algorithm", "top wrong cells"], rows, align=["l", "l"]))
        else:
            self.add("No algorithm in this run answers the relation level.\n")

        self.add("### 1.4 Segment error\n")
        seg_algos = [a for a in algos if data.totals(c, a).has_segment]
        if seg_algos:
            self.add("For algorithms that return the intersection: the Hausdorff distance between the answered "
                     "and the exact point or segment, over the pair's bounding-box diagonal. Medians are per "
                     "family (the JSON has no corpus-wide median); kind mismatch: the answer's dimension is "
                     "not the exact one's; not computed: coplanar contact found, no geometry given.\n")
            rows = []
            for a in seg_algos:
                t = data.totals(c, a)
                meds = [tb[(a, f)]["segment"].get("median_error") for f in fams
                        if (a, f) in tb and tb[(a, f)].get("segment")]
                meds = [m for m in meds if m is not None]
                rows.append([a, t.segment_answered, t.segment_measured,
                             "%s … %s" % (sci(min(meds)), sci(max(meds))) if meds else "-",
                             sci(t.segment_max), t.kind_mismatches, t.not_computed])
            self.add(table(["algorithm", "answered", "measured", "family medians (min … max)", "max",
                            "kind mismatch", "not computed"], rows))
            rows = []
            for a in seg_algos:
                row = [a]
                for f in fams:
                    s = tb.get((a, f), {}).get("segment")
                    row.append("%s / %s" % (sci(s.get("median_error")), sci(s.get("max_error"))) if s else "-")
                rows.append(row)
            self.add("Median / max per family:\n")
            self.add(table(["algorithm"] + fams, rows))
        else:
            self.add("No algorithm in this run answers the segment level.\n")

        self.add("### 1.5 Asymmetry across the symmetric variants\n")
        if "symmetry" not in self.d:
            self.add("The symmetry check (`check-symmetry.json`): %s.\n" % NOT_MEASURED)
        else:
            asym = data.asymmetry(self.d["symmetry"])
            per = self.d.get("manifest", {}).get("symmetry_variants_per_base", {})
            self.add("Each base case is checked under its symmetry variants (%s per base case in this run: the 6 "
                     "vertex orders of each triangle × both argument orders, 72 in all). The exact answer "
                     "cannot change, so an algorithm whose answers (overlap, or relation) differ between the "
                     "variants of one base case has an order-dependent defect. Cells: asymmetric base cases / "
                     "base cases.\n" % ("/".join(per.keys()) or "?"))
            fams_sym = []
            for a in asym.values():
                for f in a:
                    if f not in fams_sym:
                        fams_sym.append(f)
            rows = []
            for a, per_f in asym.items():
                bad = sum(v[0] for v in per_f.values())
                base = sum(v[1] for v in per_f.values())
                rows.append([a, "%d / %d" % (bad, base)] +
                            ["%d / %d" % tuple(per_f[f][:2]) if f in per_f else "-" for f in fams_sym])
            self.add(table(["algorithm", "all"] + fams_sym, rows))
            self.add("The segment level is not compared across variants: its endpoints legitimately differ by "
                     "rounding.\n")

        self.add("### 1.6 The checked-in cases against the recorded baselines\n")
        steps = self.d.get("steps", {})
        gate = steps.get("baseline")
        if gate:
            self.add("`tritri check --baseline algorithms/*/expected-failures.tsv` on %s: %s.\n" % (
                gate.get("inputs", "?"), gate.get("verdict", "?")))
        else:
            self.add("Baseline comparison: %s.\n" % NOT_MEASURED)

    # ---- 2 ----
    def speed_error(self):
        self.add("## 2 Speed against error\n")
        if not self.check or not self.bench:
            self.add("Needs both the check and the bench results: %s.\n" % NOT_MEASURED)
            return
        points, rows = [], []
        for a in self.algorithms():
            t, level = self.timed_ns(a)
            if t is None:
                continue
            rate = data.totals(self.check, a, predicate=lambda f: f not in data.SINGULAR_EXCLUDED).overlap_error_rate()
            if rate is None:
                continue
            points.append((a, t, rate))
        front = analysis.pareto_frontier(points)
        for a, t, rate in sorted(points, key=lambda p: p[1]):
            _, level = self.timed_ns(a)
            rows.append([a, level, ns(t), pct(rate, 3), "yes" if a in front else ""])
        fig = self.figure("speed-error.png", figures.pareto, points, front,
                          xlabel="ns per pair on ratio:0.50 (median, log scale)",
                          ylabel="overlap error rate, singular families (log)")
        self.add("One point per algorithm and per tolerance setting (each variant is registered on its own): "
                 "x is the median time per pair on the `ratio:0.50` pool, y the overlap error rate "
                 "(FP + FN + crashes + timeouts over the cases it accepts) on every corpus family but "
                 "`random`. Points with no error sit on the \"no errors\" line. The dashed line is the Pareto "
                 "frontier: no other algorithm is both faster and more accurate.\n")
        self.add("![speed against error](%s)\n" % fig)
        self.add(table(["algorithm", "level timed", "ns/pair", "error rate", "on the frontier"], rows))

    # ---- 3 ----
    def ratio_series(self):
        levels = data.primary_levels(self.bench)
        series, spreads = OrderedDict(), {}
        for a, level in levels.items():
            if a == "floor":
                continue
            pts, sp = [], {}
            for r, w in data.ratio_workloads(self.bench):
                e = data.bench_entry(self.bench, a, level, w)
                if e and e.get("ns_per_pair_median") is not None:
                    pts.append((r, e["ns_per_pair_median"]))
                    sp[r] = e.get("spread")
            if pts:
                series[a] = pts
                spreads[a] = sp
        return series, spreads

    def time_ratio(self):
        self.add("## 3 Time against intersection ratio\n")
        if not self.bench or not data.ratio_workloads(self.bench):
            self.add("The ratio workloads of `tritri bench`: %s.\n" % NOT_MEASURED)
            return
        series, spreads = self.ratio_series()
        env = analysis.envelope_changes({a: p for a, p in series.items() if a not in data.FLOORS})
        marks = [(r, t, "%s→%s @%.2f" % (a, b, r)) for r, t, a, b in env]
        pair_rows = []
        for a in series:
            if a == REFERENCE or a in data.FLOORS or REFERENCE not in series:
                continue
            for r, t, noisy in analysis.crossings(series[REFERENCE], series[a], spreads.get(REFERENCE),
                                                  spreads.get(a)):
                pair_rows.append([REFERENCE + " / " + a, "%.2f" % r, ns(t), "within noise" if noisy else ""])
                if a == "held97":
                    marks.append((r, t, "moller97=held97 @%.2f" % r))
        fig = self.figure("time-ratio.png", figures.ratio_lines, series, marks,
                          xlabel="intersection ratio R (share of the pool's pairs that intersect)",
                          ylabel="ns per pair (median, log scale)")
        pool = (self.bench.get("context", {}) or {}).get("pool_size", "?")
        self.add("Median ns per pair on pools of %s distinct pairs of which exactly R intersect, each algorithm "
                 "at its first level. Red circles: break-even points where the fastest algorithm changes, and "
                 "where moller97 and held97 (Möller's comparison with ERIT) cross.\n" % pool)
        self.add("![time against intersection ratio](%s)\n" % fig)
        rs = [r for r, _ in data.ratio_workloads(self.bench)]
        rows = []
        for a, pts in series.items():
            d = dict(pts)
            rows.append([a] + [ns(d.get(r)) for r in rs])
        self.add(table(["algorithm"] + ["%.1f" % r for r in rs], rows))
        self.add("Break-even points where the fastest algorithm changes:\n")
        if env:
            self.add(table(["R", "ns/pair", "fastest before", "fastest after"],
                           [["%.2f" % r, ns(t), a, b] for r, t, a, b in env]))
        else:
            self.add("None: one algorithm is fastest at every R.\n")
        self.add("Every crossing with moller97 (linear between measured R; \"within noise\": the gap at both "
                 "ends is smaller than the repetitions' spread):\n")
        self.add(table(["pair", "R", "ns/pair", "note"], pair_rows) if pair_rows else "None.\n")
        self.time_other_workloads()

    def time_other_workloads(self):
        """The type and family pools: what each kind of contact, and singular input, costs."""
        levels = data.primary_levels(self.bench)
        for prefix, title, intro in (
                ("type:", "3.1 Time per intersection type",
                 "Pools of only disjoint, point, segment or area pairs (the oracle's dimension), "
                 "median ns per pair at each algorithm's first level:"),
                ("family:", "3.2 Time on the corpus families",
                 "One pool per corpus family (%s): what singular and near-singular input costs, median ns per "
                 "pair; `!` marks a time measured on a pool where the algorithm answers some pairs wrongly.")):
            workloads = []
            for r in data.bench_results(self.bench):
                if r["workload"].startswith(prefix) and r["workload"] not in workloads:
                    workloads.append(r["workload"])
            self.add("### %s\n" % title)
            if not workloads:
                self.add("%s.\n" % NOT_MEASURED)
                continue
            if "%s" in intro:
                intro = intro % ((self.bench.get("context") or {}).get("family_source", "the corpus generator's"))
            rows = []
            for a, level in levels.items():
                if a == "floor":
                    continue
                row = [a]
                for w in workloads:
                    e = data.bench_entry(self.bench, a, level, w)
                    cell = ns(e.get("ns_per_pair_median")) if e else "-"
                    if e and prefix == "family:" and e.get("wrong") and a not in data.FLOORS:
                        cell += " !"
                    row.append(cell)
                rows.append(row)
            self.add(intro + "\n")
            self.add(table(["algorithm"] + [w.split(":", 1)[1] for w in workloads], rows))

    # ---- 4 ----
    def sweep_table_and_figure(self, sweep, check, name_suffix=""):
        title, xlabel, _ = analysis.SWEEPS[sweep]
        algos = [a for a in data.algorithm_names(check)]
        series, zero, rows, xs = OrderedDict(), [], [], None
        for a in algos:
            bins = analysis.sweep_bins(sweep, data.sweep_series(check, sweep, a))
            if not bins:
                continue
            if xs is None:
                xs = [(x, label) for x, label, _ in bins]
            rates = [(x, t.overlap_error_rate()) for x, _, t in bins]
            if any(r for _, r in rates):
                series[a] = rates
            else:
                zero.append(a)
            rows.append([a] + [pct(t.overlap_error_rate()) for _, _, t in bins])
        if not rows:
            return None
        n_cases = sum(t.cases for _, _, t in analysis.sweep_bins(sweep, data.sweep_series(check, sweep, algos[0])))
        fig = self.figure("stability-%s%s.png" % (sweep, name_suffix), figures.sweep_lines, series,
                          xlabel=xlabel, title=title, xscale="log")
        text = "![%s](%s)\n\n" % (title, fig)
        worst = max(((rate, a, x) for a, pts in series.items() for x, rate in pts if rate), default=None)
        if worst:
            label = dict(xs).get(worst[2], "?")
            text += "Highest error rate: %s, %s at %s.\n\n" % (worst[1], pct(worst[0]), label)
        if zero:
            text += "No overlap error at any value: %s.\n\n" % ", ".join(zero)
        header = ["algorithm"] + [label for _, label in xs]
        text += "%d cases. Overlap error rate per value:\n\n" % n_cases + table(header, rows)
        return text

    def stability(self):
        self.add("## 4 Stability\n")
        sw = self.d.get("sweeps")
        if not sw:
            self.add("The sweeps (`check-sweeps.json`): %s.\n" % NOT_MEASURED)
        else:
            self.add("From `check-sweeps.json`: the corpus cases regrouped by the quantity swept (the "
                     "construction's label, or the transformation applied), each group checked like a family. "
                     "Only exactly transformed variants carry a construction's label (symmetry, scaling, "
                     "translation); rotated and perturbed copies are grouped by their own transformation. "
                     "Error rate: FP + FN + crashes + timeouts over the cases accepted.\n")
            exact = []
            for a in data.algorithm_names(sw):
                ident = data.totals(sw, a, predicate=lambda f: f == "exact:identity")
                rot = data.totals(sw, a, predicate=lambda f: f.startswith("rotate:"))
                per = data.totals(sw, a, predicate=lambda f: f.startswith("perturb:"))
                exact.append([a, pct(ident.overlap_error_rate()), pct(rot.overlap_error_rate()),
                              pct(per.overlap_error_rate())])
            self.add("### 4.1 Exact input against rounded input\n")
            self.add("Every base construction as built (exactly singular, unpermuted), the same rotated by a random "
                     "rotation rounded to double, and perturbed by ±δ:\n")
            self.add(table(["algorithm", "exact (identity variant)", "rotated (rounded)", "perturbed (all δ)"],
                           exact))
            names = data.sweep_names(sw)
            n = 2
            for sweep in analysis.SWEEPS:
                if sweep not in names:
                    self.add("### 4.%d %s\n\n%s.\n" % (n, analysis.SWEEPS[sweep][0], NOT_MEASURED))
                    n += 1
                    continue
                text = self.sweep_table_and_figure(sweep, sw)
                self.add("### 4.%d %s\n" % (n, analysis.SWEEPS[sweep][0]))
                self.add(text or NOT_MEASURED + ".\n")
                n += 1
        self.float_double()

    def float_double(self):
        self.add("### 4.10 Float against double\n")
        cf = self.d.get("check_float")
        if not cf or not self.check:
            self.add("The float instantiations (`check-float.json`, from `tritri check --float`): %s.\n"
                     % NOT_MEASURED)
            return
        self.add("Every port that has a float instantiation, run through it (`tritri check --float`: each pair "
                 "rounded to float inside the call, judged against the oracle's answer for the double input) "
                 "on the same corpus. Ports calling a library on double (FCL, CGAL) have none. Part of what float gets "
                 "wrong is the rounding of the input itself: two triangles a double ulp apart may touch once "
                 "rounded to float, and the float answer is judged against the double input: what a caller who "
                 "converts double data to float gets.\n")
        names, dbl, flt, rows = [], [], [], []
        float_names = set(data.algorithm_names(cf))
        for a in self.algorithms():
            fa = a + "@float"
            if fa not in float_names:
                continue
            pred = lambda f: f not in data.SINGULAR_EXCLUDED  # noqa: E731
            d_s = data.totals(self.check, a, predicate=pred)
            f_s = data.totals(cf, fa, predicate=pred)
            d_r = data.totals(self.check, a, families=data.SINGULAR_EXCLUDED)
            f_r = data.totals(cf, fa, families=data.SINGULAR_EXCLUDED)
            names.append(a)
            dbl.append(d_s.overlap_error_rate())
            flt.append(f_s.overlap_error_rate())
            ratio_ = (f_s.overlap_error_rate() / d_s.overlap_error_rate()
                      if d_s.overlap_error_rate() else None)
            rows.append([a, pct(d_s.overlap_error_rate()), pct(f_s.overlap_error_rate()),
                         pct(d_r.overlap_error_rate()) if d_r.cases else "-",
                         pct(f_r.overlap_error_rate()) if f_r.cases else "-",
                         ratio(ratio_) if ratio_ is not None else "-"])
        if names:
            fig = self.figure("float-double.png", figures.paired_bars, names, dbl, flt, ("double", "float"),
                              ylabel="overlap error rate, singular families",
                              title="The same ports in double and in float")
            self.add("![float against double](%s)\n" % fig)
            self.add(table(["algorithm", "double, singular", "float, singular", "double, random",
                            "float, random", "float / double"], rows))
        swf, sw = self.d.get("sweeps_float"), self.d.get("sweeps")
        if swf and sw:
            for sweep in ("perturb", "scale"):
                panels = []
                for a in names:
                    s = OrderedDict()
                    for label, chk, nm in (("double", sw, a), ("float", swf, a + "@float")):
                        bins = analysis.sweep_bins(sweep, data.sweep_series(chk, sweep, nm))
                        s[label] = [(x, t.overlap_error_rate()) for x, _, t in bins]
                    if any(s.values()):
                        panels.append((a, s))
                if panels:
                    title, xlabel, _ = analysis.SWEEPS[sweep]
                    fig = self.figure("float-double-%s.png" % sweep, figures.small_multiples, panels,
                                      xlabel=xlabel, title="float against double: " + title)
                    self.add("![float against double, %s](%s)\n" % (sweep, fig))
        else:
            self.add("Float sweeps (`check-sweeps-float.json`): %s.\n" % NOT_MEASURED)

    # ---- 5 ----
    def papers(self):
        self.add("## 5 The papers' tables\n")
        self.add("Published figures (quoted from the papers, cited below each table) beside ours, with a verdict "
                 "and the reason for any difference. Our times are CPU time per pair on this machine, in C++, "
                 "on pools of distinct shuffled pairs; no paper measured that way, so only ratios measured "
                 "in the same run are compared, never absolute times across machines.\n")
        self.moller()
        self.tropp()
        self.sabharwal()
        self.yuhe()
        self.held_guigue()

    def _ratio_range(self, a, b, level_a=None, level_b=None):
        """t(a)/t(b) at each ratio pool: (at 0.50, min, max, mean) or None."""
        if not self.bench:
            return None
        levels = data.primary_levels(self.bench)
        la, lb = level_a or levels.get(a), level_b or levels.get(b)
        vals, mid = [], None
        for r, w in data.ratio_workloads(self.bench):
            ta = data.bench_median(self.bench, a, la, w)
            tb = data.bench_median(self.bench, b, lb, w)
            if ta and tb:
                vals.append(ta / tb)
                if abs(r - 0.5) < 1e-9:
                    mid = ta / tb
        if not vals:
            return None
        return mid, min(vals), max(vals), sum(vals) / len(vals)

    def moller(self):
        self.add("### Möller 1997\n")
        rows = []
        br = self._ratio_range("brute", "moller97")
        lo, hi = papers.MOLLER_BRUTE_RANGE
        if br:
            mid, mn, mx, _ = br
            inside = lo <= mid <= hi
            if inside and lo <= mn and mx <= hi:
                verdict = "holds"
            elif inside:
                verdict = "holds at R = 0.5; outside the range at other R"
            elif mx >= lo and mn <= hi:
                verdict = "partly: inside the range at some R only"
            else:
                verdict = "differs"
            rows.append(["brute force takes 1.3–1.6 × Möller's time", "%.1f–%.1f ×" % (lo, hi),
                         "%.2f × at R = 0.5; %.2f–%.2f × over R = 0…1" % (mid, mn, mx), verdict,
                         "Möller timed \"several different scenarios\" inside RAPID on 1997 SGI machines and did "
                         "not publish his brute force: ours (six edge–triangle tests) is a reconstruction, timed "
                         "per pair on shuffled pools. The ratio moves with R because the two tests exit early "
                         "on different pairs, so a scenario's collision ratio decides where in (or out of) the "
                         "range it falls."])
        else:
            rows.append(["brute force takes 1.3–1.6 × Möller's time", "1.3–1.6 ×", NOT_MEASURED, "-", "-"])
        hr = self._ratio_range("held97", "moller97")
        if hr:
            mid, mn, mx, _ = hr
            faster = mid - 1
            if faster < 0:
                verdict = "differs: Möller's test is the slower one here"
            elif faster <= 0.15:
                verdict = "holds"
            else:
                verdict = "holds in direction; the gap is larger"
            rows.append(["Möller ≈ 7% faster than ERIT (\"tested exactly like ERIT\", SGI Impact)", "≈ 7%",
                         "held97 takes %.2f × Möller's time at R = 0.5; %.2f–%.2f × over R" % (mid, mn, mx),
                         verdict,
                         "ERIT's code was never published: held97 is reconstructed from Möller's and Tropp's "
                         "descriptions (normalised normals, tolerance 1e-10), so its cost is ours, not Held's; "
                         "different machine and compiler."])
        else:
            rows.append(["Möller ≈ 7% faster than ERIT", "≈ 7%", NOT_MEASURED, "-", "-"])
        series, spreads = self.ratio_series() if self.bench and data.ratio_workloads(self.bench) else ({}, {})
        if "moller97" in series and "held97" in series:
            cr = analysis.crossings(series["moller97"], series["held97"], spreads.get("moller97"),
                                    spreads.get("held97"))
            if cr:
                ours = "; ".join("R = %.2f%s" % (r, " (within noise)" if n else "") for r, _, n in cr)
                close = any(abs(r - papers.MOLLER_ERIT_BREAK_EVEN) <= 0.1 and not n for r, _, n in cr)
                verdict = "holds" if close else "differs"
            else:
                d = dict(series["moller97"])
                h = dict(series["held97"])
                faster = "moller97" if all(d[r] < h[r] for r in d if r in h) else "held97"
                ours = "no crossing: %s is faster at every R" % faster
                verdict = "differs"
            rows.append(["break-even with ERIT near a 45% collision ratio (SGI O2)", "≈ 45%", ours, verdict,
                         "the break-even point depends on what each early exit costs on the machine: Möller saw it "
                         "on the O2 and not on the Impact, so it is machine-dependent even in his measurements; "
                         "and our ERIT is a reconstruction."])
        else:
            rows.append(["break-even with ERIT near 45%", "≈ 45%", NOT_MEASURED, "-", "-"])
        self.add(table(["claim", "published", "ours", "verdict", "reason"], rows, align=["l"] * 5))
        self.add("Published: %s.\n" % papers.MOLLER97)

    def tropp(self):
        self.add("### Tropp, Tal & Shimshoni 2006\n")
        if not self.bench:
            self.add("%s.\n" % NOT_MEASURED)
            return
        earlier = [a for a in ("moller97", "moller97-nodiv", "held97", "guigue03", "shen03")
                   if data.primary_levels(self.bench).get(a) == "overlap"]
        rows, detail = [], []
        ops_t, time_t = {}, {}
        for a in ["tropp06", "tropp06-fixed"] + earlier:
            ops, times = [], []
            for r, w in data.ratio_workloads(self.bench):
                e = data.bench_entry(self.bench, a, "overlap", w)
                if e:
                    o = data.ops_total(e)
                    if o is not None:
                        ops.append(o)
                    if e.get("ns_per_pair_median") is not None:
                        times.append(e["ns_per_pair_median"])
            ops_t[a] = sum(ops) / len(ops) if ops else None
            time_t[a] = sum(times) / len(times) if times else None
            if a in ("tropp06", "tropp06-fixed") or a in earlier:
                detail.append([a, "%.1f" % ops_t[a] if ops_t[a] is not None else "-",
                               ns(time_t[a])])
        timed = [a for a in earlier if time_t.get(a)]
        counted = [a for a in earlier if ops_t.get(a)]
        if time_t.get("tropp06") and timed:
            fastest = min(timed, key=lambda a: time_t[a])
            gain = 1 - time_t["tropp06"] / time_t[fastest]
            verdict = "holds" if abs(gain - papers.TROPP_FASTER) <= 0.08 else (
                "differs: slower" if gain < 0 else "differs in size")
            ours = "%+.1f%% against %s, the fastest earlier test here (mean over R = 0…1)" % (100 * gain, fastest)
            if fastest != "moller97" and time_t.get("moller97"):
                ours += "; %+.1f%% against moller97" % (100 * (1 - time_t["tropp06"] / time_t["moller97"]))
            rows.append(["18.9% faster than the fastest earlier test, on average", "18.9%", ours, verdict,
                         "Tropp timed a Pentium 4 on their collision scenarios, with the edge vectors supplied by "
                         "the caller; our harness times their computation too, on shuffled pools, against "
                         "earlier tests that include Guigue–Devillers 2003."])
        if not ops_t.get("tropp06"):
            rows.append(["about 20% fewer operations than the best earlier test", "≈ 20%",
                         "%s: tropp06 registers no operation-counting instantiation (`overlap_counted`), so "
                         "`tritri bench` counts nothing for it" % NOT_MEASURED, "-", "-"])
        elif counted:
            fewest = min(counted, key=lambda a: ops_t[a])
            fewer = 1 - ops_t["tropp06"] / ops_t[fewest]
            verdict = "holds" if abs(fewer - papers.TROPP_FEWER_OPS) <= 0.08 else (
                "differs: more operations" if fewer < 0 else "differs in size")
            rows.append(["about 20% fewer operations than the best earlier test", "≈ 20%",
                         "%+.1f%% against %s (add+mul+div+cmp per pair, mean over R)" % (100 * fewer, fewest),
                         verdict,
                         "we count every addition, multiplication, division and comparison executed, set-up "
                         "included, averaged over the pools' mix of exits; the paper's count is per full test."])
        if rows:
            self.add(table(["claim", "published", "ours", "verdict", "reason"], rows, align=["l"] * 5))
        else:
            self.add("tropp06 or the earlier tests were not timed: %s.\n" % NOT_MEASURED)
        if detail:
            self.add("Operations and time per pair, mean over the ratio pools:\n")
            self.add(table(["algorithm", "operations/pair", "ns/pair"], detail))
        self.add("Published: %s.\n" % papers.TROPP06)

    def sabharwal(self):
        self.add("### Sabharwal & Leopold 2015, Table 1\n")
        pub = papers.SABHARWAL_TABLE1
        base = pub["disjoint"]
        ours = {}
        if self.bench:
            level = data.primary_levels(self.bench).get("sabharwal15")
            for k in pub:
                ours[k] = data.bench_median(self.bench, "sabharwal15", level, "type:" + k) if level else None
        rows = []
        for k in pub:
            o = ours.get(k)
            ob = ours.get("disjoint")
            rows.append([k, "%.3f ms" % (1000 * pub[k]), "%.2f" % (pub[k] / base), ns(o),
                         ratio(o / ob) if o and ob else "-"])
        w = papers.SABHARWAL_SAMPLES
        weighted = sum(pub[k] * w[k] for k in pub) / sum(w.values())
        rows.append(["overall", "%.3f ms" % (1000 * papers.SABHARWAL_OVERALL),
                     "%.2f" % (papers.SABHARWAL_OVERALL / base), "-", "-"])
        self.add(table(["intersection type", "published (Python)", "published ÷ none", "ours ns/pair",
                        "ours ÷ none"], rows))
        have = all(ours.get(k) for k in pub)
        if have:
            pub_r = [pub[k] / base for k in pub]
            our_r = [ours[k] / ours["disjoint"] for k in pub]
            order_same = sorted(range(4), key=lambda i: pub_r[i]) == sorted(range(4), key=lambda i: our_r[i])
            self.add("Verdict: the ratios between types %s (ours ÷ none: %s against %s). Reason: the paper times "
                     "a Python implementation over 22 pairs (3 disjoint, 6 point, 4 segment, 9 area) repeated 100 "
                     "times: in an interpreter every executed statement costs about the same, so the time follows "
                     "the amount of classification work, which grows with the type. In our C++ port the extra "
                     "work of a point, segment or area answer is small beside the part every pair goes through, "
                     "on pools of 65,536 pairs per type.%s\n" % (
                         "keep their order" if order_same else "do not keep their order",
                         ", ".join("%.1f" % r for r in our_r[1:]), ", ".join("%.1f" % r for r in pub_r[1:]),
                         ""))
            fig = self.figure("sabharwal-types.png", figures.grouped_ratio_bars, list(pub.keys()),
                              OrderedDict([("published (Python, Table 1)", [pub[k] / base for k in pub]),
                                           ("ours (C++ port)", [ours[k] / ours["disjoint"] for k in pub])]),
                              ylabel="time ÷ time of disjoint pairs",
                              title="Sabharwal–Leopold: time per intersection type, relative to disjoint")
            self.add("![Sabharwal types](%s)\n" % fig)
        else:
            self.add("Our times per type: %s.\n" % NOT_MEASURED)
        self.add("The published overall time (%.3f ms) matches neither the plain mean of the four rows "
                 "(%.3f ms) nor their mean weighted by the 3/6/4/9 pairs (%.3f ms); the paper does not say how "
                 "it was formed, so it is not compared.\n" % (
                     1000 * papers.SABHARWAL_OVERALL, 1000 * sum(pub.values()) / 4, 1000 * weighted))
        chk = self.d.get("sabharwal15")
        if chk:
            rows = []
            for a in ("sabharwal15", "sabharwal15-plane"):
                if a not in data.algorithm_names(chk):
                    continue
                for f in chk.get("families", []):
                    t = data.totals(chk, a, families=[f])
                    rows.append([a, f.split(":", 1)[-1], t.cases, t.fp + t.fn, count(t.misclassified)])
            self.add("On our 22 pairs of the Table 1 types (`cases/sabharwal15.cases`; the paper prints no "
                     "coordinates, so these are ours), from `check-sabharwal15.json`:\n")
            self.add(table(["algorithm", "type", "pairs", "overlap errors", "misclassified"], rows))
        self.add("Published: %s.\n" % papers.SABHARWAL15)

    def yuhe(self):
        self.add("### Yu & He 2013, Table 1 and the singular suite\n")
        rows = []
        for m in papers.YUHE_TABLE1:
            rows.append(["published: " + m["machine"], "%.0f s" % m["transform"], "%.0f s" % m["frame"],
                         "%.0f s" % m["both"], "%.1f%%" % (100 * m["transform"] / m["both"]),
                         "%.2f M" % (papers.YUHE_PAIRS / m["both"] / 1e6)])
        stages = data.stage_results(self.bench).get("yuhe13", {}) if self.bench else {}
        t_rel, _ = self.timed_ns("yuhe13")
        machine = self.d.get("provenance", {}).get("machine_name", "this machine")
        if stages.get("transform") and stages.get("both"):
            share = stages["transform"] / stages["both"]
            rows.append(["ours: " + machine, ns(stages["transform"]) + " ns", ns(stages.get("frame-test")) + " ns",
                         ns(stages["both"]) + " ns", "%.1f%%" % (100 * share),
                         "%.1f M" % (1e3 / stages["both"])])
            verdict = ("holds" if abs(share - 0.155) <= 0.05 else "differs") + (
                ": the transform is %.0f%% of the time here, %.1f%% and %.1f%% in the paper" % (
                    100 * share, 100 * 7 / 47, 100 * 5 / 31))
            if abs(share - 0.155) > 0.05:
                verdict += (". The share depends on how much of the test in the frame each pair runs before it "
                            "exits, against a transform every pair pays in full (a normalised frame, with its "
                            "square root and divisions, and six points mapped); our pool is ratio:0.50 with "
                            "mixed sizes, while the paper does not describe its 40 pairs, so their mix of "
                            "exits is unknown")
        else:
            rows.append(["ours: " + machine, "-", "-", ns(t_rel) + " ns" if t_rel else "-", "-",
                         "%.1f M" % (1e3 / t_rel) if t_rel else "-"])
            verdict = ("the stages are %s (no `stage:` benchmarks for yuhe13 in bench.json), so the transform's "
                       "share cannot be compared" % NOT_MEASURED)
        self.add(table(["machine", "transform alone", "test in the frame", "both", "transform share",
                        "pairs per second (both)"], rows))
        self.add("Transform share: %s. Pairs per second differ by the machines' age (2008 laptop and desktop "
                 "against this one) and by our pools of distinct pairs against their 40 pairs repeated 10⁶ times, "
                 "which stay in cache and train the branch predictor; only the share is comparable.\n" % verdict)
        chk = self.d.get("yuhe13")
        if chk and "yuhe13" in data.algorithm_names(chk):
            rows = []
            for a in ("yuhe13", "yuhe13-literal"):
                if a not in data.algorithm_names(chk):
                    continue
                for f, pub in (("yuhe13-singular", papers.YUHE_SINGULAR), ("yuhe13-other", papers.YUHE_OTHER)):
                    t = data.totals(chk, a, families=[f])
                    wrong = sorted({x["case"] for x in chk.get("failures", [])
                                    if x["algorithm"] == a and x["family"] == f})
                    rows.append([a, f.split("-")[1], pub, t.cases, t.fp + t.fn, count(t.misclassified),
                                 ", ".join(wrong[:6]) + (" …" if len(wrong) > 6 else "")])
            self.add("The paper: its 23 singular and 30 other configurations are all handled correctly. Ours, on "
                     "`cases/yuhe13.cases` (rebuilt from the figures' captions: the paper prints no "
                     "coordinates), from `check-yuhe13.json`:\n")
            self.add(table(["algorithm", "set", "published: cases, all right", "our cases", "overlap errors",
                            "misclassified", "cases wrong"], rows, align=["l", "l", "r", "r", "r", "r", "l"]))
            t = data.totals(chk, "yuhe13", families=["yuhe13-singular"])
            bad = t.fp + t.fn + (t.misclassified or 0)
            self.add("Verdict: %s.\n" % (
                "holds: yuhe13 answers every case of the rebuilt singular suite as the oracle does" if bad == 0 else
                "differs: yuhe13 gets %d answers wrong on the rebuilt singular suite; the reason is in the cases "
                "listed (shown in full with `tritri show NAME cases/yuhe13.cases`), and the rebuilt suite may not "
                "be the paper's exact configurations" % bad))
        else:
            self.add("The singular suite (`check-yuhe13.json`): %s.\n" % NOT_MEASURED)
        self.add("Published: %s.\n" % papers.YUHE13)

    def held_guigue(self):
        self.add("### Held 1997 and Guigue & Devillers 2003: what can be compared\n")
        rows = []
        sw = self.d.get("sweeps")
        for a, cite, note in (
                ("held97", papers.HELD97, "ERIT's source was never public; Möller's comparisons with it are above. "
                 "'Reliable' through a tolerance: compare with held97-notol."),
                ("held97-notol", papers.HELD97, "the reconstruction with every comparison exact-zero"),
                ("guigue03", papers.GUIGUE03, "sign-only decisions (orientation determinants), no tolerance: where "
                 "it errs on exactly representable input, a determinant was rounded to the wrong sign"),
                ("guigue03-segment", papers.GUIGUE03, "the variant that constructs the segment")):
            if not self.check or a not in self.algorithms():
                continue
            sing = data.totals(self.check, a, predicate=lambda f: f not in data.SINGULAR_EXCLUDED)
            exact = data.totals(sw, a, predicate=lambda f: f == "exact:identity") if sw else None
            r = self._ratio_range(a, "moller97")
            rows.append([a, pct(sing.overlap_error_rate()),
                         pct(exact.overlap_error_rate()) if exact and exact.cases else "-",
                         ratio(r[0]) if r else "-", note])
        if rows:
            self.add("Neither paper is in shared/papers and no published figure of theirs is quoted in our notes, "
                     "so there is no number to set ours against; what the run does measure:\n")
            self.add(table(["algorithm", "error rate, singular families", "error rate, exact input",
                            "time ÷ moller97 at R = 0.5", "note"], rows, align=["l", "r", "r", "r", "l"]))
        else:
            self.add("%s.\n" % NOT_MEASURED)

    # ---- 6 ----
    def gallery(self):
        self.add("## 6 Failure gallery\n")
        if not self.check:
            self.add("%s.\n" % NOT_MEASURED)
            return
        failures = self.check.get("failures", [])
        listed = len(failures)
        total = sum(data.totals(self.check, a).fp + data.totals(self.check, a).fn +
                    (data.totals(self.check, a).misclassified or 0) for a in self.algorithms())
        self.add("For each algorithm, its worst listed failures in three orthographic views (front x–z, top x–y, "
                 "side y–z, as Yu–He draw theirs; T1 blue, T2 orange). Worst: a wrong yes/no before a wrong "
                 "relation, exactly singular input before rounded or perturbed input, then one per family. "
                 "The check lists %d of the %d disagreements (`--json-max-failures` keeps the first ones of each "
                 "algorithm × family × level). Near-singular failures look like their exact neighbours: the "
                 "coordinates are the evidence.\n" % (listed, total))
        any_drawn = False
        for a in self.algorithms():
            chosen = analysis.gallery_choice(failures, a)
            if not chosen:
                continue
            any_drawn = True
            rows = []
            for k, f in enumerate(chosen, 1):
                t1, t2 = analysis.case_triangles(f["line"])
                rows.append(("(%d) %s" % (k, f["case"]), t1, t2))
            fig = self.figure("gallery-%s.png" % a, figures.gallery, rows, title=a)
            self.add("### %s\n" % a)
            self.add("![failures of %s](%s)\n" % (a, fig))
            for k, f in enumerate(chosen, 1):
                what = ("overlap: answered %s, oracle %s" % (f["answer"], f["oracle"]) if f["level"] == "overlap"
                        else "%s: answered %s, oracle %s" % (f["level"], f["answer"], f["oracle"]))
                self.add("(%d) `%s`, family %s — %s (oracle relation %s).\n\n```\n%s\n```\n" % (
                    k, f["case"], f["family"], what, f.get("oracle_relation", "?"), f["line"]))
        if not any_drawn:
            self.add("No failure listed: every algorithm agrees with the oracle on every case.\n")

    # ---- 7 ----
    def provenance(self):
        self.add("## 7 Provenance\n")
        prov = self.d.get("provenance", {})
        man = self.d.get("manifest", {})
        ctx = (self.bench or {}).get("context", {})
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
        put("oracle", (self.check or {}).get("oracle") or ctx.get("oracle"))
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
        put("corpus cases", man.get("case_count"))
        put("bench seed", ctx.get("seed"))
        put("bench pool size", ctx.get("pool_size"))
        put("bench repetitions", ctx.get("repetitions"))
        put("bench pools hash", ctx.get("corpus_hash"))
        put("bench family pools from", ctx.get("family_source"))
        put("bench timing", ctx.get("timing"))
        put("load average at bench start", ctx.get("load_avg"))
        put("CPU frequency scaling", ctx.get("cpu_scaling_enabled"))
        if rows:
            self.add(table(["what", "value"], [[k, str(v)] for k, v in rows], align=["l", "l"]))
        else:
            self.add("%s.\n" % NOT_MEASURED)
        steps = self.d.get("steps", {}).get("steps", [])
        if steps:
            self.add("Steps of the run (wall-clock seconds):\n")
            self.add(table(["step", "seconds", "status", "command"],
                           [[s["name"], "%.1f" % s["seconds"], s.get("status", ""), "`%s`" % s.get("command", "")]
                            for s in steps], align=["l", "r", "l", "l"]))


def build_report(results_dir, out_dir):
    r = Report(results_dir, out_dir)
    r.build()
    return r


def summary_rows(results_dir):
    """A short table for the terminal: algorithm, overlap errors, error rate (singular), ns/pair."""
    r = Report(results_dir, "/nonexistent")
    rows = []
    if not r.check:
        return rows
    for a in r.algorithms():
        sing = data.totals(r.check, a, predicate=lambda f: f not in data.SINGULAR_EXCLUDED)
        allt = data.totals(r.check, a)
        t, _ = r.timed_ns(a)
        rows.append((a, allt.fp + allt.fn, pct(sing.overlap_error_rate()), ns(t)))
    return rows

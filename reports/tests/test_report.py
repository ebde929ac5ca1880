"""The report builds from a small fixed run (tests/fixture/), every figure is written and
non-empty, and the tables say what the JSON says.

The expectations are computed here from the fixture's JSON directly, not through the report's
own aggregation code, so a slip in either shows up as a mismatch.
"""

import copy
import json
import os
import shutil
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))

from tritri_report import analysis, groups, markdown, published, report  # noqa: E402
from tritri_report.sections import time_ratio  # noqa: E402

FIXTURE = os.path.join(HERE, "fixture")


def load(name):
    with open(os.path.join(FIXTURE, name), encoding="utf-8") as f:
        return json.load(f)


def load_published(folder):
    with open(os.path.join(published.ALGORITHMS_DIR, folder, "published.json"), encoding="utf-8") as f:
        return json.load(f)


def labels(group):
    """The labels a group of `tritri check --group-by` names: "subsuite=scale tilt=2^-3"."""
    return dict(field.split("=", 1) for field in group.split())


def section(text, heading):
    """The text under a '## ' or '### ' heading, up to the next heading of any level."""
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if line.lstrip("#").strip() == heading and line.startswith("#"):
            out = []
            for rest in lines[i + 1:]:
                if rest.startswith("#"):
                    break
                out.append(rest)
            return "\n".join(out)
    raise AssertionError("no heading %r" % heading)


def tables_in(text, heading):
    return markdown.parse_tables(section(text, heading))


def ns_text(x):
    return markdown.ns(x)


def in_mode(results, mode, **axes):
    """The bench results of `mode` whose fields are `axes` (a file before the modes: batch)."""
    return [r for r in results if (r.get("mode") or "batch") == mode and all(r[k] == v for k, v in axes.items())]


class ReportFromFixture(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.out = tempfile.mkdtemp(prefix="tritri-report-test-")
        cls.report = report.build_report(FIXTURE, cls.out)
        with open(os.path.join(cls.out, "README.md"), encoding="utf-8") as f:
            cls.text = f.read()
        cls.check = load("check.json")
        cls.bench = load("bench.json")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.out, ignore_errors=True)

    def algorithms(self):
        return [a["name"] for a in self.check["algorithms"] if a["name"] not in ("null", "floor")]

    def tallies(self, algorithm):
        return [t for t in self.check["tallies"] if t["algorithm"] == algorithm]

    # ---- figures ----
    def test_every_figure_is_written_and_nonempty(self):
        self.assertGreater(len(self.report.figures), 10)
        for rel in self.report.figures:
            path = os.path.join(self.out, rel)
            self.assertTrue(os.path.isfile(path), rel)
            self.assertGreater(os.path.getsize(path), 1000, rel)
            with open(path, "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n", rel)

    def test_every_referenced_figure_exists_and_every_written_one_is_referenced(self):
        import re
        referenced = set(re.findall(r"!\[[^\]]*\]\(([^)]+)\)", self.text))
        self.assertEqual(referenced, set(self.report.figures))
        on_disk = {"figures/" + n for n in os.listdir(os.path.join(self.out, "figures"))}
        self.assertEqual(on_disk, set(self.report.figures))

    def test_the_parts_are_there(self):
        for heading in ("1 Correctness", "2 Speed against error", "3 Time against intersection ratio",
                        "4 Stability", "5 What the compiler changes", "6 The papers' tables",
                        "7 Scenes: meshes in motion through a BVH broad phase",
                        "8 The tests the web ships, in their own runtime", "9 Failure gallery", "10 Provenance"):
            self.assertIn("## " + heading + "\n", self.text)

    def test_figures_for_each_part(self):
        names = {os.path.basename(f) for f in self.report.figures}
        for expected in ("correctness-heatmap.png", "speed-error.png", "time-ratio.png", "stability-tilt.png",
                         "stability-scale.png", "stability-translate.png", "stability-perturb.png",
                         "float-double.png", "sabharwal-types.png"):
            self.assertIn(expected, names)
        self.assertTrue(any(n.startswith("gallery-") for n in names))

    # ---- part 1 ----
    def test_per_algorithm_table_matches_the_tallies(self):
        (header, rows), = tables_in(self.text, "1.1 Per algorithm")
        self.assertEqual(header[:8], ["algorithm", "cases", "FP", "FN", "relation", "unsupported", "crash",
                                      "timeout"])
        self.assertEqual([r[0] for r in rows], self.algorithms())
        for r in rows:
            ts = self.tallies(r[0])
            self.assertEqual(int(r[1]), sum(t["cases"] for t in ts))
            self.assertEqual(int(r[2]), sum(t["false_positives"] for t in ts))
            self.assertEqual(int(r[3]), sum(t["false_negatives"] for t in ts))
            mis = [t["misclassified"] for t in ts if t["misclassified"] is not None]
            self.assertEqual(r[4], str(sum(mis)) if mis else "-")
            self.assertEqual(int(r[5]), sum(t["unsupported"] for t in ts))
            self.assertEqual(int(r[6]), sum(t["crashes"] for t in ts))
            self.assertEqual(int(r[7]), sum(t["timeouts"] for t in ts))

    def test_per_family_cells_match_the_tallies(self):
        (header, rows), = tables_in(self.text, "1.2 Overlap errors per family")
        self.assertEqual(header[1:], self.check["families"])
        seen = 0
        for r in rows:
            for fam, cell in zip(header[1:], r[1:]):
                t = [x for x in self.tallies(r[0]) if x["family"] == fam][0]
                fp, fn = t["false_positives"], t["false_negatives"]
                self.assertEqual(cell, "0" if fp + fn == 0 else "%d/%d" % (fp, fn), (r[0], fam))
                seen += 1
        self.assertEqual(seen, len(self.algorithms()) * len(self.check["families"]))

    def test_summary_errors_match_the_tallies(self):
        (header, rows), = tables_in(self.text, "Summary")
        self.assertEqual(header[1], "overlap errors")
        for r in rows:
            ts = self.tallies(r[0])
            self.assertEqual(int(r[1]), sum(t["false_positives"] + t["false_negatives"] for t in ts))

    def test_asymmetry_counts_every_base_case(self):
        sym = load("check-symmetry.json")
        tables = tables_in(self.text, "1.5 Asymmetry across the symmetric variants")
        header, rows = tables[0]
        for r in rows:
            groups = [t for t in sym["tallies"] if t["algorithm"] == r[0]]
            bad, base = (int(x) for x in r[1].split(" / "))
            self.assertEqual(base, len(groups))
            # A base case whose variants are all right cannot be asymmetric.
            clean = sum(1 for t in groups if t["false_positives"] + t["false_negatives"] == 0 and
                        not any(c["answer"] != c["oracle"] for c in (t["confusion"] or [])))
            self.assertLessEqual(bad, base - clean)

    def test_asymmetry_rule(self):
        def tally(cases, fp=0, fn=0, confusion=None):
            return {"cases": cases, "false_positives": fp, "false_negatives": fn, "unsupported": 0,
                    "crashes": 0, "timeouts": 0, "confusion": confusion}
        self.assertFalse(groups.group_is_asymmetric(tally(72)))
        self.assertFalse(groups.group_is_asymmetric(tally(72, fn=72)))
        self.assertTrue(groups.group_is_asymmetric(tally(72, fn=3)))
        self.assertTrue(groups.group_is_asymmetric(tally(72, confusion=[
            {"answer": "cross", "oracle": "touch-point", "count": 70},
            {"answer": "touch-point", "oracle": "touch-point", "count": 2}])))

    # ---- parts 2 and 3 ----
    def test_speed_error_table_matches_bench_and_check(self):
        (header, rows), = tables_in(self.text, "2 Speed against error")
        self.assertEqual(header[:4], ["algorithm", "level timed", "ns/pair call", "ns/pair batch"])
        for r in rows:
            for mode, cell in (("call", r[2]), ("batch", r[3])):
                entry = in_mode(self.bench["tritri"]["results"], mode, algorithm=r[0], level=r[1],
                                workload="ratio:0.50")
                self.assertEqual(len(entry), 1, (r[0], mode))
                self.assertEqual(cell, ns_text(entry[0]["ns_per_pair_median"]))
            ts = [t for t in self.tallies(r[0]) if t["family"] != "random"]
            judged = sum(t["cases"] - t["unsupported"] for t in ts)
            wrong = sum(t["false_positives"] + t["false_negatives"] + t["crashes"] + t["timeouts"] for t in ts)
            self.assertEqual(r[header.index("error rate")], markdown.pct(wrong / judged, 3))

    def test_ratio_table_matches_bench(self):
        tables = tables_in(self.text, "3 Time against intersection ratio")
        header, rows = tables[0]
        self.assertEqual(header[:2], ["algorithm", "mode"])
        rs = header[2:]
        self.assertEqual(rs[0], "0.0")
        self.assertEqual(rs[-1], "1.0")
        self.assertEqual({r[1] for r in rows}, {"call", "batch"})  # the modes side by side
        for r in rows:
            level = "overlap" if any(e["algorithm"] == r[0] and e["level"] == "overlap"
                                     for e in self.bench["tritri"]["results"]) else "relation"
            for rtext, cell in zip(rs, r[2:]):
                w = "ratio:%.2f" % float(rtext)
                e, = in_mode(self.bench["tritri"]["results"], r[1], algorithm=r[0], level=level, workload=w)
                self.assertEqual(cell, ns_text(e["ns_per_pair_median"]), (r[0], w))

    def test_ratio_part_states_the_spread_from_the_bench(self):
        part = section(self.text, "3 Time against intersection ratio")
        h = self.bench["tritri"]["harness"]
        self.assertIn("%.0f%% at the median benchmark and %.0f%% at the worst"
                      % (100 * h["spread_median"], 100 * h["spread_worst"]), part)

    def test_spread_sentence_counts_the_repetitions(self):
        bench = {"benchmarks": [{"repetitions": 5}, {"repetitions": 5}],
                 "tritri": {"harness": {"spread_median": 0.04, "spread_worst": 0.5}}}
        self.assertIn("median of 5 repetitions; their spread (slowest over fastest, minus one) is 4% at the "
                      "median benchmark and 50% at the worst", time_ratio.spread_sentence(bench))
        self.assertIn("not recorded", time_ratio.spread_sentence({"tritri": {}}))

    def test_type_table_matches_bench(self):
        (header, rows), = tables_in(self.text, "3.1 Time per intersection type")
        self.assertEqual(sorted(header[2:]), ["area", "disjoint", "point", "segment"])
        for r in rows:
            for t, cell in zip(header[2:], r[2:]):
                es = in_mode(self.bench["tritri"]["results"], r[1], algorithm=r[0], workload="type:" + t)
                levels = [x["level"] for x in es]
                level = "overlap" if "overlap" in levels else "relation"
                e = [x for x in es if x["level"] == level][0]
                self.assertEqual(cell, ns_text(e["ns_per_pair_median"]), (r[0], t))

    # ---- part 4 ----
    def test_tilt_sweep_table_matches_the_sweep_tallies(self):
        sweeps = load("check-sweeps.json")
        tables = tables_in(self.text, "4.2 near-coplanar: T2 tilted off T1's plane")
        header, rows = tables[-1]
        for r in rows:
            for label, cell in zip(header[1:], r[1:]):
                ts = [t for t in sweeps["tallies"] if t["algorithm"] == r[0] and
                      labels(t["family"]).get("tilt") == label and
                      labels(t["family"])["subsuite"] in ("symmetry", "scale", "translate")]
                judged = sum(t["cases"] - t["unsupported"] for t in ts)
                wrong = sum(t["false_positives"] + t["false_negatives"] + t["crashes"] + t["timeouts"]
                            for t in ts)
                self.assertEqual(cell, markdown.pct(wrong / judged) if judged else "-", (r[0], label))

    def test_float_table_matches_both_checks(self):
        flt = load("check-float.json")
        tables = tables_in(self.text, "4.10 Float against double")
        header, rows = tables[0]
        self.assertEqual(header[1:3], ["double, singular", "float, singular"])
        self.assertTrue(rows)
        for r in rows:
            for chk, name, cell in ((self.check, r[0], r[1]), (flt, r[0] + "@float", r[2])):
                ts = [t for t in chk["tallies"] if t["algorithm"] == name and t["family"] != "random"]
                judged = sum(t["cases"] - t["unsupported"] for t in ts)
                wrong = sum(t["false_positives"] + t["false_negatives"] + t["crashes"] + t["timeouts"]
                            for t in ts)
                self.assertEqual(cell, markdown.pct(wrong / judged), name)

    # ---- part 5 ----
    def test_exact_table_gives_each_pools_fallback_shares_and_both_paths(self):
        results = load("bench.json")["tritri"]["results"]
        header, rows = tables_in(self.text, "3.3 The exact test: where its time goes")[0]
        self.assertEqual(header[:3], ["pool", "exact ns call", "exact ns batch"])
        exact = {m: {e["workload"]: e for e in in_mode(results, m, algorithm="exact", level="overlap")}
                 for m in ("call", "batch")}
        self.assertEqual(sorted(r[0] for r in rows), sorted(exact["batch"]))
        self.assertTrue(any(r[0].startswith("family:") for r in rows))
        for r in rows:
            c = exact["batch"][r[0]]["path_counters"]  # counted through the batch entry
            self.assertNotIn("path_counters", exact["call"][r[0]])
            self.assertEqual(r[1], markdown.ns(exact["call"][r[0]]["ns_per_pair_median"]), r[0])
            self.assertEqual(r[2], markdown.ns(exact["batch"][r[0]]["ns_per_pair_median"]), r[0])
            moller, = in_mode(results, "call", algorithm="moller97", level="overlap", workload=r[0])
            self.assertEqual(r[header.index("÷ moller97 call")],
                             markdown.ratio(exact["call"][r[0]]["ns_per_pair_median"] / moller["ns_per_pair_median"]))
            lanes = c["pairs"] - c.get("one_pair_route", 0)  # pairs through the lanes
            self.assertEqual(r[header.index("undecided by SIMD")],
                             markdown.pct(c["undecided_by_simd"] / lanes) if lanes else markdown.pct(None), r[0])
            self.assertEqual(r[header.index("to scalar path")],
                             markdown.pct(c["to_scalar"] / lanes) if lanes else markdown.pct(None), r[0])
            self.assertEqual(r[header.index("one-pair route")], markdown.pct(c.get("one_pair_route", 0) / c["pairs"]), r[0])
            self.assertIn("isa:" + r[-1], c)

    # ---- part 6: the papers' own drivers (papers-bench.json) and float against double ----
    def papers_median(self, algorithm, workload, stage=None):
        """The median of a result of papers-bench.json, read here without the report's code."""
        for e in load("papers-bench.json")["tritri"]["results"]:
            if e["algorithm"] == algorithm and e["workload"] == workload and e.get("stage") == stage and (
                    stage is not None or e["level"] in ("overlap", "relation")):
                return e["ns_per_pair_median"]
        return None

    def test_shen_table_is_shen_over_moller_on_each_setup(self):
        tables = tables_in(self.text, "Shen, Heng & Tang 2003")
        header, rows = tables[1]
        self.assertEqual(header[2:4], ["ports, double", "ports, float"])
        self.assertEqual(rows[0][0], "paper:shen03")  # the authors' data files were read
        self.assertIn("ratio:0.50", [r[0] for r in rows])
        for r in rows:
            for col, suffix, prefix in ((2, "", ""), (3, "@float", ""), (4, "@float", "orig-"), (5, "", "orig-")):
                a = self.papers_median(prefix + "shen03" + suffix, r[0])
                b = self.papers_median(prefix + "moller97" + suffix, r[0])
                self.assertEqual(r[col], markdown.ratio(a / b) if a and b else "-", (r[0], header[col]))
        claim = tables[0][1][0]
        self.assertIn("ports " + markdown.ratio(self.papers_median("shen03", "paper:shen03")
                                                / self.papers_median("moller97", "paper:shen03")), claim[1])

    def test_tropp_gain_is_against_the_fastest_earlier_test_with_the_edges_given_or_not(self):
        tables = tables_in(self.text, "Tropp, Tal & Shimshoni 2006")
        header, rows = next(t for t in tables if t[0][:3] == ["set-up", "what changes", "gain, edges given"])
        earlier = load_published("tropp06")["earlier_tests"]
        checked = 0
        for r in rows[:-1]:  # the last row is the float one
            times = {a: self.papers_median(a, r[0]) for a in earlier}
            fastest = min((a for a in earlier if times[a]), key=lambda a: times[a])
            self.assertEqual(r[4], fastest, r[0])
            given = self.papers_median("tropp06", r[0], stage="edges-given")
            inside = self.papers_median("tropp06", r[0])
            self.assertEqual(r[2], "%+.1f%%" % (100 * (1 - given / times[fastest])) if given else "-", r[0])
            self.assertEqual(r[3], "%+.1f%%" % (100 * (1 - inside / times[fastest])), r[0])
            checked += 1
        self.assertGreaterEqual(checked, 4)

    def test_yuhe_table1_has_the_forty_pairs_rows(self):
        header, rows = tables_in(self.text, "Yu & He 2013, Table 1 and the singular suite")[0]
        forty = [r for r in rows if "paper:yuhe13)" in r[0]]
        self.assertEqual(len(forty), 1)
        t = self.papers_median("yuhe13", "paper:yuhe13", stage="transform")
        both = self.papers_median("yuhe13", "paper:yuhe13", stage="both")
        self.assertEqual(forty[0][4], "%.1f%%" % (100 * t / both))

    def test_float_table_gives_double_and_float_per_port_at_three_ratios(self):
        results = load("float-bench.json")["tritri"]["results"]
        header, rows = tables_in(self.text, "Float and double: time per pair")[0]
        self.assertEqual(header, ["port", "ratio:0.00", "ratio:0.50", "ratio:1.00"])
        med = {(e["algorithm"], e["workload"]): e["ns_per_pair_median"] for e in results}
        ports = sorted({e["algorithm"] for e in results if e["algorithm"] + "@float" in {x["algorithm"] for x in results}
                        and e["algorithm"] not in ("null", "floor")})
        self.assertEqual(sorted(r[0] for r in rows), ports)
        for r in rows:
            for w, cell in zip(header[1:], r[1:]):
                d, f = med[(r[0], w)], med[(r[0] + "@float", w)]
                self.assertEqual(cell, "%s / %s (%s)" % (markdown.ns(d), markdown.ns(f), markdown.ratio(f / d)))

    def test_compiler_answer_tables_match_the_diff(self):
        diff = load("compiler-diff.json")
        tables = tables_in(self.text, "5 What the compiler changes")
        _, per_port = tables[0]
        pairs = [p for p in diff["pairs"] if p["b"] == p["a"] + "@v3fma"]
        self.assertEqual([r[0] for r in per_port], [p["a"] for p in pairs])
        changed_families = []
        for row, p in zip(per_port, pairs):
            sums = {k: sum(f[k] for f in p["families"]) for k in ("a_fp", "a_fn", "b_fp", "b_fn")}
            self.assertEqual(row[1:6], [str(p["overlap_differ"]), str(sums["b_fp"]), str(sums["b_fn"]),
                                        str(sums["a_fp"]), str(sums["a_fn"])], p["a"])
            # where the builds' yes/no answers differ, exactly one of them is wrong
            self.assertEqual(sum(sums.values()), p["overlap_differ"], p["a"])
            changed_families += [(p["a"], f) for f in p["families"] if f["overlap_differ"]]
        _, per_family = tables[1]
        self.assertEqual(len(per_family), len(changed_families))
        self.assertGreater(len(per_family), 0)
        for row in per_family:
            f = [f for a, f in changed_families if a == row[0] and f["family"] == row[1]][0]
            self.assertEqual(row[3:], [str(f["overlap_differ"]), "%d / %d" % (f["b_fp"], f["b_fn"]),
                                       "%d / %d" % (f["a_fp"], f["a_fn"])])

    def test_compiler_speed_table_is_v3fma_over_baseline(self):
        bench = load("compiler-bench.json")["tritri"]["results"]
        header, rows = tables_in(self.text, "5 What the compiler changes")[2]
        self.assertEqual(header[3], "R=0")
        self.assertEqual(header[-1], "R=1")
        median = {(e["algorithm"], e["level"], e["workload"]): e["ns_per_pair_median"] for e in bench}
        self.assertEqual(len(rows), len({e["algorithm"] for e in bench if e["algorithm"].endswith("@v3fma")}))
        for r in rows:
            for rtext, cell in zip(header[3:], r[3:]):
                w = "ratio:%.2f" % float(rtext[2:])
                self.assertEqual(cell, markdown.ratio(median[(r[0] + "@v3fma", r[1], w)] / median[(r[0], r[1], w)]),
                                 (r[0], w))

    # ---- part 6 ----
    def test_sabharwal_table_quotes_the_paper_and_the_bench(self):
        header, rows = tables_in(self.text, "Sabharwal & Leopold 2015, Table 1")[0]
        by_type = {r[0]: r for r in rows}
        for k, seconds in load_published("sabharwal15")["table1"]["seconds_per_pair"].items():
            self.assertEqual(by_type[k][1], "%.3f ms" % (1000 * seconds))
            e = in_mode(self.bench["tritri"]["results"], "call", algorithm="sabharwal15", workload="type:" + k,
                        level="relation")
            self.assertEqual(by_type[k][3], ns_text(e[0]["ns_per_pair_median"]))
        self.assertEqual(by_type["overall"][1], "1.353 ms")

    def test_yuhe_suite_counts_match_the_check(self):
        chk = load("check-yuhe13.json")
        tables = tables_in(self.text, "Yu & He 2013, Table 1 and the singular suite")
        header, rows = tables[1]
        group = {st["name"]: st["group"] for st in load_published("yuhe13")["suite"]["sets"]}
        self.assertEqual(sorted(group.values()), sorted(chk["families"]))
        for r in rows:
            t = [x for x in chk["tallies"] if x["algorithm"] == r[0] and x["family"] == group[r[1]]][0]
            self.assertEqual(int(r[3]), t["cases"])
            self.assertEqual(int(r[4]), t["false_positives"] + t["false_negatives"])
        published = tables[0][1][:2]
        self.assertEqual([r[3] for r in published], ["47 s", "31 s"])

    # ---- parts 6 and 7 ----
    def test_gallery_shows_listed_failures_with_coordinates(self):
        text = section(self.text, "9 Failure gallery")
        failures = self.check["failures"]
        shown = [f for f in failures if "`%s`" % f["case"] in self.text]
        self.assertTrue(shown)
        for f in shown:
            self.assertIn(f["line"], self.text)
        self.assertIn("three orthographic views", text)

    def test_provenance_names_machine_sha_seed_and_hash(self):
        (header, rows), = tables_in(self.text, "10 Provenance")[:1]
        values = dict((r[0], r[1]) for r in rows)
        prov = load("provenance.json")
        man = load("corpus.json")
        self.assertEqual(values["machine"], prov["machine_name"])
        self.assertEqual(values["git SHA"], prov["git_sha"])
        self.assertEqual(values["corpus seed"], str(man["seed"]))
        self.assertEqual(values["corpus SHA-256 (its files' names and bytes)"], man["sha256"])
        self.assertEqual(values["bench seed"], self.bench["context"]["seed"])


    # ---- the hunt and the mutants (hunt.json, mutants.json) ----
    def test_hunt_table_matches_the_hunt_json(self):
        hunt = load("hunt.json")
        (header, rows), = tables_in(self.text, "1.8 What the hunt finds")[:1]
        self.assertEqual(header[:5], ["algorithm", "pairs", "pairs/s", "failures", "groups"])
        self.assertEqual([r[0] for r in rows], [a["name"] for a in hunt["algorithms"]])
        for r, a in zip(rows, hunt["algorithms"]):
            self.assertEqual(int(r[1]), a["pairs"])
            self.assertEqual(int(r[3]), a["failures"])
            self.assertEqual(int(r[4]), len(a["groups"]))
            small = sum(1 for g in a["groups"] if g["witness"]["small"])
            self.assertEqual(r[7], "%d/%d" % (small, len(a["groups"])))

    def test_hunt_shows_each_algorithms_largest_group_paste_ready(self):
        text = section(self.text, "1.8 What the hunt finds")
        for a in load("hunt.json")["algorithms"]:
            if a["groups"]:
                largest = max(a["groups"], key=lambda g: g["count"])
                self.assertIn(largest["line"] + "\n", text)
                self.assertTrue(largest["line"].startswith("hunt.%s." % a["name"]))
                self.assertIn("expect=" + largest["oracle"], largest["line"])

    def test_mutation_table_matches_the_summary(self):
        mutants = load("mutants.json")
        header, rows = tables_in(self.text, "1.8 What the hunt finds")[1]
        self.assertEqual(header[:2], ["port", "mutants"])
        self.assertEqual(len(header), 2 + len(mutants["sets"]))
        for r in rows:
            s = mutants["summary"][r[0]]
            built = [m for m in mutants["mutants"] if m["port"] == r[0] and m["compiled"]]
            self.assertEqual(int(r[1]), len(built))
            for k, cell in zip(mutants["sets"], r[2:]):
                caught = sum(1 for m in built if m["caught"].get(k))
                self.assertEqual(cell, markdown.pct(caught / len(built), 0))
        for name in mutants["uncaught"]:
            self.assertIn("`%s`" % name, section(self.text, "1.8 What the hunt finds"))


class MissingInputs(unittest.TestCase):
    def test_an_empty_results_directory_gives_a_report_that_says_so(self):
        src = tempfile.mkdtemp()
        out = tempfile.mkdtemp()
        try:
            r = report.build_report(src, out)
            with open(os.path.join(out, "README.md"), encoding="utf-8") as f:
                text = f.read()
            self.assertIn(markdown.NOT_MEASURED, text)
            self.assertIn("compiler-diff.json", section(text, "5 What the compiler changes"))
            self.assertIn("no float-bench.json", section(text, "Float and double: time per pair"))
            self.assertEqual(r.figures, [])
        finally:
            shutil.rmtree(src)
            shutil.rmtree(out)

    def test_check_without_bench_still_reports_correctness(self):
        src = tempfile.mkdtemp()
        out = tempfile.mkdtemp()
        try:
            shutil.copy(os.path.join(FIXTURE, "check.json"), src)
            report.build_report(src, out)
            with open(os.path.join(out, "README.md"), encoding="utf-8") as f:
                text = f.read()
            self.assertIn("### 1.1 Per algorithm", text)
            self.assertIn("Needs both the check and the bench results: " + markdown.NOT_MEASURED, text)
        finally:
            shutil.rmtree(src)
            shutil.rmtree(out)


class Analysis(unittest.TestCase):
    def test_pareto_frontier(self):
        pts = [("a", 1.0, 0.5), ("b", 2.0, 0.1), ("c", 3.0, 0.2), ("d", 4.0, 0.0)]
        self.assertEqual(analysis.pareto_frontier(pts), ["a", "b", "d"])

    def test_crossings_interpolate_between_measured_ratios(self):
        a = [(0.0, 10.0), (0.5, 20.0), (1.0, 30.0)]
        b = [(0.0, 15.0), (0.5, 15.0), (1.0, 15.0)]
        (r, t, noisy), = analysis.crossings(a, b)
        self.assertAlmostEqual(r, 0.25)
        self.assertAlmostEqual(t, 15.0)
        self.assertFalse(noisy)
        self.assertTrue(analysis.crossings(a, b, {0.0: 0.6, 0.5: 0.6}, {})[0][2])

    def test_sweep_bins_pool_both_signs_of_a_perturbation(self):
        from tritri_report import data
        t1 = data.Totals()
        t1.cases, t1.fp = 10, 1
        t2 = data.Totals()
        t2.cases, t2.fn = 10, 2
        (x, label, tot), = analysis.sweep_bins("perturb", [("+1e-8", t1), ("-1e-8", t2)])
        self.assertEqual((x, label, tot.cases, tot.fp, tot.fn), (1e-8, "1e-8", 20, 1, 2))


class Stages(unittest.TestCase):
    def test_stage_benchmarks_are_read_by_name(self):
        from tritri_report import data
        bench = {"tritri": {"results": [
            {"algorithm": "yuhe13", "level": "stage:transform", "workload": "ratio:0.50", "ns_per_pair_median": 2.0},
            {"algorithm": "yuhe13", "level": "stage:both", "workload": "ratio:0.50", "ns_per_pair_median": 8.0},
            {"algorithm": "yuhe13", "level": "relation", "workload": "ratio:0.50", "ns_per_pair_median": 9.0}]}}
        self.assertEqual(dict(data.stage_results(bench)["yuhe13"]), {"transform": 2.0, "both": 8.0})
        self.assertEqual(data.primary_levels(bench), {"yuhe13": "relation"})

    def test_a_stage_has_its_own_field_since_the_modes(self):
        from tritri_report import data
        bench = {"tritri": {"schema": "tritri-bench/2", "results": [
            {"algorithm": "yuhe13", "level": None, "stage": "transform", "mode": "batch", "workload": "ratio:0.50",
             "ns_per_pair_median": 2.0}]}}
        self.assertEqual(dict(data.stage_results(bench)["yuhe13"]), {"transform": 2.0})
        self.assertEqual(data.primary_levels(bench), {})  # a stage is not a level


class Modes(unittest.TestCase):
    BENCH = {"tritri": {"schema": "tritri-bench/2", "cpu_model": "Some CPU", "isa": "avx2",
                        "harness": {"floors": ["floor", "null"]}, "results": [
        {"algorithm": "moller97", "level": "overlap", "mode": "call", "workload": "ratio:0.50", "ns_per_pair_median": 30.0},
        {"algorithm": "moller97", "level": "overlap", "mode": "batch", "workload": "ratio:0.50", "ns_per_pair_median": 25.0}]}}

    def test_a_lookup_takes_the_mode_and_fails_loudly_without_one_when_two_match(self):
        from tritri_report import data
        self.assertEqual(data.bench_median(self.BENCH, "moller97", "overlap", "ratio:0.50", "call"), 30.0)
        self.assertEqual(data.bench_median(self.BENCH, "moller97", "overlap", "ratio:0.50", "batch"), 25.0)
        with self.assertRaisesRegex(ValueError, "matches 2 results .*name the mode"):
            data.bench_entry(self.BENCH, "moller97", "overlap", "ratio:0.50")
        self.assertEqual(data.bench_modes(self.BENCH), ["call", "batch"])
        self.assertEqual(data.floors(self.BENCH), {"floor", "null"})
        self.assertEqual(data.platform(self.BENCH), ("Some CPU", "avx2"))

    def test_a_file_from_before_the_modes_is_batch_mode(self):
        from tritri_report import data
        old = {"tritri": {"harness": {"floor_share_of_fastest": {"floor": {}, "null": {}}}, "results": [
            {"algorithm": "moller97", "level": "overlap", "workload": "ratio:0.50", "ns_per_pair_median": 25.0}]}}
        self.assertEqual(data.bench_modes(old), ["batch"])
        self.assertEqual(data.bench_median(old, "moller97", "overlap", "ratio:0.50", "batch"), 25.0)
        self.assertIsNone(data.bench_median(old, "moller97", "overlap", "ratio:0.50", "call"))
        self.assertEqual(data.floors(old), {"floor", "null"})

    def test_the_headline_sentences_name_mode_cpu_and_isa(self):
        run = report.Run(FIXTURE)
        out = tempfile.mkdtemp()
        try:
            text = report.Report(run, out).build()
        finally:
            shutil.rmtree(out)
        for heading in ("Summary", "2 Speed against error", "3 Time against intersection ratio",
                        "3.3 The exact test: where its time goes"):
            body = section(text, heading)
            for words in ("call mode", "batch mode", run.cpu, run.isa):
                self.assertIn(words, body, (heading, words))


    def test_pools_timed_in_one_mode_get_rows_for_that_mode_only(self):
        # The main job's default plan times the families in call mode only (scripts/run).
        run = report.Run(FIXTURE)
        run.bench = copy.deepcopy(run.bench)
        run.bench["tritri"]["results"] = [r for r in run.bench["tritri"]["results"]
                                          if not (r["workload"].startswith("family:") and r.get("mode") == "batch")]
        part = report.Part(tempfile.gettempdir())
        time_ratio.other_workloads(run, part)
        text = "\n".join(part.paragraphs)
        families = section(text, "Time on the corpus families")
        self.assertIn("Timed in call mode only in this run.", families)
        self.assertEqual({row[1] for _, rows in markdown.parse_tables(families) for row in rows}, {"call"})
        types = section(text, "Time per intersection type")
        self.assertEqual({row[1] for _, rows in markdown.parse_tables(types) for row in rows}, {"call", "batch"})

class WebPeers(unittest.TestCase):
    """The web peers' section: their self-timed results over moller97 timed the same way, and their
    answers from check.json."""

    class Part:
        def __init__(self):
            self.text = ""

        def add(self, text):
            self.text += text + "\n"

    class Run:
        def __init__(self, d):
            self.d = d

    def self_timed(self, algorithm, workload, ns):
        return {"algorithm": algorithm, "level": "overlap", "mode": "call", "workload": workload,
                "ns_per_pair_median": ns, "timed_by": "plug-in"}

    def test_each_peer_is_given_over_moller97_through_the_protocol_and_with_its_answers(self):
        from tritri_report.sections import web_peers
        bench = {"tritri": {"schema": "tritri-bench/2", "cpu_model": "Some CPU", "isa": "avx2", "results": [
            {"algorithm": "moller97", "level": "overlap", "mode": "call", "workload": "ratio:0.50",
             "ns_per_pair_median": 30.0}], "self_timed": [
            self.self_timed("moller97-process", "ratio:0.50", 40.0),
            self.self_timed("null-process", "ratio:0.50", 4.0),
            self.self_timed("rapier", "ratio:0.50", 4000.0)]}}
        tally = {"algorithm": "rapier", "family": "f", "cases": 10, "false_positives": 3, "false_negatives": 1,
                 "unsupported": 0, "crashes": 0, "timeouts": 0, "misclassified": None, "segment": None}
        check = {"algorithms": [{"name": "rapier"}], "tallies": [tally]}
        part = self.Part()
        web_peers.render(self.Run({"peers_bench": bench, "check": check}), part)
        (_, times), (_, answers) = markdown.parse_tables(part.text)
        times = {r[0]: r for r in times}
        self.assertEqual(times["rapier"][3], "4000.0 (100.00)")
        self.assertEqual(times["null-process"][3], "4.00 (0.10)")
        self.assertEqual(times["moller97"][3], "30.0")
        self.assertEqual(answers, [["rapier", "10", "3", "1", "0", "0", "40.00%"]])

    def test_without_the_file_it_says_not_measured(self):
        from tritri_report.sections import web_peers
        part = self.Part()
        web_peers.render(self.Run({}), part)
        self.assertIn("not measured", part.text.lower())


class Groups(unittest.TestCase):
    @staticmethod
    def grouped_check(groupings, groups_and_cases):
        tallies = [{"algorithm": "a", "family": g, "cases": n} for g, n in groups_and_cases]
        return {"group_by": groupings, "families": [g for g, _ in groups_and_cases], "tallies": tallies,
                "case_count": 5, "failures": []}

    def test_one_grouped_check_splits_into_each_groupings_file(self):
        check = self.grouped_check(
            ["subsuite=symmetry,@base", "subsuite,tilt", "family"],
            [("subsuite=symmetry @base=a.0", 3), ("subsuite=scale tilt=2^-3", 2), ("subsuite=symmetry tilt=2^-4", 1),
             ("family=f", 2), ("family=g", 3)])
        sym = groups.split_groupings(check, ["subsuite=symmetry,@base"])
        self.assertEqual(sym["group_by"], ["subsuite=symmetry,@base"])
        self.assertEqual(sym["families"], ["subsuite=symmetry @base=a.0"])
        self.assertEqual([t["family"] for t in sym["tallies"]], ["subsuite=symmetry @base=a.0"])
        tilt = groups.split_groupings(check, ["subsuite,tilt"])
        self.assertEqual(tilt["families"], ["subsuite=scale tilt=2^-3", "subsuite=symmetry tilt=2^-4"])
        # By family: as a check without --group-by names its tallies; the input is left as it was.
        fam = groups.split_groupings(check, ["family"])
        self.assertEqual((fam["group_by"], fam["families"]), ([], ["f", "g"]))
        self.assertEqual([t["family"] for t in fam["tallies"]], ["f", "g"])
        self.assertEqual(check["tallies"][3]["family"], "family=f")
        with self.assertRaisesRegex(ValueError, "not grouped by subsuite,gap"):
            groups.split_groupings(check, ["subsuite,gap"])

    def test_a_family_split_is_refused_when_some_case_has_no_family_label(self):
        check = self.grouped_check(["family"], [("family=f", 2), ("family=g", 2)])  # 4 of 5 cases
        with self.assertRaisesRegex(ValueError, "not every case has a family= label"):
            groups.split_groupings(check, ["family"])
        self.assertFalse(groups.in_grouping("subsuite=scale tilt=2^-3", "subsuite=symmetry,tilt"))
        self.assertFalse(groups.in_grouping("subsuite=scale", "subsuite,tilt"))
        self.assertTrue(groups.in_grouping("subsuite=scale tilt=2^-3", "subsuite=scale,tilt"))

    def test_the_sweep_a_group_counts_for(self):
        self.assertEqual(groups.sweep_of("subsuite=scale transform=2^-7"), ("scale", "-7"))
        self.assertEqual(groups.sweep_of("subsuite=scale tilt=2^-20"), ("tilt", "-20"))
        self.assertEqual(groups.sweep_of("subsuite=translate transform=2^12*(0,-1,1)"), ("translate", "12"))
        self.assertEqual(groups.sweep_of("subsuite=perturb transform=+1e-8"), ("perturb", "+1e-8"))
        self.assertEqual(groups.sweep_of("subsuite=symmetry transform=sym-012-012-ab"), ("exact", "identity"))
        self.assertEqual(groups.sweep_of("subsuite=symmetry offset=2^-40"), ("plane-offset", "-40"))
        self.assertIsNone(groups.sweep_of("subsuite=symmetry transform=sym-021-012-ba"))
        self.assertIsNone(groups.sweep_of("subsuite=rotate tilt=2^-20"))  # rotation moved the vertices

    def test_every_labelled_sweep_is_asked_for(self):
        asked = groups.sweep_groupings()
        for sweep, (_, _, _, label) in analysis.SWEEPS.items():
            if label:
                self.assertIn("subsuite," + label, asked, sweep)

    def test_base_cases_of_the_symmetry_check(self):
        sym = load("check-symmetry.json")
        self.assertTrue(all(labels(f)["subsuite"] == "symmetry" for f in sym["families"]))
        per = groups.variants_per_base(sym)
        self.assertEqual(sum(per.values()), len(sym["families"]))
        self.assertEqual(groups.base_family("subsuite=symmetry @base=near-coplanar.through.0"), "near-coplanar")


class Published(unittest.TestCase):
    def test_every_published_file_cites_its_paper(self):
        folders = [n for n in sorted(os.listdir(published.ALGORITHMS_DIR))
                   if os.path.exists(os.path.join(published.ALGORITHMS_DIR, n, "published.json"))]
        self.assertGreaterEqual(len(folders), 6)
        for folder in folders:
            doc = load_published(folder)
            self.assertTrue(doc["paper"] and doc["source"], folder)

    def test_the_report_finds_them_by_the_checks_folders(self):
        run = report.Run(FIXTURE)
        folders = {a["folder"] for a in load("check.json")["algorithms"]}
        self.assertEqual(set(run.published) - folders, set())
        self.assertIn("moller97", run.published)


class Reference(unittest.TestCase):
    def test_the_bench_files_reference_and_ratios_are_read(self):
        """A bench file that names its reference (here held97) and gives relative_to_reference."""
        src, out = tempfile.mkdtemp(), tempfile.mkdtemp()
        try:
            shutil.copy(os.path.join(FIXTURE, "check.json"), src)
            bench = load("bench.json")
            results = bench["tritri"]["results"]
            ref = {(r["workload"], r["mode"]): r["ns_per_pair_median"] for r in results
                   if r["algorithm"] == "held97" and r["level"] == "overlap"}
            for r in results:
                r.pop("relative_to_moller97", None)
                if r["level"] is not None:  # a stage has no reference
                    r["relative_to_reference"] = r["ns_per_pair_median"] / ref[(r["workload"], r["mode"])]
            bench["tritri"]["reference"] = "held97"
            with open(os.path.join(src, "bench.json"), "w", encoding="utf-8") as f:
                json.dump(bench, f)
            report.build_report(src, out)
            with open(os.path.join(out, "README.md"), encoding="utf-8") as f:
                text = f.read()
            (header, rows), = tables_in(text, "Summary")
            self.assertEqual(header[-2:], ["× held97 call", "× held97 batch"])
            level = {r["algorithm"]: r["level"] for r in results if r["workload"] == "ratio:0.50"
                     and r["level"] in ("overlap", "relation")}
            for row in rows:
                for mode, cell in (("call", row[-2]), ("batch", row[-1])):
                    e, = in_mode(results, mode, algorithm=row[0], workload="ratio:0.50", level=level[row[0]])
                    self.assertEqual(cell, markdown.ratio(e["relative_to_reference"]), (row[0], mode))
            self.assertIn("Every crossing with held97", text)
        finally:
            shutil.rmtree(src)
            shutil.rmtree(out)

    def test_old_bench_files_fall_back_to_moller97(self):
        from tritri_report import data
        self.assertEqual(data.reference({"tritri": {}}), "moller97")
        self.assertEqual(data.relative_to_reference({"relative_to_moller97": 1.5}), 1.5)
        self.assertEqual(data.relative_to_reference({"relative_to_reference": 2.0}), 2.0)


class SchemaChecks(unittest.TestCase):
    """A file that is there is read only as a version the report knows, with the keys it needs."""

    def load_spoiled(self, name, spoil):
        from tritri_report import data
        src = tempfile.mkdtemp()
        try:
            doc = load(name)
            spoil(doc)
            with open(os.path.join(src, name), "w", encoding="utf-8") as f:
                json.dump(doc, f)
            return data.load_results(src), os.path.join(src, name)
        finally:
            shutil.rmtree(src)

    def refusal(self, name, spoil):
        from tritri_report import schema
        with self.assertRaises(schema.SchemaError) as caught:
            self.load_spoiled(name, spoil)
        return str(caught.exception)

    def test_a_renamed_tally_key_is_named_not_read_as_zero(self):
        def rename(doc):
            doc["tallies"][2]["fn"] = doc["tallies"][2].pop("false_negatives")
        message = self.refusal("check.json", rename)
        self.assertRegex(message, r"check\.json: missing required key tallies\[2\]\.false_negatives$")

    def test_a_version_the_report_does_not_read_is_refused(self):
        def newer(doc):
            doc["schema"] = "tritri-check/4"
        self.assertRegex(self.refusal("check-float.json", newer),
                         r"check-float\.json: schema 'tritri-check/4'; the report reads tritri-check/2, tritri-check/3$")
        self.assertRegex(self.refusal("bench.json", lambda doc: doc["tritri"].pop("schema")),
                         r"bench\.json: no tritri\.schema; the report reads tritri-bench/1, tritri-bench/2$")

    def test_a_missing_nested_key_is_named_by_its_path(self):
        def drop(doc):
            doc["pairs"][0]["families"][1].pop("differ")
        self.assertRegex(self.refusal("compiler-diff.json", drop),
                         r"compiler-diff\.json: missing required key pairs\[0\]\.families\[1\]\.differ$")

    def test_every_fixture_file_is_read(self):
        from tritri_report import data
        loaded = data.load_results(FIXTURE)
        self.assertEqual(set(loaded), {role for role, name in data.FILES.items()
                                       if os.path.exists(os.path.join(FIXTURE, name))})


class LegibleFigures(unittest.TestCase):
    """Every figure, drawn from the fixture, keeps each axes to a number of series one can tell
    apart (the Okabe-Ito palette has eight colours): more go into panels by group (kinds.py)."""
    MAX_SERIES = 8

    @staticmethod
    def series_in(ax):
        named = [x for x in list(ax.get_lines()) + list(ax.collections) if not x.get_label().startswith("_")]
        return len(named)

    def test_no_axes_draws_more_series_than_can_be_told_apart(self):
        from tritri_report import figures
        counts, real = {}, figures._save

        def counting(fig, path):
            counts[os.path.basename(path)] = max([self.series_in(ax) for ax in fig.axes] + [0])
            real(fig, path)
        figures._save = counting
        out = tempfile.mkdtemp()
        try:
            report.build_report(FIXTURE, out)
        finally:
            figures._save = real
            shutil.rmtree(out)
        self.assertIn("time-ratio.png", counts)
        self.assertIn("speed-error.png", counts)
        self.assertGreater(counts["time-ratio.png"], 1)  # the count sees the series it limits
        for name, n in counts.items():
            self.assertLessEqual(n, self.MAX_SERIES, name)


class Sections(unittest.TestCase):
    def test_a_section_is_a_title_and_a_render_function(self):
        import types
        extra = types.SimpleNamespace(TITLE="Extra", render=lambda run, part: part.add("hello\n"))
        sub = types.SimpleNamespace(TITLE="Detail", LEVEL=3, render=lambda run, part: part.heading("More"))
        out = tempfile.mkdtemp()
        try:
            r = report.Report(report.Run(FIXTURE), out)
            text = r.build([extra, sub])
            self.assertEqual(text, "## 1 Extra\n\nhello\n\n### 1.1 Detail\n\n### 1.2 More\n")
        finally:
            shutil.rmtree(out)


if __name__ == "__main__":
    unittest.main()

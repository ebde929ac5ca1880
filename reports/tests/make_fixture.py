#!/usr/bin/env python3
"""Copies a small real run into tests/fixture/, trimmed to what the report reads.

The fixture was made from a run on a tiny corpus (see fixture/HOW.md). Only the bench files
(bench.json, compiler-bench.json) are cut: their "benchmarks" array (Google Benchmark's raw
repetitions) is not read by the report and is most of the file. Rerun this after a schema change, then update the tests' expectations.
"""

import json
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def main(src):
    dst = os.path.join(HERE, "fixture")
    os.makedirs(dst, exist_ok=True)
    for name in sorted(os.listdir(src)):
        if not name.endswith(".json"):
            continue
        with open(os.path.join(src, name), encoding="utf-8") as f:
            doc = json.load(f)
        if name == "bench.json" or name.endswith("-bench.json"):
            doc.pop("benchmarks", None)
            for r in doc.get("tritri", {}).get("results", []):
                r.pop("ns_per_pair", None)
        with open(os.path.join(dst, name), "w", encoding="utf-8") as f:
            json.dump(doc, f, indent=0, sort_keys=True)
            f.write("\n")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: make_fixture.py RESULTS_DIR")
    sys.exit(main(sys.argv[1]))

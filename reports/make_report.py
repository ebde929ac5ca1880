#!/usr/bin/env python3
"""Builds the tritri report from a results directory: make_report.py RESULTS_DIR OUT_DIR.

Writes OUT_DIR/README.md and OUT_DIR/figures/*.png from the JSON files in RESULTS_DIR only
(scripts/run writes them; any may be missing, and the report says which parts were not
measured). --summary also prints a short table per algorithm to stdout.
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from tritri_report import report  # noqa: E402


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("results_dir")
    p.add_argument("out_dir")
    p.add_argument("--summary", action="store_true", help="print a short table per algorithm")
    args = p.parse_args(argv)
    if not os.path.isdir(args.results_dir):
        p.error("no such results directory: %s" % args.results_dir)
    r = report.build_report(args.results_dir, args.out_dir)
    print("report: %s (%d figures)" % (os.path.join(args.out_dir, "README.md"), len(r.figures)), file=sys.stderr)
    if args.summary:
        modes, rows = report.summary_rows(args.results_dir)
        if rows:
            print("%-18s %14s %16s" % ("algorithm", "overlap errors", "err. singular")
                  + "".join(" %14s" % ("ns/pair " + (m or "")).strip() for m in modes))
            for a, errors, rate, times in rows:
                print("%-18s %14d %16s" % (a, errors, rate) + "".join(" %14s" % t for t in times))
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Helpers scripts/run calls between the tritri commands (not part of the report itself).

  prepare.py manifest CORPUS_DIR OUT.json --seed S --command CMD
  prepare.py provenance OUT.json --build-dir DIR --command CMD --started ISO
  prepare.py steps STEPS.tsv OUT.json [--baseline-inputs TEXT --baseline-verdict TEXT]
  prepare.py groupings symmetry|sweeps   the `tritri check --group-by` specs the report reads, one a line
  prepare.py suites                      the papers' named suites: CASES <TAB> LABEL <TAB> RESULTS.json
  prepare.py split CHECK.json WHICH=OUT.json...   (WHICH: symmetry, sweeps, family)
                                         one check run grouped several ways, as the files the
                                         report reads (each as if checked with its groupings alone;
                                         family: as if not grouped, each case by its family= label)

None of them reads a case: what the corpus holds, the report reads from `tritri check`'s JSON.
Every JSON file is written beside its final name and renamed into place.
"""

import argparse
import datetime
import hashlib
import json
import os
import platform
import socket
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from tritri_report import groups, published  # noqa: E402

PACKAGES = ["g++", "cmake", "libcgal-dev", "libfcl-dev", "libeigen3-dev", "libbenchmark-dev", "libgmp-dev",
            "python3-matplotlib"]


def write_json(path, doc):
    tmp = "%s.tmp.%d" % (path, os.getpid())
    try:
        with open(tmp, "w", encoding="utf-8") as f:
            json.dump(doc, f, indent=1, sort_keys=False)
            f.write("\n")
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def manifest(corpus_dir, seed, command):
    """Which corpus this is: the command and seed that made it, its files, a hash of their bytes."""
    files = sorted(n for n in os.listdir(corpus_dir) if n.endswith(".cases"))
    digest = hashlib.sha256()
    for name in files:
        digest.update(name.encode())
        with open(os.path.join(corpus_dir, name), "rb") as f:
            digest.update(f.read())
    return {"schema": "tritri-corpus-manifest/2", "command": command, "seed": seed, "files": files,
            "sha256": digest.hexdigest()}


def _run(cmd):
    try:
        return subprocess.run(cmd, capture_output=True, text=True, timeout=20).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return ""


def _cpu_model():
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def _memory():
    try:
        with open("/proc/meminfo", encoding="utf-8") as f:
            for line in f:
                if line.startswith("MemTotal"):
                    return "%.1f GiB" % (int(line.split()[1]) / 1024 / 1024)
    except OSError:
        pass
    return None


def _os_name():
    try:
        with open("/etc/os-release", encoding="utf-8") as f:
            for line in f:
                if line.startswith("PRETTY_NAME="):
                    return line.split("=", 1)[1].strip().strip('"')
    except OSError:
        pass
    return platform.platform()


def _cmake_cache(build_dir):
    values = {}
    try:
        with open(os.path.join(build_dir, "CMakeCache.txt"), encoding="utf-8") as f:
            for line in f:
                if ":" in line and "=" in line and not line.startswith(("#", "//")):
                    key, _, value = line.strip().partition("=")
                    values[key.split(":", 1)[0]] = value
    except OSError:
        pass
    return values


def provenance(args):
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    cache = _cmake_cache(args.build_dir)
    build_type = cache.get("CMAKE_BUILD_TYPE", "")
    flags = " ".join(x for x in (cache.get("CMAKE_CXX_FLAGS", ""),
                                 cache.get("CMAKE_CXX_FLAGS_" + build_type.upper(), ""),
                                 "-ffp-contract=off") if x)
    packages = {}
    for p in PACKAGES:
        v = _run(["dpkg-query", "-W", "-f=${Version}", p])
        if v:
            packages[p] = v
    try:
        import matplotlib
        mpl = matplotlib.__version__
    except ImportError:
        mpl = "not installed"
    cpu = _cpu_model()
    cores = os.cpu_count()
    sha = _run(["git", "-C", root, "rev-parse", "HEAD"])
    dirty = bool(_run(["git", "-C", root, "status", "--porcelain", "--untracked-files=no"]))
    doc = {
        "schema": "tritri-provenance/1",
        "machine_name": "%s (%s, %s cores)" % (socket.gethostname(), cpu, cores),
        "hostname": socket.gethostname(),
        "cpu": cpu,
        "cores": cores,
        "memory": _memory(),
        "os": _os_name(),
        "kernel": platform.release(),
        "compiler": (_run([cache.get("CMAKE_CXX_COMPILER", "c++"), "--version"]).splitlines() or ["unknown"])[0],
        "build_flags": "%s: %s" % (build_type or "?", flags),
        "packages": packages,
        "python": "Python %s, matplotlib %s" % (platform.python_version(), mpl),
        "git_sha": sha or "unknown",
        "git_dirty": dirty,
        "command": args.command,
        "started": args.started,
        "finished": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M:%S UTC"),
    }
    write_json(args.out, doc)


def steps(args):
    rows = []
    with open(args.tsv, encoding="utf-8") as f:
        for line in f:
            parts = line.rstrip("\n").split("\t")
            if len(parts) >= 3:
                rows.append({"name": parts[0], "seconds": float(parts[1]), "status": parts[2],
                             "command": parts[3] if len(parts) > 3 else ""})
    doc = {"schema": "tritri-steps/1", "steps": rows}
    if args.baseline_verdict:
        doc["baseline"] = {"inputs": args.baseline_inputs, "verdict": args.baseline_verdict}
    write_json(args.out, doc)


GROUPINGS = {"symmetry": lambda: [groups.SYMMETRY_GROUPING], "sweeps": groups.sweep_groupings,
             "family": lambda: [groups.FAMILY_GROUPING]}


def grouping_specs(which):
    return GROUPINGS[which]()


def split(check_path, outputs):
    with open(check_path, encoding="utf-8") as f:
        check = json.load(f)
    for spec in outputs:
        which, _, out = spec.partition("=")
        if which not in GROUPINGS or not out:
            raise SystemExit("prepare.py split: '%s' is not WHICH=OUT.json, WHICH one of %s" % (spec, ", ".join(GROUPINGS)))
        try:
            write_json(out, groups.split_groupings(check, grouping_specs(which)))
        except ValueError as e:
            raise SystemExit("prepare.py split: %s: %s" % (check_path, e))


def suites():
    """Each named suite a paper's published file asks to check, and how the paper groups it."""
    folders = sorted(os.listdir(published.ALGORITHMS_DIR))
    for doc in published.load(folders).values():
        s = doc.get("suite")
        if s:
            print("%s\t%s\t%s" % (s["cases"], s["group_by"], s["results"]))


# The arguments of the commands that take more than one: a positional NAME, an option
# --NAME=DEFAULT, or a required option --NAME!.
ARGUMENTS = {
    "manifest": "corpus_dir out --seed=1 --command=",
    "provenance": "out --build-dir! --command= --started=",
    "steps": "tsv out --baseline-inputs= --baseline-verdict=",
}


def main(argv=None):
    p = argparse.ArgumentParser(description="helpers for scripts/run")
    sub = p.add_subparsers(dest="what", required=True)
    for what, arguments in ARGUMENTS.items():
        command = sub.add_parser(what)
        for a in arguments.split():
            if a.endswith("!"):
                command.add_argument(a[:-1], required=True)
            elif "=" in a:
                name, default = a.split("=", 1)
                command.add_argument(name, default=default)
            else:
                command.add_argument(a)
    g = sub.add_parser("groupings")
    g.add_argument("which", choices=list(GROUPINGS))
    sub.add_parser("suites")
    sp = sub.add_parser("split")
    sp.add_argument("check")
    sp.add_argument("outputs", nargs="+", metavar="WHICH=OUT.json")
    args = p.parse_args(argv)
    if args.what == "manifest":
        write_json(args.out, manifest(args.corpus_dir, args.seed, args.command))
    elif args.what == "provenance":
        provenance(args)
    elif args.what == "groupings":
        print("\n".join(grouping_specs(args.which)))
    elif args.what == "suites":
        suites()
    elif args.what == "split":
        split(args.check, args.outputs)
    else:
        steps(args)
    return 0


if __name__ == "__main__":
    sys.exit(main())

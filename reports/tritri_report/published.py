"""What the papers published: algorithms/<folder>/published.json, beside each port.

The only numbers in the report that do not come from the run. Each file quotes its paper's
figures and claims with where they are printed (section, table), so a reader can check them;
the report finds the file by the folder the check JSON names for each algorithm.
"""

import os
from collections import OrderedDict

from . import data

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ALGORITHMS_DIR = os.path.join(REPO, "algorithms")
FILE_NAME = "published.json"


def old_folder(name):
    """The folder of an algorithm in a check file written before checks named folders: every
    variant of a port was named PORT-VARIANT after its folder."""
    return name.split("-", 1)[0]


def folders_of(check, bench):
    """{algorithm: folder} for every algorithm of the run, in the check's order (else the bench's)."""
    out = OrderedDict()
    for a in (check or {}).get("algorithms", []):
        out[a["name"]] = a.get("folder") or old_folder(a["name"])
    if not out:
        for r in data.bench_results(bench):
            out.setdefault(r["algorithm"], old_folder(r["algorithm"]))
    return out


def load(folders):
    """{folder: its published document} for the folders that have one, in the order given.
    A plug-in's folder may be a path outside algorithms/: os.path.join keeps an absolute one."""
    out = OrderedDict()
    for folder in folders:
        if folder and folder not in out:
            doc = data.load_json(os.path.join(ALGORITHMS_DIR, folder, FILE_NAME), "published")
            if doc is not None:
                out[folder] = doc
    return out

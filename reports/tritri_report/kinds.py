"""The groups the figures draw apart, a panel each: the published ports, their variants, the
library peers, and this project's own test. Read from each algorithm's folder (the check's, else
the name up to its first '-')."""

from . import published

# The folders of the library peers (README.md, "Library peers") and of this project's own tests.
LIBRARY_PEERS = ("fcl", "cgal", "open3d", "bullet", "ode", "vtk")
OURS = ("exact",)
GROUPS = ("published ports", "their variants", "library peers", "ours")


def group_of(run, name):
    folder = run.folders.get(name) or published.old_folder(name)
    if folder in OURS:
        return "ours"
    if folder in LIBRARY_PEERS:
        return "library peers"
    return "published ports" if name == folder else "their variants"


def split(run, names):
    """[(group, [names in it, in the order given])] for the groups that have any."""
    out = [(g, [n for n in names if group_of(run, n) == g]) for g in GROUPS]
    return [(g, ns) for g, ns in out if ns]

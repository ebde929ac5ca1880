"""Computations on the results that are more than sums: Pareto frontier, break-even points,
sweep binning, the choice of gallery cases. Pure functions, so the tests can pin them down."""

import math
import re
from collections import OrderedDict

from . import data


def pareto_frontier(points):
    """Names of the points (name, x, y) that no other point beats on both x and y."""
    front = []
    for name, x, y in points:
        dominated = any((x2 <= x and y2 <= y) and (x2 < x or y2 < y) for n2, x2, y2 in points if n2 != name)
        if not dominated:
            front.append(name)
    return front


def crossings(a_pts, b_pts, a_spread=None, b_spread=None):
    """Where two time curves over R cross: [(R, ns, within_noise)].

    Between consecutive measured R the curves are taken as straight lines. A crossing is within
    noise when, at both ends, the gap between the curves is smaller than the larger of the two
    benchmarks' repetition spreads (max/min - 1): the measurement cannot order them there.
    """
    a = dict(a_pts)
    b = dict(b_pts)
    rs = sorted(set(a) & set(b))
    out = []

    def noisy(r):
        sa = (a_spread or {}).get(r) or 0.0
        sb = (b_spread or {}).get(r) or 0.0
        return abs(a[r] - b[r]) <= max(sa, sb) * min(a[r], b[r])

    for r0, r1 in zip(rs, rs[1:]):
        d0, d1 = a[r0] - b[r0], a[r1] - b[r1]
        if d0 == 0:
            out.append((r0, a[r0], noisy(r0)))
        elif d0 * d1 < 0:
            f = d0 / (d0 - d1)
            r = r0 + (r1 - r0) * f
            t = a[r0] + (a[r1] - a[r0]) * f
            out.append((r, t, noisy(r0) and noisy(r1)))
    if rs and a[rs[-1]] - b[rs[-1]] == 0 and len(rs) > 1:
        out.append((rs[-1], a[rs[-1]], noisy(rs[-1])))
    return out


def envelope_changes(series):
    """Where the fastest curve changes: [(R, ns, before, after)], from {name: [(R, ns)]}."""
    rs = sorted({r for pts in series.values() for r, _ in pts})
    table = {n: dict(p) for n, p in series.items()}
    fastest = []
    for r in rs:
        cand = [(table[n][r], n) for n in table if r in table[n]]
        if cand:
            fastest.append((r, min(cand)[1]))
    out = []
    for (r0, n0), (r1, n1) in zip(fastest, fastest[1:]):
        if n0 != n1:
            for r, t, _ in crossings(series[n0], series[n1]):
                if r0 <= r <= r1:
                    out.append((r, t, n0, n1))
                    break
            else:
                out.append(((r0 + r1) / 2, table[n1][r1], n0, n1))
    return out


# ---- sweeps ----

SWEEPS = OrderedDict([
    # name: (title, x label, how values read, the construction label swept or None when the
    # sweep is a transformation of the corpus: groups.sweep_of)
    ("tilt", ("near-coplanar: T2 tilted off T1's plane", "tilt (slope 2^k)", "pow2", "tilt")),
    ("scale", ("scaling by 2^k (exact: the answer cannot change)", "scale factor 2^k", "pow2-binned", None)),
    ("translate", ("translation by 2^k offsets (exact: the answer cannot change)", "offset 2^k", "pow2-binned",
                   None)),
    ("perturb", ("one vertex moved by ±δ × the pair's size (the oracle judges the moved pair)",
                 "perturbation δ (both signs pooled)", "magnitude", None)),
    ("plane-offset", ("parallel planes: distance between them", "plane offset 2^k", "pow2-binned", "offset")),
    ("gap", ("coplanar-disjoint: gap between the triangles", "gap 2^k", "pow2-binned", "gap")),
    ("aspect", ("slivers: aspect ratio", "aspect ratio 2^k", "pow2", "aspect")),
    ("size-ratio", ("tiny-vs-huge: size ratio", "size ratio 2^k", "pow2-binned", "ratio")),
])
BIN_WIDTH = 10  # exponents per bin where a sweep draws k at random over a wide range


def sweep_bins(sweep, series):
    """[(x, label, Totals)] from [(value string, Totals)], merged into the sweep's bins, by x.

    A binned sweep is labelled by the exponents actually present in each bin, and drawn at
    their mean, so a bin holding only k = 40 says so.
    """
    kind = SWEEPS.get(sweep, ("", "", "raw", None))[2]
    bins = OrderedDict()
    for value, tot in series:
        if kind in ("pow2", "pow2-binned"):
            try:
                k = int(value)
            except ValueError:
                continue
            key = math.floor(k / BIN_WIDTH) if kind == "pow2-binned" else k
            point = k
        elif kind == "magnitude":
            m = re.fullmatch(r"[+-]?(\d+(?:\.\d*)?e-?\d+)", value)
            if not m:
                continue
            key = m.group(1)
            point = m.group(1)
        else:
            continue
        entry = bins.setdefault(key, [set(), data.Totals()])
        entry[0].add(point)
        t = entry[1]
        for attr in ("cases", "fp", "fn", "unsupported", "crashes", "timeouts"):
            setattr(t, attr, getattr(t, attr) + getattr(tot, attr))
        if tot.misclassified is not None:
            t.misclassified = (t.misclassified or 0) + tot.misclassified
    out = []
    for key, (points, t) in bins.items():
        if kind == "magnitude":
            (m,) = points
            out.append((float(m), m, t))
            continue
        lo, hi = min(points), max(points)
        label = "2^%d" % lo if lo == hi else "2^%d..2^%d" % (lo, hi)
        out.append((2.0 ** (sum(points) / len(points)), label, t))
    return sorted(out, key=lambda e: e[0])


# ---- the gallery ----

def _labels(line):
    return dict(f.split("=", 1) for f in line.split()[19:] if "=" in f)


def gallery_choice(failures, algorithm, limit=3):
    """The worst of an algorithm's listed failures, up to `limit`, from different families.

    Worst first: a wrong yes/no answer (overlap) before a wrong classification; an exactly
    singular input (the construction knows the answer: expect=) before a rounded or perturbed
    one, since no rounding excuses it; the unpermuted variant, as the easiest to read.
    """
    own = [f for f in failures if f["algorithm"] == algorithm and f.get("line")]

    def rank(f):
        lab = _labels(f["line"])
        return (0 if f["level"] == "overlap" else 1,
                0 if "expect" in lab else 1,
                0 if lab.get("transform", "").startswith("sym-012-012-ab") else 1)

    own.sort(key=rank)
    chosen, families = [], set()
    for f in own:
        if f["family"] in families:
            continue
        chosen.append(f)
        families.add(f["family"])
        if len(chosen) == limit:
            break
    return chosen


def case_triangles(line):
    fields = line.split()
    v = [float(x) for x in fields[1:19]]
    t1 = [v[0:3], v[3:6], v[6:9]]
    t2 = [v[9:12], v[12:15], v[15:18]]
    return t1, t2

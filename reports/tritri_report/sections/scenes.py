"""Scenes: the triangle pairs a collision query really hands its test (FCL's BVH broad phase on
meshes in motion), per scene x bounding-volume type: collision ratio, time and ranking on the
level the scene's query needs, wrong answers, the triangle test's share of a whole query, and
Moller's two claims checked at the scenes' own collision ratios.

Reads bench-scenes.json (`tritri bench --workload scene`) and scene-pictures/NAME.json
(`tritri scene NAME --picture FILE`), both written by scripts/run."""

import glob
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from .. import data  # noqa: E402
from ..markdown import NOT_MEASURED, ns, pct, ratio, table  # noqa: E402

TITLE = "Scenes: meshes in motion through a BVH broad phase"
BENCH = "bench-scenes.json"


def parse_context(bench):
    """{value: {key: value}} from the context keys "scene V" the scene workload writes."""
    out = {}
    for key, text in bench.get("context", {}).items():
        if key.startswith("scene ") and not text.startswith("skipped"):
            out[key[6:]] = dict(kv.split("=", 1) for kv in text.split() if "=" in kv)
    return out


def results(bench):
    """{(workload pool name, level): {algorithm: (ns, wrong)}}."""
    out = {}
    for r in bench.get("tritri", {}).get("results", []):
        out.setdefault((r.get("workload"), r.get("level")), {})[r["algorithm"]] = (
            r.get("ns_per_pair_median"), r.get("wrong", 0))
    return out


def floors(bench):
    return set(data.floors(bench))


def ranking(times, skip):
    rows = sorted((t[0], a) for a, t in times.items() if a not in skip and t[0] is not None)
    return ", ".join("%s %s" % (a, ns(t)) for t, a in rows)


def scene_rows(ctx, res, skip):
    rows, wrong_rows, share_rows, points = [], [], [], []
    for value, c in ctx.items():
        frames = max(1, int(c["frames"]))
        cand = int(c["candidates"]) / frames
        inter = int(c["intersecting"])
        cr = inter / max(1, int(c["candidates"]))
        self_scene = c.get("self") == "1"
        level = "segment" if self_scene else "overlap"
        allp = res.get(("scene:" + value, level), {}) or res.get(("scene:" + value, "overlap"), {})
        anyp = res.get(("scene-any:" + value, "overlap"), {})
        shuf = res.get(("scene-shuffled:" + value, level), {})
        query = "intersection curve (segment)" if self_scene else "all contacts (overlap)"
        rows.append([value, c["mode"], "%.0f" % cand, pct(cr, 1), query, ranking(allp, skip) or "-",
                     ranking(anyp, skip) or "-"])
        over = res.get(("scene:" + value, "overlap"), {})
        wrong_rows.append((value, {a: t[1] for a, t in over.items() if a not in skip}))
        fastest = min((t[0], a) for a, t in over.items() if a not in skip) if over else None
        trav = float(c["traverse_ms"]) + float(c["setup_ms"])
        fcl_share = float(c["fcl_triangle_ms"]) / float(c["collide_all_ms"]) if float(c["collide_all_ms"]) > 0 else None
        if fastest:
            t_alg = fastest[0] * cand * 1e-6  # ms per frame
            shuffled = shuf.get(fastest[1], (None,))[0]
            share_rows.append([value, "%.3f" % float(c["setup_ms"]), "%.3f" % float(c["traverse_ms"]),
                               "%.3f" % float(c["fcl_triangle_ms"]), "%.3f" % float(c["collide_all_ms"]),
                               pct(fcl_share, 0) if fcl_share is not None else "-", fastest[1],
                               pct(t_alg / (trav + t_alg), 0),
                               ratio(shuffled / fastest[0]) if shuffled else "-"])
        points.append((value, cr, {a: t[0] for a, t in over.items() if a not in skip and t[0] is not None}))
    return rows, wrong_rows, share_rows, points


def moller_claims(run, points):
    pub = run.published.get("moller97", {}).get("claims", {}) if run.published else {}
    lo, hi = pub.get("brute_force", {}).get("range", [1.3, 1.6])
    be = pub.get("break_even_with_erit", {}).get("value", 0.45)
    rows = []
    for value, cr, t in sorted(points, key=lambda p: p[1]):
        m = t.get("moller97")
        b = t.get("brute")
        h = t.get("held97")
        rb = b / m if m and b else None
        rh = h / m if m and h else None
        rows.append([value, pct(cr, 1), ratio(rb), "yes" if rb and lo <= rb <= hi else ("-" if rb is None else "no"),
                     ratio(rh), "-" if rh is None else ("Möller" if rh > 1 else "ERIT (held97)")])
    text = ("Möller: brute force takes %.1f–%.1f× his test; his test beats ERIT below a collision ratio of "
            "about %.0f%% and loses above. Below, per scene pool (overlap level, traversal order): the ratio "
            "brute / moller97 and held97 / moller97 (> 1: Möller faster), against the scene's collision "
            "ratio.\n" % (lo, hi, 100 * be))
    return text, rows, be


def draw_time_ratio(points, path):
    fig, ax = plt.subplots(figsize=(6.5, 4))
    algos = sorted({a for _, _, t in points for a in t})
    for i, a in enumerate(algos):
        xy = sorted((cr, t[a]) for _, cr, t in points if a in t)
        ax.plot([x for x, _ in xy], [y for _, y in xy], marker="os^Dv<>ph*"[i % 10], linestyle="", label=a)
    ax.set_xlabel("collision ratio of the scene pool (intersecting / candidates)")
    ax.set_ylabel("ns per pair (overlap, traversal order)")
    ax.legend(fontsize=6, ncol=2)
    fig.savefig(path, dpi=80, bbox_inches="tight")
    plt.close(fig)


def draw_scene(picture, path):
    fig = plt.figure(figsize=(3, 3))
    ax = fig.add_subplot(projection="3d")
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    colours = ["tab:blue", "tab:orange", "tab:green", "tab:red"]
    lo, hi = [1e300] * 3, [-1e300] * 3
    for b, tris in enumerate(picture["bodies"]):
        ax.add_collection3d(Poly3DCollection(tris, facecolor=colours[b % 4], edgecolor="none", alpha=0.6))
        for t in tris:
            for p in t:
                lo = [min(lo[i], p[i]) for i in range(3)]
                hi = [max(hi[i], p[i]) for i in range(3)]
    for i, setter in enumerate([ax.set_xlim, ax.set_ylim, ax.set_zlim]):
        setter(lo[i], hi[i])
    ax.set_title("%s (frame %d)" % (picture["scene"], picture["frame"]), fontsize=8)
    ax.set_axis_off()
    fig.savefig(path, dpi=80, bbox_inches="tight")
    plt.close(fig)


def render(run, part):
    bench = data.load_json(os.path.join(run.results_dir, BENCH), "bench")
    if not bench:
        part.add("The scene workloads of `tritri bench --workload scene`: %s.\n" % NOT_MEASURED)
        return
    ctx, res = parse_context(bench), results(bench)
    skip = floors(bench)
    rows, wrong_rows, share_rows, points = scene_rows(ctx, res, skip)
    part.add("Each scene is meshes in motion (cases/scenes); its pool is the candidate pairs of its frames, the "
             "leaf pairs FCL's BVH traversal lets through, in traversal order, labelled by the oracle; when "
             "all frames exceed the pool size, whole frames spread evenly over the motion (cand./frame is "
             "over the frames in the pool). "
             "`scene:V` is the all-contacts query (intersection curve for a self scene), `scene-any:V` the "
             "any-contact query (each frame up to its first contact), `scene-shuffled:V` the same pairs "
             "shuffled. Times are medians of `tritri bench`, ns per pair.\n")
    part.add(table(["scene/bv", "FCL path", "cand./frame", "collision ratio", "query", "ranking (all)",
                    "ranking (any contact)"], rows))
    part.heading("Wrong answers on the scenes")
    algos = sorted({a for (w, l), t in res.items() if w and w.startswith("scene:") for a in t} - skip)
    part.add(table(["scene/bv"] + algos, [[v] + ["%d" % w[a] if a in w else "-" for a in algos] for v, w in wrong_rows]))
    part.heading("The triangle test's share of a whole query")
    part.add("Per frame, ms: FCL's set-up (copy, transform, rebuild: AABB, k-DOPs, RSS) and traversal alone, "
             "FCL's own triangle test on the candidates and its whole fcl::collide (all contacts); FCL's "
             "share = its triangle test / fcl::collide. For the fastest algorithm: its batch time on the "
             "candidates / (set-up + traversal + that), and its shuffled / traversal-order time.\n")
    part.add(table(["scene/bv", "set-up", "traversal", "FCL tri", "fcl::collide", "FCL share", "fastest",
                    "its share", "shuffled/ordered"], share_rows))
    part.heading("Möller's claims at the scenes' collision ratios")
    text, mrows, _ = moller_claims(run, points)
    part.add(text)
    part.add(table(["scene/bv", "collision ratio", "brute/moller97", "in range", "held97/moller97", "faster"], mrows))
    if points:
        rel = part.figure("scenes_time_ratio.png", draw_time_ratio, points)
        part.add("![time against collision ratio](%s)\n" % rel)
    for f in sorted(glob.glob(os.path.join(run.results_dir, "scene-pictures", "*.json"))):
        pic = data.load_json(f, "picture")
        rel = part.figure("scene_%s.png" % pic["scene"], draw_scene, pic)
        part.add("![%s](%s)\n" % (pic["scene"], rel))

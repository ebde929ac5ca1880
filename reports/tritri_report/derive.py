"""Inputs derived from the corpus for the runs that `tritri check` tallies per family= label.

`tritri check` counts per algorithm x family, where the family is the case's `family=` label.
The stability sweeps and the symmetry test need other groupings (by tilt, by scale exponent,
by base case), so these functions write copies of the corpus cases whose `family=` names the
group instead; `tritri check` then does the counting, with its own scoring, and the report
reads its tallies. Names get a prefix so a case can sit in two sweeps of one file.

The manifest records what the corpus was (seed, sizes, hash) for the provenance section.
"""

import hashlib
import json
import os
import re
from collections import Counter, OrderedDict

IDENTITY = "sym-012-012-ab"

# Sweeps read from a construction label: (sweep name, label key). Only exactly transformed
# variants keep the label's meaning, since rotation and perturbation move the vertices.
LABEL_SWEEPS = [
    ("tilt", "tilt"),          # near-coplanar: slope of T2 off T1's plane
    ("plane-offset", "offset"),  # parallel: distance between the planes
    ("gap", "gap"),            # coplanar-disjoint: gap between the triangles
    ("aspect", "aspect"),      # slivers: aspect ratio
    ("size-ratio", "ratio"),   # tiny-vs-huge: size ratio
]
EXACT_VARIANTS = {"symmetry", "scale", "translate"}


def parse_case_line(line):
    """(name, 18 coordinate strings, [(key, value)]) of a case line, or None for a comment."""
    text = line.strip()
    if not text or text.startswith("#"):
        return None
    fields = text.split()
    if len(fields) < 19:
        raise ValueError("not a case line: %r" % line[:80])
    labels = []
    for field in fields[19:]:
        key, _, value = field.partition("=")
        labels.append((key, value))
    return fields[0], fields[1:19], labels


def format_case(name, coords, labels):
    return " ".join([name] + list(coords) + ["%s=%s" % kv for kv in labels])


def with_family(labels, family):
    out = [(k, v) for k, v in labels if k != "family"]
    return [("family", family)] + out


def read_cases(paths):
    for path in paths:
        with open(path, encoding="utf-8") as f:
            for line in f:
                parsed = parse_case_line(line)
                if parsed:
                    yield parsed


def corpus_files(corpus_dir):
    return sorted(os.path.join(corpus_dir, n) for n in os.listdir(corpus_dir) if n.endswith(".cases"))


def base_name(name):
    """The base case a variant came from: names are family.config.index.transform."""
    return name.rsplit(".", 1)[0]


def sweep_groups(name, labels):
    """Every (sweep, value) group the case belongs to."""
    lab = dict(labels)
    variant = lab.get("variant")
    transform = lab.get("transform", "")
    groups = []
    if variant == "symmetry" and transform == IDENTITY:
        groups.append(("exact", "identity"))
    if variant == "scale":
        m = re.fullmatch(r"2\^(-?\d+)", transform)
        if m:
            groups.append(("scale", m.group(1)))
    if variant == "translate":
        m = re.match(r"2\^(-?\d+)\*", transform)
        if m:
            groups.append(("translate", m.group(1)))
    if variant == "perturb":
        groups.append(("perturb", transform))
    if variant == "rotate":
        groups.append(("rotate", "random"))
    if variant in EXACT_VARIANTS:
        for sweep, key in LABEL_SWEEPS:
            value = lab.get(key)
            m = re.fullmatch(r"2\^(-?\d+)", value or "")
            if m:
                groups.append((sweep, m.group(1)))
    return groups


class _AtomicText:
    """A text file written beside its final path and renamed into place when complete."""

    def __init__(self, path):
        self.path = path
        self.tmp = "%s.tmp.%d" % (path, os.getpid())

    def __enter__(self):
        self.f = open(self.tmp, "w", encoding="utf-8")
        return self.f

    def __exit__(self, kind, value, tb):
        self.f.close()
        if kind is None:
            os.replace(self.tmp, self.path)
        else:
            os.unlink(self.tmp)
        return False


def write_derived(corpus_dir, suites_dir, out_dir):
    """Writes symmetry.cases, sweeps.cases, yuhe13.cases and sabharwal15.cases into out_dir."""
    os.makedirs(out_dir, exist_ok=True)
    files = corpus_files(corpus_dir)
    header = "# derived by reports/tritri_report/derive.py from %s; family= names the group\n" % corpus_dir
    with _AtomicText(os.path.join(out_dir, "symmetry.cases")) as sym, \
            _AtomicText(os.path.join(out_dir, "sweeps.cases")) as sweeps:
        sym.write(header)
        sweeps.write(header)
        for name, coords, labels in read_cases(files):
            lab = dict(labels)
            if lab.get("variant") == "symmetry":
                sym.write(format_case(name, coords, with_family(labels, "sym:" + base_name(name))) + "\n")
            for sweep, value in sweep_groups(name, labels):
                group = "%s:%s" % (sweep, value)
                sweeps.write(format_case(sweep + "~" + name, coords, with_family(labels, group)) + "\n")
    # The named suites, grouped the way their papers count them.
    suites = {
        "yuhe13.cases": lambda lab: "yuhe13-" + ("singular" if lab.get("singular") == "yes" else "other"),
        "sabharwal15.cases": lambda lab: "table1:" + lab.get("table1", "unlabelled"),
    }
    for file_name, group_of in suites.items():
        source = os.path.join(suites_dir, file_name)
        if not os.path.exists(source):
            continue
        with _AtomicText(os.path.join(out_dir, file_name)) as out:
            out.write("# derived from %s; family= groups the cases as the paper counts them\n" % source)
            for name, coords, labels in read_cases([source]):
                out.write(format_case(name, coords, with_family(labels, group_of(dict(labels)))) + "\n")


def manifest(corpus_dir, seed, command):
    """What the corpus is: sizes per family, relation and variant; a hash of its bytes."""
    files = corpus_files(corpus_dir)
    digest = hashlib.sha256()
    for path in files:
        digest.update(os.path.basename(path).encode())
        with open(path, "rb") as f:
            digest.update(f.read())
    families = OrderedDict()
    variants = Counter()
    symmetry_per_base = Counter()
    total = 0
    for name, _, labels in read_cases(files):
        lab = dict(labels)
        family = lab.get("family", "?")
        families.setdefault(family, Counter())[lab.get("oracle", "?")] += 1
        variants[lab.get("variant", "?")] += 1
        if lab.get("variant") == "symmetry":
            symmetry_per_base[base_name(name)] += 1
        total += 1
    per_base = Counter(symmetry_per_base.values())
    return {
        "schema": "tritri-corpus-manifest/1",
        "command": command,
        "seed": seed,
        "files": [os.path.basename(p) for p in files],
        "sha256": digest.hexdigest(),
        "case_count": total,
        "families": {f: dict(c) for f, c in families.items()},
        "variants": dict(variants),
        "base_cases": len(symmetry_per_base),
        "symmetry_variants_per_base": {str(k): v for k, v in sorted(per_base.items())},
    }


def write_json(path, doc):
    with _AtomicText(path) as f:
        json.dump(doc, f, indent=1, sort_keys=False)
        f.write("\n")

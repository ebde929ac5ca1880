"""Markdown tables and number formats, kept in one place so the tests can parse them back."""

import math
import re

NOT_MEASURED = "not measured in this run"


def table(header, rows, align=None):
    """A GitHub-flavoured Markdown table. Cells are str()-ed; '|' is escaped."""
    def cell(x):
        return str(x).replace("|", "\\|").replace("\n", " ")
    align = align or ["l"] + ["r"] * (len(header) - 1)
    marks = {"l": ":--", "r": "--:", "c": ":-:"}
    lines = ["| " + " | ".join(cell(h) for h in header) + " |",
             "|" + "|".join(marks[a] for a in align) + "|"]
    for r in rows:
        lines.append("| " + " | ".join(cell(x) for x in r) + " |")
    return "\n".join(lines) + "\n"


def parse_tables(text):
    """Every Markdown table in `text` as (header, rows) of stripped strings: for the tests."""
    tables, current = [], None
    for line in text.splitlines():
        s = line.strip()
        if s.startswith("|") and s.endswith("|"):
            cells = [c.strip().replace("\\|", "|") for c in _split_row(s[1:-1])]
            if current is None:
                current = (cells, [])
            elif all(set(c) <= set(":-") and c for c in cells):
                continue
            else:
                current[1].append(cells)
        else:
            if current is not None:
                tables.append(current)
            current = None
    if current is not None:
        tables.append(current)
    return tables


def _split_row(s):
    cells, cur, i = [], "", 0
    while i < len(s):
        if s[i] == "\\" and i + 1 < len(s) and s[i + 1] == "|":
            cur += "\\|"
            i += 2
            continue
        if s[i] == "|":
            cells.append(cur)
            cur = ""
        else:
            cur += s[i]
        i += 1
    cells.append(cur)
    return cells


def count(n):
    return "-" if n is None else str(int(n))


def pct(x, digits=2):
    """A rate as a percentage; tiny non-zero rates keep a significant digit."""
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "-"
    if x == 0:
        return "0"
    p = 100.0 * x
    if p < 10 ** (-digits):
        return "%.1g%%" % p
    return "%.*f%%" % (digits, p)


def sci(x):
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "-" if x is None else str(x)
    if x == 0:
        return "0"
    return "%.2g" % x


def ns(x):
    if x is None:
        return "-"
    return "%.1f" % x if x >= 10 else "%.2f" % x


def ratio(x):
    return "-" if x is None else "%.2f" % x


def anchor(heading):
    """GitHub's anchor of a heading: "5 The papers' tables" -> "5-the-papers-tables"."""
    return re.sub(r"[^a-z0-9 -]", "", heading.lower()).replace(" ", "-")

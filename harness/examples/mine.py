#!/usr/bin/env python3
"""An example tritri process plug-in in Python: the separating-axis test of mine.c.

tritri writes one case per line to standard input,
    name ax ay az bx by bz cx cy cz px py pz qx qy qz rx ry rz
and reads one answer per line from standard output,
    name overlap [relation]
with overlap 0, 1 or unsupported. Flush after every answer: tritri waits for it.

Run:  tritri check --exec 'python3 harness/examples/mine.py' --exec-name mine-py cases/builtin.cases
"""
import sys


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def separates(axis, t1, t2):
    if axis == (0, 0, 0):
        return False
    p1 = [dot(axis, v) for v in t1]
    p2 = [dot(axis, v) for v in t2]
    return max(p1) < min(p2) or max(p2) < min(p1)


def overlap(t1, t2):
    e1 = [sub(t1[(i + 1) % 3], t1[i]) for i in range(3)]
    e2 = [sub(t2[(i + 1) % 3], t2[i]) for i in range(3)]
    n1, n2 = cross(e1[0], e1[1]), cross(e2[0], e2[1])
    axes = [n1, n2] + [cross(a, b) for a in e1 for b in e2]
    axes += [cross(n1, e) for e in e1] + [cross(n2, e) for e in e2]
    return not any(separates(axis, t1, t2) for axis in axes)


for line in sys.stdin:
    words = line.split()
    name, xyz = words[0], [float(w) for w in words[1:19]]
    t1 = [tuple(xyz[3 * i:3 * i + 3]) for i in range(3)]
    t2 = [tuple(xyz[9 + 3 * i:9 + 3 * i + 3]) for i in range(3)]
    print(name, 1 if overlap(t1, t2) else 0, flush=True)

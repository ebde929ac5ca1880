#!/usr/bin/env python3
"""An example tritri process plug-in in Python: the separating-axis test of mine.c.

tritri writes cases to standard input, one a line,
    name ax ay az bx by bz cx cy cz px py pz qx qy qz rx ry rz
and reads one answer a line from standard output, in order,
    name overlap [relation]
with overlap 0, 1 or unsupported. Flush whenever all the input there is has been answered.

With TRITRI_PROTOCOL=2 in its environment it first greets: '#tritri 2 timing' says it times
itself. Then `tritri bench` may send '#time N REPETITIONS MIN_SECONDS' and N cases: it answers
them, times its own loop over them (time.perf_counter_ns, after a warm-up) and writes
'#timed NS...', the nanoseconds per pair of each repetition (harness/run/process_plugin.hpp).

Run:  tritri check --exec 'python3 harness/examples/mine.py' --exec-name mine-py cases/builtin.cases
"""
import os
import sys
import time


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


def read_case(line):
    words = line.split()
    xyz = [float(w) for w in words[1:19]]
    t1 = [tuple(xyz[3 * i:3 * i + 3]) for i in range(3)]
    t2 = [tuple(xyz[9 + 3 * i:9 + 3 * i + 3]) for i in range(3)]
    return words[0], t1, t2


def passes(pool, min_ns):
    """Whole passes over the pool until min_ns have passed: ns per pair."""
    count, start = 0, time.perf_counter_ns()
    while True:
        for _, t1, t2 in pool:
            overlap(t1, t2)
        count += 1
        elapsed = time.perf_counter_ns() - start
        if elapsed >= min_ns:
            return elapsed / (count * len(pool))


def time_pool(request):
    """'#time N REPETITIONS MIN_SECONDS': read the pool, answer it, warm up, time it."""
    _, n, repetitions, min_seconds = request.split()
    pool = [read_case(sys.stdin.readline()) for _ in range(int(n))]
    answers = [f"{name} {1 if overlap(t1, t2) else 0}" for name, t1, t2 in pool]
    min_ns = float(min_seconds) * 1e9
    passes(pool, min_ns)
    times = [passes(pool, min_ns) for _ in range(int(repetitions))]
    print("\n".join(answers))
    print("#timed", " ".join(f"{t:.6g}" for t in times), flush=True)


if int(os.environ.get("TRITRI_PROTOCOL", "1")) >= 2:
    print("#tritri 2 timing", flush=True)
for line in iter(sys.stdin.readline, ""):
    if line.startswith("#time "):
        time_pool(line)
        continue
    name, t1, t2 = read_case(line)
    print(name, 1 if overlap(t1, t2) else 0, flush=True)

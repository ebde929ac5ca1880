#!/usr/bin/env python3
"""A protocol-2 process plug-in for tests: greets '#tritri 2 degenerate timing' when
TRITRI_PROTOCOL says 2, answers 1 to cases named yes*, 0 to the rest, exits on cases named
boom*, and to '#time N R S' answers the N cases and the times 1.5, 2.5, ... (R of them)."""
import os
import sys


def answer(line):
    name = line.split()[0]
    if name.startswith("boom"):
        sys.exit(3)
    return f"{name} {1 if name.startswith('yes') else 0}"


if os.environ.get("TRITRI_PROTOCOL") == "2":
    print("#tritri 2 degenerate timing", flush=True)
for line in iter(sys.stdin.readline, ""):
    if line.startswith("#time "):
        _, n, repetitions, _ = line.split()
        print("\n".join(answer(sys.stdin.readline()) for _ in range(int(n))))
        print("#timed", " ".join(str(r + 1.5) for r in range(int(repetitions))), flush=True)
        continue
    print(answer(line), flush=True)

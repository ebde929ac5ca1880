#!/usr/bin/env python3
"""A process plug-in for tests: answers 1 for everything, dies on cases named boom*, hangs on
cases named slow*, and breaks the protocol on cases named garbled*."""
import sys
import time

for line in sys.stdin:
    name = line.split()[0]
    if name.startswith("boom"):
        sys.exit(3)
    if name.startswith("slow"):
        time.sleep(60)
    if name.startswith("garbled"):
        print("what is a triangle", flush=True)
        continue
    print(name, 1, flush=True)

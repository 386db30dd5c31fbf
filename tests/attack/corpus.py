#!/usr/bin/env python3
"""The short attack corpus (ctest `attack_corpus`, under a minute): one or more hostile inputs per
input surface of `chute` (tests/attack/inputs.py), run against the real binary with time and
memory limits (tests/attack/harness.py). Fails on any crash, hang, memory over the limit, command
executed or broken promise, and prints the table of outcomes per input class.
   corpus.py --chute build/bin/chute --source . --work /tmp/attack_corpus"""
import argparse
import concurrent.futures
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import harness  # noqa: E402
import inputs  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--chute", required=True)
    ap.add_argument("--source", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--verbose", action="store_true")
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    ctx = inputs.Context(os.path.abspath(a.chute), os.path.abspath(a.source),
                         harness.fresh_dir(os.path.abspath(a.work)))
    inputs.setup(ctx)
    asan = harness.sanitized(ctx.chute)
    table = harness.Table()
    todo = inputs.corpus(ctx)
    # Inputs that watch the marker file run alone; the others two at a time.
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        futures = [pool.submit(harness.run, i.cmd, ctx.work, i.expect, i.timeout, 4096, asan,
                               i.marker) if not i.marker else None for i in todo]
        results = [f.result() if f else None for f in futures]
    for inp, o in zip(todo, results):
        if o is None:
            o = harness.run(inp.cmd, ctx.work, inp.expect, timeout=inp.timeout, asan=asan,
                            marker=inp.marker)
        table.add(inp.cls, inp.name, o)
        if a.verbose or o.cls in harness.BAD:
            first = (o.stderr.strip().splitlines() or [""])[0][:150]
            print("%-8s %5.2fs %-40s %s %s" % (o.cls, o.seconds, inp.name[:40], first, o.why))
    print(table.markdown())
    for row in table.bad:
        print("FAIL: %s: %s: %s (%s) %s" % row)
    return 1 if table.failures() else 0


if __name__ == "__main__":
    sys.exit(main())

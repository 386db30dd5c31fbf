#!/usr/bin/env python3
"""Paired timing of two commands on a shared, noisy machine: A and B run in turn, n times each,
and each pair's ratio A/B taken, so that the machine's slow minutes touch both sides of a pair.

    python3 bench/paired.py -n 7 --a "CMD A" --b "CMD B"

Prints, for A and B, the least / median / largest wall time, CPU time (user + system of the
command and its children) and peak resident memory, and the least / median / largest of the
pairs' ratios A/B. Used by the bench scripts (import `paired`) and on its own.
"""
import argparse
import os
import shlex
import statistics
import subprocess
import time


def timed(cmd):
    """Wall s, CPU s (user + system) and peak RSS MiB of one run of cmd (a list)."""
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t0
    if os.waitstatus_to_exitcode(status) != 0:
        raise RuntimeError("%s: exit %d" % (" ".join(cmd), os.waitstatus_to_exitcode(status)))
    return wall, ru.ru_utime + ru.ru_stime, ru.ru_maxrss / 1024.0


def paired(a, b, n):
    """Runs a and b (lists) in turn n times; returns {"A": [(wall, cpu, rss)], "B": [...]}."""
    runs = {"A": [], "B": []}
    for _ in range(n):
        runs["A"].append(timed(a))
        runs["B"].append(timed(b))
    return runs


def report(runs):
    """Lines of text: each side's least / median / largest and the pairs' ratios."""
    def three(v):
        return "%10.4f %10.4f %10.4f" % (min(v), statistics.median(v), max(v))
    out = ["%-16s %10s %10s %10s" % ("", "least", "median", "largest")]
    for side in ("A", "B"):
        for k, name in enumerate(("wall s", "cpu s", "peak MiB")):
            out.append("%-16s %s" % (side + " " + name, three([r[k] for r in runs[side]])))
    for k, name in enumerate(("wall", "cpu")):
        ratios = [x[k] / y[k] for x, y in zip(runs["A"], runs["B"])]
        out.append("%-16s %s" % ("A/B " + name, three(ratios)))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("-n", type=int, default=7, help="pairs")
    ap.add_argument("--a", required=True, help="command A (one shell-quoted string)")
    ap.add_argument("--b", required=True, help="command B")
    args = ap.parse_args()
    print("\n".join(report(paired(shlex.split(args.a), shlex.split(args.b), args.n))))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""One thread against two on the generated full-scale C-9 (28 gores, D0 = 28 ft, 23 ft lines,
folded, free flight from line stretch at 65.6 ft/s, as bench/speed/run.py generates it) at given
element sizes: the run's own wall time (summary.json wall_time.total: set-up of the system and the
stepping, not the process's start or the case's reading), frames off, CHUTE_THREADS=1 and 2 in
turn, each binary in turn within a round; medians, ranges, and the pairwise ratios of a round.

    python3 bench/speed/threads.py [--sizes 0.35,0.25] [--t-end 0.1] [--rounds 3]
        [--bin build/bin/chute] [--before OTHER_CHUTE]
writes bench/results/threads_generated_c9.md and prints it.
"""
import argparse
import json
import os
import statistics
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def wall(chute, case, threads, t_end, out):
    env = dict(os.environ, CHUTE_THREADS=str(threads))
    subprocess.run([chute, "run", case, "--out", out, "--quiet", "--set", f"solver.t_end={t_end}",
                    "--set", "output.vtu.write=false"], check=True, env=env)
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    return s["wall_time"]["total"], s["steps"]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--sizes", default="0.35,0.25", help="element sizes in ft")
    ap.add_argument("--t-end", type=float, default=0.1)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "bin", "chute"))
    ap.add_argument("--before", help="a second chute binary, run in the same rounds")
    a = ap.parse_args()
    binaries = [("this build", a.bin)] + ([("before", a.before)] if a.before else [])
    work = tempfile.mkdtemp(prefix="chute_threads_")
    rows = []
    for size in [float(s) for s in a.sizes.split(",")]:
        msh, case = os.path.join(work, f"c9_{size:g}.msh"), os.path.join(work, f"c9_{size:g}.toml")
        subprocess.run([a.bin, "mesh", "parachute", "--gores", "28", "--diameter", "28",
                        "--vent-diameter", "1.4", "--line-length", "23", "--line-elements", "8",
                        "--element-size", str(size), "--payload-mass", "7.05", "--start", "folded",
                        "--units", "ft", "--t-end", "1", "--speed", "65.6168", "--out", msh,
                        "--case", case, "--quiet"], check=True)
        times = {(name, t): [] for name, _ in binaries for t in (1, 2)}
        steps = {}
        for _ in range(a.rounds):
            for name, chute in binaries:
                for t in (1, 2):
                    w, n = wall(chute, case, t, a.t_end, os.path.join(work, "out"))
                    times[(name, t)].append(w)
                    steps[name] = n
        with open(os.path.join(work, "out", "summary.json")) as f:
            equations = json.load(f)["system"]["equations"]
        for name, _ in binaries:
            one, two = times[(name, 1)], times[(name, 2)]
            rows.append({"size": size, "equations": equations, "binary": name, "steps": steps[name],
                         "one": one, "two": two,
                         "pairs": [x / y for x, y in zip(one, two)]})
    res = os.path.join(ROOT, "bench", "results", "threads_generated_c9.md")
    lines = ["# One thread against two on the generated full-scale C-9", "",
             f"Made by `bench/speed/threads.py` (t_end {a.t_end} s, {a.rounds} rounds, frames off): "
             "the run's own wall time (summary.json `wall_time.total`), `CHUTE_THREADS=1` and `2` "
             "in turn. Medians (least-largest); the ratio's median of the rounds' pairs.", "",
             "| element size ft | equations | binary | steps | one thread, s | two threads, s | "
             "one / two | pairs | two threads, wall s per simulated s |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        m1, m2 = statistics.median(r["one"]), statistics.median(r["two"])
        lines.append(
            f"| {r['size']:g} | {r['equations']} | {r['binary']} | {r['steps']} | {m1:.3f} "
            f"({min(r['one']):.3f}-{max(r['one']):.3f}) | {m2:.3f} ({min(r['two']):.3f}-"
            f"{max(r['two']):.3f}) | {statistics.median(r['pairs']):.3f} | "
            f"{', '.join(f'{p:.3f}' for p in r['pairs'])} | {m2 / a.t_end:.1f} |")
    text = "\n".join(lines) + "\n"
    with open(res, "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Two-thread assembly: wall and CPU time of the C-9 slider case (1 s of flight) with a build
before it (--before BIN) and this tree's build, runs interleaved (before, after, before, ...)
so that the shared machine's drift falls on both; medians of --runs and the paired ratios.
Both integrators: central differences and Bossak as shipped. Writes
bench/results/two_threads.md and prints it.

    python3 bench/two_threads.py --before /path/to/old/build/bin/chute [--runs 3] [--t-end 1.0]
    CHUTE_THREADS=1 python3 bench/two_threads.py ...   # the same two parts on one thread
"""
import argparse, json, os, statistics, tempfile, time

from paired import timed

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CASE = os.path.join(ROOT, "cases", "c9_slider.toml")
RESULTS = os.environ.get("CHUTE_BENCH_RESULTS", os.path.join(ROOT, "bench", "results"))
SETUPS = [("central differences", ['solver.integrator="central_difference"']),
          ("Bossak with the case's settings", ['solver.integrator="bossak"'])]


def run(chute, sets, t_end):
    with tempfile.TemporaryDirectory() as out:
        cmd = [chute, "run", CASE, "--out", out, "--quiet", "--set", f"solver.t_end={t_end}",
               "--set", "output.vtu.write=false"]
        for s in sets:
            cmd += ["--set", s]
        wall, cpu, _ = timed(cmd)
        s = json.load(open(os.path.join(out, "summary.json")))
        assert s["status"] == "completed", s["status"]
        return wall, cpu, s["steps"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--before", required=True)
    ap.add_argument("--after", default=os.path.join(ROOT, "build", "bin", "chute"))
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--t-end", type=float, default=1.0)
    a = ap.parse_args()
    started = time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())
    lines = ["| integrator | before wall (s) | after wall (s) | wall ratio | before CPU (s) | "
             "after CPU (s) | CPU ratio | steps before / after | after: wall per simulated s |",
             "|---|---|---|---|---|---|---|---|---|"]
    for name, sets in SETUPS:
        b, f = [], []
        for _ in range(a.runs):
            b.append(run(a.before, sets, a.t_end))
            f.append(run(a.after, sets, a.t_end))
        med = lambda xs: statistics.median(xs)
        wr = med([y[0] / x[0] for x, y in zip(b, f)])
        cr = med([y[1] / x[1] for x, y in zip(b, f)])
        lines.append(
            f"| {name} | {med([x[0] for x in b]):.2f} ({', '.join(f'{x[0]:.2f}' for x in b)}) | "
            f"{med([x[0] for x in f]):.2f} ({', '.join(f'{x[0]:.2f}' for x in f)}) | {wr:.2f} | "
            f"{med([x[1] for x in b]):.2f} | {med([x[1] for x in f]):.2f} | {cr:.2f} | "
            f"{b[0][2]} / {f[0][2]} | {med([x[0] for x in f]) / a.t_end:.2f} |")
    head = ["# Two-thread assembly: the C-9 slider case before and after", "",
            f"`python3 bench/two_threads.py --runs {a.runs} --t-end {a.t_end}` (started "
            f"{started}, load average {os.getloadavg()[0]:.1f} at the end; CHUTE_THREADS="
            f"{os.environ.get('CHUTE_THREADS', 'unset')}). Whole process, start included; runs "
            "interleaved before/after; medians, and the median of the paired after/before "
            f"ratios. Before: `{a.before}`; after: `{a.after}`.", ""]
    text = "\n".join(head + lines) + "\n"
    os.makedirs(RESULTS, exist_ok=True)
    open(os.path.join(RESULTS, "two_threads.md"), "w").write(text)
    print(text)


if __name__ == "__main__":
    main()

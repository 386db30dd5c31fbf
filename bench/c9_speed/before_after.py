#!/usr/bin/python3
"""The C-9 slider case, 1 s of flight as shipped (VTU frames included), before and after, in one
sitting: a build and checkout from before (--before-chute, --before-case: the case file of that
checkout, which it knows how to read) against this tree's build and case. Runs interleaved
(before, after, before, ...), medians of --runs; beside them this tree's build with the case's
implicit alternative (Bossak with the settings the case keeps). For each: wall time per simulated
second, steps, Newton iterations per step, the wall time split from summary.json (per Newton
iteration for implicit runs, per step for explicit ones), and the largest difference of the
skirt-radius history (skirt.mean) from a run of the same model at a quarter of the step (Bossak:
dt / 4; central differences: safety factor / 4).

Writes bench/results/c9_speed_before_after.md.

    nice /usr/bin/python3 bench/c9_speed/before_after.py --before-chute /path/old/build/bin/chute \
        --before-case /path/old/cases/c9_slider.toml [--runs 3]
"""
import argparse, csv, json, os, statistics, sys, tempfile, time

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from paired import timed  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
RESULTS = os.environ.get("CHUTE_BENCH_RESULTS", os.path.join(ROOT, "bench", "results"))
CASE = os.path.join(ROOT, "cases", "c9_slider.toml")


def run(chute, case, sets):
    with tempfile.TemporaryDirectory() as out:
        cmd = [chute, "run", case, "--out", out, "--quiet", "--set", "solver.t_end=1.0"]
        for s in sets:
            cmd += ["--set", s]
        wall = timed(cmd)[0]
        s = json.load(open(os.path.join(out, "summary.json")))
        rows = list(csv.DictReader(open(os.path.join(out, "probes.csv"))))
    return wall, s, {round(float(r["t"]), 4): float(r["skirt.mean"]) for r in rows}


def largest_difference(a, b):
    keys = [k for k in a if k in b and b[k] > 0]
    return max(abs(a[k] - b[k]) / b[k] for k in keys)


def split(s):
    wt, its, steps = s["wall_time"], s["newton_iterations"], s["steps"]
    per, unit = (its, "ms per Newton iteration") if its > 0 else (steps, "ms per step")
    parts = ", ".join(f"{k} {1e3 * wt[k] / per:.3f}" for k in
                      ("assembly", "factorisation", "solve", "search", "passes", "commits",
                       "stable_step", "balance", "other", "output", "total")
                      if wt.get(k, 0) > 0)
    return f"{parts} ({unit})"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--before-chute", required=True)
    ap.add_argument("--before-case", required=True)
    ap.add_argument("--after-chute", default=os.path.join(ROOT, "build", "bin", "chute"))
    ap.add_argument("--runs", type=int, default=3)
    a = ap.parse_args()
    setups = [("before (its case as shipped)", a.before_chute, a.before_case, []),
              ("after (the case as shipped)", a.after_chute, CASE, []),
              ("after, the implicit alternative", a.after_chute, CASE,
               ['solver.integrator="bossak"'])]
    started = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    walls = {name: [] for name, *_ in setups}
    last = {}
    for _ in range(a.runs):
        for name, chute, case, sets in setups:
            w, s, r = run(chute, case, sets)
            walls[name].append(w)
            last[name] = (s, r)
            print(name, f"{w:.2f} s", flush=True)
    lines = [f"`python3 bench/c9_speed/before_after.py --runs {a.runs}` ({started}, load average "
             f"{os.getloadavg()[0]:.1f} at the end): cases/c9_slider.toml, 1 s of flight with its "
             "VTU frames, whole process (start included), runs interleaved, medians. "
             f"Before: {a.before_chute} with {a.before_case}.", "",
             "| run | integrator | wall per simulated s (median; all) | steps | rejected | "
             "Newton/step | time split | largest skirt-radius difference to a quarter step |",
             "|---|---|---|---|---|---|---|---|"]
    for name, chute, case, sets in setups:
        s, r = last[name]
        integ = s["solver"]["integrator"]
        quarter = [f"solver.safety_factor={s['explicit']['safety_factor'] / 4}"] \
            if integ == "central_difference" else [f"solver.dt={s['solver']['dt'] / 4}"]
        _, sq, rq = run(chute, case, sets + quarter)
        lines.append(f"| {name} | {integ} | {statistics.median(walls[name]):.2f} "
                     f"({', '.join(f'{w:.2f}' for w in walls[name])}) | {s['steps']} | "
                     f"{s['rejected_steps']} | {s['newton_iterations_per_step']:.2f} | {split(s)} | "
                     f"{100 * largest_difference(r, rq):.2f} % ({sq['steps']} steps) |")
    b = statistics.median(walls[setups[0][0]])
    lines += ["", f"Before / after: {b / statistics.median(walls[setups[1][0]]):.1f}x less wall "
              f"time as shipped; before / the implicit alternative now: "
              f"{b / statistics.median(walls[setups[2][0]]):.1f}x."]
    text = "\n".join(lines) + "\n"
    open(os.path.join(RESULTS, "c9_speed_before_after.md"), "w").write(text)
    print(text)


if __name__ == "__main__":
    main()

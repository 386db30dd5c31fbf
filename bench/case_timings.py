#!/usr/bin/env python3
"""Run time (median of N runs), Newton iterations per step and error of the shipped cases, and a
dt sweep around the shipped step. Writes bench/results/case_timings.csv and prints a table.

    python3 bench/case_timings.py [--runs 5]
"""
import argparse, csv, json, os, statistics, subprocess, tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RESULTS = os.environ.get("CHUTE_BENCH_RESULTS", os.path.join(ROOT, "bench", "results"))
CHUTE = os.path.join(ROOT, "build", "bin", "chute")


def run(case, sets, runs):
    walls, summary = [], None
    for _ in range(runs):
        with tempfile.TemporaryDirectory() as out:
            cmd = [CHUTE, "run", os.path.join(ROOT, "cases", case + ".toml"), "--out", out, "--quiet"]
            for s in sets:
                cmd += ["--set", s]
            subprocess.run(cmd, check=True)
            summary = json.load(open(os.path.join(out, "summary.json")))
            walls.append(summary["wall_time"]["total"])
    return statistics.median(walls), summary


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=5)
    args = ap.parse_args()
    rows = []
    for case in ["pulley", "bead_1", "bead_5"]:
        for dt in [None, 1e-3, 2e-3, 5e-3, 1e-2, 2e-2]:
            sets = [] if dt is None else [f"solver.dt={dt}"]
            wall, s = run(case, sets, args.runs)
            ref = s.get("reference", {})
            rows.append({
                "case": case, "dt": s["solver"]["dt"], "shipped": dt is None,
                "status": s["status"], "wall_median_s": wall, "steps": s["steps"],
                "rejected": s["rejected_steps"], "event_retries": s["event_retries"],
                "newton_per_step": s["newton_iterations_per_step"],
                "relative_max_error": ref.get("relative_max_error", float("nan")),
            })
            r = rows[-1]
            print(f"{case:7s} dt={r['dt']:<7g}{' (shipped)' if dt is None else '          '} "
                  f"{r['status']:9s} wall {wall*1e3:8.1f} ms  steps {r['steps']:6d}  "
                  f"Newton/step {r['newton_per_step']:.2f}  events {r['event_retries']:4d}  "
                  f"error {100*r['relative_max_error']:.4f} %", flush=True)
    os.makedirs(RESULTS, exist_ok=True)
    with open(os.path.join(RESULTS, "case_timings.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()

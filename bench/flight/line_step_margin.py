#!/usr/bin/env python3
"""Suspension lines that set the explicit step (docs/explicit.md, "Lines that set the step";
EX6l): round-off ensembles of generated 15 m canopies whose lines, not the fabric, set the step.

    python3 bench/flight/line_step_margin.py [--runs 16] [--before OLD/bin/chute]

- the 15 m, 28-gore canopy of the flight matrix (payload 550 kg, inflated start, free descent,
  23 s) on a coarser mesh (element size 1.3 m, where the lines set the step), `--runs` runs, and
  again with the safety factor 0.8 for the whole run;
- the same canopy on the matrix's mesh (0.9 m) with `mass_scaling_quantile = 0.05`, which lifts
  the fabric's step to the lines', half as many runs.

Each with this build and, given --before, with another build (before EX6l). Per ensemble: runs
completed, the step, C_D0 (median, least, largest). Writes bench/results/line_step_margin.md.
Runs on one thread each, two at a time.
"""
import argparse
import concurrent.futures
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
from roundoff import damping_sets  # noqa: E402
from chute_run import run_case  # noqa: E402

CHUTE = os.path.join(ROOT, "build/bin/chute")
D15 = ["--units", "si", "--gores", "28", "--diameter", "15", "--line-length", "12.75",
       "--payload-mass", "550", "--start", "inflated", "--speed", "7.9929", "--t-end", "23",
       "--vent-diameter", "1.5"]


def one(chute, case, out, sets):
    return run_case(chute, case, out, sets, env=dict(os.environ, CHUTE_THREADS="1"))[0]


def ensemble(chute, case, work, tag, runs, sets):
    jobs = [(chute, case, os.path.join(work, "%s_k%d" % (tag, k)), sets + damping_sets(case, k))
            for k in range(runs)]
    with concurrent.futures.ThreadPoolExecutor(2) as ex:
        res = list(ex.map(lambda j: one(*j), jobs))
    done = [s for s in res if s["status"] == "completed"]
    cd = [s["flight"]["drag_coefficient"] for s in done]
    step = statistics.median(s["explicit"]["least_step"] for s in done) if done else float("nan")
    return "%d of %d | %.4g | %s" % (len(done), runs, step, "%.4f [%.4f .. %.4f]" % (
        statistics.median(cd), min(cd), max(cd)) if cd else "—")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--runs", type=int, default=16)
    ap.add_argument("--before", help="another chute binary (a build before EX6l)")
    ap.add_argument("--before-label", default="before")
    ap.add_argument("--out", default=os.path.join(ROOT, "bench/results/line_step_margin.md"))
    a = ap.parse_args()
    work = tempfile.mkdtemp(prefix="chute-lines-")
    cases = {}
    for size in ("1.3", "0.9"):
        case = os.path.join(work, "d15_%s.toml" % size)
        subprocess.run([CHUTE, "mesh", "parachute"] + D15 + ["--element-size", size, "--out",
                       os.path.join(work, "d15_%s.msh" % size), "--case", case, "--quiet"],
                       check=True, capture_output=True)
        cases[size] = case
    builds = [("this build", CHUTE)] + ([(a.before_label, a.before)] if a.before else [])
    trials = [("element size 1.3 m", cases["1.3"], a.runs, []),
              ("element size 1.3 m, safety_factor 0.8", cases["1.3"], a.runs,
               ["solver.safety_factor=0.8"]),
              ("element size 0.9 m, mass_scaling_quantile 0.05", cases["0.9"], a.runs // 2,
               ["solver.mass_scaling_quantile=0.05"]),
              ("element size 0.9 m, no mass scaling", cases["0.9"], a.runs // 2,
               ["solver.mass_scaling_quantile=0"])]
    head = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True,
                          text=True).stdout.strip()
    out = ["# Suspension lines that set the explicit step", "",
           "Made by `bench/flight/line_step_margin.py` (main at %s): the 15 m, 28-gore canopy of the "
           "flight matrix (550 kg, inflated start, free descent, 23 s), round-off ensembles "
           "(this build: the tree at the commit that adds this file) "
           "(stiffness damping times 1 + k 1e-12), one thread a run. The lines' own `L / c`: "
           "1.59 m elements, `c` = 818 m/s, 1.94 ms." % head, "",
           "| build | canopy | runs completed | step s (median) | `C_D0` median [least .. largest] |",
           "|---|---|---|---|---|"]
    for b, (label, chute) in enumerate(builds):
        for t, (name, case, runs, sets) in enumerate(trials):
            row = "| %s | %s | %s |" % (label, name,
                                        ensemble(chute, case, work, "b%d_t%d" % (b, t), runs, sets))
            out.append(row)
            print(row, flush=True)
    text = "\n".join(out) + "\n"
    with open(a.out, "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""What selective mass scaling (solver.mass_scaling_quantile, EX8) does to generated parachutes'
flight figures: every comparison is between round-off ensembles (runs that differ only by their
stiffness damping times 1 + k 1e-12, bench/roundoff.py) with and without it, on one build.

    python3 bench/flight/mass_scaling_flight.py [--quantiles 0,0.01] [--jobs 2]

- the matrix of bench/flight/flight_runs.py (six canopies, inflated start, free descent), four
  runs each: steps and steady figures;
- the 8.53 m canopy held at 20 and 40 m/s from a folded start (four runs each) and released at
  40 m/s with 50-200 kg (three runs each): opening figures;
- cases/c9_flight.toml (28 ft, 28 gores, 10 s), seven runs each;
- the generated folded full-scale C-9 at 12.4k triangles (element size 0.35 ft), 1 s from line
  stretch, four runs each: skirt radius, volume and opening force at 0.25-1.0 s; and its
  line-stretch peak force sampled every 0.5 ms against a run at half the step (safety 0.45);
- speed: 1 s of that C-9 at 12.4k and 24.5k triangles, both threads, in pairs (bench/paired.py),
  with nothing else running.

Writes bench/results/mass_scaling_flight.md. Runs on one thread each, two at a time (--jobs).
CHUTE_BIN names another chute binary (default build/bin/chute).
"""
import argparse
import concurrent.futures
import csv
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
from roundoff import damping_sets  # noqa: E402
from paired import paired  # noqa: E402
import chute_run  # noqa: E402

CHUTE = os.environ.get("CHUTE_BIN", os.path.join(ROOT, "build/bin/chute"))
ENV = dict(os.environ, CHUTE_THREADS="1", CHUTE_BIN=CHUTE)
C9_12K = ["--gores", "28", "--diameter", "28", "--vent-diameter", "1.4", "--line-length", "23",
          "--line-elements", "8", "--element-size", "0.35", "--payload-mass", "7.05", "--start",
          "folded", "--units", "ft", "--speed", "65.6168"]
TIMES = (0.25, 0.5, 0.75, 1.0)
PROBES = [("skirt.mean", "skirt radius ft"), ("canopy.volume", "volume ft³"),
          ("opening_force.magnitude", "opening force lbf")]


def span(values, digits=4):
    """median [least .. largest]"""
    f = "%%.%dg" % digits
    return "%s [%s .. %s]" % (f % statistics.median(values), f % min(values), f % max(values))


def shift(a, b):
    m = statistics.median(a)
    return "%+.2f %%" % (100.0 * (statistics.median(b) / m - 1.0)) if m else "—"


def flight_runs(what, q, work, extra):
    out = os.path.join(work, "%s_q%s" % (what, q))
    subprocess.run([sys.executable, os.path.join(HERE, "flight_runs.py"), what, "--jobs",
                    str(ARGS.jobs), "--set", "solver.mass_scaling_quantile=%s" % q, "--out", out]
                   + extra, check=True, capture_output=True, env=ENV)
    rows = {}
    with open(os.path.join(out, "flight_%s.csv" % what)) as f:
        for r in csv.DictReader(f):
            key = re.sub(r"(_h[0-9.]+)?(_k\d+)?$", "", r["tag"])
            rows.setdefault(key, []).append(r)
    return rows


def table(title, per_q, figures, out):
    qs = list(per_q)
    out.append("\n### " + title + "\n")
    out.append("| member | figure | " + " | ".join("q = %s" % q for q in qs) + " | median shift |")
    out.append("|---|---|" + "---|" * len(qs) + "---|")
    for key in sorted(per_q[qs[0]]):
        for fig in figures:
            vals = []
            for q in qs:
                rs = per_q[q].get(key, [])
                vals.append([float(r[fig]) for r in rs if r.get(fig) not in (None, "")])
            if not all(vals):
                continue
            bad = sum(1 for q in qs for r in per_q[q].get(key, []) if r["status"] != "completed")
            note = " (%d not completed)" % bad if bad else ""
            out.append("| %s%s | %s | %s | %s |" % (key, note, fig, " | ".join(span(v) for v in vals),
                                                   shift(vals[0], vals[-1])))


def run_case(case, out, sets):
    return chute_run.run_case(CHUTE, case, out, sets, env=ENV)


def parallel(jobs):
    with concurrent.futures.ThreadPoolExecutor(ARGS.jobs) as ex:
        return list(ex.map(lambda j: run_case(*j), jobs))


def at(rows, t, col):
    return float(min(rows, key=lambda r: abs(float(r["t"]) - t))[col])


def c9_flight(qs, work, out):
    case = os.path.join(ROOT, "cases/c9_flight.toml")
    figs = [("steady_descent_speed", "descent ft/s"), ("drag_coefficient", "C_D0"),
            ("projected_diameter_ratio", "D_p/D0"), ("filling_distance", "n"),
            ("peak_opening_force", "peak force lbf")]
    res = {}
    for q in qs:
        jobs = [(case, os.path.join(work, "c9f_q%s_k%d" % (q, k)),
                 ["solver.mass_scaling_quantile=%s" % q] + damping_sets(case, k)) for k in range(7)]
        res[q] = parallel(jobs)
    out.append("\n### cases/c9_flight.toml, 10 s, seven runs each\n")
    out.append("| figure | " + " | ".join("q = %s" % q for q in qs) + " | median shift |")
    out.append("|---|" + "---|" * len(qs) + "---|")
    out.append("| steps | " + " | ".join(span([s["steps"] for s, _ in res[q]], 6) for q in qs) +
               " | " + shift([s["steps"] for s, _ in res[qs[0]]], [s["steps"] for s, _ in res[qs[-1]]]) + " |")
    for key, name in figs:
        vals = [[s["flight"][key] for s, _ in res[q] if s["status"] == "completed"] for q in qs]
        out.append("| %s | %s | %s |" % (name, " | ".join(span(v) for v in vals),
                                        shift(vals[0], vals[-1])))


def c9_12k(qs, work, out):
    d = os.path.join(work, "c9_12k")
    os.makedirs(d, exist_ok=True)
    case = os.path.join(d, "c.toml")
    subprocess.run([CHUTE, "mesh", "parachute"] + C9_12K + ["--t-end", str(ARGS.t_end_12k)] +
                   ["--out", os.path.join(d, "c.msh"), "--case", case, "--quiet"], check=True,
                   capture_output=True)
    quiet_frames = ["output.vtu.interval=10"]
    res = {}
    for q in qs:
        jobs = [(case, os.path.join(d, "q%s_k%d" % (q, k)),
                 ["solver.mass_scaling_quantile=%s" % q] + quiet_frames + damping_sets(case, k))
                for k in range(4)]
        res[q] = parallel(jobs)
    s0 = res[qs[-1]][0][0]["explicit"]
    out.append("\n### Generated folded full-scale C-9, 12.4k triangles, %g s from line stretch, four runs "
               "each\n" % ARGS.t_end_12k)
    out.append("With q = %s: %d nodes given %.3g slug, %.2f %% of the canopy's %.4g slug." % (
        qs[-1], s0["scaled_nodes"], s0["added_mass_total"],
        100.0 * s0["added_mass_total"] / s0["scaled_parts_mass"]["canopy"],
        s0["scaled_parts_mass"]["canopy"]) + "\n")
    out.append("| figure | t s | " + " | ".join("q = %s" % q for q in qs) + " | median shift |")
    out.append("|---|---|" + "---|" * len(qs) + "---|")
    out.append("| steps | %g | " % ARGS.t_end_12k + " | ".join(span([s["steps"] for s, _ in res[q]], 6) for q in qs)
               + " | " + shift([s["steps"] for s, _ in res[qs[0]]], [s["steps"] for s, _ in res[qs[-1]]]) + " |")
    for col, name in PROBES:
        for t in TIMES:
            vals = [[at(rows, t, col) for _, rows in res[q]] for q in qs]
            out.append("| %s | %g | %s | %s |" % (name, t, " | ".join(span(v) for v in vals),
                                                 shift(vals[0], vals[-1])))
    # The line-stretch peak, sampled every 0.5 ms, against a run at half the step.
    fine = ["solver.t_end=0.25", "output.interval=0.0005"] + quiet_frames
    jobs = [(case, os.path.join(d, "fine_q%s" % q), fine + ["solver.mass_scaling_quantile=%s" % q])
            for q in qs]
    jobs.append((case, os.path.join(d, "fine_ref"),
                 fine + ["solver.mass_scaling_quantile=0", "solver.safety_factor=0.45"]))
    fine_res = parallel(jobs)
    out.append("\nLine-stretch peak of the opening force, probes every 0.5 ms over 0-0.25 s, one run each:\n")
    out.append("| run | step s | peak lbf | at s |")
    out.append("|---|---|---|---|")
    names = ["q = %s" % q for q in qs] + ["q = 0, safety 0.45 (half the step)"]
    for name, (s, rows) in zip(names, fine_res):
        pk = max(rows, key=lambda r: float(r["opening_force.magnitude"]))
        out.append("| %s | %.3g | %.1f | %s |" % (name, s["explicit"]["least_step"],
                                                 float(pk["opening_force.magnitude"]), pk["t"]))


def speed(qs, work, out):
    """Wall time of 1 s of the generated folded C-9 at 12.4k and 24.5k triangles, both threads,
    the last quantile against the first in pairs (bench/paired.py), alone on the machine."""
    out.append("\n### Speed: the generated folded full-scale C-9, 1 s from line stretch, two threads\n")
    out.append("Whole process (start-up and the VTU frames included), q = %s and q = %s in turn; "
               "least / median / largest, and the pairs' ratios." % (qs[-1], qs[0]) + "\n")
    out.append("| triangles | pairs | steps, q = %s | steps, q = %s | wall s, q = %s | wall s, q = %s "
               "| ratio of the pairs |" % (qs[0], qs[-1], qs[0], qs[-1]))
    out.append("|---|---|---|---|---|---|---|")
    for size, pairs in (("0.35", ARGS.pairs_12k), ("0.25", ARGS.pairs_24k)):
        d = os.path.join(work, "speed_" + size)
        os.makedirs(d, exist_ok=True)
        case = os.path.join(d, "c.toml")
        sizes = list(C9_12K)
        sizes[sizes.index("--element-size") + 1] = size
        subprocess.run([CHUTE, "mesh", "parachute"] + sizes + ["--t-end", "1", "--out",
                       os.path.join(d, "c.msh"), "--case", case, "--quiet"], check=True,
                       capture_output=True)
        cmd = lambda q: [CHUTE, "run", case, "--out", os.path.join(d, "q" + q), "--quiet", "--set",
                         "solver.mass_scaling_quantile=" + q]
        runs = paired(cmd(qs[-1]), cmd(qs[0]), pairs)
        steps, tri = {}, ""
        for q in qs:
            with open(os.path.join(d, "q" + q, "summary.json")) as f:
                steps[q] = json.load(f)["steps"]
        with open(case) as f:
            tri = re.search(r"(\d+) canopy triangles", f.read()).group(1)
        wall = lambda side: span([r[0] for r in runs[side]])
        ratio = span([a[0] / b[0] for a, b in zip(runs["A"], runs["B"])], 3)
        out.append("| %s | %d | %d | %d | %s | %s | %s |" % (tri, pairs, steps[qs[0]], steps[qs[-1]],
                                                         wall("B"), wall("A"), ratio))


def main():
    global ARGS
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quantiles", default="0,0.01")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench/results/mass_scaling_flight.md"))
    ap.add_argument("--t-end-12k", type=float, default=1.0, help="the 12.4k C-9's run, s")
    ap.add_argument("--pairs-12k", type=int, default=5)
    ap.add_argument("--pairs-24k", type=int, default=3)
    ap.add_argument("--sections", default="matrix,opening,payload,c9_flight,c9_12k,speed")
    ARGS = ap.parse_args()
    qs = ARGS.quantiles.split(",")
    work = tempfile.mkdtemp(prefix="chute-msf-")
    head = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True,
                          text=True).stdout.strip()
    out = ["# Selective mass scaling and the generated parachutes' flight figures", "",
           "Made by `bench/flight/mass_scaling_flight.py` (main at %s): round-off ensembles "
           "(stiffness damping times 1 + k 1e-12) with `solver.mass_scaling_quantile` = %s, one "
           "build, one thread a run. Each cell: median [least .. largest] over the ensemble; the "
           "shift: the last column's median against the first's." % (head, " and ".join(qs))]
    sections = ARGS.sections.split(",")
    if "matrix" in sections:
        per = {q: flight_runs("convergence", q, work, ["--runs", "4", "--size-factors", "1.00"])
               for q in qs}
        table("The matrix: inflated start, free descent, steady figures (four runs each)", per,
              ["steps", "drag_coefficient", "projected_diameter_ratio", "steady_descent_speed"], out)
    if "opening" in sections:
        per = {q: flight_runs("opening", q, work, ["--speeds", "20,40", "--ensemble", "4"])
               for q in qs}
        table("The 8.53 m canopy held from a folded start (four runs each)", per,
              ["steps", "opening_force_factor", "filling_distance", "drag_coefficient"], out)
    if "payload" in sections:
        per = {q: flight_runs("payload", q, work, ["--ensemble", "3"]) for q in qs}
        table("The 8.53 m canopy released at 40 m/s from a folded start (three runs each)", per,
              ["steps", "peak_opening_force", "filling_distance"], out)
    if "c9_flight" in sections:
        c9_flight(qs, work, out)
    if "c9_12k" in sections:
        c9_12k(qs, work, out)
    if "speed" in sections:
        speed(qs, work, out)
    text = "\n".join(out) + "\n"
    with open(ARGS.out, "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main()

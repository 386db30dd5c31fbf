#!/usr/bin/env python3
"""C-9 slider speed: wall seconds per simulated second (median of N runs), Newton iterations per
step, the wall-time split per Newton iteration (summary.json "wall_time" / "newton_iterations"),
and the skirt-radius history against a reference run of the same model at dt/4.

    python3 bench/c9_speed/run.py --reference            # once: the dt/4 reference (bench/results)
    python3 bench/c9_speed/run.py --label NAME [--chute BIN] [--case TOML] [--runs 3] [--t-end 1.0]

A binary of main needs main's case file (--case /work/main/cases/c9_slider.toml): the shipped
case now sets keys main does not know.

Appends one row per label to bench/results/c9_speed.csv and prints it. The skirt error is
max over the probe times of |r - r_ref| / r_ref for skirt.mean, skirt.min and skirt.max (the
reference is interpolated linearly in time; probe times of both runs are on the 0.005 s grid).
"""
import argparse, csv, json, os, statistics, subprocess, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
RESULTS = os.path.join(ROOT, "bench", "results")
CASE = os.path.join(ROOT, "cases", "c9_slider.toml")
REF = os.path.join(RESULTS, "c9_speed_reference_probes.csv")
COLS = ["skirt.mean", "skirt.min", "skirt.max"]


def run(chute, sets, out, case=CASE):
    cmd = ["nice", chute, "run", case, "--out", out, "--quiet"]
    for s in sets:
        cmd += ["--set", s]
    t0 = time.monotonic()
    subprocess.run(cmd, check=True)
    wall = time.monotonic() - t0
    return wall, json.load(open(os.path.join(out, "summary.json")))


def read_probes(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return [float(r["t"]) for r in rows], {c: [float(r[c]) for r in rows] for c in COLS}


def interp(ts, ys, t):
    if t <= ts[0]:
        return ys[0]
    for i in range(1, len(ts)):
        if t <= ts[i]:
            w = (t - ts[i - 1]) / (ts[i] - ts[i - 1])
            return (1 - w) * ys[i - 1] + w * ys[i]
    return ys[-1]


def skirt_error(probes):
    rt, rv = read_probes(REF)
    t, v = read_probes(probes)
    worst = 0.0
    for c in COLS:
        for ti, yi in zip(t, v[c]):
            if ti > rt[-1] + 1e-12:
                continue
            r = interp(rt, rv[c], ti)
            worst = max(worst, abs(yi - r) / abs(r))
    return worst


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--chute", default=os.path.join(ROOT, "build", "bin", "chute"))
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--t-end", type=float, default=1.0)
    ap.add_argument("--label", default="run")
    ap.add_argument("--case", default=CASE)
    ap.add_argument("--set", action="append", default=[], help="extra --set KEY=VALUE")
    ap.add_argument("--reference", action="store_true")
    args = ap.parse_args()
    sets = [f"solver.t_end={args.t_end}"] + args.set
    if args.reference:
        with tempfile.TemporaryDirectory() as out:
            wall, s = run(args.chute, sets + ["solver.dt=0.0005"], out, args.case)
            assert s["status"] == "completed", s["status"]
            os.replace(os.path.join(out, "probes.csv"), REF)
        print(f"reference: dt/4 = 0.0005, {s['steps']} steps, {wall:.1f} s wall -> {REF}")
        return
    walls, err = [], None
    for i in range(args.runs):
        with tempfile.TemporaryDirectory() as out:
            wall, s = run(args.chute, sets, out, args.case)
            assert s["status"] == "completed", s["status"]
            walls.append(wall)
            if err is None:
                err = skirt_error(os.path.join(out, "probes.csv"))
                summary = s
    sim = summary["final_time"]
    its = summary["newton_iterations"]
    wt = summary["wall_time"]
    # c9_speed.csv's "other" keeps its meaning: what wall_time now splits further (the passes,
    # commits, stable-step estimate and energy balance) is added back.
    wt = dict(wt)
    wt["other"] += sum(wt.get(k, 0.0) for k in ("passes", "commits", "stable_step", "balance"))
    per_it = {k: 1e3 * wt[k] / its for k in ["assembly", "factorisation", "solve", "search", "other", "total"]}
    row = {
        "label": args.label,
        "t_end": sim,
        "runs": args.runs,
        "wall_median_s": round(statistics.median(walls), 2),
        "wall_all_s": " ".join(f"{w:.2f}" for w in walls),
        "wall_per_sim_s": round(statistics.median(walls) / sim, 2),
        "steps": summary["steps"],
        "rejected": summary["rejected_steps"],
        "newton_per_step": round(summary["newton_iterations_per_step"], 3),
        "factorisations": summary["counts"]["factorisations"],
        "assemblies": summary["counts"]["assemblies"],
        "linear_solver": summary["system"]["linear_solver"],
        **{f"ms_per_it_{k}": round(v, 3) for k, v in per_it.items()},
        "skirt_max_rel_err_vs_dt4": f"{err:.3e}",
        "extra_sets": " ".join(args.set),
    }
    path = os.path.join(RESULTS, "c9_speed.csv")
    new = not os.path.exists(path)
    with open(path, "a", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(row))
        if new:
            w.writeheader()
        w.writerow(row)
    for k, v in row.items():
        print(f"{k:28s} {v}")


if __name__ == "__main__":
    main()

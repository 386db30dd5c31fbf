#!/usr/bin/env python3
"""Robustness matrix of generated parachutes: each member is made by `chute mesh parachute
... --case` and flown by `chute run` with the generated case unchanged (only t_end set), one
after the other. Writes results.csv and results.md (steps, rejected, Newton/step, wall per
simulated second, peak memory, final skirt radius / D) beside this script, or under --out.

    nice python3 bench/parachutes/run_matrix.py                 # the full matrix, 2 s each
    python3 bench/parachutes/run_matrix.py --only p16_ft --t-end 0.2
    python3 bench/parachutes/run_matrix.py --chute /path/to/chute --results-dir /tmp/m

Re-run it after solver changes: the members and their options are the table MEMBERS below.
"""
import argparse
import concurrent.futures
import csv
import json
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

# name, units, gores, D, vent / D, slider side / D (0: none), start, payload ("point" or "box").
# Nominal diameters 1.5 m to 30 m (5 ft to 98 ft); element size D / 16, lines 0.85 D (the C-9's
# 23 / 28), a box payload 0.1 D x 0.1 D x 0.08 D on risers of 0.15 D.
MEMBERS = [
    ("g8_1.5m_flat", "si", 8, 1.5, 0.0, 0.0, "flat", "point"),
    ("g12_1.5m_vent_slider_folded", "si", 12, 1.5, 0.1, 0.1, "folded", "point"),
    ("g8_3m_slider_inflated_box", "si", 8, 3.0, 0.0, 0.1, "inflated", "box"),
    ("g12_5ft_slider_inflated", "ft", 12, 5.0, 0.0, 0.1, "inflated", "point"),
    ("p16_ft", "ft", 16, 10.0, 0.0, 0.1, "folded", "point"),
    ("g16_10ft_vent_inflated", "ft", 16, 10.0, 0.1, 0.0, "inflated", "point"),
    ("g20_16ft_folded_box", "ft", 20, 16.0, 0.0, 0.0, "folded", "box"),
    ("g24_20ft_vent_slider_flat", "ft", 24, 20.0, 0.1, 0.1, "flat", "point"),
    ("c9_28ft_vent_slider_folded", "ft", 28, 28.0, 0.1, 0.1, "folded", "point"),
    ("g28_28ft_inflated_box", "ft", 28, 28.0, 0.0, 0.0, "inflated", "box"),
    ("g32_10m_vent_slider_folded_box", "si", 32, 10.0, 0.1, 0.1, "folded", "box"),
    ("g32_20m_folded", "si", 32, 20.0, 0.0, 0.0, "folded", "point"),
    ("g24_30m_vent_slider_inflated", "si", 24, 30.0, 0.1, 0.1, "inflated", "point"),
    ("g32_30m_slider_flat_box", "si", 32, 30.0, 0.0, 0.1, "flat", "box"),
]


def mesh_args(member):
    name, units, gores, d, vent, slider, start, payload = member
    args = ["--gores", gores, "--diameter", d, "--line-length", 0.85 * d,
            "--element-size", d / 16, "--start", start, "--units", units,
            "--payload-mass", 1.0]
    if vent > 0:
        args += ["--vent-diameter", vent * d]
    if slider > 0:
        args += ["--slider", slider * d]
    if payload == "box":
        args += ["--payload-box", f"{0.1 * d:g},{0.1 * d:g},{0.08 * d:g}",
                 "--riser-length", 0.15 * d]
    return [str(a) if not isinstance(a, float) else f"{a:g}" for a in args]


def peak_mib(stderr):
    m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", stderr)
    return int(m.group(1)) / 1024 if m else float("nan")


def cpu_seconds(stderr):
    """User + system time of the run (/usr/bin/time -v): on a shared machine, the figure that
    load does not inflate as much as wall time."""
    t = [float(x) for x in re.findall(r"(?:User|System) time \(seconds\): ([\d.]+)", stderr)]
    return sum(t) if t else float("nan")


def run_member(chute, member, t_end, work, sets=()):
    name, d = member[0], member[3]
    folder = os.path.join(work, name)
    os.makedirs(folder, exist_ok=True)
    msh, case = os.path.join(folder, name + ".msh"), os.path.join(folder, name + ".toml")
    mesh = subprocess.run([chute, "mesh", "parachute", *mesh_args(member), "--out", msh,
                           "--case", case], capture_output=True, text=True)
    if mesh.returncode != 0:
        return {"name": name, "status": "mesh failed: " + mesh.stderr.strip()}
    triangles = int(re.search(r"(\d+) canopy triangles", mesh.stdout).group(1))
    out = os.path.join(folder, "out")
    t0 = time.time()
    extra = [x for s in sets for x in ("--set", s)]
    run = subprocess.run(["/usr/bin/time", "-v", chute, "run", case, "--out", out, "--set",
                          f"solver.t_end={t_end}", *extra], capture_output=True, text=True)
    wall = time.time() - t0
    row = {"name": name, "units": member[1], "gores": member[2], "D": d, "vent": member[4],
           "slider": member[5], "start": member[6], "payload": member[7],
           "triangles": triangles, "exit": run.returncode, "peak_MiB": peak_mib(run.stderr),
           "cpu": cpu_seconds(run.stderr)}
    try:
        s = json.load(open(os.path.join(out, "summary.json")))
    except (OSError, ValueError):
        row["status"] = "no summary"
        return row
    row.update(status=s["status"], final_time=s["final_time"], steps=s["steps"],
               rejected=s["rejected_steps"], newton_per_step=s["newton_iterations_per_step"],
               equations=s["system"]["equations"], wall=wall,
               wall_per_s=s["wall_time"]["total"] / max(s["final_time"], 1e-12),
               cpu_per_s=row["cpu"] / max(s["final_time"], 1e-12))
    with open(os.path.join(out, "probes.csv")) as f:
        rows = list(csv.DictReader(f))
    r0, r1 = float(rows[0]["skirt.mean"]), float(rows[-1]["skirt.mean"])
    row.update(skirt0_D=r0 / d, skirt_D=r1 / d,
               skirt_max_D=max(float(r["skirt.mean"]) for r in rows) / d)
    return row


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--chute", default=os.path.join(ROOT, "build", "bin", "chute"))
    ap.add_argument("--set", action="append", default=[],
                    help="KEY=VALUE for every member's run (e.g. solver.integrator=...)")
    ap.add_argument("--t-end", type=float, default=2.0)
    ap.add_argument("--only", nargs="*", help="member names")
    ap.add_argument("--work", default=os.path.join(ROOT, "out", "parachute_matrix"))
    ap.add_argument("--results-dir", default=HERE)
    ap.add_argument("--jobs", type=int, default=1, help="members run at once (wall times then "
                    "share the machine: compare the CPU column)")
    a = ap.parse_args()
    members = [m for m in MEMBERS if not a.only or m[0] in a.only]
    def one(m):
        r = run_member(a.chute, m, a.t_end, a.work, a.set)
        print(json.dumps(r), flush=True)
        return r

    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
        rows = list(pool.map(one, members))
    cols = ["name", "units", "gores", "D", "vent", "slider", "start", "payload", "triangles",
            "equations", "status", "exit", "final_time", "steps", "rejected", "newton_per_step",
            "wall", "wall_per_s", "cpu", "cpu_per_s", "peak_MiB", "skirt0_D", "skirt_D", "skirt_max_D"]
    os.makedirs(a.results_dir, exist_ok=True)
    with open(os.path.join(a.results_dir, "results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=cols, extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)
    unit = {"si": "m", "ft": "ft"}

    def g(r, k, fmt):
        return fmt.format(r[k]) if k in r else "-"

    with open(os.path.join(a.results_dir, "results.md"), "w") as f:
        f.write("# Generated-parachute matrix\n\n")
        changed = f" but for {', '.join(a.set)}" if a.set else ""
        f.write(f"Generated parachutes flown {a.t_end:g} s with the generated case unchanged{changed} "
                f"(`{' '.join(['python3', 'bench/parachutes/run_matrix.py'] + sys.argv[1:])}`); "
                "vent and slider as fractions of D; skirt radius (mean distance of the skirt "
                "nodes from the axis) over D at the start and the end.\n\n")
        f.write("| member | gores | D | vent | slider | start | payload | triangles | "
                "equations | status | steps | rejected | Newton/step | wall (CPU) per simulated s | "
                "peak memory | skirt r/D start → end (max) |\n")
        f.write("|" + "---|" * 16 + "\n")
        for r in rows:
            f.write(f"| {r['name']} | {r.get('gores', '-')} | {r.get('D', '-')} "
                    f"{unit.get(r.get('units'), '')} | {r.get('vent', '-')} | "
                    f"{r.get('slider', '-')} | {r.get('start', '-')} | {r.get('payload', '-')} | "
                    f"{r.get('triangles', '-')} | {r.get('equations', '-')} | "
                    f"{r['status']} at {g(r, 'final_time', '{:g}')} s | {g(r, 'steps', '{}')} | "
                    f"{g(r, 'rejected', '{}')} | {g(r, 'newton_per_step', '{:.2f}')} | "
                    f"{g(r, 'wall_per_s', '{:.0f}')} ({g(r, 'cpu_per_s', '{:.0f}')}) s | {g(r, 'peak_MiB', '{:.0f}')} MiB | "
                    f"{g(r, 'skirt0_D', '{:.3f}')} → {g(r, 'skirt_D', '{:.3f}')} "
                    f"({g(r, 'skirt_max_D', '{:.3f}')}) |\n")
    bad = [r["name"] for r in rows if r.get("status") != "completed"]
    print("all completed" if not bad else "not completed: " + ", ".join(bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())

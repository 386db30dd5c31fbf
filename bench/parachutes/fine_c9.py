#!/usr/bin/env python3
"""The fine full-scale C-9: 28 ft, 28 gores, vent 2.8 ft, lines of 23 ft (twice the paper's
half-scale model), slider 2.8 ft, folded start, canopy element size 0.25 ft (about 24,000
triangles), made by `chute mesh parachute --case` and flown with the generated case unchanged
but for t_end. Measures wall and CPU time per simulated second, peak memory (/usr/bin/time -v),
equations and Newton iterations per step; appends a row to fine_c9.csv beside this script.

    nice python3 bench/parachutes/fine_c9.py                    # 0.2 s of flight
    nice python3 bench/parachutes/fine_c9.py --integrator central_difference --t-end 0.5
    python3 bench/parachutes/fine_c9.py --t-end 0.05 --element-size 0.5

An interrupted run (SIGINT to chute) still writes summary.json (status "interrupted"): its
figures are those of the flight so far.
"""
import argparse
import csv
import json
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--chute", default=os.path.join(ROOT, "build", "bin", "chute"))
    ap.add_argument("--t-end", type=float, default=0.2)
    ap.add_argument("--element-size", type=float, default=0.25)
    ap.add_argument("--work", default=os.path.join(ROOT, "out", "c9_full_fine"))
    ap.add_argument("--integrator", default="bossak",
                    help="the generated case's (bossak) or central_difference")
    ap.add_argument("--safety", type=float, default=0.9,
                    help="central_difference's solver.safety_factor")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    msh, case = os.path.join(a.work, "c9_full_fine.msh"), os.path.join(a.work, "c9_full_fine.toml")
    mesh_cmd = [a.chute, "mesh", "parachute", "--gores", "28", "--diameter", "28",
                "--vent-diameter", "2.8", "--line-length", "23", "--line-elements", "16",
                "--element-size", str(a.element_size), "--slider", "2.8", "--payload-mass", "6.2",
                "--start", "folded", "--bundle-radius", "1.4", "--out", msh, "--case", case]
    m = subprocess.run(mesh_cmd, capture_output=True, text=True, check=True)
    print(m.stdout, end="")
    triangles = int(re.search(r"(\d+) canopy triangles", m.stdout).group(1))
    out = os.path.join(a.work, "out")
    t0 = time.time()
    sets = ["--set", f"solver.t_end={a.t_end}"]
    if a.integrator != "bossak":
        sets += ["--set", f'solver.integrator="{a.integrator}"',
                 "--set", f"solver.safety_factor={a.safety}"]
    r = subprocess.run(["/usr/bin/time", "-v", a.chute, "run", case, "--out", out] + sets,
                       capture_output=True, text=True)
    wall = time.time() - t0
    rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", r.stderr).group(1))
    cpu = sum(float(x) for x in re.findall(r"(?:User|System) time \(seconds\): ([\d.]+)",
                                            r.stderr))
    s = json.load(open(os.path.join(out, "summary.json")))
    T = max(s["final_time"], 1e-12)
    probes = list(csv.DictReader(open(os.path.join(out, "probes.csv"))))
    row = {"element_size": a.element_size, "triangles": triangles,
           "integrator": a.integrator,
           "safety": a.safety if a.integrator != "bossak" else "",
           "equations": s["system"]["equations"], "non_zeros": s["system"]["nonzeros"],
           "linear_solver": s["system"]["linear_solver"], "status": s["status"],
           "final_time": s["final_time"], "steps": s["steps"], "rejected": s["rejected_steps"],
           "newton_per_step": round(s["newton_iterations_per_step"], 3),
           "wall_s": round(wall, 1), "cpu_s": round(cpu, 1),
           "wall_per_sim_s": round(s["wall_time"]["total"] / T, 1),
           "cpu_per_sim_s": round(cpu / T, 1), "peak_MiB": round(rss / 1024, 1),
           "skirt_mean_end": round(float(probes[-1]["skirt.mean"]), 4) if probes else "",
           "factorisation_share": round(s["wall_time"]["factorisation"] /
                                        s["wall_time"]["total"], 3),
           "assembly_share": round(s["wall_time"]["assembly"] / s["wall_time"]["total"], 3),
           "load_average": os.getloadavg()[0]}
    print(json.dumps(row))
    path = os.path.join(HERE, "fine_c9.csv")
    rows = list(csv.DictReader(open(path))) if os.path.exists(path) else []
    for r in rows:  # rows from before --integrator were the generated case's Bossak runs
        r["integrator"] = r.get("integrator") or "bossak"
    fields = list(row) + [k for r in rows for k in r if k not in row]
    with open(path, "w", newline="") as f:  # rewritten: earlier rows keep their columns
        w = csv.DictWriter(f, fieldnames=list(dict.fromkeys(fields)), restval="")
        w.writeheader()
        w.writerows(rows + [row])
    return 0 if s["status"] == "completed" else 1


if __name__ == "__main__":
    sys.exit(main())

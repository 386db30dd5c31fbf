#!/usr/bin/env python3
"""Generates solid flat circular parachutes with `chute mesh parachute`, flies them with the
airflow's loads (docs/flight.md) and collects the flight figures of their summary.json.

    bench/flight/flight_runs.py matrix      # steady descent of the matrix (free, inflated start)
    bench/flight/flight_runs.py opening     # held in a 20-40 m/s wind from a folded start
    bench/flight/flight_runs.py payload     # released at 40 m/s with payloads of 50-200 kg
    bench/flight/flight_runs.py porosity    # C_D0 against the cloth's permeability
    bench/flight/flight_runs.py calibrate   # the base pressure coefficient on one canopy
    bench/flight/flight_runs.py convergence # the matrix on two meshes, ensembles of round-off runs

Each writes bench/results/flight_<what>.csv and .md (or --out). Runs go in parallel (--jobs);
CHUTE_BIN names another chute binary (default build/bin/chute).
"""
import argparse
import concurrent.futures
import csv
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from roundoff import damping_sets  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CHUTE = os.environ.get("CHUTE_BIN", os.path.join(ROOT, "build/bin/chute"))
G = 9.80665

# The matrix (SI): D0, gores, vent diameter, line length, payload (kg), element size. Payloads
# give 4-9 m/s with C_D0 ~ 0.78; lines ~0.85 D0 (the C-9's 23 ft on 28 ft: 0.82).
MATRIX = [
    dict(name="d1.5_g12", D=1.5, gores=12, vent=0.0, lines=1.3, payload=2.2, size=0.09),
    dict(name="d3_g16_vent", D=3.0, gores=16, vent=0.3, lines=2.55, payload=17.0, size=0.18),
    dict(name="d5_g20", D=5.0, gores=20, vent=0.0, lines=4.25, payload=34.0, size=0.3),
    dict(name="c9_d8.53_g28", D=8.5344, gores=28, vent=0.4267, lines=7.01, payload=103.0,
         size=0.43),
    dict(name="d15_g28_vent", D=15.0, gores=28, vent=1.5, lines=12.75, payload=550.0, size=0.9),
    dict(name="d30_g32_vent", D=30.0, gores=32, vent=3.0, lines=25.5, payload=2770.0, size=1.8),
]
CALIBRATION = "d5_g20"  # the one member the base pressure is fitted on


def descent_speed(m, payload):
    """The release speed: the steady descent speed with C_D0 ~ 0.78 at sea level."""
    return math.sqrt(2 * payload * G / (1.225 * 0.78 * math.pi * m["D"] ** 2 / 4))


def matrix_t_end(m):
    """The matrix's run length: four diameters' fall at the descent speed, and 4 s, 6 s least."""
    return max(6.0, 4.0 * m["D"] / descent_speed(m, m["payload"]) + 4.0)


def generate_and_run(tag, m, workdir, start="inflated", speed=None, held=False, t_end=6.0,
                     size_factor=1.0, sets=(), permeability=None, payload=None, perturb=0):
    d = os.path.join(workdir, tag)
    os.makedirs(d, exist_ok=True)
    msh, case = os.path.join(d, "p.msh"), os.path.join(d, "p.toml")
    pay = m["payload"] if payload is None else payload
    V = speed if speed is not None else descent_speed(m, pay)
    cmd = [CHUTE, "mesh", "parachute", "--units", "si", "--gores", str(m["gores"]), "--diameter",
           str(m["D"]), "--line-length", str(m["lines"]), "--element-size",
           str(m["size"] * size_factor), "--payload-mass", str(pay), "--start", start,
           "--speed", "%.4f" % V, "--t-end", str(t_end), "--out", msh, "--case", case, "--quiet"]
    if m["vent"] > 0:
        cmd += ["--vent-diameter", str(m["vent"])]
    if held:
        cmd += ["--held"]
    if permeability is not None:
        cmd += ["--cloth-permeability", str(permeability)]
    subprocess.run(cmd, check=True, capture_output=True)
    out = os.path.join(d, "out")
    run = [CHUTE, "run", case, "--out", out, "--quiet"]
    for s in sets:
        run += ["--set", s]
    for s in damping_sets(case, perturb):  # round-off only (bench/roundoff.py)
        run += ["--set", s]
    t0 = time.time()
    p = subprocess.run(run, capture_output=True, text=True)
    wall = time.time() - t0
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    fl = s.get("flight", {})
    return dict(tag=tag, status=s["status"], exit=p.returncode, wall=round(wall, 1), t_end=t_end,
                steps=s["steps"], triangles=None, speed=V, payload=pay, **fl)


def table(rows, keys, path_md, title, notes=""):
    with open(path_md, "w") as f:
        f.write("# " + title + "\n\n" + notes + "\n\n")
        f.write("| " + " | ".join(keys) + " |\n|" + "---|" * len(keys) + "\n")
        for r in rows:
            f.write("| " + " | ".join(fmt(r.get(k)) for k in keys) + " |\n")
    print(open(path_md).read())


def fmt(v):
    if isinstance(v, float):
        return "%.4g" % v
    return str(v)


def write_csv(rows, path):
    keys = sorted({k for r in rows for k in r})
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)


FIGURES = [("drag_coefficient", "C_D0"), ("projected_diameter_ratio", "D_p/D0"),
           ("steady_descent_speed", "descent m/s")]


def convergence_table(rows, a, base):
    write_csv(rows, base + ".csv")
    ok = [r for r in rows if r.get("status") == "completed"]
    levels = sorted({float(r["tag"].rsplit("_h", 1)[1].split("_k")[0]) for r in ok}, reverse=True)
    with open(base + ".md", "w") as f:
        f.write("# Flight figures: mesh convergence of ensemble means\n\n")
        f.write("Made by bench/flight/flight_runs.py convergence (%s). Each canopy of the matrix "
                "on its mesh (h 1.00) and on elements %s of it; on each, runs that differ by "
                "round-off only (stiffness damping times 1 + k 1e-12, k = 0, 1, ...), %g times the "
                "matrix's run length; steady figures over the last fifth of each run. Per mesh: "
                "the ensemble's mean (least .. largest, runs); `finest pair`: the finest mesh's "
                "mean against the next coarser one's. Runs not completed: %d.\n\n"
                % (" ".join(sys.argv[2:]), ", ".join("%.2f" % h for h in levels[1:]), a.t_factor,
                   len(rows) - len(ok)))
        head = ["canopy", "figure"] + ["h %.2f" % h for h in levels] + ["finest pair"]
        f.write("| " + " | ".join(head) + " |\n|" + "---|" * len(head) + "\n")
        for m in MATRIX:
            ens = {h: [r for r in ok if r["tag"].startswith("%s_h%.2f_k" % (m["name"], h))]
                   for h in levels}
            have = [h for h in levels if ens[h]]
            if len(have) < 2:
                continue
            for key, name in FIGURES:
                cells, means = [m["name"], name], {}
                for h in levels:
                    vals = [float(r[key]) for r in ens[h]]  # runs' floats or CSV text
                    if not vals:
                        cells.append("")
                        continue
                    means[h] = statistics.mean(vals)
                    cells.append("%.4g (%.4g .. %.4g, %d)" % (means[h], min(vals), max(vals),
                                                             len(vals)))
                fine, coarse = have[-1], have[-2]
                cells.append("%+.2f %%" % (100.0 * (means[fine] / means[coarse] - 1.0)))
                f.write("| " + " | ".join(cells) + " |\n")
    print(open(base + ".md").read())


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("what", choices=["matrix", "opening", "payload", "porosity", "calibrate",
                                     "convergence"])
    ap.add_argument("--runs", type=int, default=6, help="convergence: runs per canopy and mesh")
    ap.add_argument("--t-factor", type=float, default=2.0,
                    help="convergence: the matrix's run length times this")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench/results"))
    ap.add_argument("--set", action="append", default=[], help="passed to every chute run")
    ap.add_argument("--only", default="")
    ap.add_argument("--t-end", type=float, default=None)
    ap.add_argument("--size-factors", default="1.0")
    ap.add_argument("--cb", default="-0.6,-0.7,-0.8,-0.9")
    ap.add_argument("--speeds", default="20,30,40", help="opening: the winds, m/s")
    ap.add_argument("--ensemble", type=int, default=1,
                    help="opening, payload: runs per speed or payload that differ by round-off "
                         "only (k = 0, 1, ...)")
    ap.add_argument("--from-csv", default="",
                    help="convergence: no runs; the table from these comma-separated CSV files "
                         "of earlier convergence runs (e.g. a finer mesh run apart)")
    a = ap.parse_args()
    if a.what == "convergence" and a.from_csv:
        rows = []
        for path in a.from_csv.split(","):
            with open(path) as f:
                rows += list(csv.DictReader(f))
        os.makedirs(a.out, exist_ok=True)
        convergence_table(rows, a, os.path.join(a.out, "flight_convergence"))
        return
    work = tempfile.mkdtemp(prefix="chute-flight-")
    jobs = []
    members = [m for m in MATRIX if a.only in m["name"]]
    if a.what == "matrix":
        for m in members:
            for sf in [float(x) for x in a.size_factors.split(",")]:
                te = a.t_end or matrix_t_end(m)
                jobs.append(("%s_h%.2f" % (m["name"], sf), m, dict(t_end=te, size_factor=sf,
                                                                    sets=a.set)))
    elif a.what == "convergence":
        # Each canopy on its matrix mesh and on elements 0.7 of it, each an ensemble of runs that
        # differ by round-off only, run longer than the matrix's so that the steady window (the
        # last fifth) holds more of the canopy's breathing.
        levels = [float(x) for x in a.size_factors.split(",")] if a.size_factors != "1.0" \
            else [1.0, 0.7]
        for m in members:
            for sf in levels:
                te = a.t_end or a.t_factor * matrix_t_end(m)
                for k in range(a.runs):
                    jobs.append(("%s_h%.2f_k%d" % (m["name"], sf, k), m,
                                 dict(t_end=te, size_factor=sf, sets=a.set, perturb=k)))
    elif a.what == "calibrate":
        m = next(x for x in MATRIX if x["name"] == CALIBRATION)
        for cb in a.cb.split(","):
            jobs.append(("cb%s" % cb, m, dict(t_end=a.t_end or 8.0, sets=a.set + [
                "loads.canopy_flow.0.base_pressure=%s" % cb])))
    elif a.what == "opening":
        m = next(x for x in MATRIX if x["name"].startswith("c9"))
        for V in [float(x) for x in a.speeds.split(",")]:
            for k in range(a.ensemble):  # k > 0: round-off only (bench/roundoff.py)
                jobs.append(("held_%g" % V + ("_k%d" % k if a.ensemble > 1 else ""), m,
                             dict(start="folded", speed=V, held=True,
                                  t_end=a.t_end or 4.0 * 20.0 / V + 2.0, sets=a.set, perturb=k)))
    elif a.what == "payload":
        m = next(x for x in MATRIX if x["name"].startswith("c9"))
        for pay in (50.0, 100.0, 150.0, 200.0):
            for k in range(a.ensemble):  # k > 0: round-off only (bench/roundoff.py)
                jobs.append(("payload_%g" % pay + ("_k%d" % k if a.ensemble > 1 else ""), m,
                             dict(start="folded", speed=40.0, payload=pay,
                                  t_end=a.t_end or 6.0, sets=a.set, perturb=k)))
    elif a.what == "porosity":
        m = next(x for x in MATRIX if x["name"].startswith("c9"))
        for cfm in (0.0, 30.0, 100.0, 200.0, 300.0):
            jobs.append(("cfm_%g" % cfm, m, dict(permeability=cfm, t_end=a.t_end or 8.0,
                                                 sets=a.set)))
    rows = []
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as ex:
        futs = {ex.submit(generate_and_run, tag, m, work, **kw): tag for tag, m, kw in jobs}
        for fu in concurrent.futures.as_completed(futs):
            try:
                r = fu.result()
            except Exception as e:  # noqa
                r = dict(tag=futs[fu], status="error: %s" % e)
            rows.append(r)
            print(json.dumps(r), flush=True)
    rows.sort(key=lambda r: r["tag"])
    os.makedirs(a.out, exist_ok=True)
    if a.what == "convergence":
        convergence_table(rows, a, os.path.join(a.out, "flight_convergence"))
        return
    base = os.path.join(a.out, "flight_" + a.what)
    write_csv(rows, base + ".csv")
    keys = ["tag", "status", "speed", "payload", "steady_descent_speed", "drag_coefficient",
            "projected_diameter_ratio", "opening_force_factor", "peak_opening_force",
            "filling_time", "filling_distance", "largest_swing", "steady_force_variation", "wall"]
    table(rows, keys, base + ".md", "Flight figures: " + a.what,
          "Made by bench/flight/flight_runs.py %s (%s)." % (a.what, " ".join(sys.argv[2:])))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Payload re-orientation (Zhou, Accorsi & Leonard 2004, section 4.2; issue 6): runs both models,
renders the Fig. 14 snapshots and draws Figs. 15-16, and prints the rotation of the payload.

  python3 cases/c9_payload_figures.py            # runs, snapshots, plots into out/c9_payload/
  python3 cases/c9_payload_figures.py --no-run   # figures from existing runs
  python3 cases/c9_payload_figures.py --remesh   # remake cases/c9_payload.msh first

Models: cases/c9_payload_reorientation.toml (full C-9, free confluence) and
cases/payload_fixed_slider.toml (payload and cables only, slider point fixed). Standard library
only; the pictures are made by `chute render` and `chute plot`.

Output (out/c9_payload/ unless --out):
  fig14/                       side views at 0.7, 0.8, 0.9, 1.5 s, full model beside the fixed one
  fig15_horizontal.png         horizontal displacement of payload corner bot_p relative to the
                               confluence (slider point), both models
  fig16_vertical.png           the same, vertical
  rotation.png, rotation.csv   angle of the box's long edge to the vertical
  payload_figures.json         the figures: rotation table, extremes, steps, wall time
"""
import argparse
import csv
import json
import math
import os
import resource
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CHUTE = os.path.join(ROOT, "build", "bin", "chute")
MODELS = [("c9_payload_reorientation", "full C-9"), ("payload_fixed_slider", "fixed slider")]
SNAPSHOTS = [0.7, 0.8, 0.9, 1.5]
TABLE_TIMES = [0.0, 0.25, 0.5, 0.7, 0.8, 0.9, 1.0, 1.25, 1.5, 1.75, 2.0]
MESH_ARGS = ["mesh", "parachute", "--gores", "28", "--diameter", "28", "--vent-diameter", "2.8",
             "--line-length", "23", "--line-elements", "8", "--element-size", "1.2",
             "--start", "inflated", "--out", os.path.join(ROOT, "cases", "c9_payload.msh")]


def run(args):
    print("+", " ".join(args), flush=True)
    subprocess.run(args, check=True)


def read_probes(run_dir):
    with open(os.path.join(run_dir, "probes.csv")) as f:
        rows = list(csv.DictReader(f))
    return [{k: float(v) for k, v in r.items()} for r in rows]


def relative_corner(rows):
    """Corner bot_p relative to the confluence, minus its start value: (t, horizontal, vertical).
    Horizontal is the displacement in the plane of the swing (x), vertical is z."""
    r0 = rows[0]
    dx0 = r0["corner.x"] - r0["confluence.x"]
    dz0 = r0["corner.z"] - r0["confluence.z"]
    out = []
    for r in rows:
        out.append((r["t"], r["corner.x"] - r["confluence.x"] - dx0,
                    r["corner.z"] - r["confluence.z"] - dz0, r["long_edge.angle"]))
    return out


def at(rows, t):
    return min(rows, key=lambda r: abs(r["t"] - t))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "c9_payload"))
    ap.add_argument("--no-run", action="store_true", help="use the runs already in --out")
    ap.add_argument("--remesh", action="store_true", help="remake cases/c9_payload.msh")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    if a.remesh:
        run([CHUTE] + MESH_ARGS)
    dirs = {name: os.path.join(a.out, name) for name, _ in MODELS}
    timing = {}
    if not a.no_run:
        for name, _ in MODELS:
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            t0 = time.monotonic()
            run([CHUTE, "run", os.path.join(ROOT, "cases", name + ".toml"), "--out", dirs[name],
                 "--quiet"])
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            timing[name] = {"wall_s_measured": time.monotonic() - t0,
                            "cpu_s": (after.ru_utime - before.ru_utime) +
                                     (after.ru_stime - before.ru_stime)}

    figures = {"models": {}}
    relative = {}
    for name, label in MODELS:
        rows = read_probes(dirs[name])
        rel = relative_corner(rows)
        relative[name] = rel
        with open(os.path.join(dirs[name], "summary.json")) as f:
            s = json.load(f)
        angles = [r[3] for r in rel]
        first90 = next((r[0] for r in rel if r[3] >= 90.0), None)
        figures["models"][name] = {
            "label": label,
            "status": s["status"],
            "steps": s["steps"],
            "rejected_steps": s["rejected_steps"],
            "newton_per_step": s["newton_iterations_per_step"],
            "wall_time_s": s["wall_time"]["total"],
            "simulated_s": s["final_time"],
            "wall_per_simulated_s": s["wall_time"]["total"] / max(s["final_time"], 1e-300),
            "final_angle_deg": angles[-1],
            "max_angle_deg": max(angles),
            "first_level_s": first90,
            "horizontal_min_max_ft": [min(r[1] for r in rel), max(r[1] for r in rel)],
            "vertical_min_max_ft": [min(r[2] for r in rel), max(r[2] for r in rel)],
            "rotation": [[t, at(rows, t)["long_edge.angle"]] for t in TABLE_TIMES
                         if t <= rows[-1]["t"] + 1e-9],
            # settling: the angle's range over the last quarter of the run
            "last_quarter_angle_range_deg": [
                min(r[3] for r in rel if r[0] >= 0.75 * rel[-1][0]),
                max(r[3] for r in rel if r[0] >= 0.75 * rel[-1][0])],
        }
        figures["models"][name].update(timing.get(name, {}))
        # Derived series for `chute plot` (it reads probes.csv of a run directory).
        d = os.path.join(a.out, "relative", label.replace(" ", "_"))
        os.makedirs(d, exist_ok=True)
        with open(os.path.join(d, "probes.csv"), "w") as f:
            f.write("t,corner.horizontal,corner.vertical,long_edge.angle\n")
            for r in rel:
                f.write("%.6g,%.9g,%.9g,%.9g\n" % r)

    rel_dirs = [os.path.join(a.out, "relative", label.replace(" ", "_")) for _, label in MODELS]
    run([CHUTE, "plot"] + rel_dirs + ["--columns", "corner.horizontal", "--title",
        "Fig. 15: horizontal displacement of corner bot_p relative to the confluence (ft)",
        "--out", os.path.join(a.out, "fig15_horizontal.png")])
    run([CHUTE, "plot"] + rel_dirs + ["--columns", "corner.vertical", "--title",
        "Fig. 16: vertical displacement of corner bot_p relative to the confluence (ft)",
        "--out", os.path.join(a.out, "fig16_vertical.png")])
    run([CHUTE, "plot"] + rel_dirs + ["--columns", "long_edge.angle", "--title",
        "Angle of the payload's long edge to the vertical (degrees)",
        "--out", os.path.join(a.out, "rotation.png")])
    run([CHUTE, "render", dirs["c9_payload_reorientation"], "--times"] +
        [str(t) for t in SNAPSHOTS] + ["--view", "side", "--compare",
        dirs["payload_fixed_slider"], "--size", "1600x800", "--out",
        os.path.join(a.out, "fig14"), "--quiet"])

    with open(os.path.join(a.out, "rotation.csv"), "w") as f:
        f.write("t," + ",".join(n + ".angle" for n, _ in MODELS) + "\n")
        for k, t in enumerate(TABLE_TIMES):
            vals = [figures["models"][n]["rotation"] for n, _ in MODELS]
            if all(k < len(v) for v in vals):
                f.write("%g,%s\n" % (t, ",".join("%.2f" % v[k][1] for v in vals)))
    figures["load_average_1min"] = os.getloadavg()[0]
    figures["cpus"] = os.cpu_count()
    with open(os.path.join(a.out, "payload_figures.json"), "w") as f:
        json.dump(figures, f, indent=2)

    print("\nangle of the long edge to the vertical (deg; 0 vertical, 90 level):")
    print("   t   " + "".join("%16s" % label for _, label in MODELS))
    for k, t in enumerate(TABLE_TIMES):
        vals = [figures["models"][n]["rotation"] for n, _ in MODELS]
        if all(k < len(v) for v in vals):
            print("%5.2f  " % t + "".join("%16.1f" % v[k][1] for v in vals))
    for name, label in MODELS:
        m = figures["models"][name]
        print("%-13s %s: %d steps, %d rejected, %.2f Newton/step, wall %.1f s for %.2f s "
              "(%.1f s per simulated s; CPU %s s); final angle %.1f, max %.1f, last quarter "
              "%.1f..%.1f, level first at %s s; corner horizontal %.2f..%.2f ft, vertical "
              "%.2f..%.2f ft" % (
                  label, m["status"], m["steps"], m["rejected_steps"], m["newton_per_step"],
                  m["wall_time_s"], m["simulated_s"], m["wall_per_simulated_s"],
                  "%.1f" % m["cpu_s"] if "cpu_s" in m else "-",
                  m["final_angle_deg"], m["max_angle_deg"],
                  *m["last_quarter_angle_range_deg"], m["first_level_s"],
                  *m["horizontal_min_max_ft"], *m["vertical_min_max_ft"]))
    print("machine: %d CPUs, load average %.1f" % (figures["cpus"], figures["load_average_1min"]))
    ok = all(m["status"] == "completed" for m in figures["models"].values())
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

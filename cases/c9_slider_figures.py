#!/usr/bin/python3
"""Slider reefing of the half-scale C-9 (paper section 4, Figs. 11-12) and its acceptance figures.

Runs cases/c9_slider.toml and cases/c9_no_slider.toml, renders Fig. 11 (snapshots at 0.25, 0.5,
0.75 and 1.0 s, with and without the slider side by side), plots Fig. 12 (skirt radius against
time for both runs) and prints the acceptance figures: time to 90 % of the final skirt radius
with and without the slider and their ratio, the final radii and their difference, steps,
rejected steps, Newton iterations per step, wall and CPU time per run. The same figures go to
OUT/c9_slider_acceptance.json. Standard library only.

    python3 cases/c9_slider_figures.py                 # runs, renders and plots into out/c9_slider_figures
    python3 cases/c9_slider_figures.py --no-run        # figures from runs already in OUT
    python3 cases/c9_slider_figures.py --set solver.t_end=1.5

The payload re-orientation figures (Figs. 14-16) are made by their own script.
"""
import argparse
import csv
import json
import os
import resource
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
CASES = ("c9_slider", "c9_no_slider")
FIG11_TIMES = ("0.25", "0.5", "0.75", "1.0")
RADIUS = "skirt.mean"  # mean distance of the skirt nodes from the confluence -> vent axis
SLIDER = "slider_0.s"  # grommet 0's reference arc length from the skirt along line 0 (ft)
FINAL_WINDOW = 0.1  # the final radius: mean over the last 10 % of the run (breathing averaged)


def run(cmd):
    print("+", " ".join(cmd), flush=True)
    subprocess.run(cmd, check=True)


def run_case(chute, name, out, overrides):
    """Runs one case; returns its wall and CPU time (this child process only)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    cmd = [chute, "run", os.path.join(HERE, name + ".toml"), "--out", out, "--quiet"]
    for s in overrides:
        cmd += ["--set", s]
    print("+", " ".join(cmd), flush=True)
    status = subprocess.run(cmd).returncode
    wall = time.monotonic() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if status != 0:
        print(f"{name}: chute run exited with status {status}", file=sys.stderr)
    return {"exit_status": status, "wall_s_measured": wall, "cpu_s": cpu}


def read_column(out, name):
    with open(os.path.join(out, "probes.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    return [float(r[name]) for r in rows] if rows and name in rows[0] else []


def read_radius(out):
    return read_column(out, "t"), read_column(out, RADIUS)


def inflation_figures(t, r):
    """Final radius (mean over the last FINAL_WINDOW of the run), its value at the end and t90:
    the first time the radius reaches 90 % of the FINAL radius. A canopy whose final radius is
    not above its starting radius / 0.9 never inflated to it (or closed again): t90 is then
    "not reached" (None), never the start time."""
    t_end = t[-1]
    window = [ri for ti, ri in zip(t, r) if ti >= (1.0 - FINAL_WINDOW) * t_end]
    final = sum(window) / len(window)
    inflated = r[0] < 0.9 * final
    t90 = next((ti for ti, ri in zip(t, r) if ri >= 0.9 * final), None) if inflated else None
    return {"t_end": t_end, "initial_radius": r[0], "final_radius": final, "radius_at_end": r[-1],
            "peak_radius": max(r), "t_peak": t[r.index(max(r))], "t90": t90,
            "t90_note": None if inflated else
            "not reached: the final radius is not above the start's / 0.9 (closed or never opened)"}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--chute", default=os.path.join(ROOT, "build", "bin", "chute"))
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "c9_slider_figures"))
    ap.add_argument("--no-run", action="store_true", help="use the runs already in OUT")
    ap.add_argument("--no-render", action="store_true", help="skip Fig. 11 (needs VTK)")
    ap.add_argument("--set", action="append", default=[], help="override for both runs")
    a = ap.parse_args()

    runs = {n: os.path.join(a.out, n) for n in CASES}
    timing = {}
    if not a.no_run:
        for n in CASES:
            timing[n] = run_case(a.chute, n, runs[n], a.set)

    if not a.no_render:
        run([a.chute, "render", runs["c9_slider"], "--compare", runs["c9_no_slider"], "--times",
             *FIG11_TIMES, "--view", "side", "--color", "displacement", "--size", "1600x800",
             "--out", os.path.join(a.out, "fig11")])
    run([a.chute, "plot", runs["c9_slider"], runs["c9_no_slider"], "--columns", RADIUS, "--title",
         "Fig. 12: skirt radius (ft), half-scale C-9 with and without slider", "--out",
         os.path.join(a.out, "fig12_skirt_radius.png")])

    result = {"cases": {}}
    for n in CASES:
        with open(os.path.join(runs[n], "summary.json")) as f:
            s = json.load(f)
        t, r = read_radius(runs[n])
        fig = inflation_figures(t, r)
        fig.update({"status": s["status"], "steps": s["steps"],
                    "rejected_steps": s["rejected_steps"],
                    "newton_per_step": s["newton_iterations_per_step"],
                    "max_newton_in_a_step": s["max_newton_iterations_in_a_step"],
                    "event_retries": s["event_retries"],
                    "slider_handovers": sum(s.get("sliding_handovers", [])),
                    "wall_s": s["wall_time"]["total"],
                    "wall_s_per_simulated_s": s["wall_time"]["total"] / fig["t_end"]})
        fig.update(timing.get(n, {}))
        slider = read_column(runs[n], SLIDER)
        if slider:  # where the slider settled: line length from the skirt to its grommet
            fig["slider_position_at_end"] = slider[-1]
        result["cases"][n] = fig
    ws, wo = result["cases"]["c9_slider"], result["cases"]["c9_no_slider"]
    result["t90_ratio_slider_over_no_slider"] = (ws["t90"] / wo["t90"]
                                                 if ws["t90"] and wo["t90"] else None)
    result["final_radius_difference"] = abs(ws["final_radius"] - wo["final_radius"]) / wo[
        "final_radius"]
    result["load_average_1min"] = os.getloadavg()[0]
    result["cpus"] = os.cpu_count()
    with open(os.path.join(a.out, "c9_slider_acceptance.json"), "w") as f:
        json.dump(result, f, indent=2)

    print(f"\n{'':14}{'t90 (s)':>12}{'R final':>9}{'R(t_end)':>9}{'steps':>7}{'rej.':>6}"
          f"{'Newton/step':>12}{'wall (s)':>10}{'cpu (s)':>9}  status")
    for n in CASES:
        c = result["cases"][n]
        t90 = f"{c['t90']:.3f}" if c["t90"] is not None else "not reached"
        cpu = f"{c['cpu_s']:.1f}" if "cpu_s" in c else "-"
        print(f"{n:14}{t90:>12}{c['final_radius']:9.3f}{c['radius_at_end']:9.3f}{c['steps']:7d}"
              f"{c['rejected_steps']:6d}{c['newton_per_step']:12.2f}{c['wall_s']:10.1f}{cpu:>9}"
              f"  {c['status']}")
    ratio = result["t90_ratio_slider_over_no_slider"]
    print(f"t90 ratio (slider / no slider): {ratio:.2f}" if ratio else
          "t90 ratio: not available (t90 not reached in a run)")
    print(f"final skirt radius difference: {100 * result['final_radius_difference']:.2f} % "
          f"(required <= 5 %)")
    if "slider_position_at_end" in ws:
        print(f"slider at the end: {ws['slider_position_at_end']:.2f} ft down the lines from the "
              f"skirt; {ws['slider_handovers']} line nodes passed, {ws['event_retries']} steps cut")
    print(f"machine: {result['cpus']} CPUs, load average {result['load_average_1min']:.1f}")
    print(f"figures in {a.out}: fig11/, fig12_skirt_radius.png, c9_slider_acceptance.json")
    ok = all(result["cases"][n]["status"] == "completed" for n in CASES)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Is the C-9 slider history converged? cases/c9_slider.toml to 1 s with Bossak (as shipped,
rho_inf = 0) at steps halved from 2e-3 s, and central differences at safety factors 0.9, 0.45,
0.225: the skirt radius (mean distance of the skirt nodes from the axis) and grommet 0's place
along its line (slider_0.s) at 0.5, 0.7 and 1.0 s, the hand-overs of lines 0-3, and the largest
difference of every run's skirt-radius history from the finest Bossak run over 0-1 s.

Run it with one build (--chute, default build/bin/chute) and, for the comparison, with a build
from before the whirl damping of sliders (RG8, docs/formulation.md) via --chute OLD --tag before.
Writes bench/results/c9_convergence_<tag>.md and the probes of each run under
bench/results/c9_convergence_<tag>/ (skirt radius, slider columns only).

    nice /usr/bin/python3 bench/c9_convergence.py [--tag after] [--chute build/bin/chute]
"""
import argparse, csv, json, os, subprocess, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CASE = os.path.join(ROOT, "cases", "c9_slider.toml")
RESULTS = os.environ.get("CHUTE_BENCH_RESULTS", os.path.join(ROOT, "bench", "results"))
BOSSAK_DT = [2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4]
EXPLICIT_SAFETY = [0.9, 0.45, 0.225]
TIMES = [0.5, 0.7, 1.0]
KEEP = ["t", "skirt.mean", "slider_0.s", "slider_0.element"]


def run(chute, sets):
    with tempfile.TemporaryDirectory() as out:
        cmd = [chute, "run", CASE, "--out", out, "--quiet", "--set", "solver.t_end=1.0",
               "--set", "output.vtu.write=false", "--set", "output.interval=0.004"]
        for s in sets:
            cmd += ["--set", s]
        t0 = time.monotonic()
        p = subprocess.run(cmd, capture_output=True, text=True)
        wall = time.monotonic() - t0
        summary = json.load(open(os.path.join(out, "summary.json")))
        rows = list(csv.DictReader(open(os.path.join(out, "probes.csv"))))
        return p.returncode, summary, rows, wall


def at(rows, t):
    return min(rows, key=lambda r: abs(float(r["t"]) - t))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--chute", default=os.path.join(ROOT, "build", "bin", "chute"))
    ap.add_argument("--tag", default="after")
    a = ap.parse_args()
    # Bossak as the case sets it up (rho_inf 0, crossings inside the Newton solve); the case itself
    # ships with central differences.
    runs = [(f"Bossak dt = {dt:g}", ['solver.integrator="bossak"', f"solver.dt={dt}"])
            for dt in BOSSAK_DT]
    runs += [(f"central differences, safety {s:g}",
              ['solver.integrator="central_difference"', f"solver.safety_factor={s}"])
             for s in EXPLICIT_SAFETY]
    outdir = os.path.join(RESULTS, f"c9_convergence_{a.tag}")
    os.makedirs(outdir, exist_ok=True)
    results = []
    for name, sets in runs:
        rc, s, rows, wall = run(a.chute, sets)
        results.append((name, rc, s, rows, wall))
        slug = name.replace(" ", "_").replace(",", "").replace("=", "")
        with open(os.path.join(outdir, slug + ".csv"), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(KEEP)
            for r in rows:
                w.writerow([r[k] for k in KEEP])
        print(name, s["status"], f"{wall:.1f} s", flush=True)
    ref = results[len(BOSSAK_DT) - 1][3]  # the finest Bossak run
    refmap = {round(float(r["t"]), 4): float(r["skirt.mean"]) for r in ref}
    lines = [f"`python3 bench/c9_convergence.py --tag {a.tag}` "
             f"({time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, build "
             f"{os.path.relpath(a.chute, ROOT) if a.chute.startswith(ROOT) else a.chute}). "
             "Skirt radius (ft) / grommet 0's material coordinate s (ft) at each time; "
             "largest difference = max over 0-1 s of |skirt radius - that of the finest Bossak "
             "run| / the finest run's.", "",
             "| run | status | steps | rejected | Newton/step | " +
             " | ".join(f"skirt / s at {t} s" for t in TIMES) +
             " | hand-overs lines 0-3 | largest difference | wall (s) |",
             "|---|---|---|---|---|" + "---|" * len(TIMES) + "---|---|---|"]
    for name, rc, s, rows, wall in results:
        cells = []
        for t in TIMES:
            r = at(rows, t)
            cells.append(f"{float(r['skirt.mean']):.4f} / {float(r['slider_0.s']):.3f}")
        worst = 0.0
        for r in rows:
            key = round(float(r["t"]), 4)
            if key in refmap and refmap[key] > 0:
                worst = max(worst, abs(float(r["skirt.mean"]) - refmap[key]) / refmap[key])
        hand = ", ".join(str(h) for h in s.get("sliding_handovers", [])[:4])
        lines.append(f"| {name} | {s['status']} | {s['steps']} | {s['rejected_steps']} | "
                     f"{s['newton_iterations_per_step']:.2f} | " + " | ".join(cells) +
                     f" | {hand} | {100 * worst:.1f} % | {wall:.1f} |")
    text = "\n".join(lines) + "\n"
    with open(os.path.join(RESULTS, f"c9_convergence_{a.tag}.md"), "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main()

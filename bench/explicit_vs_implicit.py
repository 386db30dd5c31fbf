#!/usr/bin/python3
"""Work-precision of implicit (Bossak) against explicit (central differences) integration on the
same scenes (issue 21, item 5). For each scene and setting: the median wall time and CPU time
of N runs (one sitting) and the error against the scene's reference:

  pulley          analytic (docs/formulation.md F13): the case's own [reference] error
  bead_rope_mass  bench/explicit/bead_rope_mass.toml, a bead on a rope WITH mass (5 sliding
                  elements), to 0.4 s (it bounces off the first node at 0.45 s in both methods):
                  max |bead position - reference| / max bead displacement, reference = Bossak
                  rho_inf = 0.9 at dt = 2e-5
  c9_slider       cases/c9_slider.toml to T (default 0.5 s): max |skirt radius - reference| /
                  reference skirt radius at T, and max |slider s - reference|, at the output times;
                  reference = Bossak at dt = 5e-4 (a quarter of the shipped dt) whose probes are
                  kept in bench/results/explicit_c9_reference_probes.csv
  stiff_lines     c9_slider with the suspension lines' E x 10 and x 100 (stiffness ratio to the
                  fabric): the cost of each method per simulated time at its usual setting

Implicit settings swept: dt; explicit: the safety factor (its step is the stable step).
Writes bench/results/explicit_vs_implicit.csv, explicit_vs_implicit.md (table) and one PNG per
scene (error against wall time, log-log).

    nice /usr/bin/python3 bench/explicit_vs_implicit.py [--runs 3] [--skip-c9]
"""
import argparse, csv, json, math, os, resource, statistics, subprocess, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CHUTE = os.path.join(ROOT, "build", "bin", "chute")
RESULTS = os.environ.get("CHUTE_BENCH_RESULTS", os.path.join(ROOT, "bench", "results"))
EXPLICIT = 'solver.integrator="central_difference"'
# The bead reaches the first rope node at t ~ 0.45 s and bounces off it instead of crossing, in
# both methods (measured: its element never changes; implicit runs at different dt then part
# ways): the comparison stops before, at 0.4 s.
BEAD = ["solver.t_end=0.4"]


def case_path(scene):
    if scene == "bead_rope_mass":
        return os.path.join(ROOT, "bench", "explicit", "bead_rope_mass.toml")
    return os.path.join(ROOT, "cases", scene + ".toml")


def run_once(case, sets, keep=None):
    out = keep or tempfile.mkdtemp()
    cmd = [CHUTE, "run", case, "--out", out, "--quiet"]
    for s in sets:
        cmd += ["--set", s]
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.run(cmd, capture_output=True, text=True)
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    summary = json.load(open(os.path.join(out, "summary.json"))) if os.path.exists(
        os.path.join(out, "summary.json")) else None
    rows = list(csv.DictReader(open(os.path.join(out, "probes.csv")))) if summary else []
    return p.returncode, summary, rows, cpu


def run(case, sets, runs):
    walls, cpus, last = [], [], None
    for _ in range(runs):
        code, summary, rows, cpu = run_once(case, sets)
        if code != 0 or summary is None:
            return None, None, summary, rows
        walls.append(summary["wall_time"]["total"])
        cpus.append(cpu)
        last = (summary, rows)
    return statistics.median(walls), statistics.median(cpus), last[0], last[1]


def by_time(rows):
    return {round(float(r["t"]), 9): r for r in rows}


def bead_error(rows, ref):
    R = by_time(ref)
    x0 = [float(ref[0]["bead." + c]) for c in "xyz"]
    size = max(math.dist([float(r["bead." + c]) for c in "xyz"], x0) for r in ref)
    err = 0.0
    for r in rows:
        t = round(float(r["t"]), 9)
        if t in R:
            err = max(err, math.dist([float(r["bead." + c]) for c in "xyz"],
                                     [float(R[t]["bead." + c]) for c in "xyz"]))
    return err / size


def c9_errors(rows, ref, times=(0.5, 1.0)):
    R = by_time(ref)
    skirt = slider = 0.0
    at = {}
    for r in rows:
        t = round(float(r["t"]), 9)
        if t not in R:
            continue
        rr = float(R[t]["skirt.mean"])
        skirt = max(skirt, abs(float(r["skirt.mean"]) - rr) / rr)
        slider = max(slider, abs(float(r["slider_0.s"]) - float(R[t]["slider_0.s"])))
        for T in times:
            if abs(t - T) < 1e-9:
                at[T] = (float(r["skirt.mean"]) - rr) / rr
    return skirt, slider, at


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--skip-c9", action="store_true")
    ap.add_argument("--c9-end", type=float, default=0.5)
    ap.add_argument("--only-c9", action="store_true", help="C-9 scenes only (appended)")
    ap.add_argument("--append", action="store_true", help="keep other rows of the CSV")
    ap.add_argument("--report", action="store_true", help="table and plots from the CSV only")
    args = ap.parse_args()
    if args.report:
        report()
        return
    os.makedirs(RESULTS, exist_ok=True)
    out = []

    def add(scene, method, setting, wall, cpu, summary, err, extra=""):
        steps = summary["steps"] if summary else 0
        out.append(dict(scene=scene, method=method, setting=setting,
                        wall_median=wall if wall else float("nan"),
                        cpu_median=cpu if cpu else float("nan"),
                        steps=steps, status=summary["status"] if summary else "failed",
                        error=err, extra=extra))
        print(out[-1], flush=True)

    # ---- pulley: analytic reference
    for dt in ([] if args.only_c9 else [1e-3, 2e-3, 5e-3, 1e-2, 2e-2]):
        w, c, s, _ = run(case_path("pulley"), [f"solver.dt={dt}", "output.interval=0.02"], args.runs)
        add("pulley", "bossak", f"dt={dt}", w, c, s,
            s["reference"]["relative_max_error"] if w else float("nan"))
    for sf in ([] if args.only_c9 else [0.1, 0.2, 0.35, 0.5, 0.7, 0.9]):
        w, c, s, _ = run(case_path("pulley"),
                         [EXPLICIT, f"solver.safety_factor={sf}", "output.interval=0.02"], args.runs)
        add("pulley", "central_difference", f"safety={sf}", w, c, s,
            s["reference"]["relative_max_error"] if w else float("nan"))

    # ---- bead on a rope with mass: converged implicit reference
    if not args.only_c9:
        code, s, ref, _ = run_once(case_path("bead_rope_mass"), BEAD + ["solver.dt=2e-5"])
    for dt in ([] if args.only_c9 else [1e-4, 2e-4, 5e-4, 1e-3, 2e-3]):
        w, c, s, rows = run(case_path("bead_rope_mass"), BEAD + [f"solver.dt={dt}"], args.runs)
        add("bead_rope_mass", "bossak", f"dt={dt}", w, c, s,
            bead_error(rows, ref) if w else float("nan"))
    for sf in ([] if args.only_c9 else [0.2, 0.5, 0.9]):
        w, c, s, rows = run(case_path("bead_rope_mass"),
                            BEAD + [EXPLICIT, f"solver.safety_factor={sf}"], args.runs)
        add("bead_rope_mass", "central_difference", f"safety={sf}", w, c, s,
            bead_error(rows, ref) if w else float("nan"),
            f"handovers={s['sliding_handovers'] if s else ''}")

    if not args.skip_c9:
        T = args.c9_end
        refcsv = os.path.join(RESULTS, "explicit_c9_reference_probes.csv")
        ref = list(csv.DictReader(open(refcsv)))
        base = [f"solver.t_end={T}", "output.vtu.write=false"]
        for dt in [2e-3, 1e-3]:
            w, c, s, rows = run(case_path("c9_slider"), base + [f"solver.dt={dt}"], args.runs)
            e = c9_errors(rows, ref) if w else (float("nan"),) * 2 + ({},)
            add("c9_slider", "bossak", f"dt={dt}", w, c, s, e[0], f"slider_s_error={e[1]:.3g}")
        for sf in [0.9, 0.5]:
            w, c, s, rows = run(case_path("c9_slider"), base + [EXPLICIT, f"solver.safety_factor={sf}"],
                                args.runs)
            e = c9_errors(rows, ref) if w else (float("nan"),) * 2 + ({},)
            add("c9_slider", "central_difference", f"safety={sf}", w, c, s, e[0],
                f"slider_s_error={e[1]:.3g}")
        # Stiffer lines than fabric: cost per simulated time (0.1 s) of each method at its usual
        # setting; the error column is left empty (no reference for these variants).
        for ratio in [1, 10, 100]:
            E = 4.32e6 * ratio
            sets = ["solver.t_end=0.1", "output.vtu.write=false",
                    f"materials.suspension_line.E={E}"]
            w, c, s, _ = run(case_path("c9_slider"), sets, 1)
            add("stiff_lines", "bossak", f"E_line/E_fabric={ratio}", w, c, s, float("nan"))
            w, c, s, _ = run(case_path("c9_slider"), sets + [EXPLICIT], 1)
            add("stiff_lines", "central_difference", f"E_line/E_fabric={ratio}", w, c, s,
                float("nan"), f"least_step={s['explicit']['least_step'] if s else ''}")

    path = os.path.join(RESULTS, "explicit_vs_implicit.csv")
    if os.path.exists(path) and args.append:
        old = list(csv.DictReader(open(path)))
        keep = {(r["scene"], r["method"], r["setting"]) for r in out}
        out = [r for r in old if (r["scene"], r["method"], r["setting"]) not in keep] + out
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(out[0].keys()))
        w.writeheader()
        w.writerows(out)
    report()


def report():
    """The table (markdown) and the plots from bench/results/explicit_vs_implicit.csv."""
    out = list(csv.DictReader(open(os.path.join(RESULTS, "explicit_vs_implicit.csv"))))
    for r in out:
        for k in ("wall_median", "cpu_median", "error"):
            r[k] = float(r[k])
    with open(os.path.join(RESULTS, "explicit_vs_implicit.md"), "w") as f:
        f.write("Made by `nice /usr/bin/python3 bench/explicit_vs_implicit.py` (see its docstring); "
                "wall = the run's own wall_time.total, CPU = the process's user + system time "
                "(includes ~0.15 s of program start), medians of the runs; the machine was shared "
                "(load average 15-20 on 2 cores): compare within a scene only.\n\n")
        f.write("| scene | method | setting | steps | wall (median) s | CPU (median) s | error | note |\n")
        f.write("|---|---|---|---|---|---|---|---|\n")
        for r in out:
            f.write(f"| {r['scene']} | {r['method']} | {r['setting']} | {r['steps']} | "
                    f"{r['wall_median']:.3g} | {r['cpu_median']:.3g} | {r['error']:.3g} | "
                    f"{r['status']} {r['extra']} |\n")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    for scene in sorted({r["scene"] for r in out}):
        pts = [r for r in out if r["scene"] == scene and r["error"] == r["error"] and r["error"] > 0]
        if not pts:
            continue
        plt.figure(figsize=(5.5, 4))
        for method, mk in [("bossak", "o-"), ("central_difference", "s-")]:
            p = sorted((r["wall_median"], r["error"], r["setting"]) for r in pts
                       if r["method"] == method)
            if p:
                plt.loglog([a for a, _, _ in p], [b for _, b, _ in p], mk, label=method)
                for a, b, lab in p:
                    plt.annotate(lab.split("=")[1], (a, b), fontsize=7)
        plt.xlabel("wall time of the run (median), s")
        plt.ylabel("relative error")
        plt.title(scene + " (labels: dt or safety factor)")
        plt.grid(True, which="both", alpha=0.3)
        plt.legend()
        plt.tight_layout()
        plt.savefig(os.path.join(RESULTS, f"explicit_vs_implicit_{scene}.png"), dpi=110)
        plt.close()


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Work-precision of implicit (Bossak) against explicit (central differences) integration on the
same scenes (issue 21, item 5). For each scene and setting: the median wall time and CPU time
of N runs (one sitting) and the error against the scene's reference:

  pulley          analytic (docs/formulation.md F13): the case's own [reference] error
  bead_rope_mass  bench/explicit/bead_rope_mass.toml, a bead on a rope WITH mass (5 sliding
                  elements), to 2 s (it crosses two rope nodes and turns):
                  max |bead position - reference| / max bead displacement, reference = Bossak
                  rho_inf = 0.9 at dt = 2e-5
  c9_slider       cases/c9_slider.toml to 1 s: max over the output times of |skirt radius -
                  reference| / reference (the skirt radius at 0.5 and 1.0 s and the largest slider
                  s error in the note); reference = Bossak (rho_inf = 0) at dt = C9_REF_DT, its
                  probes kept in bench/results/explicit_c9_reference_dt<dt>_probes.csv
  stiff_lines_x100 c9_slider with the suspension lines' E x 100, to 0.3 s: the same error against
                  Bossak at dt = 1.25e-4 of that scene; and the cost of 0.1 s of each method at
                  line/fabric stiffness ratios 1, 10, 30, 100 (stiffness_ratio rows)

Implicit settings swept: dt; explicit: the safety factor or the stiffness damping beta (its step
is the stable step). C-9 settings run once each (--c9-runs): their CPU times carry the noise of
the shared machine (~10-20 %).
Writes bench/results/explicit_vs_implicit.csv, explicit_vs_implicit.md (table) and one PNG per
scene (error against CPU time, log-log).

    nice /usr/bin/python3 bench/explicit_vs_implicit.py [--runs 3] [--skip-c9] [--only-c9 --append]
    nice /usr/bin/python3 bench/explicit_vs_implicit.py --rescore   # errors against new references
"""
import argparse, csv, json, math, os, resource, statistics, subprocess, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CHUTE = os.environ.get("CHUTE_BIN", os.path.join(ROOT, "build", "bin", "chute"))
RESULTS = os.environ.get("CHUTE_BENCH_RESULTS", os.path.join(ROOT, "bench", "results"))
EXPLICIT = 'solver.integrator="central_difference"'
BOSSAK = 'solver.integrator="bossak"'  # the C-9 cases ship with central differences
# Two seconds: the bead crosses two rope nodes and turns (RG8, F12b).
BEAD = ["solver.t_end=2.0"]


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


C9_REF_DT = 6.25e-5     # the C-9 reference's step (Bossak, rho_inf = 0, the case's settings);
                        # Bossak's convergence: bench/results/c9_convergence_after.md
STIFF_RATIO = 100       # suspension lines' E / fabric E of the stiff-lines scene
STIFF_END = 0.3         # its length, s
STIFF_REF_DT = 1.25e-4  # its reference's step


def runs_path(scene, method, setting):
    return os.path.join(RESULTS, "explicit_vs_implicit_runs", f"{scene}__{method}__{setting}.csv")


def c9_note(rows, ref, times, s):
    skirt, slider, at = c9_errors(rows, ref, times)
    note = " ".join(f"skirt@{T}={100 * at[T]:+.2f}%" for T in times if T in at)
    note += f" slider_s_error={slider:.3g}"
    if s.get("explicit"):
        note += f" step={s['explicit']['least_step']:.3g}"
    note += f" handovers_line0={s['sliding_handovers'][0]}"
    return skirt, note


def add_c9(scene, method, setting, w, c, s, rows, ref, add, times=(0.5, 1.0)):
    """A C-9 row: error = max over the output times of |skirt radius - ref| / ref; the note gives
    the skirt radius error at `times`, the largest slider s error and the hand-overs of line 0.
    The run's probes are kept (explicit_vs_implicit_runs/, not in git) for --rescore."""
    if not w:
        add(scene, method, setting, w, c, s, float("nan"))
        return
    os.makedirs(os.path.dirname(runs_path(scene, method, setting)), exist_ok=True)
    with open(runs_path(scene, method, setting), "w", newline="") as f:
        wr = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        wr.writeheader()
        wr.writerows(rows)
    with open(runs_path(scene, method, setting)[:-4] + ".json", "w") as f:
        json.dump(s, f)
    skirt, note = c9_note(rows, ref, times, s)
    add(scene, method, setting, w, c, s, skirt, note)


def rescore():
    """C-9 and stiff-lines errors again, from the kept probes, against the current references."""
    path = os.path.join(RESULTS, "explicit_vs_implicit.csv")
    out = list(csv.DictReader(open(path)))
    refs = {"c9_slider": (f"explicit_c9_reference_dt{C9_REF_DT}_probes.csv", (0.5, 1.0)),
            f"stiff_lines_x{STIFF_RATIO}":
            (f"explicit_stiff_lines_x{STIFF_RATIO}_reference_probes.csv", (STIFF_END,))}
    for r in out:
        if r["scene"] not in refs or not os.path.exists(runs_path(r["scene"], r["method"],
                                                                  r["setting"])):
            continue
        refcsv, times = refs[r["scene"]]
        ref = list(csv.DictReader(open(os.path.join(RESULTS, refcsv))))
        p = runs_path(r["scene"], r["method"], r["setting"])
        rows = list(csv.DictReader(open(p)))
        s = json.load(open(p[:-4] + ".json"))
        r["error"], r["extra"] = c9_note(rows, ref, times, s)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(out[0].keys()))
        w.writeheader()
        w.writerows(out)


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
    ap.add_argument("--c9-end", type=float, default=1.0)
    ap.add_argument("--c9-runs", type=int, default=1, help="runs per C-9 setting (CPU median)")
    ap.add_argument("--skip-stiff", action="store_true")
    ap.add_argument("--skip-ratios", action="store_true")
    ap.add_argument("--explicit-only", action="store_true",
                    help="C-9 scenes: the central-difference rows only (the Bossak rows kept)")
    ap.add_argument("--only-c9", action="store_true", help="C-9 scenes only (appended)")
    ap.add_argument("--append", action="store_true", help="keep other rows of the CSV")
    ap.add_argument("--report", action="store_true", help="table and plots from the CSV only")
    ap.add_argument("--rescore", action="store_true",
                    help="C-9 errors again from the kept probes against the current references")
    args = ap.parse_args()
    if args.report or args.rescore:
        if args.rescore:
            rescore()
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
        # C-9 with slider to 1 s. Reference: Bossak at dt = C9_REF_DT, its probes kept in
        # bench/results (made by this script if absent; its own convergence: docs/explicit.md).
        T = args.c9_end
        refcsv = os.path.join(RESULTS, f"explicit_c9_reference_dt{C9_REF_DT}_probes.csv")
        base = [f"solver.t_end={T}", "output.vtu.write=false"]
        if not os.path.exists(refcsv):
            keep = tempfile.mkdtemp()
            run_once(case_path("c9_slider"), base + [BOSSAK, f"solver.dt={C9_REF_DT}"], keep)
            subprocess.run(["cp", os.path.join(keep, "probes.csv"), refcsv], check=True)
        ref = list(csv.DictReader(open(refcsv)))
        for dt in ([] if args.explicit_only else [2e-3, 1e-3, 5e-4, 2.5e-4]):
            if dt <= C9_REF_DT:
                continue
            w, c, s, rows = run(case_path("c9_slider"), base + [BOSSAK, f"solver.dt={dt}"],
                                args.c9_runs)
            add_c9("c9_slider", "bossak", f"dt={dt}", w, c, s, rows, ref, add)
        for beta in [0.0, 1e-5, 2e-5, 3e-5]:
            w, c, s, rows = run(case_path("c9_slider"),
                                base + [EXPLICIT, f"solver.stiffness_damping={beta}"], args.c9_runs)
            add_c9("c9_slider", "central_difference", f"beta={beta}", w, c, s, rows, ref, add)

    if not args.skip_stiff:
        # Lines STIFF_RATIO x stiffer than the fabric (suspension lines' E x STIFF_RATIO): the
        # explicit step shrinks to the lines' wave speed. To STIFF_END s, reference Bossak at
        # dt = STIFF_REF_DT of the same scene.
        E = 4.32e6 * STIFF_RATIO
        base = [f"solver.t_end={STIFF_END}", "output.vtu.write=false",
                f"materials.suspension_line.E={E}"]
        refcsv = os.path.join(RESULTS, f"explicit_stiff_lines_x{STIFF_RATIO}_reference_probes.csv")
        if not os.path.exists(refcsv):
            keep = tempfile.mkdtemp()
            run_once(case_path("c9_slider"), base + [BOSSAK, f"solver.dt={STIFF_REF_DT}"], keep)
            subprocess.run(["cp", os.path.join(keep, "probes.csv"), refcsv], check=True)
        ref = list(csv.DictReader(open(refcsv)))
        scene = f"stiff_lines_x{STIFF_RATIO}"
        for dt in ([] if args.explicit_only else [2e-3, 1e-3, 5e-4]):
            w, c, s, rows = run(case_path("c9_slider"), base + [BOSSAK, f"solver.dt={dt}"],
                                args.c9_runs)
            add_c9(scene, "bossak", f"dt={dt}", w, c, s, rows, ref, add, times=(STIFF_END,))
        for beta in [0.0, 1e-5]:
            w, c, s, rows = run(case_path("c9_slider"),
                                base + [EXPLICIT, f"solver.stiffness_damping={beta}"], args.c9_runs)
            add_c9(scene, "central_difference", f"beta={beta}", w, c, s, rows, ref, add,
                   times=(STIFF_END,))
        # Cost per simulated time (0.1 s, one run) against the stiffness ratio: the crossover.
        for ratio in ([] if args.skip_ratios else [1, 10, 30, 100]):
            sets = ["solver.t_end=0.1", "output.vtu.write=false",
                    f"materials.suspension_line.E={4.32e6 * ratio}"]
            if not args.explicit_only:
                w, c, s, _ = run(case_path("c9_slider"), sets + [BOSSAK], 1)
                add("stiffness_ratio", "bossak", f"E_line/E_fabric={ratio}", w, c, s,
                    float("nan"))
            w, c, s, _ = run(case_path("c9_slider"), sets + [EXPLICIT], 1)
            add("stiffness_ratio", "central_difference", f"E_line/E_fabric={ratio}", w, c, s,
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
                "(includes ~0.15-0.25 s of program start), medians of 3 runs for pulley and bead, one "
                "run for the C-9 scenes; the 2-core machine is shared (this sitting: load "
                "average 1-2, 2026-11-25): compare within a scene only. C-9 errors: the skirt radius against Bossak at "
                f"dt = {C9_REF_DT} (c9_slider) and 1.25e-4 (stiff lines), see "
                "bench/results/c9_convergence_after.md for how converged Bossak is.\n\n")
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
            p = sorted((r["cpu_median"], r["error"], r["setting"]) for r in pts
                       if r["method"] == method)
            if p:
                plt.loglog([a for a, _, _ in p], [b for _, b, _ in p], mk, label=method)
                for a, b, lab in p:
                    plt.annotate(lab.split("=")[1], (a, b), fontsize=7)
        plt.xlabel("CPU time of the run (user + system, median), s")
        plt.ylabel("relative error")
        plt.title(scene + " (labels: dt, safety factor or beta)")
        plt.grid(True, which="both", alpha=0.3)
        plt.legend()
        plt.tight_layout()
        plt.savefig(os.path.join(RESULTS, f"explicit_vs_implicit_{scene}.png"), dpi=110)
        plt.close()


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Implicit against explicit as the canopy mesh is refined: the half-scale C-9 with its slider
(mesh/examples/c9_half_scale.toml: 14 ft, 28 gores, slider, folded start), generated with
`chute mesh parachute --case` at canopy element sizes from 1.4 to 0.25 ft, each generated case
flown for --t-end seconds as generated (central differences, safety 0.9, stiffness damping
1e-5 s) and with the case's implicit alternative (Bossak, dt 2 ms, rho_inf 0). Reports per mesh: triangles, equations, the
explicit stable step, wall time per simulated second of each method (one run each, the machine's
load average beside it) and their ratio, and the skirt radius at the end of both runs (how far the
two answers are apart). The crossover is the element size where the ratio passes 1.

Writes bench/results/explicit_crossover.{md,csv,png}.

    nice /usr/bin/python3 bench/explicit_crossover.py [--t-end 0.2] [--sizes 1.4,0.7,0.35]
"""
import argparse, csv, json, os, re, subprocess, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RESULTS = os.environ.get("CHUTE_BENCH_RESULTS", os.path.join(ROOT, "bench", "results"))
CONFIG = os.path.join(ROOT, "mesh", "examples", "c9_half_scale.toml")


def run(chute, case, out, sets):
    cmd = [chute, "run", case, "--out", out, "--quiet", "--set", "output.vtu.write=false"]
    for s in sets:
        cmd += ["--set", s]
    t0 = time.monotonic()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.monotonic() - t0
    s = json.load(open(os.path.join(out, "summary.json")))
    rows = list(csv.DictReader(open(os.path.join(out, "probes.csv"))))
    skirt = float(rows[-1]["skirt.mean"]) if rows and "skirt.mean" in rows[-1] else float("nan")
    return p.returncode, s, wall, skirt


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--chute", default=os.path.join(ROOT, "build", "bin", "chute"))
    ap.add_argument("--t-end", type=float, default=0.2)
    ap.add_argument("--sizes", default="1.4,1.0,0.7,0.5,0.35,0.25")
    a = ap.parse_args()
    rows = []
    started = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    with tempfile.TemporaryDirectory() as tmp:
        for h in [float(x) for x in a.sizes.split(",")]:
            msh, case = os.path.join(tmp, f"c9_{h}.msh"), os.path.join(tmp, f"c9_{h}.toml")
            m = subprocess.run([a.chute, "mesh", "parachute", "--config", CONFIG, "--element-size",
                                str(h), "--out", msh, "--case", case], capture_output=True,
                               text=True, check=True)
            triangles = int(re.search(r"(\d+) canopy triangles", m.stdout).group(1))
            row = {"element_size_ft": h, "triangles": triangles}
            # The generated case flies central differences with stiffness damping 1e-5 s; its
            # implicit alternative is Bossak with the settings the case writes for it.
            for name, sets in (("implicit", ['solver.integrator="bossak"']),
                               ("explicit", [])):
                out = os.path.join(tmp, f"out_{h}_{name}")
                rc, s, wall, skirt = run(a.chute, case, out, sets + [f"solver.t_end={a.t_end}"])
                T = max(s["final_time"], 1e-12)
                row[f"{name}_status"] = s["status"]
                row[f"{name}_steps"] = s["steps"]
                row[f"{name}_wall_per_s"] = round(s["wall_time"]["total"] / T, 2)
                row[f"{name}_skirt_end"] = round(skirt, 4)
                row["equations"] = s["system"]["equations"]
                if name == "implicit":
                    row["implicit_newton_per_step"] = round(s["newton_iterations_per_step"], 2)
                else:
                    row["explicit_step"] = s.get("explicit", {}).get("least_step", float("nan"))
                row[f"{name}_load"] = round(os.getloadavg()[0], 1)
                print(h, name, s["status"], f"{wall:.1f} s", flush=True)
            row["ratio_implicit_over_explicit"] = round(
                row["implicit_wall_per_s"] / row["explicit_wall_per_s"], 2)
            row["skirt_difference"] = round(
                abs(row["implicit_skirt_end"] - row["explicit_skirt_end"]) /
                row["implicit_skirt_end"], 4)
            rows.append(row)
    os.makedirs(RESULTS, exist_ok=True)
    keys = list(rows[0].keys())
    with open(os.path.join(RESULTS, "explicit_crossover.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)
    lines = [f"`python3 bench/explicit_crossover.py --t-end {a.t_end}` ({started}; one run of "
             "each, load average beside it): the half-scale C-9 with its slider generated at each "
             "canopy element size and flown as generated (central differences, safety 0.9, "
             "stiffness damping 1e-5 s) and with the case's Bossak (dt 2 ms). Skirt radius at the end of each run, and their "
             "difference relative to the implicit one.", "",
             "| element size (ft) | triangles | equations | explicit step (s) | implicit: steps, "
             "Newton/step | implicit wall per simulated s | explicit wall per simulated s | "
             "implicit / explicit | skirt radius implicit / explicit (ft) | difference | load |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(
            f"| {r['element_size_ft']} | {r['triangles']} | {r['equations']} | "
            f"{r['explicit_step']:.3g} | {r['implicit_steps']}, {r['implicit_newton_per_step']} | "
            f"{r['implicit_wall_per_s']} | {r['explicit_wall_per_s']} | "
            f"{r['ratio_implicit_over_explicit']} | {r['implicit_skirt_end']} / "
            f"{r['explicit_skirt_end']} | {100 * r['skirt_difference']:.1f} % | "
            f"{r['implicit_load']} / {r['explicit_load']} |")
    text = "\n".join(lines) + "\n"
    open(os.path.join(RESULTS, "explicit_crossover.md"), "w").write(text)
    print(text)
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    plt.figure(figsize=(5.5, 4))
    hs = [r["element_size_ft"] for r in rows]
    plt.loglog(hs, [r["implicit_wall_per_s"] for r in rows], "o-", label="Bossak, dt 2 ms")
    plt.loglog(hs, [r["explicit_wall_per_s"] for r in rows], "s-",
               label="central differences, safety 0.9")
    plt.gca().invert_xaxis()
    plt.xlabel("canopy element size, ft (finer to the right)")
    plt.ylabel("wall time per simulated second, s")
    plt.title("half-scale C-9 with slider: cost against mesh size")
    plt.grid(True, which="both", alpha=0.3)
    plt.legend()
    plt.tight_layout()
    plt.savefig(os.path.join(RESULTS, "explicit_crossover.png"), dpi=110)


if __name__ == "__main__":
    main()

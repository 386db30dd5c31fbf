#!/usr/bin/python3
"""Work-precision of the verification cases (issue 8, item 1): for pulley, bead_1 and bead_5,
sweep the time step over more than two decades, rho_inf in (1, 0.9, 0.6) and the mass matrix
(lumped, consistent); for each point the median wall time of N runs (in one sitting) and the
maximum error against the case's independent reference. Writes bench/results/work_precision.csv,
one PNG per case (error against run time, log-log, one curve per setting) and
bench/results/work_precision_orders.csv (observed order in dt per setting).

Probes are compared at a common output interval of 0.05 s for every dt (the reference error is
the maximum over those times), so steps up to 0.05 s are not cut by the output clock.

    /usr/bin/python3 bench/work_precision.py [--runs 3] [--quick]
"""
import argparse, csv, json, math, os, statistics, subprocess, tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CHUTE = os.path.join(ROOT, "build", "bin", "chute")
RESULTS = os.environ.get("CHUTE_BENCH_RESULTS", os.path.join(ROOT, "bench", "results"))
CASES = ["pulley", "bead_1", "bead_5"]
DTS = [2e-4, 5e-4, 1e-3, 2e-3, 5e-3, 1e-2, 2e-2, 5e-2]
RHOS = [1.0, 0.9, 0.6]
MASSES = ["lumped", "consistent"]
OUTPUT_INTERVAL = 0.05


def run(case, sets, runs):
    walls, summary = [], None
    for _ in range(runs):
        with tempfile.TemporaryDirectory() as out:
            cmd = [CHUTE, "run", os.path.join(ROOT, "cases", case + ".toml"), "--out", out, "--quiet"]
            for s in sets:
                cmd += ["--set", s]
            p = subprocess.run(cmd, capture_output=True, text=True)
            summary = json.load(open(os.path.join(out, "summary.json")))
            if p.returncode != 0:
                return None, summary
            walls.append(summary["wall_time"]["total"])
    return statistics.median(walls), summary


def fit_order(points):
    """Least-squares slope of log(error) against log(dt) over the points above the error floor
    (the smallest errors, where round-off and the reference's own tolerance dominate, are left
    out once the curve flattens)."""
    pts = sorted((dt, e) for dt, e in points if e > 0 and math.isfinite(e))
    while len(pts) >= 3:
        xs = [math.log(d) for d, _ in pts]
        ys = [math.log(e) for _, e in pts]
        # Drop the smallest-dt point while the first segment is much flatter than the rest.
        s0 = (ys[1] - ys[0]) / (xs[1] - xs[0])
        s_rest = (ys[-1] - ys[1]) / (xs[-1] - xs[1])
        if s0 < 0.5 * s_rest:
            pts = pts[1:]
            continue
        break
    if len(pts) < 2:
        return float("nan"), 0
    xs = [math.log(d) for d, _ in pts]
    ys = [math.log(e) for _, e in pts]
    mx, my = statistics.fmean(xs), statistics.fmean(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx, len(pts)


def plot(case, rows, orders):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(8, 5.5))
    for rho in RHOS:
        for mass in MASSES:
            pts = [r for r in rows if r["case"] == case and r["rho_inf"] == rho and r["mass"] == mass
                   and r["status"] == "completed"]
            pts.sort(key=lambda r: r["wall_median_s"])
            if not pts:
                continue
            order = orders[(case, rho, mass)]
            ax.loglog([r["wall_median_s"] for r in pts], [100 * r["relative_max_error"] for r in pts],
                      "o-" if mass == "lumped" else "s--",
                      label=f"rho_inf={rho:g}, {mass} (order {order:.2f})")
    ax.set_xlabel("wall time [s] (median)")
    ax.set_ylabel("max error [% of the motion]")
    ax.set_title(f"{case}: error against run time, dt from {DTS[0]:g} to {DTS[-1]:g}")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    path = os.path.join(RESULTS, f"work_precision_{case}.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--quick", action="store_true", help="one case, fewer points (a smoke test)")
    args = ap.parse_args()
    cases, dts = (["bead_1"], DTS[2::2]) if args.quick else (CASES, DTS)
    rows = []
    for case in cases:
        for rho in RHOS:
            for mass in MASSES:
                for dt in dts:
                    sets = [f"solver.dt={dt}", f"solver.rho_inf={rho}", f"solver.mass={mass}",
                            f"output.interval={OUTPUT_INTERVAL}"]
                    wall, s = run(case, sets, args.runs)
                    ref = s.get("reference", {})
                    rows.append({
                        "case": case, "dt": dt, "rho_inf": rho, "mass": mass,
                        "status": s["status"] if wall is not None else "failed",
                        "wall_median_s": wall if wall is not None else float("nan"),
                        "steps": s["steps"], "rejected": s["rejected_steps"],
                        "event_retries": s["event_retries"],
                        "newton_per_step": s["newton_iterations_per_step"],
                        "relative_max_error": ref.get("relative_max_error", float("nan")),
                    })
                    r = rows[-1]
                    print(f"{case:7s} rho_inf={rho:<4g} {mass:10s} dt={dt:<7g} {r['status']:9s} "
                          f"wall {1e3 * r['wall_median_s']:8.2f} ms  Newton/step "
                          f"{r['newton_per_step']:.2f}  error {100 * r['relative_max_error']:.5f} %",
                          flush=True)
    os.makedirs(RESULTS, exist_ok=True)
    with open(os.path.join(RESULTS, "work_precision.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    orders, order_rows = {}, []
    for case in cases:
        for rho in RHOS:
            for mass in MASSES:
                pts = [(r["dt"], r["relative_max_error"]) for r in rows
                       if r["case"] == case and r["rho_inf"] == rho and r["mass"] == mass
                       and r["status"] == "completed"]
                order, used = fit_order(pts)
                orders[(case, rho, mass)] = order
                order_rows.append({"case": case, "rho_inf": rho, "mass": mass,
                                   "observed_order": round(order, 3), "points_fitted": used})
                print(f"{case:7s} rho_inf={rho:<4g} {mass:10s} observed order {order:.2f} "
                      f"({used} points)")
    with open(os.path.join(RESULTS, "work_precision_orders.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(order_rows[0].keys()))
        w.writeheader()
        w.writerows(order_rows)
    try:
        for case in cases:
            print("wrote", plot(case, rows, orders))
    except ImportError:
        print("matplotlib missing (Debian python3-matplotlib): CSV written, no plots")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Plots of the scaling and peer benchmarks from their CSV files (issue 8):
  bench/results/scaling.csv        -> scaling.png (time per Newton iteration split into assembly,
                                      sliding search, factorisation, solve, and the floor of one
                                      factorisation, against dof, log-log, fitted exponents) and
                                      scaling_memory.png (peak resident memory against dof);
  bench/results/peer_calculix.csv  -> peer_calculix.png (wall time of chute and CalculiX per case,
                                      with the agreement printed over each pair).
Prints the fitted exponents and writes them to bench/results/scaling_fit.csv.

    /usr/bin/python3 bench/plot_results.py
"""
import csv, math, os, sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RESULTS = os.environ.get("CHUTE_BENCH_RESULTS", os.path.join(ROOT, "bench", "results"))



def finish(plt, fig, ax, name, grid=True):
    """Legend (and log grid), tight layout, written to RESULTS/name and closed."""
    if grid:
        ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, name), dpi=110)
    plt.close(fig)

def fit_exponent(xs, ys):
    """Least-squares slope of log y against log x (positive values only)."""
    pts = [(math.log(x), math.log(y)) for x, y in zip(xs, ys) if x > 0 and y > 0]
    if len(pts) < 2:
        return float("nan")
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx if sxx > 0 else float("nan")


def scaling(plt):
    path = os.path.join(RESULTS, "scaling.csv")
    if not os.path.exists(path):
        print("no", path)
        return
    rows = sorted(csv.DictReader(open(path)), key=lambda r: int(r["dof"]))
    dof = [int(r["dof"]) for r in rows]
    series = [("total per iteration", "total_s_per_it", "k-o"),
              ("assembly", "assembly_s_per_it", "C0-s"),
              ("sliding search", "search_s_per_it", "C4-^"),
              ("factorisation", "factorisation_s_per_it", "C1-d"),
              ("solve", "solve_s_per_it", "C2-v"),
              ("floor: one factorisation alone", "floor_factorisation_s", "k--")]
    fits = []
    fig, ax = plt.subplots(figsize=(7.5, 5.2))
    for label, key, style in series:
        ys = [float(r[key]) for r in rows]
        p = fit_exponent(dof, ys)
        fits.append({"series": key, "exponent": round(p, 3) if p == p else ""})
        shown = [(d, y) for d, y in zip(dof, ys) if y > 0]
        if shown:
            ax.plot(*zip(*shown), style, label=f"{label} (~ dof^{p:.2f})" if p == p else label)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("degrees of freedom")
    ax.set_ylabel("seconds per Newton iteration")
    ax.set_title("Pressurised canopy with 28 lines: cost of a Newton iteration")
    finish(plt, fig, ax, "scaling.png")

    fig, ax = plt.subplots(figsize=(6, 4))
    mem = [float(r["peak_rss_mb"]) for r in rows]
    p = fit_exponent(dof, mem)
    fits.append({"series": "peak_rss_mb", "exponent": round(p, 3)})
    ax.loglog(dof, mem, "C3-o", label=f"peak resident memory (~ dof^{p:.2f})")
    ax.set_xlabel("degrees of freedom")
    ax.set_ylabel("MB")
    finish(plt, fig, ax, "scaling_memory.png")
    ratios = ", ".join(f"{d}: {float(r['ratio_to_floor']):.2f}" for d, r in zip(dof, rows))
    print("iteration / one factorisation by dof:", ratios)
    with open(os.path.join(RESULTS, "scaling_fit.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["series", "exponent"])
        w.writeheader()
        w.writerows(fits)
    for x in fits:
        print(f"  {x['series']}: exponent {x['exponent']}")


def peer(plt):
    path = os.path.join(RESULTS, "peer_calculix.csv")
    if not os.path.exists(path):
        print("no", path)
        return
    rows = list(csv.DictReader(open(path)))
    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    x = range(len(rows))
    chute = [float(r["chute_wall"]) for r in rows]
    ccx = [float(r["ccx_wall_1t"]) for r in rows]
    ax.bar([i - 0.2 for i in x], chute, 0.4, label="chute")
    ax.bar([i + 0.2 for i in x], ccx, 0.4, label="CalculiX (1 thread)")
    for i, r in enumerate(rows):
        ax.annotate(f"{float(r['ratio_1t']):.1f}x\ndiff {float(r['max_diff_rel']):.1e}",
                    (i, max(chute[i], ccx[i])), ha="center", va="bottom", fontsize=8)
    ax.set_xticks(list(x))
    ax.set_xticklabels([f"{r['case']}\n{r['dof']} dof" for r in rows], fontsize=8)
    ax.set_yscale("log")
    ax.set_ylabel("wall time (s, median)")
    ax.set_title("Peer problem: wall time and displacement difference / max displacement")
    finish(plt, fig, ax, "peer_calculix.png", grid=False)


def main():
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib missing (Debian python3-matplotlib: bash bench/install-bench-deps.sh)")
        return 1
    scaling(plt)
    peer(plt)
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""The acceptance figures of issue 8 from the benchmark CSVs, as one markdown table:
bench/results/summary.md and the summary section of bench/README.md (bench/run_all runs it last). Every number is read from a CSV the other
scripts wrote in the same sitting; nothing is typed in.

    /usr/bin/python3 bench/summarize.py
"""
import csv, os

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RESULTS = os.environ.get("CHUTE_BENCH_RESULTS", os.path.join(ROOT, "bench", "results"))


def rows(name):
    path = os.path.join(RESULTS, name)
    return list(csv.DictReader(open(path))) if os.path.exists(path) else []


def summary_table():
    """The acceptance table (markdown), every number read from the CSVs of bench/results."""
    out = ["| figure | required | measured | source |", "|---|---|---|---|"]
    wp = [r for r in rows("work_precision.csv") if r["status"] == "completed"]
    ok = [r for r in wp if r["case"] == "bead_5" and float(r["relative_max_error"]) <= 0.005]
    if ok:
        best = min(ok, key=lambda r: float(r["wall_median_s"]))
        out.append(f"| bead_5 at <= 0.5 % error: fastest run | < 1 s | {1e3 * float(best['wall_median_s']):.1f} ms "
                   f"(dt {best['dt']}, rho_inf {best['rho_inf']}, {best['mass']} mass, error "
                   f"{100 * float(best['relative_max_error']):.3f} %) | work_precision.csv |")
    orders = rows("work_precision_orders.csv")
    for case in ("pulley", "bead_1", "bead_5"):
        o = [float(r["observed_order"]) for r in orders if r["case"] == case and r["mass"] == "lumped"]
        if o:
            out.append(f"| observed order in dt, {case} (lumped; rho_inf 1 / 0.9 / 0.6) | ~2 | "
                       + " / ".join(f"{x:.2f}" for x in o) + " | work_precision_orders.csv |")
    sc = rows("scaling.csv")
    if sc:
        big = max(sc, key=lambda r: int(r["dof"]))
        near100k = min(sc, key=lambda r: abs(int(r["dof"]) - 100000))
        for r in sorted({id(big): big, id(near100k): near100k}.values(), key=lambda r: int(r["dof"])):
            out.append(f"| Newton iteration / one factorisation, {int(r['dof'])} dof | <= 2 | "
                       f"{float(r['ratio_to_floor']):.2f} ({float(r['total_s_per_it']):.2f} s vs "
                       f"{float(r['floor_factorisation_s']):.2f} s; peak {float(r['peak_rss_mb']):.0f} MB) | scaling.csv |")
    fits = {r["series"]: r["exponent"] for r in rows("scaling_fit.csv")}
    if fits:
        out.append(f"| fitted exponent of cost per iteration in dof (total / assembly / factorisation / solve) | | "
                   f"{fits.get('total_s_per_it')} / {fits.get('assembly_s_per_it')} / "
                   f"{fits.get('factorisation_s_per_it')} / {fits.get('solve_s_per_it')} | scaling_fit.csv |")
    for r in rows("peer_calculix.csv"):
        out.append(f"| CalculiX / chute wall time, {r['case']} ({r['dof']} dof) | >= 1 at equal agreement | "
                   f"{float(r['ratio_1t']):.1f} (1 thread), max difference {float(r['max_diff_rel']):.1e} of the largest "
                   f"displacement | peer_calculix.csv |")
    for r in rows("output_cost.csv"):
        extra = ""
        if "file_create_floor_us" in r:
            extra = (f"; creating one file of a frame's size costs {r['file_create_floor_us']} us = "
                     f"{r['floor_share_of_step_pct']} % of a step")
        out.append(f"| VTU at every step, {r['case']} ({r['frames']} frames, {r['us_per_step_without']} us a step) | "
                   f"< 20 % (pulley) | run {r['slowdown_pct']} % longer (loop), process {r['process_slowdown_pct']} %"
                   f"{extra} | output_cost.csv |")
    for r in rows("stress.csv"):
        out.append(f"| stress: {r['case']} | completes with energy bounded, or stops unstable (exit 3) | {r['status']}, drift {float(r['relative_drift']):.1e}, "
                   f"{r['rejected']} rejected, {r['handovers']} hand-overs | stress.csv |")
    machine = os.path.join(RESULTS, "machine.txt")
    text = "\n".join(out) + "\n"
    if os.path.exists(machine):
        loads = [l.split("load ")[1].split(",")[0] for l in open(machine) if "load " in l]
        text += f"\nMachine load (1-, 5-, 15-min) during the runs: {loads[0]} ... {loads[-1]} (bench/results/machine.txt).\n"
    return text


def main():
    text = summary_table()
    open(os.path.join(RESULTS, "summary.md"), "w").write(text)
    # The table also goes into bench/README.md between its summary markers (full runs only).
    readme = os.path.join(ROOT, "bench", "README.md")
    if os.path.samefile(RESULTS, os.path.join(ROOT, "bench", "results")) and os.path.exists(readme):
        doc = open(readme).read()
        a, b = "<!-- summary -->", "<!-- /summary -->"
        if a in doc:
            head, rest = doc.split(a, 1)
            tail = rest.split(b, 1)[1] if b in rest else rest
            open(readme, "w").write(head + a + "\n" + text + b + tail)
    print(text)


if __name__ == "__main__":
    main()

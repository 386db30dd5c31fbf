#!/usr/bin/env python3
"""chute's explicit step per canopy triangle against the lean fused canopy loop, at four mesh
sizes of the generated full-scale C-9 (28 gores, D0 = 28 ft, 23 ft lines, free flight from line
stretch as `chute mesh parachute` writes it): one bench_lean_canopy_step run per size (it times
both in one process), and the scaling table: triangles, steps per simulated second, ns per
triangle-step, CPU per simulated second, peak memory, and the exponents of steps and CPU per
simulated second against the number of triangles (least squares on the logs).

    python3 bench/speed/run.py [--sizes 0.7,0.5,0.35,0.25] [--steps 300] [--repeat 5] [--bin DIR]
writes bench/results/lean_canopy_step.md and .csv.
"""
import argparse
import json
import math
import os
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BIN = os.path.join(ROOT, "build", "bin")


def fit(xs, ys):
    lx = [math.log(x) for x in xs]
    ly = [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--sizes", default="0.7,0.5,0.35,0.25", help="element sizes in ft")
    ap.add_argument("--steps", type=int, default=300)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--bin", default=BIN, help="the directory of chute and bench_lean_canopy_step")
    a = ap.parse_args()
    work = tempfile.mkdtemp(prefix="chute_lean_")
    rows = []
    for size in [float(s) for s in a.sizes.split(",")]:
        msh, case = os.path.join(work, "c9_%g.msh" % size), os.path.join(work, "c9_%g.toml" % size)
        subprocess.run([os.path.join(a.bin, "chute"), "mesh", "parachute", "--gores", "28",
                        "--diameter", "28", "--vent-diameter", "1.4", "--line-length", "23",
                        "--line-elements", "8", "--element-size", str(size), "--payload-mass",
                        "7.05", "--start", "folded", "--units", "ft", "--t-end", "1",
                        "--speed", "65.6168", "--out", msh, "--case", case, "--quiet"], check=True)
        # One thread: CPU per step without the second thread's polling (docs/performance.md).
        env = dict(os.environ, CHUTE_THREADS="1")
        out = subprocess.run([os.path.join(a.bin, "bench_lean_canopy_step"), case, "--steps",
                              str(a.steps), "--repeat", str(a.repeat)], check=True,
                             capture_output=True, text=True, env=env).stdout
        r = json.loads(out.strip().splitlines()[-1])
        r["size_ft"] = size
        rows.append(r)
        print(json.dumps(r))
    tri = [r["triangles"] for r in rows]
    e_steps = fit(tri, [r["steps_per_simulated_s"] for r in rows])
    e_cpu = fit(tri, [r["cpu_per_simulated_s"] for r in rows])
    keys = ["size_ft", "triangles", "steps_per_simulated_s", "lean_ns_per_triangle",
            "chute_ns_per_triangle_step", "ratio", "cpu_per_simulated_s", "peak_rss_MiB"]
    res = os.path.join(ROOT, "bench", "results")
    with open(os.path.join(res, "lean_canopy_step.csv"), "w") as f:
        f.write(",".join(keys) + "\n")
        for r in rows:
            f.write(",".join(str(r[k]) for k in keys) + "\n")
    simd = ("are taken one at a time (`CHUTE_SIMD=baseline`)" if os.environ.get("CHUTE_SIMD") == "baseline"
            else "take their four-lane AVX2 copy where the processor has it (kernels/MembraneTriangleBatch.hpp)")
    with open(os.path.join(res, "lean_canopy_step.md"), "w") as f:
        f.write("# chute's explicit step against a lean fused canopy loop\n\n")
        f.write("Made by `bench/speed/run.py` (steps %d, medians of %d): the generated full-scale C-9 "
                "(free flight, loads from the airflow) at four element sizes. `lean`: CPU ns per "
                "triangle of one fused pass (membrane with branch-free wrinkling, pressure, face "
                "drag); `chute`: CPU ns per canopy triangle of chute's whole explicit step (every "
                "term, lines included, the update, the energy balance, the stable step), from two "
                "runs' difference, on one thread (`CHUTE_THREADS=1`); both as the CPU time of that thread (the BLAS library's worker spins for about 0.1 s after start-up: in the process's time it inflated the first lean measurement 1.5-2x). The lean loop is built for the baseline instruction set; chute's membranes %s.\n\n"
                % (a.steps, a.repeat, simd))
        f.write("| element size ft | triangles | steps per simulated s | lean ns/triangle | chute "
                "ns/triangle-step | ratio | CPU s per simulated s | peak RSS MiB |\n"
                "|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            f.write("| %g | %d | %.0f | %.1f | %.1f | %.2f | %.3g | %.0f |\n" % tuple(
                r[k] for k in keys))
        f.write("\nExponents against triangles: steps per simulated second ^%.2f, CPU per "
                "simulated second ^%.2f.\n" % (e_steps, e_cpu))
    print("exponents: steps %.2f, cpu %.2f" % (e_steps, e_cpu))


if __name__ == "__main__":
    main()

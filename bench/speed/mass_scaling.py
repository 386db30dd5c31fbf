#!/usr/bin/env python3
"""Selective mass scaling (solver.mass_scaling_quantile, docs/explicit.md): steps, nodes given
mass, mass added and the effect on the answer, on the C-9 slider case and on the generated
folded full-scale C-9.

    python3 bench/speed/mass_scaling.py [--quantiles 0.05,0.1] [--generated-size 0.35]

Writes bench/results/mass_scaling.md. The C-9 slider case: 1 s with each quantile, against the
run without (q = 0) and the run at half the step (safety factor 0.45), skirt radius (probe
skirt.mean). The generated C-9: 1 s from line stretch with q = 0.01, against q = 0 and against a
safety factor of 0.85 (how far a perturbation of the step alone moves its chaotic opening).
"""
import argparse
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from chute_run import run_case  # noqa: E402
CHUTE = os.environ.get("CHUTE_BIN", os.path.join(ROOT, "build/bin/chute"))


def run(case, out, sets):
    return run_case(CHUTE, case, out, sets, check=True)


def series(rows, key):
    return {round(float(r["t"]), 6): float(r[key]) for r in rows}


def at(rows, key, t):
    return float(min(rows, key=lambda r: abs(float(r["t"]) - t))[key])


def largest_relative(a, b, key, t_max):
    A, B = series(a, key), series(b, key)
    return max(abs(A[t] - B[t]) / abs(B[t]) for t in A if t in B and t <= t_max and B[t] != 0)


def largest_of_scale(a, b, key):
    A, B = series(a, key), series(b, key)
    scale = max(abs(v) for v in B.values())
    return max(abs(A[t] - B[t]) for t in A if t in B) / scale


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quantiles", default="0.05,0.1")
    ap.add_argument("--generated-size", default="0.35", help="element size of the generated C-9, ft")
    ap.add_argument("--out", default=os.path.join(ROOT, "bench/results/mass_scaling.md"))
    a = ap.parse_args()
    w = tempfile.mkdtemp(prefix="chute_mass_scaling_")
    lines = ["# Selective mass scaling: what it saves and what it moves", "",
             "Made by `bench/speed/mass_scaling.py`. Steps, nodes given mass and mass added are "
             "exact counts of one run each; skirt radius from the probe `skirt.mean`.", ""]

    # The C-9 slider case.
    case = os.path.join(ROOT, "cases/c9_slider.toml")
    base = ["solver.t_end=1.0"]
    s0, r0 = run(case, os.path.join(w, "q0"), base)
    _, ref = run(case, os.path.join(w, "half"), base + ["solver.safety_factor=0.45"])
    n = s0["explicit"]["nodal_stable_steps"]
    lines += ["## `cases/c9_slider.toml`, 1 s", "",
              "Nodal stable steps at the start: least %.3e s, 1 %% %.3e, 10 %% %.3e, median %.3e." % (
                  n["least"], n["quantile_01"], n["quantile_10"], n["median"]), "",
              "| q | steps | target_dt s | nodes given mass | mass added / canopy's | skirt at 0.5 s vs q = 0 | at 1.0 s | largest vs half step, to 0.5 s | to 1.0 s |",
              "|---|---|---|---|---|---|---|---|---|"]
    lines.append("| 0 | %d | — | 0 | 0 | — | — | %.2f %% | %.2f %% |" % (
        s0["steps"], 100 * largest_relative(r0, ref, "skirt.mean", 0.5),
        100 * largest_relative(r0, ref, "skirt.mean", 1.0)))
    for q in a.quantiles.split(","):
        s, r = run(case, os.path.join(w, "q" + q), base + ["solver.mass_scaling_quantile=" + q])
        e = s["explicit"]
        part = sum(e["scaled_parts_mass"].values()) or float("nan")
        lines.append("| %s | %d | %.3e | %d | %.2f %% | %+.2f %% | %+.2f %% | %.2f %% | %.2f %% |" % (
            q, s["steps"], e["target_dt"], e["scaled_nodes"], 100 * e["added_mass_total"] / part,
            100 * (at(r, "skirt.mean", 0.5) / at(r0, "skirt.mean", 0.5) - 1),
            100 * (at(r, "skirt.mean", 1.0) / at(r0, "skirt.mean", 1.0) - 1),
            100 * largest_relative(r, ref, "skirt.mean", 0.5),
            100 * largest_relative(r, ref, "skirt.mean", 1.0)))

    # The generated folded full-scale C-9.
    msh, gen = os.path.join(w, "c9.msh"), os.path.join(w, "c9.toml")
    subprocess.run([CHUTE, "mesh", "parachute", "--gores", "28", "--diameter", "28",
                    "--vent-diameter", "1.4", "--line-length", "23", "--line-elements", "8",
                    "--element-size", a.generated_size, "--payload-mass", "7.05", "--start",
                    "folded", "--units", "ft", "--t-end", "1", "--speed", "65.6168", "--out", msh,
                    "--case", gen, "--quiet"], check=True)
    g0, q0 = run(gen, os.path.join(w, "g0"), [])
    g1, q1 = run(gen, os.path.join(w, "g1"), ["solver.mass_scaling_quantile=0.01"])
    g2, q2 = run(gen, os.path.join(w, "g2"), ["solver.safety_factor=0.85"])
    n = g0["explicit"]["nodal_stable_steps"]
    e = g1["explicit"]
    part = sum(e["scaled_parts_mass"].values()) or float("nan")
    lines += ["", "## Generated folded full-scale C-9 (element size %s ft), 1 s from line stretch" %
              a.generated_size, "",
              "Nodal stable steps at the start: least %.3e s, 1 %% %.3e (least / 1 %%: %.2f), 10 %% %.3e, median %.3e." % (
                  n["least"], n["quantile_01"], n["least"] / n["quantile_01"], n["quantile_10"], n["median"]), "",
              "| run | steps | nodes given mass | mass added / canopy's | peak opening force | largest difference from q = 0 (of the largest value): skirt radius | volume | opening force |",
              "|---|---|---|---|---|---|---|---|"]
    pk = lambda s: s.get("flight", {}).get("peak_opening_force", float("nan"))
    lines.append("| q = 0 | %d | 0 | 0 | %.1f | — | — | — |" % (g0["steps"], pk(g0)))
    for label, s, r, nodes, added in (("q = 0.01", g1, q1, e["scaled_nodes"], e["added_mass_total"] / part),
                                      ("q = 0, safety 0.85", g2, q2, 0, 0.0)):
        lines.append("| %s | %d | %d | %.2f %% | %.1f | %.0f %% | %.0f %% | %.0f %% |" % (
            label, s["steps"], nodes, 100 * added, pk(s),
            100 * largest_of_scale(r, q0, "skirt.mean"), 100 * largest_of_scale(r, q0, "canopy.volume"),
            100 * largest_of_scale(r, q0, "opening_force.magnitude")))
    with open(a.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""The full-scale C-9's flight figures under round-off: how far a 1e-12 change moves them.

    python3 bench/flight/roundoff_ensemble.py [--runs 6] [--case cases/c9_flight.toml]

The case (a folded canopy opening from line stretch) is run as given and with its stiffness
damping multiplied by 1 + k 1e-12 (k = 1 .. runs), which changes no physics; two runs at a time on
one thread each. Its summary's flight figures (docs/flight.md) are tabulated run by run with
their least, median and largest. Writes bench/results/c9_flight_roundoff.md. CHUTE_BIN names
another chute binary (default build/bin/chute).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from roundoff import damping_sets  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CHUTE = os.environ.get("CHUTE_BIN", os.path.join(ROOT, "build/bin/chute"))
FIGURES = [("steady_descent_speed", "descent", 3), ("drag_coefficient", "C_D0", 4),
           ("projected_diameter_ratio", "D_p/D0", 4), ("filling_distance", "n", 2),
           ("peak_opening_force", "peak force", 1), ("peak_opening_force_time", "at s", 2)]


def run(case, k, out):
    cmd = [CHUTE, "run", case, "--out", out, "--quiet"]
    for s in damping_sets(case, k):
        cmd += ["--set", s]
    subprocess.run(cmd, check=True, capture_output=True, env=dict(os.environ, CHUTE_THREADS="1"))
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)["flight"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--runs", type=int, default=6)
    ap.add_argument("--case", default=os.path.join(ROOT, "cases/c9_flight.toml"))
    ap.add_argument("--out", default=os.path.join(ROOT, "bench/results/c9_flight_roundoff.md"))
    args = ap.parse_args()
    tmp = tempfile.mkdtemp(prefix="flight_roundoff_")
    ks = list(range(args.runs + 1))
    with ThreadPoolExecutor(max_workers=2) as pool:
        flights = list(pool.map(lambda k: run(args.case, k, os.path.join(tmp, str(k))), ks))
    head = "| run | " + " | ".join(label for _, label, _ in FIGURES) + " |"
    lines = ["# The full-scale C-9's flight figures under round-off", "",
             f"Made by `bench/flight/roundoff_ensemble.py`: `{os.path.relpath(args.case, ROOT)}` "
             "run as given (k = 0) and with its stiffness damping multiplied by 1 + k 1e-12, "
             "which changes no physics. Descent in the case's units (ft/s), peak force in lbf.", "",
             head, "|" + "---|" * (len(FIGURES) + 1)]
    for k, f in zip(ks, flights):
        lines.append(f"| k = {k} | " + " | ".join(f"{f[key]:.{d}f}" for key, _, d in FIGURES) + " |")
    for label, fn in (("least", min), ("median", statistics.median), ("largest", max)):
        lines.append(f"| {label} | " + " | ".join(
            f"{fn(f[key] for f in flights):.{d}f}" for key, _, d in FIGURES) + " |")
    lines.append("")
    out = "\n".join(lines)
    print(out)
    with open(args.out, "w") as f:
        f.write(out)


if __name__ == "__main__":
    main()

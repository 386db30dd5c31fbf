#!/usr/bin/env python3
"""How far round-off alone moves the C-9 slider case's answer: the band a change of the explicit
step must be judged against.

    python3 bench/speed/roundoff_band.py [--runs 10] [--reference BIN] [--candidate NAME=BIN[:SET...]]

The folded C-9 opens chaotically: a perturbation at round-off grows about e-fold every 5 ms of
its opening (docs/performance.md). Each ensemble run is `cases/c9_slider.toml` to 1 s with the
stiffness damping multiplied by 1 + k 1e-12 (k = 1 .. runs), which changes no physics; every
configuration (the reference binary, and each candidate: another binary, or one with --set
overrides separated by ':') is run so, and the medians and spreads of the skirt radius (probe
skirt.mean) at 0.5 s and 1.0 s are set side by side. Writes
bench/results/c9_slider_roundoff_band.md.
"""
import argparse
import csv
import os
import statistics
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from roundoff import damping_sets  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CASE = os.path.join(ROOT, "cases/c9_slider.toml")
TIMES = (0.5, 1.0)


def skirt(binary, sets, out):
    cmd = [binary, "run", CASE, "--out", out, "--quiet", "--set", "solver.t_end=1.0",
           "--set", "output.vtu.interval=1.0"]
    for s in sets:
        cmd += ["--set", s]
    env = dict(os.environ, CHUTE_THREADS="1")  # two runs at once, one core each
    subprocess.run(cmd, check=True, capture_output=True, env=env)
    with open(os.path.join(out, "probes.csv")) as f:
        rows = list(csv.DictReader(f))
    value = {}
    for t in TIMES:
        row = min(rows, key=lambda r: abs(float(r["t"]) - t))
        assert abs(float(row["t"]) - t) < 1e-9, f"no probe row at t = {t}"
        value[t] = float(row["skirt.mean"])
    return value


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--runs", type=int, default=10)
    ap.add_argument("--reference", default=os.path.join(ROOT, "build/bin/chute"))
    ap.add_argument("--candidate", action="append", default=[],
                    help="NAME=BIN[:SET...] (BIN empty: the reference binary)")
    ap.add_argument("--out", default=os.path.join(ROOT, "bench/results/c9_slider_roundoff_band.md"))
    args = ap.parse_args()
    tmp = tempfile.mkdtemp(prefix="roundoff_band_")
    configs = [("reference", args.reference, [])]
    for c in args.candidate:
        name, spec = c.split("=", 1)
        parts = spec.split(":")
        configs.append((name, parts[0] or args.reference, parts[1:]))
    # Every configuration: its unperturbed run (k = 0) and its ensemble (k = 1 .. runs).
    jobs = []
    for ci, (name, binary, sets) in enumerate(configs):
        for k in range(args.runs + 1):
            jobs.append((ci, k, binary, sets + damping_sets(CASE, k),
                         os.path.join(tmp, f"{ci}_{k}")))
    with ThreadPoolExecutor(max_workers=2) as pool:
        values = list(pool.map(lambda j: skirt(j[2], j[3], j[4]), jobs))
    runs = {}
    for j, v in zip(jobs, values):
        runs.setdefault(j[0], []).append(v)
    ref_median = {t: statistics.median(r[t] for r in runs[0]) for t in TIMES}
    lines = ["# C-9 slider case: the band round-off alone moves the skirt radius in", "",
             "Made by `bench/speed/roundoff_band.py`. Each configuration is run "
             f"{args.runs + 1} times, `cases/c9_slider.toml` to 1 s, once as given and with its "
             "stiffness damping multiplied by 1 + k 1e-12 (k = 1 .. "
             f"{args.runs}), which changes no physics: the skirt radius (probe skirt.mean) of "
             "those runs is the spread round-off alone gives the case's chaotic opening. "
             "Relative differences are against the reference's median.", "",
             "| configuration | at 0.5 s: median, ft | least .. largest | median vs reference's |"
             " at 1.0 s: median, ft | least .. largest | median vs reference's |",
             "|---|---|---|---|---|---|---|"]
    for ci, (name, binary, sets) in enumerate(configs):
        row = [f"{name}" + (f" (`{' '.join(sets)}`)" if sets else "")]
        for t in TIMES:
            vals = [r[t] for r in runs[ci]]
            med = statistics.median(vals)
            row += [f"{med:.5f}",
                    f"{min(vals) / ref_median[t] - 1:+.2%} .. {max(vals) / ref_median[t] - 1:+.2%}",
                    f"{med / ref_median[t] - 1:+.3%}"]
        lines.append("| " + " | ".join(row) + " |")
    lines += ["", "Binaries: " + ", ".join(f"{name}: `{os.path.basename(binary)}`"
                                          for name, binary, _ in configs) + ".", ""]
    text = "\n".join(lines)
    print(text)
    with open(args.out, "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()

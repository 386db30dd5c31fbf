#!/usr/bin/env python3
"""Runs every shipped case (and each integrator and the coupled demo on small cases) and prints a
SHA-256 of each run's probes.csv / coupling.csv: the evidence that a change which should not move
any result (a restructuring) moved none.

    bench/identity/probe_identity.py --out before.json          # on the old tree
    bench/identity/probe_identity.py --out after.json --compare before.json

Every run's status and hash go into the JSON; --compare lists the runs whose hashes differ.
"""
import argparse
import hashlib
import json
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# (label, verb, case, extra arguments). The long C-9 runs are shortened; each integrator runs on a
# case it suits, and the coupled demo with both coupling schemes.
RUNS = [
    ("airbag", "run", "airbag", []),
    ("bead_1", "run", "bead_1", []),
    ("bead_5", "run", "bead_5", []),
    ("bead_two_ropes", "run", "bead_two_ropes", []),
    ("c9_no_slider 1s", "run", "c9_no_slider", ["--set", "solver.t_end=1.0"]),
    ("c9_slider 1s", "run", "c9_slider", ["--set", "solver.t_end=1.0"]),
    ("c9_slider bossak 0.1s", "run", "c9_slider",
     ["--set", "solver.t_end=0.1", "--set", 'solver.integrator="bossak"']),
    ("c9_payload_reorientation", "run", "c9_payload_reorientation", []),
    ("canopy_coupled", "run", "canopy_coupled", []),
    ("capstan_belt", "run", "capstan_belt", []),
    ("capstan_masses", "run", "capstan_masses", []),
    ("capstan_pulley", "run", "capstan_pulley", []),
    ("hencky", "run", "hencky", []),
    ("payload_fixed_slider", "run", "payload_fixed_slider", []),
    ("pulley", "run", "pulley", []),
    ("stress_driven_slider", "run", "stress_driven_slider", []),
    ("stress_on_node", "run", "stress_on_node", []),
    ("stress_ring28", "run", "stress_ring28", []),
    ("stress_snatch", "run", "stress_snatch", []),
    ("stress_swing50", "run", "stress_swing50", []),
    ("bead_5 energy_momentum", "run", "bead_5", ["--set", 'solver.integrator="energy_momentum"']),
    ("bead_5 energy_momentum order 4", "run", "bead_5",
     ["--set", 'solver.integrator="energy_momentum"', "--set", "solver.em_order=4",
      "--set", "solver.t_end=1.0"]),
    ("bead_1 central_difference", "run", "bead_1", ["--set", 'solver.integrator="central_difference"']),
    ("pulley central_difference", "run", "pulley", ["--set", 'solver.integrator="central_difference"']),
    ("pulley generalized_alpha", "run", "pulley", ["--set", 'solver.integrator="generalized_alpha"']),
    ("canopy_coupled generalized_alpha", "run", "canopy_coupled",
     ["--set", 'solver.integrator="generalized_alpha"']),
    ("couple implicit", "couple", "canopy_coupled", ["--quiet"]),
    ("couple explicit", "couple", "canopy_coupled", ["--quiet", "--scheme", "explicit"]),
]


def sha(path):
    if not os.path.exists(path):
        return None
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()[:16]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--chute", default=os.path.join(ROOT, "build/bin/chute"))
    ap.add_argument("--out", required=True)
    ap.add_argument("--compare")
    ap.add_argument("--only", help="labels containing this text")
    a = ap.parse_args()
    results = {}
    for label, verb, case, extra in RUNS:
        if a.only and a.only not in label:
            continue
        with tempfile.TemporaryDirectory() as d:
            cmd = [a.chute, verb, os.path.join(ROOT, "cases", case + ".toml"), "--out", d] + extra
            t0 = time.time()
            p = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
            wall = time.time() - t0
            out = {"exit": p.returncode, "wall": round(wall, 2)}
            for name in ("probes.csv", "coupling.csv"):
                h = sha(os.path.join(d, name))
                if h:
                    out[name] = h
            summ = os.path.join(d, "summary.json")
            if os.path.exists(summ):
                with open(summ) as f:
                    s = json.load(f)
                out["status"] = s.get("status")
                out["steps"] = s.get("steps")
        results[label] = out
        print(f"{label:36s} exit {out['exit']} {out.get('status', ''):10s} "
              f"{out.get('probes.csv', out.get('coupling.csv', '-'))}  {wall:7.2f} s", flush=True)
    with open(a.out, "w") as f:
        json.dump(results, f, indent=1)
    if a.compare:
        with open(a.compare) as f:
            before = json.load(f)
        # Files that only one of the two trees writes (a new output) are not compared.
        def same(a, b):
            keys = [x for x in ("probes.csv", "coupling.csv") if x in a and x in b]
            return a.get("exit") == b.get("exit") and all(a[x] == b[x] for x in keys)
        differ = [k for k in results if k in before and not same(results[k], before[k])]
        print(f"{len(results) - len(differ)} of {len(results)} identical; differ: {differ}")
        return 1 if differ else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())

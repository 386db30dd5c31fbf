"""Round-off ensembles: runs of one case that differ by round-off only.

A case's stiffness damping multiplied by 1 + k 1e-12 changes no physics, yet a chaotic run (a
folded opening, a breathing canopy) takes another course; the spread of an ensemble k = 0, 1, ...
is the band within which a figure is not resolved (docs/flight.md, bench/README.md). One function
for the scripts that make such ensembles (flight/flight_runs.py, flight/roundoff_ensemble.py,
speed/roundoff_band.py).
"""
import re


def damping_sets(case_path, k):
    """The `--set` values of run k of the ensemble of the case at case_path: none for k = 0, else
    its [solver] stiffness_damping times 1 + k 1e-12."""
    if not k:
        return []
    with open(case_path) as f:
        damping = float(re.search(r"^stiffness_damping\s*=\s*([0-9.eE+-]+)", f.read(),
                                  re.M).group(1))
    return ["solver.stiffness_damping=%.17g" % (damping * (1.0 + k * 1e-12))]

#!/usr/bin/env python3
"""Compares the flight benches' figures (bench/results/flight_*.csv, made by flight_runs.py) with
the published figures and writes bench/results/flight_validation.md.

    bench/flight/compare.py [--results bench/results] [--c9 run_dir_of_cases/c9_flight]

Published figures (docs/flight.md has the sources): solid flat circular canopies C_D0 0.75-0.80,
D_p/D0 0.67-0.70, filling distance n about 8 at infinite mass (Knacke); opening-force factor of an
8.53 m canopy at 40 m/s 1.5 (wind tunnel) to 1.54-1.6 (simulated) (Lingard); Pflanz's force
reduction X1 for a finite mass, derived below for drag area growing as (t/t_f)^j.
"""
import argparse
import csv
import json
import math
import os

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
RHO = 1.225


def rows(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [{k: _num(v) for k, v in r.items()} for r in csv.DictReader(f)]


def _num(v):
    try:
        return float(v)
    except ValueError:
        return v


def pflanz_x1(A, j):
    """Peak of F / (C_D S q0) for a mass m decelerated by a drag area C_D S (t/t_f)^j, gravity
    left out: m dv/dt = -rho/2 C_D S (t/t_f)^j v^2 gives v0/v = 1 + tau^(j+1) / ((j+1) A),
    tau = t/t_f, A = 2 m / (rho C_D S v0 t_f), and F / (C_D S q0) = tau^j (v/v0)^2, largest where
    its derivative vanishes, tau*^(j+1) = j (j+1) A / (j+2), when tau* < 1, else at tau = 1
    (j = 2: X1 = (1.5 A)^(2/3) / 2.25 below A = 2/3)."""
    tau = (j * (j + 1) * A / (j + 2)) ** (1.0 / (j + 1))
    tau = min(tau, 1.0)
    return tau ** j / (1.0 + tau ** (j + 1) / ((j + 1) * A)) ** 2


def within(v, lo, hi):
    return "yes" if lo <= v <= hi else "no (%+.1f %%)" % (100 * ((v - hi) / hi if v > hi else (v - lo) / lo))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--results", default=os.path.join(ROOT, "bench/results"))
    ap.add_argument("--c9", default="")
    ap.add_argument("--note", default="", help="a line on the trees that made the figures")
    a = ap.parse_args()
    R = a.results
    out = []
    w = out.append
    w("# Flight: chute's figures against the published ones\n")
    w("Made by `bench/flight/compare.py` from `flight_*.csv` (made by `bench/flight/flight_runs.py`;"
      " SI, sea level, 100 ft³/ft²/min cloth unless said). `C_b` = −0.83 calibrated on `d5_g20`"
      " alone ([docs/flight.md](../../docs/flight.md#calibration)); everything else is a prediction.\n")
    if a.note:
        w(a.note + "\n")

    cal = rows(os.path.join(R, "flight_calibrate.csv"))
    if cal:
        w("## Calibration (`d5_g20`, 8 s, free, inflated start)\n")
        w("| C_b | C_D0 | D_p/D0 | descent m/s |\n|---|---|---|---|")
        for r in sorted(cal, key=lambda r: -float(r["tag"][2:])):
            w("| %s | %.4f | %.4f | %.3f |" % (r["tag"][2:], r["drag_coefficient"],
                                            r["projected_diameter_ratio"], r["steady_descent_speed"]))
        w("")

    coarse = {r["tag"].rsplit("_h", 1)[0]: r for r in rows(os.path.join(R, "flight_matrix.csv"))}
    fine = {r["tag"].rsplit("_h", 1)[0]: r for r in rows(os.path.join(R, "flight_matrix_fine.csv"))}
    if coarse:
        w("## Steady descent of the matrix (free, inflated start)\n")
        w("Coarse: the matrix's element size; fine: 0.7 of it. Published: C_D0 0.75-0.80, "
          "D_p/D0 0.67-0.70 (Knacke). Change: fine against coarse.\n")
        w("| canopy | payload kg | descent m/s (fine) | C_D0 coarse | C_D0 fine | change | in 0.75-0.80 |"
          " D_p/D0 coarse | D_p/D0 fine | change | in 0.67-0.70 |\n|---|---|---|---|---|---|---|---|---|---|---|")
        for name, c in coarse.items():
            f = fine.get(name)
            if f and f.get("status") == "completed":
                w("| %s | %g | %.3f | %.4f | %.4f | %+.2f %% | %s | %.4f | %.4f | %+.2f %% | %s |" % (
                    name, c["payload"], f["steady_descent_speed"], c["drag_coefficient"],
                    f["drag_coefficient"], 100 * (f["drag_coefficient"] / c["drag_coefficient"] - 1),
                    within(f["drag_coefficient"], 0.75, 0.80), c["projected_diameter_ratio"],
                    f["projected_diameter_ratio"],
                    100 * (f["projected_diameter_ratio"] / c["projected_diameter_ratio"] - 1),
                    within(f["projected_diameter_ratio"], 0.67, 0.70)))
            else:
                w("| %s | %g | (coarse %.3f) | %.4f | — | — | %s | %.4f | — | — | %s |" % (
                    name, c["payload"], c["steady_descent_speed"], c["drag_coefficient"],
                    within(c["drag_coefficient"], 0.75, 0.80), c["projected_diameter_ratio"],
                    within(c["projected_diameter_ratio"], 0.67, 0.70)))
        w("")

    conv = rows(os.path.join(R, "flight_convergence.csv"))
    if conv:
        w("## Steady descent of the matrix, mesh-converged (ensemble means)\n")
        w("From flight_convergence.csv (`flight_runs.py convergence`, table in flight_convergence.md):"
          " per canopy the finest mesh's mean over its round-off ensemble, and the change from the"
          " next coarser mesh's mean (the criterion: within 2 %). Published: C_D0 0.75-0.80, D_p/D0"
          " 0.67-0.70 (Knacke).\n")
        w("| canopy | finest h | runs | descent m/s | C_D0 | change | in 0.75-0.80 | D_p/D0 | change |"
          " in 0.67-0.70 |\n|---|---|---|---|---|---|---|---|---|---|")
        groups = {}
        for r in conv:
            if r.get("status") != "completed":
                continue
            name, rest = r["tag"].rsplit("_h", 1)
            groups.setdefault(name, {}).setdefault(float(rest.split("_k")[0]), []).append(r)

        def mean(rs, key):
            return sum(r[key] for r in rs) / len(rs)

        for name, by_h in groups.items():
            hs = sorted(by_h)
            if len(hs) < 2:
                continue
            fine_rs, coarse_rs = by_h[hs[0]], by_h[hs[1]]
            cd, cdc = mean(fine_rs, "drag_coefficient"), mean(coarse_rs, "drag_coefficient")
            dp = mean(fine_rs, "projected_diameter_ratio")
            dpc = mean(coarse_rs, "projected_diameter_ratio")
            w("| %s | %.2f | %d | %.3f | %.4f | %+.2f %% | %s | %.4f | %+.2f %% | %s |" % (
                name, hs[0], len(fine_rs), mean(fine_rs, "steady_descent_speed"), cd,
                100 * (cd / cdc - 1), within(cd, 0.75, 0.80), dp, 100 * (dp / dpc - 1),
                within(dp, 0.67, 0.70)))
        w("")

    if a.c9 and os.path.exists(os.path.join(a.c9, "summary.json")):
        fl = json.load(open(os.path.join(a.c9, "summary.json")))["flight"]
        w("## The full-scale C-9 (`cases/c9_flight.toml`, ft)\n")
        w("| figure | chute | published | within |\n|---|---|---|---|")
        w("| descent ft/s | %.2f | about 20 (±10 %%: 18-22) | %s |" % (
            fl["steady_descent_speed"], within(fl["steady_descent_speed"], 18.0, 22.0)))
        w("| C_D0 | %.4f | 0.75-0.80 | %s |" % (fl["drag_coefficient"],
                                              within(fl["drag_coefficient"], 0.75, 0.80)))
        w("| D_p/D0 | %.4f | 0.67-0.70 | %s |" % (fl["projected_diameter_ratio"],
                                                within(fl["projected_diameter_ratio"], 0.67, 0.70)))
        w("| filling distance n | %.2f | about 8 | — |" % fl["filling_distance"])
        w("| peak force lbf (time s) | %.0f (%.2f) | — | — |\n" % (fl["peak_opening_force"],
                                                               fl["peak_opening_force_time"]))

    op = rows(os.path.join(R, "flight_opening.csv"))
    if op:
        w("## Held in a wind from a folded start (the 8.53 m C-9 canopy)\n")
        w("Published: opening-force factor C_k 1.5 (wind tunnel) and 1.54-1.6 (simulated) at 40 m/s "
          "(Lingard); filling distance n about 8 (Knacke).\n")
        w("| wind m/s | C_k = peak / steady | peak N | steady N | filling time s | n | C_D0 |\n"
          "|---|---|---|---|---|---|---|")
        for r in sorted(op, key=lambda r: r["speed"]):
            w("| %g | %.3f | %.0f | %.0f | %.2f | %.2f | %.4f |" % (
                r["speed"], r["opening_force_factor"], r["peak_opening_force"], r["steady_force"],
                r["filling_time"], r["filling_distance"], r["drag_coefficient"]))
        w("")

    pay = rows(os.path.join(R, "flight_payload.csv"))
    if pay:
        w("## Released at 40 m/s from a folded start: peak force against payload mass\n")
        w("Pflanz's X1 (gravity and apparent mass left out) with this canopy's own steady C_D S and"
          " t_f = 8 D0 / V (n = 8), for drag area growing linearly (j = 1) and quadratically (j = 2)"
          " in time. chute: peak / (C_D S q0), C_D S the run's steady drag area.\n")
        w("| payload kg | peak N | chute peak / (C_D S q0) | Pflanz X1, j = 1 | j = 2 | chute / Pflanz (j = 1) |"
          " filling time s |\n|---|---|---|---|---|---|---|")
        D0, V = 8.5344, 40.0
        tf = 8.0 * D0 / V
        for r in sorted(pay, key=lambda r: r["payload"]):
            cds = r["drag_area"]
            A = 2 * r["payload"] / (RHO * cds * V * tf)
            x = r["peak_opening_force"] / (cds * 0.5 * RHO * V * V)
            w("| %g | %.0f | %.4f | %.4f | %.4f | %.2f | %.2f |" % (
                r["payload"], r["peak_opening_force"], x, pflanz_x1(A, 1), pflanz_x1(A, 2),
                x / pflanz_x1(A, 1), r["filling_time"]))
        w("")

    por = rows(os.path.join(R, "flight_porosity.csv"))
    if por:
        w("## C_D0 against the cloth's permeability (the 8.53 m canopy, 103 kg, free)\n")
        w("Effective porosity: the cloth's velocity at the steady dynamic pressure over the descent"
          " speed (FL6, linear law).\n")
        w("| permeability ft³/ft²/min | descent m/s | effective porosity | C_D0 | D_p/D0 |\n"
          "|---|---|---|---|---|")
        for r in sorted(por, key=lambda r: float(r["tag"][4:])):
            cfm = float(r["tag"][4:])
            u_ref = cfm * 0.3048 / 60.0
            v = r["steady_descent_speed"]
            q = 0.5 * RHO * v * v
            w("| %g | %.3f | %.4f | %.4f | %.4f |" % (cfm, v, u_ref * q / 124.5 / v,
                                                      r["drag_coefficient"],
                                                      r["projected_diameter_ratio"]))
        w("")
    path = os.path.join(R, "flight_validation.md")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")
    print("\n".join(out))


if __name__ == "__main__":
    main()

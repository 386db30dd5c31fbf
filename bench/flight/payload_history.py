#!/usr/bin/env python3
"""Released at 40 m/s with 50-200 kg: where the peak force's excess over Pflanz's X1 comes from.

    bench/flight/payload_history.py [--ensemble 2] [--jobs 2] [--out bench/results]

Flies the 8.53 m canopy of `flight_runs.py payload` (folded, released at 40 m/s) with each payload
and reads its probes: the drag area the lines see, C_D S(t) = F / (rho V^2 / 2) with F the lines'
pull on the confluence and V the canopy's airspeed. The main rise of the drag area is taken as the
straight line through its first passages of 10 % and 90 % of the steady drag area: it starts at
t_s (where that line is zero) and lasts t_f' (zero to the steady value), from the airspeed v_s at
t_s. Pflanz's X1 (drag area linear in time, gravity and apparent mass left out; compare.py) is
then evaluated twice: as published (t_f = 8 D0 / 40 m/s, from the release) and with the run's own
main rise (t_f', from v_s at t_s). The run's peak over each says how much of the excess is the
timing of the inflation and how much the force at a given inflation.

Writes <out>/flight_payload_history.md and .csv.
"""
import argparse
import concurrent.futures
import csv
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import flight_runs  # noqa: E402
from compare import pflanz_x1  # noqa: E402

RHO = 1.225
D0 = 8.5344
V0 = 40.0


def first_passage(t, cds, level):
    for ti, c in zip(t, cds):
        if c >= level:
            return ti
    return None


def analyse(tag, payload, out_dir, steady_cds):
    with open(os.path.join(out_dir, "probes.csv")) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    t = [r["t"] for r in rows]
    force = [r["opening_force.magnitude"] for r in rows]
    speed = [r["canopy.airspeed"] for r in rows]
    cds = [F / (0.5 * RHO * v * v) if v > 1.0 else 0.0 for F, v in zip(force, speed)]
    ip = max(range(len(force)), key=lambda i: force[i])
    t10 = first_passage(t, cds, 0.1 * steady_cds)
    t90 = first_passage(t, cds, 0.9 * steady_cds)
    row = dict(tag=tag, payload=payload, peak=force[ip], t_peak=t[ip],
               cds_at_peak=cds[ip] / steady_cds, speed_at_peak=speed[ip], steady_cds=steady_cds,
               t10=t10, t90=t90)
    # Pflanz as published: from the release, t_f = 8 D0 / V0.
    tf = 8.0 * D0 / V0
    A = 2.0 * payload / (RHO * steady_cds * V0 * tf)
    row["pflanz_published"] = force[ip] / (pflanz_x1(A, 1) * steady_cds * 0.5 * RHO * V0 * V0)
    if t10 is None or t90 is None or t90 <= t10:
        return row
    slope = 0.8 / (t90 - t10)  # fraction of the steady drag area per second
    ts = t10 - 0.1 / slope
    tf_own = 1.0 / slope
    vs = next(v for ti, v in zip(t, speed) if ti >= ts)
    A_own = 2.0 * payload / (RHO * steady_cds * vs * tf_own)
    predicted = pflanz_x1(A_own, 1) * steady_cds * 0.5 * RHO * vs * vs
    row.update(t_start=ts, t_fill=tf_own, speed_at_start=vs, n_own=tf_own * vs / D0,
               pflanz_own=force[ip] / predicted, pflanz_own_peak=predicted)
    return row


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ensemble", type=int, default=2,
                    help="runs per payload that differ by round-off only (k = 0, 1, ...)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--payloads", default="50,100,150,200")
    ap.add_argument("--t-end", type=float, default=6.0)
    ap.add_argument("--out", default=os.path.join(flight_runs.ROOT, "bench/results"))
    a = ap.parse_args()
    m = next(x for x in flight_runs.MATRIX if x["name"].startswith("c9"))
    work = tempfile.mkdtemp(prefix="chute-payload-")
    jobs = []
    for pay in [float(x) for x in a.payloads.split(",")]:
        for k in range(a.ensemble):
            jobs.append(("payload_%g_k%d" % (pay, k), pay, k))
    rows = []
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as ex:
        futs = {ex.submit(flight_runs.generate_and_run, tag, m, work, start="folded", speed=V0,
                          payload=pay, t_end=a.t_end, perturb=k): (tag, pay)
                for tag, pay, k in jobs}
        for fu in concurrent.futures.as_completed(futs):
            tag, pay = futs[fu]
            s = fu.result()
            if s["status"] != "completed":
                rows.append(dict(tag=tag, payload=pay, status=s["status"]))
                continue
            rows.append(analyse(tag, pay, os.path.join(work, tag, "out"), s["drag_area"]))
    rows.sort(key=lambda r: (r["payload"], r["tag"]))
    keys = ["tag", "payload", "peak", "t_peak", "cds_at_peak", "speed_at_peak", "t10", "t90",
            "t_start", "t_fill", "speed_at_start", "n_own", "pflanz_published", "pflanz_own"]
    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "flight_payload_history.csv"), "w", newline="") as f:
        wr = csv.DictWriter(f, fieldnames=keys, extrasaction="ignore")
        wr.writeheader()
        wr.writerows(rows)

    def fmt(v, spec):
        return "-" if v is None else spec % v

    lines = ["# Released at 40 m/s: the peak force against the inflation's own timing", "",
             "Made by `bench/flight/payload_history.py` (%d runs per payload that differ by "
             "round-off only). The drag area the lines see, `C_D S(t) = F / (rho V^2 / 2)`; its "
             "main rise is the straight line through its first passages of 10 %% and 90 %% of "
             "the steady drag area, starting at `t_s` from the airspeed `v_s` and reaching the "
             "steady value `t_f'` later (`n' = t_f' v_s / D0`). chute's peak over Pflanz's X1 "
             "(linear drag area, gravity and apparent mass left out), as published (`n` = 8 "
             "from the release at 40 m/s) and with the run's own main rise." % a.ensemble, "",
             "| run | payload kg | peak N | at s | C_D S at peak / steady | V at peak m/s "
             "| t_10 s | t_90 s | t_s s | t_f' s | v_s m/s | n' | peak / Pflanz (n = 8) "
             "| peak / Pflanz (own rise) |",
             "|" + "---|" * 14]
    for r in rows:
        if "peak" not in r:
            lines.append("| %s | %g | %s |" % (r["tag"], r["payload"], r.get("status")))
            continue
        lines.append("| %s | %g | %.0f | %.2f | %.2f | %.1f | %s | %s | %s | %s | %s | %s | %.2f | %s |"
                     % (r["tag"], r["payload"], r["peak"], r["t_peak"], r["cds_at_peak"],
                        r["speed_at_peak"], fmt(r["t10"], "%.2f"), fmt(r["t90"], "%.2f"),
                        fmt(r.get("t_start"), "%.2f"), fmt(r.get("t_fill"), "%.2f"),
                        fmt(r.get("speed_at_start"), "%.1f"), fmt(r.get("n_own"), "%.1f"),
                        r["pflanz_published"], fmt(r.get("pflanz_own"), "%.2f")))
    text = "\n".join(lines) + "\n"
    with open(os.path.join(a.out, "flight_payload_history.md"), "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main()

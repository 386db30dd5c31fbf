#!/usr/bin/python3
"""Issue 8, item 3: the peer problem in chute and in CalculiX (ccx 2.20, Debian calculix-ccx).

The same canopy (quad membranes, St Venant-Kirchhoff, no wrinkling), the same truss lines to a
fixed confluence, the same ramped follower pressure, consistent membrane mass (the lines' mass as
point masses at their nodes in both), the same fixed dt and number of steps, HHT alpha = 0 in
CalculiX = Newmark's trapezoidal rule = chute's Bossak with rho_inf = 1. build/bin/peer_bench
builds the problem, runs chute (runCase) and writes the CalculiX deck; this script runs ccx, parses
its .dat, and compares the probe displacements (canopy apex, a rim node, a line midpoint) over
every step: max |u_chute - u_ccx| / max |u|. Wall times are medians of --runs runs (ccx: the
whole process, OMP_NUM_THREADS = 1 and 2; chute: runCase).

Writes bench/results/peer_calculix.csv and bench/results/peer_calculix.md.

    /usr/bin/python3 bench/peer/run_peer.py [--runs 3] [--quick]
"""
import argparse, csv, json, os, re, statistics, subprocess, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BENCH = os.path.join(ROOT, "build", "bin", "peer_bench")
RESULTS = os.environ.get("CHUTE_BENCH_RESULTS", os.path.join(ROOT, "bench", "results"))
PROBES = ["apex", "rim", "line_mid"]


def parse_dat(path, nodes):
    """ccx .dat: one 'displacements ... time T' block per increment, rows 'node ux uy uz'."""
    out, t = {}, None
    for line in open(path):
        if "displacements" in line:
            t = float(re.search(r"time\s+(\S+)", line).group(1))
            out[t] = {}
        elif t is not None:
            p = line.split()
            if len(p) == 4 and int(p[0]) in nodes:
                out[t][int(p[0])] = [float(x) for x in p[1:]]
    return out


def parse_chute(path):
    rows = list(csv.reader(open(path)))[1:]
    return {float(r[0]): [float(x) for x in r[1:]] for r in rows}


def compare(chute, ccx, nodes):
    """Max over steps and probes of |du| (vector norm), max |u|, and per probe."""
    times = sorted(ccx)
    max_diff, max_u = 0.0, 0.0
    per = [0.0] * len(nodes)
    for t in times:
        tc = min(chute, key=lambda s: abs(s - t))
        if abs(tc - t) > 1e-9 * max(1.0, t):
            raise RuntimeError(f"no chute output at t = {t}")
        for i, n in enumerate(nodes):
            uc = chute[tc][3 * i:3 * i + 3]
            ux = ccx[t][n]
            d = sum((a - b) ** 2 for a, b in zip(uc, ux)) ** 0.5
            per[i] = max(per[i], d)
            max_diff = max(max_diff, d)
            max_u = max(max_u, sum(a * a for a in uc) ** 0.5, sum(b * b for b in ux) ** 0.5)
    return max_diff, max_u, per, len(times)


def run_ccx(inp_dir, job, threads, runs):
    walls = []
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    for _ in range(runs):
        t0 = time.perf_counter()
        p = subprocess.run(["ccx", job], cwd=inp_dir, env=env, capture_output=True, text=True)
        walls.append(time.perf_counter() - t0)
        if p.returncode != 0 or "ERROR" in p.stdout:
            raise RuntimeError(f"ccx failed ({p.returncode}):\n" + p.stdout[-2000:])
    its = 0
    for line in open(os.path.join(inp_dir, job + ".sta")).readlines()[2:]:
        f = line.split()
        if len(f) >= 4:
            its += int(f[3])
    return statistics.median(walls), walls, its


def case(label, args, runs, threads=(1, 2), ccx_tol=None, time_chute=True):
    with tempfile.TemporaryDirectory() as d:
        inp = os.path.join(d, "peer.inp")
        cmd = [BENCH, "--write-inp", inp, "--csv", os.path.join(d, "chute.csv"),
               "--runs", str(runs if time_chute else 1)] + args
        if ccx_tol:
            cmd += ["--ccx-rtol", str(ccx_tol), "--ccx-ctol", str(ccx_tol)]
        info = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)
        row = {"case": label, "element": info["element"], "nodes": info["nodes"],
               "dof": info["dofs"], "equations": info["equations"],
               "membranes": info["membranes"], "lines": info["lines"],
               "trusses": info["trusses"], "steps": info["steps"],
               "dt": float(args[args.index("--dt") + 1]),
               "ccx_tolerance": ccx_tol or "default (R 0.005, C 0.01)",
               "chute_wall": info["wall_median"], "chute_newton": info["newton_iterations"]}
        for th in threads:
            wall, walls, its = run_ccx(d, "peer", th, runs)
            row[f"ccx_wall_{th}t"] = wall
            row["ccx_iterations"] = its
            row[f"ratio_{th}t"] = wall / info["wall_median"]
        nodes = info["probe_nodes"]
        diff, umax, per, n = compare(parse_chute(os.path.join(d, "chute.csv")),
                                     parse_dat(os.path.join(d, "peer.dat"), set(nodes)), nodes)
        row.update({"max_disp": umax, "max_diff": diff, "max_diff_rel": diff / umax,
                    **{f"diff_rel_{p}": v / umax for p, v in zip(PROBES, per)}})
        print(json.dumps(row), flush=True)
        return row


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--quick", action="store_true", help="one small case, one run")
    a = ap.parse_args()
    if not os.path.exists(BENCH):
        raise SystemExit(f"{BENCH} missing: build the peer_bench target first")
    base = ["--dt", "1e-4", "--steps", "100"]
    rows = []
    if a.quick:
        rows.append(case("quick", ["--square", "8", "--rings", "4", "--dt", "1e-4", "--steps", "30"],
                         1, threads=(1,)))
    else:
        small = ["--square", "8", "--rings", "4"]
        large = ["--square", "12", "--rings", "6"]
        rows.append(case("small", small + base, a.runs))
        rows.append(case("large", large + base, a.runs))
        # Time-step refinement over the same 10 ms: the difference that stays is spatial.
        for k in (2,):
            rows.append(case(f"small, dt/{k}", small + ["--dt", str(1e-4 / k), "--steps",
                             str(100 * k)], 1, threads=(1,)))
        # Triangles (CalculiX M3D3): its mass is integrated at one point (see README.md).
        rows.append(case("triangles (M3D3)", ["--triangles", "--rings", "6"] + base, 1,
                         threads=(1,)))
    os.makedirs(RESULTS, exist_ok=True)
    keys = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    with open(os.path.join(RESULTS, "peer_calculix.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(RESULTS, "peer_calculix.md"), "w") as f:
        f.write("| case | element | nodes | dof | steps | dt | ccx tolerance | chute wall s | "
                "ccx wall 1 thr s | ccx wall 2 thr s | ratio ccx/chute (1 thr) | ratio (2 thr) | "
                "Newton it. chute / ccx | max diff / max disp |\n")
        f.write("|" + "---|" * 14 + "\n")
        for r in rows:
            g = lambda k, fmt: (fmt % r[k]) if k in r else "–"
            f.write(f"| {r['case']} | {r['element']} | {r['nodes']} | {r['dof']} | {r['steps']} | "
                    f"{r['dt']:.3g} | {r['ccx_tolerance']} | {r['chute_wall']:.3f} | "
                    f"{g('ccx_wall_1t', '%.2f')} | {g('ccx_wall_2t', '%.2f')} | "
                    f"{g('ratio_1t', '%.1f')} | {g('ratio_2t', '%.1f')} | "
                    f"{r['chute_newton']} / {r['ccx_iterations']} | {r['max_diff_rel']:.2e} |\n")
    print("wrote", os.path.join(RESULTS, "peer_calculix.csv"))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Cost of the VTU series: each case run without VTU and with a frame at every step (median of
N runs each, in one sitting), the output share of the run and the slowdown (run = the stepping
loop as summary.json times it; process = the whole `chute run` command). Frames are written on a
background thread, so `output_s` is the stepping thread's share (building frames, waiting for the
writer at the end) and `output_background_s` the writer thread's time. The floor: creating,
writing and closing one new file of a frame's size on the same file system (Python os calls,
median of 5 x 400), against the cost of a step: if a file costs more than a step, a frame at every
step holds the run back whoever writes it. Writes
bench/results/output_cost.csv and prints a table.

    python3 bench/output_cost.py [--runs 5]
"""
import argparse, csv, json, os, statistics, subprocess, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RESULTS = os.environ.get("CHUTE_BENCH_RESULTS", os.path.join(ROOT, "bench", "results"))
CHUTE = os.path.join(ROOT, "build", "bin", "chute")

# (case, settings that make every step an output time)
CASES = [
    ("pulley", ["output.vtu.every=1"]),
    ("bead_5", ["output.vtu.every=1"]),
    ("airbag", ["output.vtu.interval=1.25e-4", "output.interval=1.25e-4"]),
]


def run(case, sets, runs):
    walls, outs, bgs, procs, frames, steps = [], [], [], [], 0, 0
    for _ in range(runs):
        with tempfile.TemporaryDirectory() as out:
            cmd = [CHUTE, "run", os.path.join(ROOT, "cases", case + ".toml"), "--out", out, "--quiet"]
            for s in sets:
                cmd += ["--set", s]
            t0 = time.perf_counter()
            subprocess.run(cmd, check=True)
            procs.append(time.perf_counter() - t0)
            s = json.load(open(os.path.join(out, "summary.json")))
            walls.append(s["wall_time"]["total"])
            outs.append(s["wall_time"]["output"])
            bgs.append(s["wall_time"].get("output_background", 0.0))
            frames, steps = s["output"]["vtu_frames"], s["steps"]
    m = statistics.median
    return m(walls), m(outs), m(bgs), m(procs), frames, steps


def file_floor_us(nbytes, files=400, runs=5):
    """Median cost of creating, writing and closing one new file of nbytes in the output's file
    system (what one VTU frame needs at least, whoever writes it)."""
    data = b"x" * nbytes
    times = []
    for _ in range(runs):
        with tempfile.TemporaryDirectory(dir=os.path.join(ROOT, "build")) as d:
            t0 = time.perf_counter()
            for i in range(files):
                fd = os.open(os.path.join(d, f"f_{i:06d}.vtu"), os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o644)
                os.write(fd, data)
                os.close(fd)
            times.append((time.perf_counter() - t0) / files)
    return 1e6 * statistics.median(times)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=5)
    args = ap.parse_args()
    rows = []
    for case, every in CASES:
        base_wall, base_out, _, base_proc, _, steps = run(case, ["output.vtu.write=false"], args.runs)
        wall, out, bg, proc, frames, _ = run(case, ["output.vtu.write=true"] + every, args.runs)
        frame_bytes = 0
        with tempfile.TemporaryDirectory() as tmp:
            subprocess.run([CHUTE, "run", os.path.join(ROOT, "cases", case + ".toml"), "--out", tmp, "--quiet",
                            "--set", "output.vtu.write=true", "--set", "solver.t_end=1e-9"], check=True)
            vtus = [f for f in os.listdir(tmp) if f.endswith(".vtu")]
            frame_bytes = os.path.getsize(os.path.join(tmp, sorted(vtus)[-1])) if vtus else 0
        floor = file_floor_us(frame_bytes)
        rows.append({
            "case": case, "steps": steps, "frames": frames,
            "wall_without_vtu_s": round(base_wall, 4), "wall_with_vtu_s": round(wall, 4),
            "output_s": round(out, 4), "output_background_s": round(bg, 4),
            "ms_per_frame_background": round(1e3 * bg / max(1, frames), 3),
            "us_per_step_without": round(1e6 * base_wall / max(1, steps), 1),
            "output_share_pct": round(100 * out / wall, 1),
            "slowdown_pct": round(100 * (wall - base_wall) / base_wall, 1),
            "process_without_vtu_s": round(base_proc, 4), "process_with_vtu_s": round(proc, 4),
            "process_slowdown_pct": round(100 * (proc - base_proc) / base_proc, 1),
            "frame_bytes": frame_bytes, "file_create_floor_us": round(floor, 1),
            "floor_share_of_step_pct": round(100 * floor / (1e6 * base_wall / max(1, steps)), 1),
        })
        print(rows[-1], flush=True)
    os.makedirs(RESULTS, exist_ok=True)
    path = os.path.join(RESULTS, "output_cost.csv")
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    print("wrote", path)


if __name__ == "__main__":
    main()

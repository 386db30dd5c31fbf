#!/usr/bin/env python3
"""Restart bit for bit, measured: every shipped case restarted from a checkpoint taken mid-run,
and runs stopped by SIGTERM or SIGINT at random moments and restarted, each compared byte for
byte with the uninterrupted run (probes.csv, the .pvd collection and every VTU frame).

  bench/restart/restart_trials.py [--chute build/bin/chute] [--out out/restart_trials]
      [--trials CASE=N ...] [--mid-run] [--seed S]

Writes a table (Markdown) to OUT/restart_trials.md and prints it.
"""
import argparse, glob, hashlib, json, os, random, shutil, signal, subprocess, sys, time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# Shortened where a full run would take minutes: the same stepping machinery is exercised.
SETS = {"c9_slider": ["solver.t_end=0.3"], "c9_no_slider": ["solver.t_end=0.3"],
        "c9_payload_reorientation": ["solver.t_end=0.3"], "payload_fixed_slider": []}


def run(chute, case, out, extra=(), sets=()):
    cmd = [chute, "run", os.path.join(ROOT, "cases", case + ".toml"), "--quiet", "--out", out]
    for s in sets:
        cmd += ["--set", s]
    return subprocess.run(cmd + list(extra), capture_output=True, text=True)


def digest(out):
    """Hashes of what a run wrote that must be identical: probes.csv, .pvd, VTU frames."""
    files = {}
    for p in sorted(glob.glob(os.path.join(out, "*"))):
        name = os.path.basename(p)
        if name == "probes.csv" or name.endswith(".pvd") or name.endswith(".vtu"):
            with open(p, "rb") as f:
                files[name] = hashlib.sha256(f.read()).hexdigest()
    return files


def compare(ref, got):
    if ref == got:
        return ""
    missing = sorted(set(ref) - set(got))
    extra = sorted(set(got) - set(ref))
    differ = sorted(k for k in set(ref) & set(got) if ref[k] != got[k])
    return f"missing {missing[:3]} extra {extra[:3]} differ {differ[:3]}"


def summary(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def mid_run(chute, case, work):
    sets = SETS.get(case, [])
    ref = os.path.join(work, case, "ref")
    r = run(chute, case, ref, sets=sets)
    if r.returncode != 0:
        return (case, "reference run failed: " + r.stderr.strip()[-200:])
    steps = summary(ref)["steps"]
    every = max(1, int(0.4 * steps))
    a = os.path.join(work, case, "ckpt")
    r = run(chute, case, a, ["--checkpoint-every", str(every)], sets)
    if compare(digest(ref), digest(a)):
        return (case, "run with checkpoints differs from the run without")
    ck = summary(a)["output"]["checkpoints"]
    if ck == 0:
        return (case, f"no checkpoint taken ({steps} steps, every {every})")
    b = os.path.join(work, case, "restarted")
    shutil.rmtree(b, ignore_errors=True)
    shutil.copytree(a, b)
    # What a restart must cut away: scribble a row and a frame after the checkpoint.
    with open(os.path.join(b, "probes.csv"), "a") as f:
        f.write("1e9,garbage\n")
    r = run(chute, case, b, ["--restart", os.path.join(b, "checkpoint.cbor")], sets)
    if r.returncode != 0:
        return (case, "restart failed: " + r.stderr.strip()[-200:])
    diff = compare(digest(ref), digest(b))
    restarted_steps = summary(b)["steps"]
    return (case, f"identical ({steps} steps, checkpoint every {every}, restarted summary {restarted_steps} steps)"
            if not diff else "DIFFERS: " + diff)


def signal_trials(chute, case, work, n, rng):
    sets = SETS.get(case, [])
    ref = os.path.join(work, case, "sigref")
    t0 = time.time()
    r = run(chute, case, ref, sets=sets)
    wall = time.time() - t0
    if r.returncode != 0:
        return dict(case=case, trials=0, identical=0, note="reference failed")
    ref_digest = digest(ref)
    identical = tried = finished_first = 0
    notes = []
    attempts = 0
    while tried < n and attempts < 4 * n:
        attempts += 1
        out = os.path.join(work, case, f"sig{attempts}")
        shutil.rmtree(out, ignore_errors=True)
        sig = rng.choice([signal.SIGTERM, signal.SIGINT])
        cmd = [chute, "run", os.path.join(ROOT, "cases", case + ".toml"), "--quiet", "--out", out]
        for s in sets:
            cmd += ["--set", s]
        start = time.time()
        p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        # A moment of the run itself: once it has begun writing (before that the process is still
        # being loaded by the system, where no program can catch a signal).
        while not os.path.exists(os.path.join(out, "probes.csv")) and p.poll() is None:
            time.sleep(0.002)
        begun = time.time() - start
        time.sleep(rng.uniform(0.0, 0.95) * max(wall - begun, 0.01))
        p.send_signal(sig)
        _, err = p.communicate()
        if p.returncode == 0:
            finished_first += 1
            continue
        tried += 1
        if p.returncode != 4:
            notes.append(f"trial {tried}: exit {p.returncode} ({err.strip()[-120:]})")
            continue
        r = run(chute, case, out, ["--restart", os.path.join(out, "checkpoint.cbor")], sets)
        if r.returncode != 0:
            notes.append(f"trial {tried}: restart exit {r.returncode} {r.stderr.strip()[-120:]}")
            continue
        diff = compare(ref_digest, digest(out))
        if diff:
            notes.append(f"trial {tried}: {diff}")
        else:
            identical += 1
        shutil.rmtree(out, ignore_errors=True)
    return dict(case=case, trials=tried, identical=identical, finished_first=finished_first,
                wall=wall, note="; ".join(notes[:3]))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--chute", default=os.path.join(ROOT, "build", "bin", "chute"))
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "restart_trials"))
    ap.add_argument("--trials", nargs="*", default=[])
    ap.add_argument("--mid-run", action="store_true")
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    rng = random.Random(a.seed)
    os.makedirs(a.out, exist_ok=True)
    lines = []
    if a.mid_run:
        lines += ["## Restart from a checkpoint taken mid-run, every shipped case", "",
                  "| case | result |", "|---|---|"]
        for toml in sorted(glob.glob(os.path.join(ROOT, "cases", "*.toml"))):
            case = os.path.basename(toml)[:-5]
            c, res = mid_run(a.chute, case, a.out)
            lines.append(f"| {c} | {res} |")
            print(lines[-1], flush=True)
        lines.append("")
    if a.trials:
        lines += ["## SIGTERM / SIGINT at random moments, then --restart", "",
                  "| case | trials | identical | finished before the signal | run wall s | notes |",
                  "|---|---|---|---|---|---|"]
        for spec in a.trials:
            case, n = spec.split("=")
            t = signal_trials(a.chute, case, a.out, int(n), rng)
            lines.append(f"| {t['case']} | {t['trials']} | {t['identical']} | "
                         f"{t.get('finished_first', 0)} | {t.get('wall', 0):.2f} | {t['note']} |")
            print(lines[-1], flush=True)
    with open(os.path.join(a.out, "restart_trials.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    bad = [l for l in lines if "DIFFERS" in l or "failed" in l]
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Contact's share of an explicit step on a C-9 case (docs/contact.md, "What it costs"):
cases/<case>.toml (default c9_slider, the half-scale C-9 with its slider) for 0.2 s without VTU
output, as shipped and with a [contact] section appended (fabric and lines, the given thickness
and skin), run alternately --runs times in one sitting; medians of wall and user time. Writes a
Markdown table.

    python3 bench/contact/c9_contact_cost.py --chute build/bin/chute --out bench/results/contact_c9_cost.md
    python3 bench/contact/c9_contact_cost.py --case c9_no_slider --out ...
"""
import argparse
import json
import os
import pathlib
import resource
import statistics
import subprocess
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]


def run(chute, case, out, extra):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    subprocess.run([chute, "run", str(case), "--out", str(out), "--set", "solver.t_end=0.2",
                    "--set", "output.vtu.write=false"] + extra, check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wall = time.monotonic() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    summary = json.loads((out / "summary.json").read_text())
    return wall, after.ru_utime - before.ru_utime, summary


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--chute", default=str(ROOT / "build/bin/chute"))
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--thickness", type=float, default=0.01)
    ap.add_argument("--skin", type=float, default=None)
    ap.add_argument("--out", default=str(ROOT / "bench/results/contact_c9_cost.md"))
    ap.add_argument("--case", default="c9_slider", help="a case of cases/ (its mesh beside it)")
    a = ap.parse_args()
    work = pathlib.Path(tempfile.mkdtemp(prefix="chute_contact_cost_"))
    shipped = ROOT / f"cases/{a.case}.toml"
    text = shipped.read_text().replace(f'file = "{a.case}.msh"',
                                       f'file = "{ROOT / "cases" / (a.case + ".msh")}"')
    section = f"\n[contact]\nthickness = {a.thickness}\n"
    if a.skin is not None:
        section += f"skin = {a.skin}\n"
    with_contact = work / f"{a.case}_contact.toml"
    with_contact.write_text(text + section)
    rows = {"without": [], "with": []}
    for r in range(a.runs):
        for kind, case in (("without", shipped), ("with", with_contact)):
            wall, user, s = run(a.chute, case, work / f"{kind}_{r}", [])
            rows[kind].append((wall, user, s))
            print(f"run {r + 1} {kind} contact: wall {wall:.2f} s, user {user:.2f} s", flush=True)
    med = {k: (statistics.median(w for w, _, _ in v), statistics.median(u for _, u, _ in v))
           for k, v in rows.items()}
    s0, s1 = rows["without"][0][2], rows["with"][0][2]
    c = s1["contact"]
    load = os.getloadavg()[0]
    lines = [
        "# Contact's cost on the explicit C-9 (`bench/contact/c9_contact_cost.py`)",
        "",
        f"`cases/{a.case}.toml`, 0.2 s, no VTU, as shipped and with `[contact]` thickness = "
        f"{a.thickness} ft{'' if a.skin is None else f', skin = {a.skin} ft'} (fabric and lines, "
        f"the other keys at their defaults); {a.runs} runs of each, alternately, in one sitting "
        f"(load average {load:.1f} on the machine's 2 cores at the end).",
        "",
        "| | steps | least step (s) | wall, median (s) | user, median (s) |",
        "|---|---|---|---|---|",
        f"| without contact | {s0['steps'] if 'steps' in s0 else s0['counts']['assemblies']} | "
        f"{s0['explicit']['least_step']:.3e} | {med['without'][0]:.2f} | {med['without'][1]:.2f} |",
        f"| with contact | {s1['steps'] if 'steps' in s1 else s1['counts']['assemblies']} | "
        f"{s1['explicit']['least_step']:.3e} | {med['with'][0]:.2f} | {med['with'][1]:.2f} |",
        f"| ratio | | | {med['with'][0] / med['without'][0]:.3f} | "
        f"{med['with'][1] / med['without'][1]:.3f} |",
        "",
        f"Contact: {c['broad_phase_builds']} candidate lists built ({c['tree_builds']} trees built "
        f"afresh), {s1['work']['contact_pair_kernels']} pair distances computed, at most "
        f"{c['most_pairs_in_contact']} pairs in contact, closest d / dHat "
        f"{c['closest_over_thickness']:.3f}, largest approach per step "
        f"{c['largest_approach_per_step']:.3g} dHat (CT13), largest approach energy ratio "
        f"{c['largest_approach_energy']:.3g}.",
        "",
        "Per run (wall, user in s):",
        "",
    ]
    for k, v in rows.items():
        lines.append(f"- {k} contact: " + ", ".join(f"{w:.2f} / {u:.2f}" for w, u, _ in v))
    pathlib.Path(a.out).write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()

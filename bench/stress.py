#!/usr/bin/env python3
"""Stability stress suite, long runs (issue 8, item 5). Runs build/bin/chute on the stress cases
with long settings and writes bench/results/stress.csv (the short versions are ctest's
test_stress). Energy drift is max |E(t) - E(0)| relative to the run's largest kinetic energy.

  python3 bench/stress.py
"""
import csv
import os
import json
import pathlib
import subprocess
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
RESULTS = os.environ.get("CHUTE_BENCH_RESULTS", os.path.join(ROOT, "bench", "results"))
CHUTE = ROOT / 'build' / 'bin' / 'chute'
RHO1 = ['solver.rho_inf=1']

RUNS = [('driven_slider 40 s', 'cases/stress_driven_slider.toml', ['solver.t_end=40']),
        ('swing50 40 s', 'cases/stress_swing50.toml', ['solver.t_end=40']),
        ('on_node 10 s', 'cases/stress_on_node.toml', ['solver.t_end=10'])]
for e in range(3, 13):
    RUNS.append((f'bead_5 EA/W=1e{e}', 'cases/bead_5.toml',
                 [f'materials.rope.E={10.0 ** (e + 4):.17g}',
                  f'sliding_groups.0.prestrain={10.0 ** -e:.17g}'] + RHO1))
for e in range(-6, 0):
    dt = 10.0 ** e
    RUNS.append((f'bead_5 dt=1e{e}', 'cases/bead_5.toml',
                 [f'solver.dt={dt:.17g}', f'solver.t_end={min(4.0, 1e5 * dt):.17g}',
                  f'output.interval={max(dt, 1e-3):.17g}'] + RHO1))
RUNS += [('snatch 20 s', 'cases/stress_snatch.toml', ['solver.t_end=20']),
         ('snatch_line_with_mass 20 s', 'cases/stress_snatch.toml',
          ['solver.t_end=20', 'materials.line.density=10000']),
         ('snatch_line_with_mass rho 0.5', 'cases/stress_snatch.toml',
          ['solver.t_end=1', 'materials.line.density=10000', 'solver.rho_inf=0.5']),
         ('bead_5 20 massless el. 40 s', 'cases/bead_5.toml',
          ['sliding_groups.0.elements=20', 'solver.t_end=40'] + RHO1),
         ('ring28 10 s', 'cases/stress_ring28.toml', ['solver.t_end=10'])]


def periodic_drift(probes, period=1.0):
    """A driven scene has no kinetic energy to compare with: the largest change of its energy
    from one period to the next, relative to its peak."""
    rows = list(csv.DictReader(probes.open()))
    e = {round(float(r['t']), 6): float(r['energy.total']) for r in rows}
    drift = max(abs(e[round(t + period, 6)] - v) for t, v in e.items() if round(t + period, 6) in e)
    return drift / max(abs(v) for v in e.values())


def main():
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, case, sets in RUNS:
            out = pathlib.Path(tmp) / 'run'
            cmd = [str(CHUTE), 'run', str(ROOT / case), '--out', str(out), '--quiet']
            for s in sets:
                cmd += ['--set', s]
            proc = subprocess.run(cmd, capture_output=True, text=True)
            j = json.loads((out / 'summary.json').read_text())
            e = j['energy']
            rel = e['max_drift'] / e['max_kinetic'] if e['max_kinetic'] > 0 else float('nan')
            if name.startswith('driven'):
                rel = periodic_drift(out / 'probes.csv')
            row = dict(case=name, status=j['status'], exit=proc.returncode, steps=j['steps'],
                       handovers=sum(j['sliding_handovers']), rejected=j['rejected_steps'],
                       event_retries=j['event_retries'],
                       newton_per_step=round(j['newton_iterations_per_step'], 2),
                       energy_max_drift=f"{e['max_drift']:.3e}", max_kinetic=f"{e['max_kinetic']:.3e}",
                       relative_drift=f'{rel:.3e}', wall_time=round(j['wall_time']['total'], 3),
                       reason=j.get('reason', ''))
            rows.append(row)
            print(' '.join(f'{k}={v}' for k, v in row.items() if k != 'reason'), row['reason'])
    path = pathlib.Path(RESULTS) / 'stress.csv'
    path.parent.mkdir(exist_ok=True)
    with path.open('w', newline='') as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print('wrote', path)


if __name__ == '__main__':
    main()

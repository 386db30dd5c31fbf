#!/usr/bin/env python3
"""Pendulum acceptance per integrator (issue 19): a point mass on a stiff massless member
(E A = 1e8 N, m g = 9.81 N, L = 1 m), released from rest undamped, truss at 120 deg and cable at
75 deg, as tests/cases/test_pendulum.cpp. For each integrator and steps per period: the peak
member force against the rigid pendulum's m g (3 - 2 cos theta0), the period (mean time between
leftward crossings of the bottom) against 4 sqrt(L/g) K(sin(theta0/2)), and the largest energy
drift |E - E0| / (m g L). The implicit schemes are run at 60, 120 and 240 steps per period (the
order of the period error from the last two); central_difference runs at its stable step.
Writes bench/results/pendulum_acceptance.md.

  nice python3 bench/pendulum_acceptance.py
"""
import json
import math
import os
import pathlib
import subprocess
import tempfile

import pendulum_scene
from pendulum_scene import G, M, L, period

ROOT = pathlib.Path(__file__).resolve().parent.parent
CHUTE = os.environ.get('CHUTE', str(ROOT / 'build' / 'bin' / 'chute'))
RESULTS = ROOT / 'bench' / 'results' / 'pendulum_acceptance.md'
PERIODS = float(os.environ.get('PERIODS', '4.3'))


def case(kind, deg, integrator, dt, t_end, rho):
    # "energy_momentum_4": energy_momentum with em_order = 4 (EM14), which crosses slack / taut
    # kinks inside its steps.
    extra = 'em_order = 4\nslack_events = false\n' if integrator == 'energy_momentum_4' else ''
    integrator = integrator.replace('_4', '')
    solver = (f'dt = {dt!r}\nt_end = {t_end!r}\nrho_inf = {rho!r}\n'
              f'integrator = "{integrator}"\n{extra}')
    return pendulum_scene.case(f"pendulum_{kind}", kind, deg, solver, position_probe=True)


def measure(kind, deg, integrator, spp, rho, tmp):
    P = period(math.radians(deg))
    dt = P / spp
    t_end = dt * round(PERIODS * spp)
    path = pathlib.Path(tmp) / 'p.toml'
    path.write_text(case(kind, deg, integrator, dt, t_end, rho))
    out = pathlib.Path(tmp) / 'out'
    p = subprocess.run([CHUTE, 'run', str(path), '--out', str(out), '--quiet'],
                       capture_output=True, text=True)
    j = json.load(open(out / 'summary.json'))
    rows = (out / 'probes.csv').read_text().splitlines()
    head = rows[0].split(',')
    cols = [[float(v) for v in r.split(',')] for r in rows[1:]]
    t = [c[0] for c in cols]
    x = [c[head.index('mass.x')] for c in cols]
    N = [c[head.index('rod.N')] for c in cols]
    E = [c[head.index('energy.total')] for c in cols]
    k = max(range(len(N)), key=lambda i: N[i])
    peak = N[k]
    if 0 < k < len(N) - 1:
        a, b, c = N[k - 1], N[k], N[k + 1]
        den = a - 2 * b + c
        if den < 0:
            peak = b - 0.125 * (c - a) ** 2 / den
    cross = [t[i - 1] + (t[i] - t[i - 1]) * x[i - 1] / (x[i - 1] - x[i])
             for i in range(1, len(x)) if x[i - 1] > 0 >= x[i]]
    per = (cross[-1] - cross[0]) / (len(cross) - 1) if len(cross) >= 2 else float('nan')
    exact_N = M * G * (3 - 2 * math.cos(math.radians(deg)))
    drift = max(abs(e - E[0]) for e in E) / (M * G * L)
    return dict(status=j['status'], exit=p.returncode, steps=j['steps'],
                newton=j['newton_iterations_per_step'], t=j['final_time'],
                force_err=100 * (peak - exact_N) / exact_N, peak=peak,
                period_err=100 * (per - P) / P, drift=drift)


def main():
    lines = ['# Pendulum acceptance per integrator', '',
             'Made by `nice python3 bench/pendulum_acceptance.py` (build/bin/chute; '
             f'{PERIODS:g} periods per run). Stiff massless member (E A = 1e8 N), m = 1 kg, '
             'L = 1 m, released from rest, undamped. Exact: peak force m g (3 - 2 cos theta0) = '
             '39.24 N (120 deg), 24.35 N (75 deg); period 4 sqrt(L/g) K(sin(theta0/2)) = '
             f'{period(math.radians(120)):.6f} s (120 deg), {period(math.radians(75)):.6f} s '
             '(75 deg). Acceptance: force within 1 %, period within 0.2 % at 60 steps/period. '
             'Drift: max |E - E0| / (m g L). Order: log2 of the period error ratio 120 -> 240 '
             'steps/period.', '',
             '| scene | integrator | rho_inf | steps/period | status | peak N error % | '
             'period error % | energy drift / mgL | Newton/step |', '|---|---|---|---|---|---|---|---|---|']
    runs = []
    for kind, deg in (('truss', 120.0), ('cable', 75.0)):
        for integ, rhos in (('bossak', (1.0, 0.9, 0.8)), ('generalized_alpha', (1.0, 0.9, 0.8)),
                            ('energy_momentum', (1.0,)), ('energy_momentum_4', (1.0,))):
            for rho in rhos:
                for spp in (60, 120, 240):
                    runs.append((kind, deg, integ, spp, rho))
        runs.append((kind, deg, 'central_difference', 60, 1.0))
    order = {}
    with tempfile.TemporaryDirectory() as tmp:
        for kind, deg, integ, spp, rho in runs:
            r = measure(kind, deg, integ, spp, rho, tmp)
            key = (kind, integ, rho)
            order.setdefault(key, {})[spp] = r['period_err']
            spp_txt = str(spp) if integ != 'central_difference' else \
                f"stable step ({r['steps'] / (r['t'] / period(math.radians(deg))):.0f})"
            note = ''
            if spp == 240 and r['status'] == 'completed':
                e1, e2 = order[key].get(120), order[key].get(240)
                if e1 and e2 and e1 * e2 > 0:
                    note = f" (order {math.log2(e1 / e2):.2f})"
            lines.append(
                f"| {kind} {deg:g} deg | {integ} | {rho:g} | {spp_txt} | {r['status']} "
                f"({r['exit']}) | {r['force_err']:+.3f} | {r['period_err']:+.4f}{note} | "
                f"{r['drift']:.2e} | {r['newton']:.2f} |")
            print(lines[-1], flush=True)
    RESULTS.write_text('\n'.join(lines) + '\n')


if __name__ == '__main__':
    main()

#!/usr/bin/env bash
# energy_momentum (with its energy-decaying variant) beside Bossak on the C-9 without slider
# (membranes with wrinkling, cables, pressure, drag), shortened. The case ships with central
# differences: Bossak is asked for. Usage: bench/energy_momentum/c9_no_slider.sh T_END CHI...
set -eu
chute=${CHUTE:-build/bin/chute}; tend=$1; shift
out=${OUT:-/tmp/em_c9}; mkdir -p "$out"
row() {  # label, summary.json
  python3 - "$1" "$2" <<'PY'
import json, sys
d = json.load(open(sys.argv[2]))
print(f"| {sys.argv[1]} | {d['status']} | {d['final_time']:.3f} | {d['steps']} | {d['rejected_steps']} | "
      f"{d['newton_iterations_per_step']:.2f} | {d['wall_time']['total']:.1f} |")
PY
}
echo "| run | status | t reached | steps | rejected | Newton/step | wall s |"
echo "|---|---|---|---|---|---|---|"
"$chute" run cases/c9_no_slider.toml --set 'solver.integrator="bossak"' --set solver.t_end="$tend" \
  --out "$out/bossak" --quiet || true
row "bossak (shipped: rho_inf 0, dt 2 ms)" "$out/bossak/summary.json"
for chi in "$@"; do
  "$chute" run cases/c9_no_slider.toml --set 'solver.integrator="energy_momentum"' \
    --set solver.em_dissipation="$chi" --set solver.t_end="$tend" --out "$out/em_$chi" --quiet || true
  row "energy_momentum, em_dissipation $chi" "$out/em_$chi/summary.json"
done

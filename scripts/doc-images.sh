#!/usr/bin/env bash
# Re-makes the pictures in docs/images/ (README, docs/output.md): the default run's snapshots and
# skirt-radius plot (scripts/run-default.sh), and a generated 5 m, 20-gore SI parachute with a
# 20 kg payload on a riser, flown 3 s from line stretch (it fills in about 2 s): a snapshot by stress, one by wrinkling
# state, and a plot of its skirt radius, line forces and kinetic energy. About a minute after the
# build.
set -euo pipefail
cd "$(dirname "$0")/.."
CHUTE=build/bin/chute
bash scripts/run-default.sh > /dev/null
cp out/c9_slider/snapshots/c9_slider_side_t1.200000.png docs/images/c9_slider.png
cp out/c9_slider/snapshots/c9_slider_side_t0.600000.png docs/images/c9_slider_t0.6.png
cp out/c9_slider/skirt_radius.png docs/images/c9_slider_skirt_radius.png

SI=out/si_parachute
rm -rf "$SI"
mkdir -p "$SI"
"$CHUTE" mesh parachute --units si --gores 20 --diameter 5 --vent-diameter 0.5 --line-length 4.5 \
  --element-size 0.3 --payload-mass 20 --riser-length 0.5 --start folded \
  --t-end 3 --out "$SI/si_parachute.msh" --case "$SI/si_parachute.toml" --quiet
"$CHUTE" run "$SI/si_parachute.toml" --out "$SI/run" --quiet
"$CHUTE" render "$SI/run" --view side --times 3 --quiet
"$CHUTE" render "$SI/run" --view side --times 3 --color wrinkling_state --quiet
"$CHUTE" plot "$SI/run" --columns skirt.mean,skirt.max,line_0.N,riser.N,energy.kinetic \
  --title "5 m, 20 gores, 20 kg payload, free flight from 20 m/s (SI)" --out "$SI/plot.png" > /dev/null
cp "$SI/run/snapshots/si_parachute_side_t3.000000.png" docs/images/si_parachute.png
cp "$SI/run/snapshots/si_parachute_side_wrinkling_state_t3.000000.png" \
  docs/images/si_parachute_wrinkling.png
cp "$SI/plot.png" docs/images/si_parachute_plot.png
ls -la docs/images

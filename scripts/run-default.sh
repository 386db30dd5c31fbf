#!/usr/bin/env bash
# From a fresh clone: installs what is missing (apt), builds, and flies the half-scale C-9 with its
# slider (cases/c9_slider.toml, paper section 4) for 1.2 s of inflation: probes, the ParaView
# series, side-view snapshots coloured by membrane stress and line force, and a skirt-radius plot,
# all in out/c9_slider/. Extra arguments go to `chute run` (e.g. --set solver.t_end=2).
# The flight takes about 1.4 s of wall time per simulated second on 2 idle cores (central
# differences), plus the first build of chute (about 7 min of compiler time: some 4 min on two
# idle cores).
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=out/c9_slider
CHUTE=build/bin/chute
start=$(date +%s)
bash scripts/build.sh --target chute  # the executable and its gmsh plugin only
built=$(date +%s)
echo "== flying cases/c9_slider.toml (1.2 s of inflation) into $OUT =="
"$CHUTE" run cases/c9_slider.toml --out "$OUT" --set solver.t_end=1.2 "$@"
flown=$(date +%s)
echo "== snapshots and plot =="
rm -rf "$OUT/snapshots"
"$CHUTE" render "$OUT" --view side --times 0,0.3,0.6,0.9,1.2 --size 1280x720 --quiet
"$CHUTE" plot "$OUT" --columns skirt.mean,skirt.min,skirt.max \
  --title "C-9 with slider: skirt radius" --out "$OUT/skirt_radius.png" > /dev/null
done_=$(date +%s)

pvd=$(ls "$OUT"/*.pvd)
cat <<MSG

Done in $((done_ - start)) s (build $((built - start)) s, flight $((flown - built)) s, pictures $((done_ - flown)) s).
Everything is in $OUT/:
  $(ls "$OUT"/*.vtu | wc -l) VTU frames and the series $pvd (every 0.05 s)
  $OUT/probes.csv          skirt radius, grommet and slider positions, energy, per output time
  $OUT/summary.json        status, steps, Newton iterations, timings
  $OUT/skirt_radius.png    skirt radius (mean, least, largest) against time
  side views at t = 0, 0.3, 0.6, 0.9, 1.2 s (membrane stress, line force):
$(ls "$OUT"/snapshots/*.png | sed 's/^/    /')

Open the series in ParaView (apt-get install paraview): paraview $pvd
  then Apply, colour by principal_stress or axial_force, and press Play.
Other cases are one command away, e.g.  $CHUTE run cases/bead_5.toml  (see README.md).
MSG

#!/bin/bash
# What the airflow's loads cost in an explicit step of the full-scale C-9 (cases/c9_flight.toml):
# the case against itself with [[loads.canopy_flow]] replaced by a constant [[loads.pressure]]
# (and the canopy probe dropped), and with the constant pressure and the face drag the generated
# case had before (--pressure). Instructions per step from callgrind (two run lengths, their
# difference: set-up cancels), and paired wall / cpu medians of whole runs (bench/paired.py).
#   bench/flight/cost.sh [chute binary]   -> bench/results/flight_cost.md
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
CHUTE=${1:-$ROOT/build/bin/chute}
W=$(mktemp -d)
python3 - "$ROOT" "$W" <<'PY'
import sys
root, w = sys.argv[1], sys.argv[2]
s = open(root + '/cases/c9_flight.toml').read().replace('file = "c9_flight.msh"', 'file = "%s/cases/c9_flight.msh"' % root)
open(w + '/with_flow.toml', 'w').write(s)
i = s.index('[[loads.canopy_flow]]'); j = s.index('\n[', i + 5)
s = s[:i] + '[[loads.pressure]]\nmembranes = "canopy"\npressure = 1.0\n' + s[j:]
i = s.index('[[output.probes]]   # volume'); j = s.index('\n[', i + 5)
s = s[:i] + s[j + 1:]
open(w + '/without_flow.toml', 'w').write(s)
# The loads a generated case had before the airflow's (chute mesh parachute --pressure): the
# constant pressure and the fabric's normal drag, which FL8 now includes.
s = s.replace('[[loads.pressure]]\nmembranes = "canopy"\npressure = 1.0\n',
              '[[loads.pressure]]\nmembranes = "canopy"\npressure = 1.0\n\n[[loads.face_drag]]\n'
              'membranes = "canopy"\ncd = 1.2\nair_density = 0.0023769\nwind = [0.0, 0.0, 0.0]\n')
open(w + '/pressure_face_drag.toml', 'w').write(s)
PY
cd "$W"
per_step() {  # instructions per step of case $1 between t = 0.004 and 0.008
  # One thread: with two, the second thread's spin while it waits for work counts as
  # instructions, as many as the scheduling under valgrind happens to give.
  local a b sa sb
  for te in 0.004 0.008; do
    CHUTE_THREADS=1 valgrind --tool=callgrind --callgrind-out-file=cg_$1_$te "$CHUTE" run $1.toml --set solver.t_end=$te --out o_$1_$te > log_$1_$te 2>&1
  done
  a=$(grep 'I   refs' log_$1_0.004 | awk '{gsub(",","",$4); print $4}'); b=$(grep 'I   refs' log_$1_0.008 | awk '{gsub(",","",$4); print $4}')
  sa=$(grep -oE '[0-9]+ steps,' log_$1_0.004 | head -1 | tr -dc 0-9); sb=$(grep -oE '[0-9]+ steps,' log_$1_0.008 | head -1 | tr -dc 0-9)
  python3 -c "print(($b - $a) / ($sb - $sa))"
}
IW=$(per_step with_flow); IO=$(per_step without_flow); IP=$(per_step pressure_face_drag)
python3 "$ROOT/bench/paired.py" -n 7 --a "$CHUTE run with_flow.toml --set solver.t_end=0.1 --out $W/wa --quiet" --b "$CHUTE run without_flow.toml --set solver.t_end=0.1 --out $W/wb --quiet" > bench.txt 2>&1
python3 "$ROOT/bench/paired.py" -n 7 --a "$CHUTE run with_flow.toml --set solver.t_end=0.1 --out $W/wc --quiet" --b "$CHUTE run pressure_face_drag.toml --set solver.t_end=0.1 --out $W/wd --quiet" > bench2.txt 2>&1
{
  echo "# The airflow's loads in an explicit step of the full-scale C-9"
  echo
  echo "Made by \`bench/flight/cost.sh\` on $(date -u +%F): \`cases/c9_flight.toml\` (2156 canopy triangles, 1345 nodes) against"
  echo "itself with a constant canopy pressure instead of \`[[loads.canopy_flow]]\`."
  echo
  echo "| measure | with the airflow's loads | constant pressure | ratio | constant pressure and face drag (the loads of \`--pressure\`) | ratio |"
  echo "|---|---|---|---|---|---|"
  python3 -c "print('| instructions per step (callgrind, one thread, t = 0.004 to 0.008 s) | %.4g | %.4g | %.3f | %.4g | %.3f |' % ($IW, $IO, $IW / $IO, $IP, $IW / $IP))"
  echo
  echo "Whole runs to t = 0.1 s ($(grep -h '"steps"' wa/summary.json | tr -dc 0-9) / $(grep -h '"steps"' wb/summary.json | tr -dc 0-9) steps; set-up included), paired A/B, min / median / max of 7. A: with the airflow's loads; B: constant pressure:"
  echo
  echo '```'
  grep -E "A/B|A wall|B wall|A cpu|B cpu" bench.txt
  echo '```'
  echo
  echo "A: with the airflow's loads; B: constant pressure and face drag ($(grep -h '"steps"' wd/summary.json | tr -dc 0-9) steps):"
  echo
  echo '```'
  grep -E "A/B|A wall|B wall|A cpu|B cpu" bench2.txt
  echo '```'
} > "$ROOT/bench/results/flight_cost.md"
cat "$ROOT/bench/results/flight_cost.md"

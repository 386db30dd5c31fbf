#!/usr/bin/env bash
# From a fresh clone: installs what is missing (apt), builds, and runs the default case, the
# paper's bead on a five-element rope (sliding across rope nodes), into out/bead_5/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
build/bin/chute run cases/bead_5.toml --out out/bead_5 "$@"
echo "probes: out/bead_5/probes.csv   summary: out/bead_5/summary.json"

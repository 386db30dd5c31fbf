#!/usr/bin/env bash
# Installs the Debian packages that only the benchmarks need (not the build or the tests):
# CalculiX for the peer comparison (bench/peer/run_peer.py) and matplotlib for the plots.
# Only those missing are installed (scripts/install-deps.sh does the work).
set -euo pipefail
exec "$(dirname "$0")/../scripts/install-deps.sh" --as install-bench-deps \
  calculix-ccx python3-matplotlib python3-numpy

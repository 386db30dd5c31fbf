#!/usr/bin/env bash
# Installs the Debian packages that only the benchmarks need (not the build or the tests):
# CalculiX for the peer comparison (bench/peer/run_peer.py) and matplotlib for the plots.
# Only those missing are installed; needs root (or sudo) when something is missing.
set -euo pipefail
PKGS=(calculix-ccx python3-matplotlib python3-numpy)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-bench-deps: all ${#PKGS[@]} packages present"
  exit 0
fi
echo "install-bench-deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"

#!/usr/bin/env bash
# Installs the Debian packages chute needs, only those that are missing.
# Safe to run repeatedly; needs root (or sudo) when something is missing.
#   scripts/install-deps.sh                  # what the build and the tests need
#   scripts/install-deps.sh --as NAME PKG..  # these packages instead (bench/install-bench-deps.sh)
set -euo pipefail
NAME=install-deps
PKGS=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libsuitesparse-dev libopenblas0-pthread
  libvtk9-dev libgmsh-dev gmsh
  libtoml11-dev libfmt-dev nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev xvfb xauth
)
if [ "${1:-}" = "--as" ]; then
  NAME=$2
  shift 2
  PKGS=("$@")
fi
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "$NAME: all ${#PKGS[@]} packages present"
  exit 0
fi
echo "$NAME: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"

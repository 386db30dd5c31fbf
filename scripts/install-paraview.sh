#!/usr/bin/env bash
# ParaView's Python (pvpython) beside the VTK chute builds against, for the test that opens a run's
# series with ParaView's own reader (ParaView.OpensTheSeriesWithItsOwnReader).
#
# Debian 12's python3-paraview (which holds pvpython) conflicts with python3-vtk9, which
# libvtk9-dev needs, so apt cannot install both. The paraview package itself installs beside VTK.
# So: apt installs paraview (when missing), and python3-paraview of the same version is unpacked,
# not installed, into a private prefix. Its pvpython finds its own Python modules there first.
#   scripts/install-paraview.sh [PREFIX]      # default build/paraview; prints the pvpython path
set -euo pipefail
cd "$(dirname "$0")/.."
PREFIX=${1:-build/paraview}
PVPYTHON="$PREFIX/usr/bin/pvpython"
bash scripts/install-deps.sh --as install-paraview paraview >&2
version=$(dpkg-query -W -f='${Version}' paraview)
if [ -x "$PVPYTHON" ] && [ "$(cat "$PREFIX/version" 2>/dev/null)" = "$version" ]; then
  echo "$PVPYTHON"
  exit 0
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "install-paraview: unpacking python3-paraview $version into $PREFIX" >&2
# As root, apt's download sandbox user cannot write to a private temporary directory.
download() { (cd "$tmp" && apt-get download -q -o APT::Sandbox::User=root "python3-paraview=$version" >&2); }
if ! download; then  # no package lists yet (a fresh image): fetch them once and retry
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  download
fi
rm -rf "$PREFIX/usr" "$PREFIX/version"  # only what an earlier unpacking left
mkdir -p "$PREFIX"
dpkg-deb -x "$tmp"/python3-paraview_*.deb "$PREFIX"
echo "$version" > "$PREFIX/version"
[ -x "$PVPYTHON" ] || { echo "install-paraview: no pvpython in python3-paraview" >&2; exit 1; }
echo "$PVPYTHON"

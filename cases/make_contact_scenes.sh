#!/usr/bin/env bash
# Regenerates the scenes of fabric contact (issue: self-contact, packed starts, clusters) with
# `chute mesh`: their .msh and case files in cases/. Run from the repository root after a build.
# Each case gets the [contact] section its acceptance run used (docs/contact.md, "The scenes");
# `--set contact.enabled=false` runs it without (the fabric passes through itself).
# Intersection counts: chute intersections out/<case>.
set -euo pipefail
CHUTE=${CHUTE:-build/bin/chute}
cd "$(dirname "$0")"
C=../$CHUTE
# The full-scale C-9 (28 ft, 28 gores, vent 0.1 D, lines 23 ft) packed in its bag, 227 lb
# (7.06 slug) payload, 0.48 psf: the dynamic pressure of its 20 ft/s descent; 1 s of inflation.
"$C" mesh parachute --gores 28 --diameter 28 --vent-diameter 2.8 --line-length 23 \
  --element-size 0.98 --payload-mass 7.06 --start packed --pressure 0.48 --t-end 1 \
  --out c9_packed.msh --case c9_packed.toml --quiet
# The half-scale C-9 with its slider (as cases/c9_slider.toml) from a packed start, 1.2 s.
"$C" mesh parachute --gores 28 --diameter 14 --vent-diameter 1.4 --line-length 11.5 \
  --element-size 0.49 --slider 1.4 --payload-mass 6 --start packed --t-end 1.2 \
  --out c9_slider_packed.msh --case c9_slider_packed.toml --quiet
# Three half-scale C-9 canopies (no sliders) packed, on risers to one 18 slug payload, 2 s.
"$C" mesh cluster --canopies 3 --gores 28 --diameter 14 --vent-diameter 1.4 --line-length 11.5 \
  --element-size 0.49 --payload-mass 18 --start packed --t-end 2 \
  --out cluster3.msh --case cluster3.toml --quiet

# The contact settings of each scene (docs/contact.md), before its [solver] table.
add_contact() {  # case thickness skin
  python3 - "$1" "$2" "$3" <<'PY'
import sys
path, thickness, skin = sys.argv[1:]
s = open(path).read()
block = ("[contact]   # the packed canopy apart (docs/contact.md, \"The scenes\")\n"
         "thickness = %s\nskin = %s\nstiffness_scale = 0.3\n\n" % (thickness, skin))
i = s.index("\n[solver]") + 1
open(path, "w").write(s[:i] + block + s[i:])
PY
}
add_contact c9_packed.toml 0.005 0.003
add_contact cluster3.toml 0.005 0.003
add_contact c9_slider_packed.toml 0.01 0.006

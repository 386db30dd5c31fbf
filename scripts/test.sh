#!/usr/bin/env bash
# From a fresh clone: installs what is missing (apt), builds with warnings as errors, sets up
# ParaView's Python beside the build (scripts/install-paraview.sh) so the ParaView check runs
# instead of skipping, prints the verification figures, and runs every test with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh -DCHUTE_WERROR=ON
echo "== ParaView (pvpython) for the ParaView reader check =="
bash scripts/install-paraview.sh
export CHUTE_REQUIRE_PARAVIEW=1  # ParaView.OpensTheSeriesWithItsOwnReader fails instead of skipping
echo "== verification figures (paper section 3) =="
build/bin/test_verification --gtest_brief=1 | grep -vE '^\[' || true
cd build
# ParaView's reader check on its own, first: in the parallel run it failed twice in CI with "bad X
# server connection" right after another X test had shut its Xvfb down (it passes alone).
echo "== ParaView reader check =="
ctest --output-on-failure -R '^ParaView\.'
echo "== all other tests =="
ctest --output-on-failure --parallel "$(nproc)" -E '^ParaView\.'

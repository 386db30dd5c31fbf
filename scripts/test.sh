#!/usr/bin/env bash
# From a fresh clone: installs what is missing (apt), builds with warnings as errors, prints the
# verification figures, and runs every test with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh -DCHUTE_WERROR=ON
echo "== verification figures (paper section 3) =="
build/bin/test_verification --gtest_brief=1 | grep -vE '^\[' || true
echo "== all tests =="
cd build && ctest --output-on-failure --parallel "$(nproc)"

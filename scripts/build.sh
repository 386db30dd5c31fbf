#!/usr/bin/env bash
# Configures and builds chute (Release) in build/.
#   scripts/build.sh [--target T ...] [CMAKE_CONFIGURE_ARGS ...]
# --target T builds only T and what it needs (run-default.sh builds just `chute`); without it
# everything is built (tests, benchmarks). Other arguments go to cmake's configure step.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
targets=()
configure=()
while [ $# -gt 0 ]; do
  if [ "$1" = "--target" ] && [ $# -ge 2 ]; then
    targets+=(--target "$2")
    shift 2
  else
    configure+=("$1")
    shift
  fi
done
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
if [ ! -f build/CMakeCache.txt ]; then
  cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE=Release "${configure[@]}"
elif [ ${#configure[@]} -gt 0 ]; then
  cmake -S . -B build "${configure[@]}"
fi
cmake --build build --parallel "$(nproc)" "${targets[@]}"

#!/usr/bin/env bash
# Fuzzes the case-file reader with libFuzzer under AddressSanitizer + UBSan (issue 9, item 4).
#   bench/fuzz.sh [SECONDS]      (default 120)
# Builds fuzz/ in build-fuzz/ with clang (-DCHUTE_FUZZ=ON), seeds the corpus from cases/*.toml
# (plus the same cases with "#set" override lines), runs each target for SECONDS, prints the
# executions and findings, appends a line to bench/results/fuzz.txt and exits 1 on any finding
# (crash, leak, timeout, out-of-memory: their inputs are kept in build-fuzz/artifacts/).
# Needs clang and libclang-rt-14-dev (installed here when missing; not needed by the default build).
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_PER_TARGET=${1:-120}
TARGETS=(${FUZZ_TARGETS:-fuzz_case_reader fuzz_msh_reader})

missing=()
for p in clang libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

B=build-fuzz
if [ ! -f $B/CMakeCache.txt ]; then
  CC=clang CXX=clang++ cmake -S . -B $B -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCHUTE_FUZZ=ON -DCHUTE_BUILD_TESTS=OFF >/dev/null
fi
cmake --build $B --target "${TARGETS[@]}" --parallel 2

mkdir -p $B/artifacts bench/results
status=0
for t in "${TARGETS[@]}"; do
  corpus=$B/corpus/$t seeds=$B/seeds/$t
  mkdir -p "$corpus" "$seeds"
  if [ "$t" = fuzz_case_reader ]; then
    for f in cases/*.toml; do
      cp "$f" "$seeds/"
      { echo "#set solver.dt=1e-3"; echo "#set output.vtu.write=true"; cat "$f"; } \
        > "$seeds/set_$(basename "$f")"
    done
    dict=(-dict=fuzz/case.dict)
  else  # fuzz_msh_reader: the example geometry meshed by gmsh, in ASCII msh 4.1 and 2.2
    gmsh mesh/examples/flat_canopy.geo -2 -format msh41 -o "$seeds/flat_canopy41.msh" >/dev/null
    gmsh mesh/examples/flat_canopy.geo -1 -format msh22 -o "$seeds/flat_canopy22.msh" >/dev/null
    dict=()
  fi
  before=$(find $B/artifacts -type f | wc -l)
  log=$B/$t.log
  # -timeout: one input taking 10 s is a hang; -rss_limit_mb: 2 GB is an out-of-memory finding.
  ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS="suppressions=$PWD/bench/lsan.supp:print_suppressions=0" UBSAN_OPTIONS=print_stacktrace=1 \
    $B/bin/$t "$corpus" "$seeds" "${dict[@]}" -max_total_time="$SECONDS_PER_TARGET" \
    -timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
    -artifact_prefix=$B/artifacts/ >"$log" 2>&1 || true
  execs=$(grep -oP 'stat::number_of_executed_units:\s*\K[0-9]+' "$log" || echo 0)
  rate=$(grep -oP 'stat::average_exec_per_sec:\s*\K[0-9]+' "$log" || echo 0)
  cov=$(grep -oP '#[0-9]+\s+(DONE|INITED).*?cov: \K[0-9]+' "$log" | tail -1 || echo 0)
  findings=$(($(find $B/artifacts -type f | wc -l) - before))
  corpus_size=$(find "$corpus" -type f | wc -l)
  line="$(date -u +%Y-%m-%dT%H:%MZ) $t ${SECONDS_PER_TARGET}s: $execs executions ($rate/s), coverage $cov edges, corpus $corpus_size, findings $findings (crashes, leaks, timeouts, OOMs)"
  echo "$line"
  echo "$line" >> bench/results/fuzz.txt
  if [ "$findings" -gt 0 ] || ! grep -q 'Done [0-9]* runs' "$log"; then
    status=1
    echo "fuzz: $t: findings (see $log and $B/artifacts/)" >&2
    grep -m5 -E 'ERROR|SUMMARY|runtime error|deadly signal|terminate' "$log" >&2 || true
  fi
done
exit $status

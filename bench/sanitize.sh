#!/usr/bin/env bash
# Builds the whole test suite with AddressSanitizer + UndefinedBehaviorSanitizer (gcc) in
# build-asan/ and runs ctest there (issue 9, item 4). Any sanitizer report fails the test that
# triggered it (-fno-sanitize-recover: UBSan aborts; ASan/LSan exit non-zero).
#   bench/sanitize.sh [extra ctest arguments, e.g. -R test_bad_input]
# Appends the outcome to bench/results/sanitize.txt.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh >/dev/null
B=build-asan
FLAGS="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
# No -Werror here: gcc 12 with ASan reports -Wmaybe-uninitialized inside libstdc++ (std::regex,
# std::function), false positives the CI build (-Werror, no sanitizers) does not see.
if [ ! -f $B/CMakeCache.txt ]; then
  cmake -S . -B $B -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCHUTE_WERROR=OFF \
    -DCMAKE_CXX_FLAGS="$FLAGS" -DCMAKE_C_FLAGS="$FLAGS" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
fi
start=$(date +%s)
cmake --build $B --parallel 2
# Leaks in third-party libraries (OpenGL drivers, X) are not ours: bench/lsan.supp lists them.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=1"
export LSAN_OPTIONS="suppressions=$PWD/bench/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# Two passes. (1) Everything but the OpenGL tests, leak detection on. FrameCostStaysSmall is a
# timing bound (ms per VTU frame) that an ASan build cannot meet: it is left out.
# (2) The render and plot tests (they run `chute render|plot`, which loads Mesa's llvmpipe driver
# through dlopen): Mesa's allocations are reported as leaks from an "<unknown module>" (the driver
# is unloaded before the leak check), which no suppression can name, so this pass runs with leak
# detection off; ASan's memory errors and UBSan stay on.
GL='Render\.|Plot\.|ParaView\.'
set +e
(cd $B && ctest --output-on-failure --parallel 2 -E "$GL|FrameCostStaysSmall" "$@") | tee $B/ctest.log
rc1=${PIPESTATUS[0]}
(cd $B && ASAN_OPTIONS="$ASAN_OPTIONS:detect_leaks=0" ctest --output-on-failure --parallel 2 \
  -R "$GL" "$@") | tee $B/ctest_gl.log
rc2=${PIPESTATUS[0]}
set -e
rc=$((rc1 | rc2))
summary="$(grep -E '^[0-9]+% tests passed' $B/ctest.log || echo "ctest did not finish") (leaks checked); $(grep -E '^[0-9]+% tests passed' $B/ctest_gl.log || echo "GL ctest did not finish") (OpenGL tests, leaks not checked)"
reports=$(cat $B/ctest.log $B/ctest_gl.log | grep -cE 'ERROR: (AddressSanitizer|LeakSanitizer)|runtime error:' || true)
mkdir -p bench/results
line="$(date -u +%Y-%m-%dT%H:%MZ) gcc ASan+UBSan ($FLAGS): $summary; sanitizer reports: $reports; $(($(date +%s) - start)) s incl. build"
echo "$line"
echo "$line" >> bench/results/sanitize.txt
exit $rc

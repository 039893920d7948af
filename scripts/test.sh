#!/usr/bin/env bash
# Installs, builds, and runs every test (CTest; the window's GL tests in Xvfb).
#   scripts/test.sh              the suite, built in build/
#   scripts/test.sh --sanitize   the same suite built with AddressSanitizer and
#                                UndefinedBehaviorSanitizer, in build-asan/
#   scripts/test.sh --fuzz       the libFuzzer targets (installs clang), built in build-fuzz/,
#                                each fuzzing for a bounded time
# Further arguments go to ctest.
set -euo pipefail
cd "$(dirname "$0")/.."

mode=normal
if [[ ${1:-} == --sanitize || ${1:-} == --fuzz ]]; then
  mode=${1#--}
  shift
fi

case $mode in
  normal)
    bash scripts/setup.sh
    cd build ;;
  sanitize)
    AMAZEBALLS_BUILD_DIR=build-asan bash scripts/setup.sh -DCMAKE_BUILD_TYPE=RelWithDebInfo -DAMAZEBALLS_SANITIZE=ON
    # Leaks inside system libraries (fontconfig, Mesa) are theirs: see the suppressions.
    export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}
    export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0}
    export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
    cd build-asan ;;
  fuzz)
    AMAZEBALLS_EXTRA_PACKAGES="clang libclang-rt-14-dev" AMAZEBALLS_BUILD_DIR=build-fuzz bash scripts/setup.sh \
      -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DAMAZEBALLS_FUZZ=ON -DAMAZEBALLS_BUILD_TESTS=OFF
    cd build-fuzz ;;
esac
ctest --output-on-failure -j "$(nproc)" "$@"

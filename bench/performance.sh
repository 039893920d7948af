#!/usr/bin/env bash
# Regenerates the measurements in docs/performance.md: builds the CLI and the Bullet
# comparison (Release, -DAMAZEBALLS_BENCH_BULLET=ON; needs libbullet-dev), then runs every
# table one after the other, writing CSV and Markdown into RESULTS_DIR (default
# BUILD_DIR/results). Takes about 10 minutes on a quiet 2-core machine.
#   bash bench/performance.sh [BUILD_DIR] [RESULTS_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-bench}
out=${2:-$build/results}
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DAMAZEBALLS_BENCH_BULLET=ON -DAMAZEBALLS_BUILD_TESTS=OFF \
  "${launcher[@]}" >/dev/null
cmake --build "$build" -j "$(nproc)" --target amazeballs-cli amazeballs-bench-bullet >/dev/null
mkdir -p "$out"
cli="$build/app/amazeballs-cli"

{
  echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
  lscpu | grep -E '^(Model name|CPU\(s\)|Thread|Core|Socket|L1d|L2|L3|Flags)' | sed 's/Flags:.*avx2.*/Flags: ... avx2 ... (and more)/'
  echo "compiler: $(c++ --version | head -n 1)"
  echo "flags: $(grep -E '^CMAKE_CXX_FLAGS(_RELEASE)?:' "$build/CMakeCache.txt" | tr '\n' ' ') -Wall -Wextra -pedantic, C++20"
  echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
} >"$out/machine.txt"

# The physical model on one thread (grid for every N, all-pairs for N <= 1000), then two.
"$cli" bench --threads 1 --out "$out/physical-1.csv" --markdown "$out/physical-1.md"
"$cli" bench --threads 2 --broadphase grid --balls 10000 --balls 100000 --balls 1000000 \
  --out "$out/physical-2.csv" --markdown "$out/physical-2.md"
# The report model (one thread by its nature), both broadphases.
"$cli" bench --model report --broadphase grid --balls 150 --balls 1000 --balls 10000 --balls 100000 \
  --out "$out/report-grid.csv" --markdown "$out/report-grid.md"
"$cli" bench --model report --broadphase all-pairs --balls 150 --balls 1000 --balls 10000 --repeats 3 \
  --out "$out/report-all-pairs.csv" --markdown "$out/report-all-pairs.md"
# Bullet and the physical model in one process, one after the other for each N.
"$build/bench/amazeballs-bench-bullet" --balls 150 --balls 1000 --balls 10000 --balls 100000 --repeats 3 \
  --out "$out/bullet.csv" --markdown "$out/bullet.md"

echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)" >>"$out/machine.txt"
cat "$out/machine.txt"

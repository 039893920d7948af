#!/usr/bin/env bash
# Regenerates the measurements in docs/performance.md: builds the CLI and the Bullet
# comparison (Release, -DAMAZEBALLS_BENCH_BULLET=ON; needs libbullet-dev and GNU time),
# then runs every table one after the other, writing a CSV and a Markdown table per table
# into RESULTS_DIR (default BUILD_DIR/results), all rows joined in RESULTS_DIR/performance.csv,
# and the machine, the load average before each table and the peak memory at 1,000,000
# balls in RESULTS_DIR/machine.txt. The amazeballs tables are the median of 3 runs; Bullet
# costs about 1.3 s a step at 100,000 balls, so its rows are one run each (100 warm-up and
# 200 timed steps: about 7 minutes at 100,000 balls). The whole script takes about 20
# minutes on a quiet 2-core machine.
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
bullet="$build/bench/amazeballs-bench-bullet"
load() { echo "load average before $1: $(cut -d' ' -f1-3 /proc/loadavg)" >>"$out/machine.txt"; }

{
  echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
  lscpu | grep -E '^(Model name|CPU\(s\)|Thread|Core|Socket|L1d|L2|L3)'
  echo "memory: $(free -m | awk '/^Mem:/ {print $2 " MiB"}')"
  echo "compiler: $(c++ --version | head -n 1)"
  echo "flags: $(grep -E '^CMAKE_CXX_FLAGS(_RELEASE)?:' "$build/CMakeCache.txt" | tr '\n' ' ') -Wall -Wextra -pedantic, C++20"
} >"$out/machine.txt"

# The physical model on one thread (grid for every N, all-pairs for N <= 1000), then two.
load physical-1
"$cli" bench --threads 1 --repeats 3 --out "$out/physical-1.csv" --markdown "$out/physical-1.md"
load physical-2
"$cli" bench --threads 2 --repeats 3 --broadphase grid --balls 10000 --balls 100000 --balls 1000000 \
  --out "$out/physical-2.csv" --markdown "$out/physical-2.md"
# The report model (one thread by its nature), both broadphases.
load report-grid
"$cli" bench --model report --broadphase grid --balls 150 --balls 1000 --balls 10000 --balls 100000 \
  --out "$out/report-grid.csv" --markdown "$out/report-grid.md"
load report-all-pairs
"$cli" bench --model report --broadphase all-pairs --balls 150 --balls 1000 \
  --out "$out/report-all-pairs.csv" --markdown "$out/report-all-pairs.md"
# Peak memory of a whole process that steps 1,000,000 balls, as the system counts it.
load memory
/usr/bin/time -v "$cli" bench --threads 1 --repeats 1 --broadphase grid --balls 1000000 \
  --out "$out/memory-1m.csv" >/dev/null 2>"$out/memory-1m.time"
echo "peak memory at 1000000 balls (GNU time, maximum resident set size): $(awk -F': ' \
  '/Maximum resident set size/ {printf "%.0f MiB", $2 / 1024}' "$out/memory-1m.time")" >>"$out/machine.txt"
# Bullet and the physical model in one process, one after the other for each N.
load bullet
"$bullet" --balls 150 --balls 1000 --balls 10000 --repeats 1 --out "$out/bullet-small.csv" \
  --markdown "$out/bullet-small.md"
load bullet-100k
"$bullet" --balls 100000 --repeats 1 --out "$out/bullet-100k.csv" --markdown "$out/bullet-100k.md"
load end

# Every row in one CSV: the columns of both tools, by name, with the table each came from.
# The Bullet comparison's rows name their engine; its own are the physical model on the grid.
awk -F, -v OFS=, '
  BEGIN { n = split("table,balls,model,engine,broadphase,threads,ns_per_ball_step,steps_per_second," \
                    "cpu_ns_per_ball_step,engine_mib,peak_rss_mib,kinetic_energy_at_end", cols, ","); }
  FNR == 1 { delete at; for (i = 1; i <= NF; ++i) at[$i] = i; table = FILENAME; sub(/.*\//, "", table);
             sub(/\.csv$/, "", table); if (NR == 1) { line = cols[1]; for (c = 2; c <= n; ++c) line = line OFS cols[c];
             print line; } next }
  { engine = ("engine" in at) ? $(at["engine"]) : "amazeballs"; bullet = engine == "bullet"; line = table;
    for (c = 2; c <= n; ++c) { v = (cols[c] in at) ? $(at[cols[c]]) : "";
      if (cols[c] == "engine") v = engine;
      else if (cols[c] == "model" && v == "") v = bullet ? "bullet-3.24" : "physical";
      else if (cols[c] == "broadphase" && v == "") v = bullet ? "dbvt" : "grid";
      line = line OFS v; } print line }' \
  "$out"/physical-1.csv "$out"/physical-2.csv "$out"/report-grid.csv "$out"/report-all-pairs.csv \
  "$out"/bullet-small.csv "$out"/bullet-100k.csv >"$out/performance.csv"
cat "$out/machine.txt"

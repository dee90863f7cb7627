#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Host benchmark of dhmath against peer libraries (speed goals); writes
# docs/generated/performance_host.md.
#
#   tools/bench.sh [output.md]      (default docs/generated/performance_host.md)
#
# Environment: BUILD (default build-bench-host), REPS (timing repetitions,
# >= 11, default 31), COUNT (iterations per op under callgrind, default 10000),
# OPW_DIR (a clone of opw_kinematics for its rows: git clone --branch 0.5.5
# https://github.com/Jmeyer1292/opw_kinematics; unset: the rows are skipped and
# the page says how to get it; never copied into this repository).
# Steps:
#   1. configure BUILD with -DDH_BUILD_BENCH=ON -DCMAKE_BUILD_TYPE=Release and
#      -O2 (no -march) for C and C++, build bench_host;
#   2. time every operation (bench_host --reps REPS --csv ...);
#   3. count instructions: valgrind --tool=callgrind bench_host --count COUNT,
#      callgrind_annotate --inclusive=yes (Ir of bw_<id> / COUNT);
#   4. bench/bench_report.py writes docs/generated/performance_host.md (table, flags,
#      package versions, goals) and appends bench/performance_notes.md;
#   5. tools/stamp.sh puts the stamp line (commit, date, machine) on top.
# The accuracy plots are separate: /usr/bin/python3 tools/plot_accuracy.py
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${BUILD:-$ROOT/build-bench-host}
REPS=${REPS:-31}
COUNT=${COUNT:-10000}
OUT=${1:-$ROOT/docs/generated/performance_host.md}
. "$ROOT/tools/opw_dir.sh"
opw_dir_check bench.sh
OPT="-O2 -DNDEBUG"

cmake -S "$ROOT" -B "$BUILD" -DDH_BUILD_BENCH=ON -DDH_BUILD_TESTS=OFF -DDH_BUILD_TOOLS=OFF \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_FLAGS_RELEASE="$OPT" -DCMAKE_CXX_FLAGS_RELEASE="$OPT" \
  -DBENCH_OPW_DIR="$OPW_DIR" >/dev/null
cmake --build "$BUILD" --target bench_host -j2

LOAD0=$(cut -d' ' -f1-3 /proc/loadavg)
"$BUILD/bench/bench_host" --reps "$REPS" --csv "$BUILD/bench_times.csv" | tee "$BUILD/bench_stdout.txt"
LOAD1=$(cut -d' ' -f1-3 /proc/loadavg)

if ! command -v valgrind >/dev/null 2>&1; then
  echo "valgrind not found (apt-get install valgrind): no instruction counts" >&2
  exit 1
fi
valgrind --tool=callgrind --callgrind-out-file="$BUILD/callgrind.out" \
  "$BUILD/bench/bench_host" --count "$COUNT" >/dev/null 2>"$BUILD/callgrind.log"
callgrind_annotate --inclusive=yes --threshold=100 "$BUILD/callgrind.out" >"$BUILD/callgrind.txt"

/usr/bin/python3 "$ROOT/bench/bench_report.py" --times "$BUILD/bench_times.csv" \
  --callgrind "$BUILD/callgrind.txt" --count "$COUNT" --build "$BUILD" \
  --stdout "$BUILD/bench_stdout.txt" --load "$LOAD0 / $LOAD1" --opw "$OPW_DIR" --out "$OUT"
"$ROOT/tools/stamp.sh" tools/bench.sh "$OUT"

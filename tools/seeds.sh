#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs the seeded test suites (ctest label "seeded": every test/<family>/test_*.c
# that draws random inputs) for many values of DHT_SEED and reports the
# failing suites per seed. Every bound in those suites must hold for ANY
# seed, so any failure here is a bug (in the code or in the bound).
#
#   tools/seeds.sh            200 seeds
#   tools/seeds.sh N          N seeds: splitmix64(START + k), k = 1..N
#   tools/seeds.sh N START    the same from another START (default 0)
#   SEEDS="0x1 42" tools/seeds.sh   exactly these seeds
#
# Environment: SEEDS_BUILD (build dir, default build/host: configured
# Release and built once, then reused), JOBS (ctest -j, default 2),
# DHT_ITER_DIV (loop counts divided by this, default 10: 200 seeds take
# about 10 minutes on two cores; DHT_ITER_DIV=1 runs the full counts of the
# default ctest run, about 12 s per seed, 40 minutes for 200).
# FULL_COUNT_SUITES (default test_ik) run at full counts whatever
# DHT_ITER_DIV says: their checks are success rates, which a tenth of the
# targets would turn into coarser statistics (98/100 against >= 99 %). A failing seed reproduces with
#   DHT_SEED=<seed> ctest --test-dir build/host -R <suite> --output-on-failure
# (and the same DHT_ITER_DIV). test_builds_agree (DH_SMALL vs default build,
# bit-identical outputs, about a minute per seed) is not in the label; run it
# for a seed with DHT_SEED=<seed> ctest -R builds_agree.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${SEEDS_BUILD:-build/host}
JOBS=${JOBS:-2}
N=${1:-200}
START=${2:-0}
export DHT_ITER_DIV=${DHT_ITER_DIV:-10}
FULL=${FULL_COUNT_SUITES-test_ik}
full_re="^($(echo $FULL | tr ' ' '|'))\$"

case $N in ''|*[!0-9]*) echo "seeds.sh: N must be a number of seeds, got '$N'" >&2; exit 2 ;; esac
case $START in ''|*[!0-9]*) echo "seeds.sh: START must be a decimal number, got '$START'" >&2; exit 2 ;; esac

# splitmix64 (Steele, Lea, Flood 2014) in bash's 64-bit arithmetic; the
# logical right shifts are arithmetic shifts masked to the remaining bits
splitmix64() {
  local z=$(( $1 * -7046029254386353131 ))           # 0x9e3779b97f4a7c15
  z=$(( (z ^ ((z >> 30) & 0x3ffffffff)) * -4658895280553007687 ))  # 0xbf58476d1ce4e5b9
  z=$(( (z ^ ((z >> 27) & 0x1fffffffff)) * -7723592293110705685 )) # 0x94d049bb133111eb
  z=$(( z ^ ((z >> 31) & 0x1ffffffff) ))
  printf '0x%016x' "$z"
}

if [ -n "${SEEDS:-}" ]; then
  seeds=$SEEDS
else
  seeds=""
  for ((k = 1; k <= N; k++)); do seeds="$seeds $(splitmix64 $((START + k)))"; done
fi

cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD" -j"$JOBS" >/dev/null
suites=$(ctest --test-dir "$BUILD" -N -L seeded | grep -c 'Test *#' || true)
count=$(echo $seeds | wc -w)
echo "seeds.sh: $suites seeded suites x $count seeds, DHT_ITER_DIV $DHT_ITER_DIV${FULL:+ (1 for $FULL)}, build $BUILD"

logdir=$BUILD/seeds-logs
mkdir -p "$logdir"
failed=0
report=""
t0=$(date +%s)
for s in $seeds; do
  log=$logdir/$s.log
  ok=1
  if [ -n "$FULL" ]; then
    DHT_SEED=$s ctest --test-dir "$BUILD" -L seeded -E "$full_re" -j"$JOBS" --output-on-failure >"$log" 2>&1 || ok=0
    DHT_SEED=$s DHT_ITER_DIV=1 ctest --test-dir "$BUILD" -L seeded -R "$full_re" -j"$JOBS" --output-on-failure \
      >>"$log" 2>&1 || ok=0
  else
    DHT_SEED=$s ctest --test-dir "$BUILD" -L seeded -j"$JOBS" --output-on-failure >"$log" 2>&1 || ok=0
  fi
  if [ "$ok" -eq 1 ]; then
    echo "seed $s: passed"
  else
    failed=$((failed + 1))
    bad=$(sed -n 's/^[[:space:]]*[0-9]* - \(test_[a-z0-9_]*\) .*/\1/p' "$log" | tr '\n' ' ')
    echo "seed $s: FAILED $bad(log $log)"
    grep -h -E "^ERROR: |^\[  FAILED  \] [a-z]|is not a" "$log" | sort -u | head -20 | sed "s/^/    /"
    report="$report
  DHT_SEED=$s: $bad"
  fi
done
echo "seeds.sh: $count seeds in $(( $(date +%s) - t0 )) s, $failed failed"
if [ "$failed" -ne 0 ]; then
  echo "failing seeds:$report"
  exit 1
fi

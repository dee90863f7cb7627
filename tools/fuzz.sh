#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# tools/fuzz.sh [seconds] - build the libFuzzer targets of fuzz/ with clang
# (-fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all), run each
# for N seconds (default 60), then replay the committed seed corpus
# fuzz/corpus/<target>/ once (fuzz_robotfile also starts from and replays
# the shipped robots, examples/robots/*.dh). `tools/fuzz.sh 10` is the CI smoke;
# `tools/fuzz.sh 0` only builds and replays the corpus.
#
# Environment: FUZZ_SEED (libFuzzer -seed; check.sh sets one for CI), CC (default clang), FUZZ_TARGETS (default: every
# fuzz/fuzz_*.c), FUZZ_BUILD (default build/fuzz).
# Inputs found during the run go to $FUZZ_BUILD/work/<target>/ (not
# committed; copy interesting ones into fuzz/corpus/<target>/ by hand),
# crashes to $FUZZ_BUILD/artifacts/, logs to $FUZZ_BUILD/logs/.
# Exit status 0 when every target survived and every corpus file replays;
# prints one summary line.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
SECS=${1:-60}
case $SECS in ''|*[!0-9]*) echo "usage: tools/fuzz.sh [seconds]" >&2; exit 2 ;; esac
CC=${CC:-clang}
B=${FUZZ_BUILD:-$ROOT/build/fuzz}
t0=$(date +%s)

if ! command -v "$CC" >/dev/null 2>&1; then
  echo "fuzz.sh: FAILED: compiler '$CC' not found (apt-get install clang libclang-rt-14-dev)"
  exit 1
fi

TARGETS=${FUZZ_TARGETS:-$(cd fuzz && ls fuzz_*.c | sed 's/\.c$//' | tr '\n' ' ')}
mkdir -p "$B/obj" "$B/bin" "$B/logs" "$B/artifacts"

SAN="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
CFLAGS="-std=c99 -O1 -g $SAN -Wall -Wextra -I$ROOT/include -I$ROOT/src -I$ROOT/cli"
# -Werror only for the fuzz targets: the library's warning policy is
# enforced by its own CMake build and by tools/static.sh; a clang-only
# warning there must not stop the fuzzing.
TFLAGS="-Werror"

# ---- build: library + CLI parsers (cli/, the dhmath_parsers library) once (fuzzer-no-link, in parallel), then
# each target linked with them. Objects are rebuilt when their source, any
# header or this script is newer.
JOBS=${JOBS:-$(nproc)}
newest_h=$(find include port src cli fuzz -name '*.h' -newer "$B/stamp" 2>/dev/null | head -1 || true)
[ -f "$B/stamp" ] || newest_h=force
objs=()
pids=()
for f in src/*/*.c cli/dh_expr.c cli/dh_robotfile.c; do
  o="$B/obj/$(echo "$f" | tr '/' '_').o"
  objs+=("$o")
  if [ -n "$newest_h" ] || [ ! -f "$o" ] || [ "$f" -nt "$o" ] || [ "$0" -nt "$o" ]; then
    while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do sleep 0.1; done
    ( $CC $CFLAGS -fsanitize=fuzzer-no-link -c "$f" -o "$o" 2>"$o.log" || { rm -f "$o"; exit 1; } ) &
    pids+=($!)
  fi
done
bad=0
for p in "${pids[@]}"; do wait "$p" || bad=1; done
if [ $bad -ne 0 ]; then
  cat "$B"/obj/*.log
  echo "fuzz.sh: FAILED: library does not compile with $CC"
  exit 1
fi
touch "$B/stamp"
pids=()
for t in $TARGETS; do
  while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do sleep 0.1; done
  ( $CC $CFLAGS $TFLAGS -fsanitize=fuzzer "fuzz/$t.c" "${objs[@]}" -lm -o "$B/bin/$t" 2>"$B/logs/$t.build.log" ) &
  pids+=($!)
done
for p in "${pids[@]}"; do wait "$p" || bad=1; done
if [ $bad -ne 0 ]; then
  cat "$B"/logs/*.build.log
  echo "fuzz.sh: FAILED: a fuzz target does not build"
  exit 1
fi
t1=$(date +%s)

# corpus directories read besides fuzz/corpus/<target>/
extra_corpus() {
  case $1 in
    fuzz_robotfile) echo examples/robots ;;
  esac
}

# ---- fuzz each target for SECS seconds, starting from the committed corpus
failed=""
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export ASAN_OPTIONS=abort_on_error=0:detect_leaks=1
if [ "$SECS" -gt 0 ]; then
  for t in $TARGETS; do
    mkdir -p "$B/work/$t" "fuzz/corpus/$t"
    dict=()
    [ -f "fuzz/$t.dict" ] && dict=(-dict="fuzz/$t.dict")
    # FUZZ_SEED (optional): libFuzzer's -seed, so a CI smoke explores the
    # same sequence every time (a new finding then reproduces locally)
    [ -n "${FUZZ_SEED:-}" ] && dict+=(-seed="$FUZZ_SEED")
    if ! "$B/bin/$t" "${dict[@]}" -max_total_time="$SECS" -timeout=5 -rss_limit_mb=2048 -max_len=4096 \
         -artifact_prefix="$B/artifacts/$t-" -print_final_stats=1 \
         "$B/work/$t" "fuzz/corpus/$t" $(extra_corpus "$t") >"$B/logs/$t.log" 2>&1; then
      echo "--- $t: FAILED (log $B/logs/$t.log) ---"
      grep -E "invariant failed|ERROR: |runtime error|SUMMARY|Test unit written|^  " "$B/logs/$t.log" | head -20 || true
      failed="$failed $t"
    else
      runs=$(grep -Eo "stat::number_of_executed_units: *[0-9]+" "$B/logs/$t.log" | grep -Eo "[0-9]+$" || echo "?")
      echo "$t: ok, $runs runs in ${SECS} s"
    fi
  done
fi

# ---- replay every committed corpus file once (regressions)
nrep=0
for t in $TARGETS; do
  files=()
  for d in "fuzz/corpus/$t" $(extra_corpus "$t"); do
    [ -d "$d" ] || continue
    while IFS= read -r -d '' f; do files+=("$f"); done < <(find "$d" -type f -print0 | sort -z)
  done
  [ ${#files[@]} -eq 0 ] && continue
  nrep=$((nrep + ${#files[@]}))
  if ! "$B/bin/$t" -timeout=5 "${files[@]}" >"$B/logs/$t.replay.log" 2>&1; then
    echo "--- $t: corpus replay FAILED (log $B/logs/$t.replay.log) ---"
    grep -E "invariant failed|ERROR: |runtime error|Running: " "$B/logs/$t.replay.log" | tail -10 || true
    failed="$failed $t(replay)"
  fi
done
t2=$(date +%s)

ntg=$(echo $TARGETS | wc -w)
if [ -n "$failed" ]; then
  echo "fuzz.sh: FAILED:$failed ($ntg targets x ${SECS} s, $nrep corpus files; build $((t1 - t0)) s, total $((t2 - t0)) s)"
  exit 1
fi
echo "fuzz.sh: passed ($ntg targets x ${SECS} s, $nrep corpus files replayed; build $((t1 - t0)) s, total $((t2 - t0)) s)"

#!/usr/bin/env bash
# The README's test command: builds and runs every test suite.
#   tools/check.sh            all stages
#   tools/check.sh host asan  only the named stages
# Stages: host (Release build, cmocka suite + CLI tests), seeds (the seeded
# suites again for 3 fresh seeds, printed, full loop counts; any seed
# reproduces with tools/seeds.sh, see there), asan (ASan+UBSan),
# target suites under QEMU (M0+, M4F, M7; M0+ and M4F again with DH_SMALL at
# -Os), riscv32 compile check, guards
# (no .data/.bss, no heap/printf, fixed path free of float/64-bit division,
# stack <= 256 B), config variants, coverage >= 95 % lines / 90 % branches,
# cppcheck (MISRA addon) + clang-tidy, public contracts (tools/check_contracts.py:
# function comments <= 30 lines, no history markers in src/ and include/),
# and a 10 s libFuzzer smoke per target.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
JOBS=${JOBS:-$(nproc)}
STAGES=${*:-"host seeds asan m0 m4f m7 small riscv32 guards variants coverage static contracts fuzz apidoc"}
failed=""

run_stage() {
  local name=$1; shift
  echo "=== stage $name ==="
  if "$@"; then echo "=== stage $name: passed ==="; else echo "=== stage $name: FAILED ==="; failed="$failed $name"; fi
}

host_suite() { # builddir, extra cmake args...
  local dir=$1; shift
  cmake -S "$ROOT" -B "$dir" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null &&
  cmake --build "$dir" -j"$JOBS" >/dev/null &&
  ctest --test-dir "$dir" -j"$JOBS" --output-on-failure
}

target_suite() { # builddir, toolchain file, extra cmake args...
  local dir=$1 tc=$2; shift 2
  cmake -S "$ROOT" -B "$dir" -DCMAKE_TOOLCHAIN_FILE="$ROOT/port/$tc" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null &&
  cmake --build "$dir" -j"$JOBS" >/dev/null &&
  ctest --test-dir "$dir" -j"$JOBS" --output-on-failure
}

# DH_SMALL (size-first code, dh_config.h) on the two cores it is for, at
# the -Os it is measured with (docs/footprint.md)
small_suite() {
  target_suite build/m4f-small cortex-m4f.cmake -DDH_SMALL=ON -DCMAKE_BUILD_TYPE=MinSizeRel &&
  target_suite build/m0-small cortex-m0plus.cmake -DDH_SMALL=ON -DCMAKE_BUILD_TYPE=MinSizeRel
}

# n fresh 64-bit seeds from /dev/urandom (the date when it is missing)
fresh_seeds() {
  local k
  for ((k = 0; k < $1; k++)); do
    if [ -r /dev/urandom ]; then printf '0x%s ' "$(od -An -N8 -tx8 /dev/urandom | tr -d ' ')"
    else printf '%s ' "$(( $(date +%s%N) + k ))"; fi
  done
}

for s in $STAGES; do
  case $s in
    host) run_stage host host_suite build/host ;;
    seeds) run_stage seeds env SEEDS="$(fresh_seeds 3)" DHT_ITER_DIV=1 JOBS="$JOBS" tools/seeds.sh ;;
    asan) run_stage asan host_suite build/asan -DDH_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug ;;
    m0) [ -f port/cortex-m0plus.cmake ] && run_stage m0 target_suite build/m0 cortex-m0plus.cmake ;;
    m4f) [ -f port/cortex-m4f.cmake ] && run_stage m4f target_suite build/m4f cortex-m4f.cmake ;;
    m7) [ -f port/cortex-m7.cmake ] && run_stage m7 target_suite build/m7 cortex-m7.cmake ;;
    small) run_stage small small_suite ;;
    riscv32) [ -f port/riscv32.cmake ] && run_stage riscv32 bash -c "cmake -S '$ROOT' -B build/rv32 -DCMAKE_TOOLCHAIN_FILE='$ROOT/port/riscv32.cmake' -DDH_BUILD_TESTS=OFF >/dev/null && cmake --build build/rv32 -j$JOBS" ;;
    guards) [ -x tools/check_guards.sh ] && run_stage guards tools/check_guards.sh ;;
    variants) [ -x tools/check_variants.sh ] && run_stage variants tools/check_variants.sh ;;
    coverage) [ -x tools/coverage.sh ] && run_stage coverage tools/coverage.sh build/coverage ;;
    static) [ -x tools/static.sh ] && run_stage static bash -c "tools/static.sh && STATIC_BUILD='$ROOT/build/static-small' STATIC_CMAKE_ARGS=-DDH_SMALL=ON tools/static.sh" ;;
    contracts) run_stage contracts python3 tools/check_contracts.py ;;
    fuzz) [ -x tools/fuzz.sh ] && run_stage fuzz env FUZZ_SEED=${FUZZ_SEED:-20261124} tools/fuzz.sh 10 ;;
    apidoc) run_stage apidoc bash -c 'mkdir -p build && doxygen docs/Doxyfile' ;;
    *) echo "unknown stage $s"; exit 2 ;;
  esac
done

if [ -n "$failed" ]; then
  echo "check.sh: FAILED stages:$failed"
  exit 1
fi
echo "check.sh: all stages passed ($STAGES)"

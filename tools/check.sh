#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The README's test command: builds and runs every test suite.
#   tools/check.sh            all stages
#   tools/check.sh host asan  only the named stages
# Stages: host (Release build, cmocka suite + CLI tests, each suite at its
# default seed and at its committed regression seeds), seeds (every seeded
# suite at every committed regression seed of test/regression_seeds.txt, a
# tenth of the loop counts: deterministic; tools/seeds.sh searches fresh
# seeds outside the landing gate), asan (ASan+UBSan; the regression seeds
# run in the host stage only, as in variants and coverage),
# target suites under QEMU (M0+, M4F, M7; M0+ and M4F again with DH_SMALL at
# -Os; RV32IMAC and RV32IMAFC with picolibc), firmware examples, guards
# (no .data/.bss, no heap/printf, fixed path free of float/64-bit division,
# stack <= 256 B), config variants, coverage >= 95 % lines / 90 % branches,
# cppcheck (MISRA addon) + clang-tidy, public contracts (tools/check_contracts.py:
# function comments <= 30 lines, no history markers in src/ and include/),
# a 10 s libFuzzer smoke per target, and package (test/consumer/run.sh:
# install, find_package, pkg-config and add_subdirectory consumers, the
# configuration-mismatch link failure, parent-project options, minimal
# cross toolchains without libm, Zephyr/PlatformIO metadata).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
JOBS=${JOBS:-$(nproc)}
STAGES=${*:-"host seeds asan m0 m4f m7 small rv32imac rv32imafc examples guards variants coverage static contracts fuzz apidoc package"}
failed=""

run_stage() {
  local name=$1; shift
  echo "=== stage $name ==="
  if "$@"; then echo "=== stage $name: passed ==="; else echo "=== stage $name: FAILED ==="; failed="$failed $name"; fi
}

host_suite() { # builddir, extra cmake args... (CTEST_ARGS: extra ctest arguments)
  local dir=$1; shift
  cmake -S "$ROOT" -B "$dir" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null &&
  cmake --build "$dir" -j"$JOBS" >/dev/null &&
  ctest --test-dir "$dir" -j"$JOBS" --output-on-failure ${CTEST_ARGS:-}
}

target_suite() { # builddir, toolchain file, extra cmake args...
  local dir=$1 tc=$2; shift 2
  cmake -S "$ROOT" -B "$dir" -DCMAKE_TOOLCHAIN_FILE="$ROOT/port/$tc" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null &&
  cmake --build "$dir" -j"$JOBS" >/dev/null &&
  ctest --test-dir "$dir" -j"$JOBS" --output-on-failure
}

# DH_SMALL (size-first code, config.h) on the two cores it is for, at
# the -Os it is measured with (docs/generated/footprint.md)
small_suite() {
  target_suite build/m4f-small cortex-m4f.cmake -DDH_SMALL=ON -DCMAKE_BUILD_TYPE=MinSizeRel &&
  target_suite build/m0-small cortex-m0plus.cmake -DDH_SMALL=ON -DCMAKE_BUILD_TYPE=MinSizeRel
}

# The committed regression seeds (test/regression_seeds.txt), once each
regression_seeds() {
  sed -e 's/#.*//' "$ROOT/test/regression_seeds.txt" | awk 'NF >= 3 { print $2 }' | sort -u | tr '\n' ' '
}

# The examples: the host ones (README's C example, the C++ example) and the
# firmware ones (examples/firmware/) on the M0+ and the M4F under QEMU, each
# output checked against an independent reference. The target suites run
# the firmware examples as well; this stage builds only the examples.
examples_suite() {
  local b tc
  cmake -S "$ROOT" -B build/host -DCMAKE_BUILD_TYPE=Release >/dev/null &&
  cmake --build build/host -j"$JOBS" --target readme_example cpp_example >/dev/null &&
  ctest --test-dir build/host --output-on-failure -R '^(readme_example|readme_example_in_sync|cpp_example)$' || return 1
  for b in m0:cortex-m0plus.cmake m4f:cortex-m4f.cmake; do
    tc=${b#*:}; b=build/${b%%:*}
    fw="fw_fixed_fk fw_float_ik fw_fixed_kin fw_fixed_track fw_fixed_motion"
    [ "$tc" = cortex-m4f.cmake ] && fw="$fw fw_float_motion"   # float motion: FPU cores only
    cmake -S "$ROOT" -B "$b" -DCMAKE_TOOLCHAIN_FILE="$ROOT/port/$tc" -DCMAKE_BUILD_TYPE=Release >/dev/null &&
    cmake --build "$b" -j"$JOBS" --target $fw >/dev/null &&
    ctest --test-dir "$b" --output-on-failure -R '^example_' || return 1
  done
}

for s in $STAGES; do
  case $s in
    host) run_stage host host_suite build/host ;;
    seeds) run_stage seeds env SEEDS="$(regression_seeds)" DHT_ITER_DIV=10 JOBS="$JOBS" tools/seeds.sh ;;
    asan) CTEST_ARGS="-LE regression" run_stage asan host_suite build/asan -DDH_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug ;;
    m0) [ -f port/cortex-m0plus.cmake ] && run_stage m0 target_suite build/m0 cortex-m0plus.cmake ;;
    m4f) [ -f port/cortex-m4f.cmake ] && run_stage m4f target_suite build/m4f cortex-m4f.cmake ;;
    m7) [ -f port/cortex-m7.cmake ] && run_stage m7 target_suite build/m7 cortex-m7.cmake ;;
    small) run_stage small small_suite ;;
    examples) run_stage examples examples_suite ;;
    rv32imac) run_stage rv32imac target_suite build/rv32imac riscv32-imac.cmake ;;
    rv32imafc) run_stage rv32imafc target_suite build/rv32imafc riscv32-imafc.cmake ;;
    guards) [ -x tools/check_guards.sh ] && run_stage guards tools/check_guards.sh ;;
    variants) [ -x tools/check_variants.sh ] && run_stage variants tools/check_variants.sh ;;
    coverage) [ -x tools/coverage.sh ] && run_stage coverage tools/coverage.sh build/coverage ;;
    static) [ -x tools/static.sh ] && run_stage static bash -c "tools/static.sh && STATIC_BUILD='$ROOT/build/static-small' STATIC_CMAKE_ARGS=-DDH_SMALL=ON tools/static.sh" ;;
    contracts) run_stage contracts python3 tools/check_contracts.py ;;
    fuzz) [ -x tools/fuzz.sh ] && run_stage fuzz env FUZZ_SEED=${FUZZ_SEED:-20261124} tools/fuzz.sh 10 ;;
    package) run_stage package env JOBS="$JOBS" test/consumer/run.sh ;;
    apidoc) run_stage apidoc bash -c 'mkdir -p build && doxygen docs/Doxyfile' ;;
    *) echo "unknown stage $s"; exit 2 ;;
  esac
done

if [ -n "$failed" ]; then
  echo "check.sh: FAILED stages:$failed"
  exit 1
fi
echo "check.sh: all stages passed ($STAGES)"

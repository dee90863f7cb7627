#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# target_bench.sh - on-target benchmark: builds the firmware in bench/target
# for Cortex-M0 (micro:bit), Cortex-M4F (mps2-an386) and Cortex-M7
# (mps2-an500) at -O2, -Os and -Os with DH_SMALL=1 (size-first build), runs each image under QEMU with
# -icount shift=0 (executed instructions counted exactly through SysTick)
# and writes docs/generated/performance_target.md, stamped by tools/stamp.sh.
#
#   tools/target_bench.sh [output.md]
#
# Environment:
#   TBENCH_CORES  cores to run (default "m0 m4f m7")
#   TBENCH_OPTS   optimisation levels (default "O2 Os Os-small"; Os-small =
#                 -Os with -DDH_SMALL=ON)
#   JOBS          parallel compile jobs (default: nproc)
#   QEMU          emulator (default qemu-system-arm)
#   TBENCH_LIB    benchmark the library (src/ include/ port/ cmake/ CMakeLists.txt)
#                 of this commit instead of the working tree, e.g. HEAD: it is
#                 exported with git archive to build/tbench-lib/ (the
#                 firmware sources always come from the working tree). The
#                 committed docs/generated/performance_target.md is made this way, so
#                 its figures belong to the commit it names.
#   OPW_DIR       a clone of opw_kinematics (git clone --branch 0.5.5
#                 https://github.com/Jmeyer1292/opw_kinematics; never copied into
#                 this repository): its inverse<float> is measured beside
#                 dh_ikc_f32 / dh_ikc_q on the cores with an FPU (needs
#                 libeigen3-dev and libstdc++-arm-none-eabi-newlib). Unset: no
#                 opw row, and the page says how to get it.
# Build trees: build/tbench-<core>-<opt>/ ; logs: build/tbench-logs/.
# Needs gcc-arm-none-eabi, libnewlib-arm-none-eabi, qemu-system-arm,
# python3; libcglm-dev for the cglm peer rows (omitted without it).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
OUT=${1:-docs/generated/performance_target.md}
CORES=${TBENCH_CORES:-m0 m4f m7}
OPTS=${TBENCH_OPTS:-O2 Os Os-small}
JOBS=${JOBS:-$(nproc)}
QEMU=${QEMU:-qemu-system-arm}
PY=/usr/bin/python3
LOGS=build/tbench-logs
. "$ROOT/tools/opw_dir.sh"
opw_dir_check target_bench.sh
mkdir -p "$LOGS"
rm -f "$LOGS"/*.log

toolchain() { # core -> toolchain file
  case $1 in
    m0) echo port/cortex-m0plus.cmake ;;
    m4f) echo port/cortex-m4f.cmake ;;
    m7) echo port/cortex-m7.cmake ;;
    *) echo "target_bench.sh: unknown core $1" >&2; exit 2 ;;
  esac
}

cache_get() { # dir var
  sed -n "s/^$2:[A-Z]*=//p" "$1/CMakeCache.txt"
}

libroot=$ROOT
if [ -n "${TBENCH_LIB:-}" ]; then
  libcommit=$(git rev-parse --short "$TBENCH_LIB^{commit}")
  libroot=$ROOT/build/tbench-lib
  rm -rf "$libroot"
  mkdir -p "$libroot"
  git archive "$libcommit" CMakeLists.txt cmake src include port | tar -x -C "$libroot"
  libdesc="$libcommit (exported with git archive)"
else
  libcommit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
  libdesc="working tree at $libcommit"
  if ! git diff --quiet HEAD -- CMakeLists.txt cmake src include port 2>/dev/null ||
     [ -n "$(git ls-files --others --exclude-standard -- cmake src include port 2>/dev/null)" ]; then
    libdesc="$libdesc with uncommitted changes in cmake/src/include/port"
  fi
fi
echo "== library: $libdesc"

logs=()
for core in $CORES; do
  for opt in $OPTS; do
    extra=
    case $opt in O2) bt=RelWithDebInfo ;; Os) bt=MinSizeRel ;;
      Os-small) bt=MinSizeRel; extra=-DDH_SMALL=ON ;;
      *) echo "target_bench.sh: unknown optimisation $opt (O2, Os or Os-small)" >&2; exit 2 ;; esac
    dir=build/tbench-$core-$opt
    echo "== $core -$opt: build ($dir)"
    cmake -S bench/target -B "$dir" -DCMAKE_TOOLCHAIN_FILE="$ROOT/$(toolchain "$core")" \
          -DCMAKE_BUILD_TYPE=$bt -DBENCH_LIB_ROOT="$libroot" -DBENCH_OPW_DIR="$OPW_DIR" $extra >"$dir.configure.log" 2>&1 ||
      { cat "$dir.configure.log"; exit 1; }
    cmake --build "$dir" -j"$JOBS" >"$dir.build.log" 2>&1 ||
      { tail -40 "$dir.build.log"; exit 1; }
    board=$(cache_get "$dir" DH_TARGET_BOARD)
    cpu=$(cache_get "$dir" DH_TARGET_CPU)
    log=$LOGS/$core-$opt.log
    echo "== $core -$opt: run ($QEMU -machine $board -cpu $cpu -icount shift=0)"
    rc=0
    timeout 120 "$QEMU" -machine "$board" -cpu "$cpu" -icount shift=0 \
      -semihosting-config enable=on,target=native -nographic -monitor none -serial none \
      -kernel "$dir/bench_target.elf" >"$log" 2>&1 || rc=$?
    if [ $rc -ne 0 ]; then
      cat "$log"
      echo "target_bench.sh: $core -$opt exited with status $rc" >&2
      exit 1
    fi
    eval "flags_$core=\$(cache_get \"\$dir\" CMAKE_C_FLAGS)"
    logs+=("$log=$dir/bench_target.elf")
  done
done

meta=$LOGS/meta.txt
{
  echo "compiler=$(arm-none-eabi-gcc --version | head -1)"
  echo "qemu=$($QEMU --version | head -1)"
  v=$(dpkg-query -W -f='${Version}' libnewlib-arm-none-eabi 2>/dev/null || true)
  [ -n "$v" ] && echo "newlib=libnewlib-arm-none-eabi $v (Debian), full newlib + rdimon semihosting"
  v=$(dpkg-query -W -f='${Version}' libcglm-dev 2>/dev/null || true)
  [ -n "$v" ] && echo "cglm=libcglm-dev $v (Debian)"
  echo "library=$libdesc"
  if [ -n "$OPW_DIR" ]; then
    v=$(sed -n 's:.*<version>\(.*\)</version>.*:\1:p' "$OPW_DIR/package.xml" 2>/dev/null | head -1)
    g=
    [ -e "$OPW_DIR/.git" ] && g=", git $(git -C "$OPW_DIR" describe --tags --always 2>/dev/null)"
    s=$(dpkg-query -W -f='${Version}' libstdc++-arm-none-eabi-newlib 2>/dev/null || true)
    e=$(dpkg-query -W -f='${Version}' libeigen3-dev 2>/dev/null || true)
    echo "opw=version ${v:-?} (package.xml$g), the user's clone; libstdc++-arm-none-eabi-newlib ${s:-?}, libeigen3-dev ${e:-?}"
  fi
  echo "qemu-cmd=$QEMU -machine <board> -cpu <cpu> -icount shift=0 -semihosting-config enable=on,target=native -nographic -monitor none -serial none -kernel bench_target.elf"
  for core in $CORES; do
    f=flags_$core
    # only the core flags (-mcpu/-mthumb/-mfpu/-mfloat-abi)
    echo "flags-$core=$(echo "${!f}" | tr ' ' '\n' | grep -E '^-m(cpu|thumb|fpu|float-abi)' | tr '\n' ' ' | sed 's/ $//')"
  done
} >"$meta"

$PY bench/target/report.py "$OUT" "$meta" "${logs[@]}"
tools/stamp.sh tools/target_bench.sh "$OUT"
echo "== wrote $OUT"

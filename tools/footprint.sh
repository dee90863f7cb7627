#!/usr/bin/env bash
# footprint.sh - flash and stack of the library on Cortex-M0+ and Cortex-M4F
# at -Os and -O2, written to docs/footprint.md (tools/footprint.py).
# Builds the library alone in build/guards-<cpu>-<opt> (the same
# configurations as tools/check_guards.sh, so running both builds once).
#   tools/footprint.sh [output.md]
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
OUT=${1:-docs/footprint.md}
JOBS=${JOBS:-$(nproc)}

build() { # cpu opt
  local cpu=$1 opt=$2 bt dir f
  case $opt in Os) bt=MinSizeRel ;; O2) bt=RelWithDebInfo ;; esac
  dir=build/guards-$cpu-$opt
  cmake -S "$ROOT" -B "$dir" -DCMAKE_TOOLCHAIN_FILE="$ROOT/port/cortex-$cpu.cmake" \
        -DCMAKE_BUILD_TYPE=$bt -DDH_BUILD_TESTS=OFF \
        "-DCMAKE_C_FLAGS=-fstack-usage -fcallgraph-info=su" >/dev/null
  for f in "$dir"/CMakeFiles/dhmath.dir/src/*.c.ci; do
    [ -e "$f" ] || continue
    f=$(basename "$f" .ci)
    [ -e "$ROOT/src/$f" ] || rm -f "$dir/CMakeFiles/dhmath.dir/src/$f".*
  done
  cmake --build "$dir" -j"$JOBS" --target dhmath >/dev/null
}

for cpu in m0plus m4f; do
  for opt in Os O2; do build $cpu $opt; done
done

M0="-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft"
M4F="-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard"
/usr/bin/python3 tools/footprint.py "$OUT" \
  "M0+ -Os=build/guards-m0plus-Os=$M0 -Os" \
  "M0+ -O2=build/guards-m0plus-O2=$M0 -O2" \
  "M4F -Os=build/guards-m4f-Os=$M4F -Os" \
  "M4F -O2=build/guards-m4f-O2=$M4F -O2"

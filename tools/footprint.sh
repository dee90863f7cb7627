#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# footprint.sh - flash and stack of the library on Cortex-M0+ and Cortex-M4F
# at -Os and -O2, and at -Os with DH_SMALL=1 (the size-first build), written
# to docs/generated/footprint.md (tools/footprint.py), stamped by tools/stamp.sh.
# The report opens with the size goal's flash budget (the float + fixed core on
# Cortex-M4F -Os against 8 KiB) and includes firmware profiles: entry tables
# generated from the public headers, linked with --gc-sections, flash split
# into dhmath / libgcc / libm+libc from the map file (tools/footprint.py).
#
#   tools/footprint.sh [--rev <commit>] [output.md]
#
# Default: measures the working tree, building the library alone in
# build/guards-<cpu>-<opt> (the same configurations as tools/check_guards.sh,
# so running both builds once). With --rev (e.g. --rev HEAD, as used for the
# committed docs/generated/footprint.md) it measures that commit instead: `git archive`
# into build/footprint-src, fresh builds in build/footprint-<cpu>-<opt>, so
# uncommitted edits in the tree do not enter the figures.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
REV=
if [ "${1:-}" = "--rev" ]; then
  REV=${2:?--rev needs a commit}
  shift 2
fi
OUT=${1:-docs/generated/footprint.md}
JOBS=${JOBS:-$(nproc)}

if [ -n "$REV" ]; then
  SHA=$(git rev-parse --verify "$REV^{commit}")
  SRC=$ROOT/build/footprint-src
  PREFIX=build/footprint
  rm -rf "$SRC"
  mkdir -p "$SRC"
  git archive "$SHA" | tar -x -C "$SRC"
  DESC="commit ${SHA:0:12} (\`$REV\`, exported with git archive)"
else
  SRC=$ROOT
  PREFIX=build/guards
  SHA=$(git rev-parse HEAD)
  DIRTY=$(git status --porcelain -- src include port CMakeLists.txt | awk '{print $NF}' | tr '\n' ' ')
  DESC="working tree at commit ${SHA:0:12}"
  [ -z "$DIRTY" ] || DESC="$DESC, with uncommitted changes in: ${DIRTY% }"
fi

build() { # cpu opt [small]
  local cpu=$1 opt=$2 small=${3:-} bt dir f extra=
  case $opt in Os) bt=MinSizeRel ;; O2) bt=RelWithDebInfo ;; esac
  dir=$PREFIX-$cpu-$opt
  if [ -n "$small" ]; then dir=$dir-small; extra=-DDH_SMALL=ON; fi
  [ -z "$REV" ] || rm -rf "$dir"
  cmake -S "$SRC" -B "$dir" -DCMAKE_TOOLCHAIN_FILE="$SRC/port/cortex-$cpu.cmake" \
        -DCMAKE_BUILD_TYPE=$bt -DDH_BUILD_TESTS=OFF $extra \
        "-DCMAKE_C_FLAGS=-fstack-usage -fcallgraph-info=su" >/dev/null
  for f in "$dir"/CMakeFiles/dhmath.dir/src/*.c.ci "$dir"/CMakeFiles/dhmath.dir/src/*/*.c.ci; do
    [ -e "$f" ] || continue
    f=${f#"$dir"/CMakeFiles/dhmath.dir/}
    f=${f%.ci}
    [ -e "$SRC/$f" ] || rm -f "$dir/CMakeFiles/dhmath.dir/$f".*
  done
  cmake --build "$dir" -j"$JOBS" --target dhmath >/dev/null
}

for cpu in m0plus m4f; do
  for opt in Os O2; do build $cpu $opt; done
  build $cpu Os small
done

M0="-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft"
M4F="-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard"
CMD="tools/footprint.sh${REV:+ --rev $REV}"
[ "$OUT" = docs/generated/footprint.md ] || CMD="$CMD $OUT"
/usr/bin/python3 tools/footprint.py "$OUT" \
  "--src=$SRC" "--desc=$DESC" "--cmd=$CMD" \
  "M0+ -Os=$PREFIX-m0plus-Os=$M0 -Os" \
  "M0+ -O2=$PREFIX-m0plus-O2=$M0 -O2" \
  "M4F -Os=$PREFIX-m4f-Os=$M4F -Os" \
  "M4F -O2=$PREFIX-m4f-O2=$M4F -O2" \
  "M0+ -Os DH_SMALL=$PREFIX-m0plus-Os-small=$M0 -Os" \
  "M4F -Os DH_SMALL=$PREFIX-m4f-Os-small=$M4F -Os"
tools/stamp.sh tools/footprint.sh "$OUT"

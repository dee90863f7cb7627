#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# check_guards.sh - CI guards on the cross-compiled library (libdhmath.a).
#
# Builds the library alone (no tests) for Cortex-M0+ (soft float, so every
# float operation is a visible __aeabi_* call) and Cortex-M4F (hard float,
# so float code is visible as VFP instructions), each at -Os and -O2, with
# -fstack-usage -fcallgraph-info=su, and checks:
#   1. no .data, .bss or COMMON in any library object (no mutable globals);
#   2. no heap (malloc/calloc/realloc/free...), no stdio (printf family,
#      puts...), no exit/abort from library code;
#   3. the fixed-point objects (src/*_q.c) reference only integer helpers:
#      no float or double soft-float calls (__aeabi_f*, __aeabi_d*,
#      __addsf3...), no libm, no 64-bit division (__aeabi_ldivmod,
#      __aeabi_uldivmod, __divdi3...), no *_f32 library functions; and on
#      the M4F they contain no VFP instruction;
#   4. no recursion, no dynamic or unbounded stack (VLA, alloca, indirect
#      calls), and the worst-case stack of every public function, including
#      the libgcc/libm/libc functions it calls, is <= 256 bytes
#      (tools/dh_stack.py);
#   5. the size goal: the float + fixed core (profile (k) of
#      tools/footprint.py) fits in 8192 bytes of flash on Cortex-M4F at
#      -Os with DH_SMALL=1.
# Exit status 0 when every guard holds. Build dirs: build/guards-<cpu>-<opt>
# (and build/guards-<cpu>-Os-small for DH_SMALL=1 at -Os).
#   tools/check_guards.sh              all six configurations
#   STACK_LIMIT=512 tools/check_guards.sh
set -uo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
PY=/usr/bin/python3
LIMIT=${STACK_LIMIT:-256}
JOBS=${JOBS:-$(nproc)}
fail=0
problems=""

bad() { echo "GUARD FAILED: $*"; problems="$problems\n  $*"; fail=1; }

configure_build() { # cpu opt [small] -> builddir
  local cpu=$1 opt=$2 small=${3:-} bt dir extra=
  case $opt in
    Os) bt=MinSizeRel ;;
    O2) bt=RelWithDebInfo ;;
    O3) bt=Release ;;
  esac
  dir=build/guards-$cpu-$opt
  if [ -n "$small" ]; then dir=$dir-small; extra=-DDH_SMALL=ON; fi
  cmake -S "$ROOT" -B "$dir" -DCMAKE_TOOLCHAIN_FILE="$ROOT/port/cortex-$cpu.cmake" \
        -DCMAKE_BUILD_TYPE=$bt -DDH_BUILD_TESTS=OFF $extra \
        "-DCMAKE_C_FLAGS=-fstack-usage -fcallgraph-info=su" >/dev/null || return 1
  # call graphs of sources that no longer exist would skew the stack check
  local f
  for f in "$dir"/CMakeFiles/dhmath.dir/src/*.c.ci "$dir"/CMakeFiles/dhmath.dir/src/*/*.c.ci; do
    [ -e "$f" ] || continue
    f=${f#"$dir"/CMakeFiles/dhmath.dir/}
    f=${f%.ci}
    [ -e "$ROOT/$f" ] || rm -f "$dir/CMakeFiles/dhmath.dir/$f".*
  done
  cmake --build "$dir" -j"$JOBS" --target dhmath >/dev/null 2>"$dir.err" || { cat "$dir.err"; return 1; }
  echo "$dir"
}

check_config() { # cpu opt [small]
  local cpu=$1 opt=$2 small=${3:-} dir lib flags
  echo "=== guards: cortex-$cpu -$opt${small:+ DH_SMALL} ==="
  dir=$(configure_build "$cpu" "$opt" "$small") || { bad "cortex-$cpu -$opt${small:+ DH_SMALL}: library does not build"; return; }
  lib=$dir/libdhmath.a
  # 1-3. sections and symbols (tools/dh_guards.py)
  local mode=soft
  [ "$cpu" = m4f ] && mode=vfp
  if ! $PY "$ROOT/tools/dh_guards.py" "$lib" $mode; then
    bad "cortex-$cpu -$opt: section/symbol guards (see GUARD FAILED lines above)"
  fi

  # 4. stack
  case $cpu in
    m0plus) flags="-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft" ;;
    m4f) flags="-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard" ;;
  esac
  if $PY "$ROOT/tools/dh_stack.py" "$dir/CMakeFiles/dhmath.dir" "$lib" "$LIMIT" -- $flags > "$dir/stack.txt"; then
    echo "ok: worst-case stack of every public function <= $LIMIT bytes (max $(head -1 "$dir/stack.txt" | awk '{print $1 " bytes, " $2}')); no recursion"
  else
    bad "cortex-$cpu -$opt: stack guard (limit $LIMIT bytes incl. libgcc/libm; full list $dir/stack.txt):"
    grep -E 'OVER LIMIT|ERROR' "$dir/stack.txt" | sed 's/^/    /'
  fi

  # 5. the size goal: the float + fixed core on Cortex-M4F, size-first -Os
  if [ "$cpu" = m4f ] && [ "$opt" = Os ] && [ -n "$small" ]; then
    $PY "$ROOT/tools/footprint.py" --budget "$dir" "$flags -Os" || bad "cortex-m4f -Os DH_SMALL: size-first core over its flash budget"
  fi
}

for cpu in m0plus m4f; do
  for opt in Os O2; do
    check_config $cpu $opt
  done
  # the size-first build (DH_SMALL, config.h) is meant for -Os
  check_config $cpu Os small
done

if [ $fail -ne 0 ]; then
  echo -e "check_guards: FAILED:$problems"
  exit 1
fi
echo "check_guards: all guards hold"

#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# test/consumer/run.sh - the "package" stage of tools/check.sh: dhmath as a
# dependency of an external project (test/consumer/app.c).
#   1. install: a top-level configure without a build type builds Release
#      with DH_WERROR ON; cmake --install puts headers, libdhmath.a, the CMake
#      package (dhmathConfig.cmake + version file + dhmath_add_robot()),
#      dhmath.pc, bin/dhmath and the licence under a prefix;
#   2. find_package(dhmath 0.3 CONFIG REQUIRED) -> dhmath::dhmath, built and run;
#   3. a plain Makefile with pkg-config, built and run (no -lm); the .pc
#      file names the licence and pkg-config --validate accepts it;
#   4. configuration guard: the same program compiled with DH_MAX_JOINTS 6
#      or DH_QPOS_FRAC 12 against the installed library must FAIL to link,
#      naming the setting (also with --gc-sections);
#   5. parent project (subdir/): set(DH_MAX_JOINTS 6) before add_subdirectory
#      reaches library and program, the parent's own option(DH_APP_FEATURE)
#      is accepted, DH_WERROR is OFF and the build type the parent's, a
#      misspelled dhmath option on the command line is reported (warning
#      under a parent, error at the top level), a misspelled set(DH_MAX_JOINT)
#      of the parent gets a warning naming it;
#   5b. strict parent (strict/): -Wall -Wextra -Wpedantic -Wconversion
#      -Wshadow -Wundef -Wfloat-equal -Wcast-qual -Wstrict-prototypes
#      -Wmissing-prototypes -Wdouble-promotion -Werror on the whole build,
#      library sources included, with GCC and with Clang;
#   6. cross builds through add_subdirectory with minimal toolchain files
#      (cross/m0plus.cmake with DH_SMALL, cross/m4f.cmake with
#      -ffreestanding and --gc-sections): the firmware links without libm;
#      the mismatched firmware fails to link, also with --gc-sections;
#   6b. installed cross package (port/cortex-m4f.cmake, cmake --install to a
#      prefix): a cross consumer (robot/) finds it through CMAKE_PREFIX_PATH
#      alone, turns a robot file into C source with dhmath_add_robot() and
#      the installed host bin/dhmath, links with --orphan-handling=error
#      (port's linker script) and runs under QEMU; the same consumer on the
#      host, linked with --orphan-handling=warn: no orphan section but the
#      C runtime's start files' (Debian's own crt objects have some); and
#      a host consumer that vendors dhmath (add_subdirectory), whose
#      dhmath_add_robot() builds and runs the CLI target; a cross one with no
#      host dhmath stops at configure time saying how to get one;
#   7. no libm: no undefined symbol of the host, M0+ or M4F library is one
#      that libm defines (nm against the toolchain's own libm);
#   8. ecosystem metadata: zephyr/module.yml, zephyr/Kconfig (every DH_*
#      setting), zephyr/CMakeLists.txt and library.json parse, and every
#      version equals DH_VERSION_STRING; library.json names the licence,
#      repository, authors and the platforms; the installed licence is the
#      LICENSE file and the CMake package's dhmath_LICENSE is Apache-2.0.
# DHMATH_SRC=<tree> runs it against another source tree (default: this one);
# CONSUMER_BUILD=<dir> (default build/consumer). Exit status 0 = all hold.
set -uo pipefail
cd "$(dirname "$0")/../.."
ROOT=$(pwd)
SRC=$(cd "${DHMATH_SRC:-$ROOT}" && pwd)
B=${CONSUMER_BUILD:-$ROOT/build/consumer}
T=$ROOT/test/consumer
JOBS=${JOBS:-2}
fail=0
rm -rf "$B"
mkdir -p "$B"

ok() { echo "ok: $*"; }
bad() { echo "PACKAGE CHECK FAILED: $*"; fail=1; }
quiet() { # log, command... : run, output to the log, shown on failure
  local log=$1; shift
  if "$@" >"$log" 2>&1; then return 0; fi
  tail -20 "$log"; return 1
}
# must_fail log pattern command...: the command fails and prints the pattern
must_fail() {
  local log=$1 pat=$2; shift 2
  if "$@" >"$log" 2>&1; then echo "  (succeeded, see $log)"; return 1; fi
  grep -q -- "$pat" "$log" || { tail -5 "$log"; echo "  (no '$pat' in $log)"; return 1; }
}

# ---- 1. install
P=$B/prefix
if quiet "$B/install.log" bash -c "cmake -S '$SRC' -B '$B/lib' -DDH_BUILD_TESTS=OFF \
      -DCMAKE_INSTALL_PREFIX='$P' && cmake --build '$B/lib' -j$JOBS && cmake --install '$B/lib'"; then
  missing=""
  for f in include/dhmath/dhmath.h include/dhmath/config.h lib/libdhmath.a lib/cmake/dhmath/dhmathConfig.cmake \
           lib/cmake/dhmath/dhmathConfigVersion.cmake lib/cmake/dhmath/dhmathTargets.cmake lib/pkgconfig/dhmath.pc \
           lib/cmake/dhmath/dhmathRobot.cmake lib/cmake/dhmath/dhmathGen.cmake bin/dhmath share/doc/dhmath/LICENSE; do
    [ -f "$P/$f" ] || missing="$missing $f"
  done
  if [ -z "$missing" ]; then
    ok "cmake --install: headers, library, CMake package with dhmath_add_robot, dhmath.pc, bin/dhmath, LICENSE"
  else
    bad "not installed:$missing"
  fi
  [ -x "$P/bin/dhmath" ] && "$P/bin/dhmath" --version >/dev/null 2>&1 || bad "installed bin/dhmath does not run"
  cmp -s "$SRC/LICENSE" "$P/share/doc/dhmath/LICENSE" || bad "installed share/doc/dhmath/LICENSE is not LICENSE"
  if grep -qx "CMAKE_BUILD_TYPE:STRING=Release" "$B/lib/CMakeCache.txt" &&
     grep -qx "DH_WERROR:BOOL=ON" "$B/lib/CMakeCache.txt"; then
    ok "top level, no build type given: Release, DH_WERROR ON"
  else
    bad "top-level defaults: $(grep -E '^(CMAKE_BUILD_TYPE|DH_WERROR):' "$B/lib/CMakeCache.txt" | tr '\n' ' ')"
  fi
else
  bad "library build/install"
fi

# ---- 2. find_package
if quiet "$B/find_package.log" bash -c "cmake -S '$T/installed' -B '$B/installed' -DCMAKE_PREFIX_PATH='$P' && \
      cmake --build '$B/installed' && '$B/installed/consumer'"; then
  ok "find_package(dhmath 0.3 CONFIG REQUIRED): $(tail -1 "$B/find_package.log")"
else
  bad "installed find_package consumer"
fi

# ---- 3. pkg-config + plain Makefile
export PKG_CONFIG_PATH=$P/lib/pkgconfig
ver=$(pkg-config --modversion dhmath 2>/dev/null)
hver=$(sed -n 's/^#define DH_VERSION_STRING "\([^"]*\)".*/\1/p' "$SRC/include/dhmath/config.h")
if [ -n "$ver" ] && [ "$ver" = "$hver" ] &&
   quiet "$B/pkgconfig.log" bash -c "make -f '$T/Makefile' O='$B' && '$B/consumer_pc'"; then
  ok "pkg-config dhmath $ver + Makefile: $(tail -1 "$B/pkgconfig.log")"
else
  bad "pkg-config consumer (modversion '$ver', header '$hver')"
fi
if grep -qx "License: Apache-2.0" "$P/lib/pkgconfig/dhmath.pc" && pkg-config --validate dhmath &&
   pkg-config --cflags --libs dhmath >/dev/null; then
  ok "dhmath.pc: License: Apache-2.0, pkg-config --validate and --cflags --libs accept it"
else
  bad "dhmath.pc licence line or validation"
fi

# ---- 4. configuration mismatch against the installed library
CF=$(pkg-config --cflags dhmath 2>/dev/null)
LB=$(pkg-config --libs dhmath 2>/dev/null)
# shellcheck disable=SC2086
if must_fail "$B/mismatch_joints.log" dhmath_config_mismatch_DH_MAX_JOINTS_is_6 \
     cc -std=c99 $CF -UDH_MAX_JOINTS -DDH_MAX_JOINTS=6 -DEXPECT_MAX_JOINTS=6 -o "$B/mm" "$T/app.c" $LB; then
  ok "DH_MAX_JOINTS 6 against a library built with 8: link fails ($(grep -o 'undefined reference to .dhmath_config_mismatch_DH_MAX_JOINTS_is_6.' "$B/mismatch_joints.log" | head -1))"
else
  bad "DH_MAX_JOINTS mismatch not caught at link time"
fi
# shellcheck disable=SC2086
if must_fail "$B/mismatch_frac.log" dhmath_config_mismatch_DH_QPOS_FRAC_is_12 \
     cc -std=c99 $CF -UDH_QPOS_FRAC -DDH_QPOS_FRAC=12 -o "$B/mm" "$T/app.c" $LB; then
  ok "DH_QPOS_FRAC 12 against a library built with 16: link fails"
else
  bad "DH_QPOS_FRAC mismatch not caught at link time"
fi

# shellcheck disable=SC2086
if must_fail "$B/mismatch_gc.log" dhmath_config_mismatch_DH_MAX_JOINTS_is_6 \
     cc -std=c99 -O2 -ffunction-sections -fdata-sections $CF -UDH_MAX_JOINTS -DDH_MAX_JOINTS=6 -DEXPECT_MAX_JOINTS=6 \
     -o "$B/mm" "$T/app.c" $LB -Wl,--gc-sections; then
  ok "DH_MAX_JOINTS 6 with -ffunction-sections -fdata-sections --gc-sections: link fails"
else
  bad "DH_MAX_JOINTS mismatch not caught at link time with --gc-sections"
fi

# ---- 5. parent project: set(), its own DH_* option, misspelled options
if quiet "$B/subdir.log" bash -c "cmake -S '$T/subdir' -B '$B/subdir' -DDHMATH_SRC='$SRC' && \
      cmake --build '$B/subdir' -j$JOBS && '$B/subdir/consumer'"; then
  ok "add_subdirectory with set(DH_MAX_JOINTS 6) and option(DH_APP_FEATURE): $(tail -1 "$B/subdir.log")"
else
  bad "add_subdirectory consumer (parent set()/option())"
fi
if grep -qx "DH_WERROR:BOOL=OFF" "$B/subdir/CMakeCache.txt" && grep -qx "CMAKE_BUILD_TYPE:STRING=" "$B/subdir/CMakeCache.txt"; then
  ok "under a parent: DH_WERROR OFF, the build type left to the parent (none)"
else
  bad "under a parent: $(grep -E '^(CMAKE_BUILD_TYPE|DH_WERROR):' "$B/subdir/CMakeCache.txt" | tr '\n' ' ')"
fi
if quiet "$B/subdir_settypo.log" cmake -S "$T/subdir" -B "$B/subdir-settypo" -DDHMATH_SRC="$SRC" -DSUBDIR_TYPO=ON &&
   grep -A1 "CMake Warning" "$B/subdir_settypo.log" | grep -q . &&
   grep -q "Unknown dhmath option DH_MAX_JOINT set by the parent" "$B/subdir_settypo.log"; then
  ok "parent's set(DH_MAX_JOINT 6): warning naming it"
else
  bad "parent's misspelled set(DH_MAX_JOINT) not reported"
fi
if quiet "$B/subdir_typo.log" cmake -S "$T/subdir" -B "$B/subdir-typo" -DDHMATH_SRC="$SRC" -DDH_MAX_JOINT=6 &&
   grep -q "Unknown dhmath option DH_MAX_JOINT " "$B/subdir_typo.log"; then
  ok "misspelled -DDH_MAX_JOINT under a parent: reported"
else
  bad "misspelled option under a parent not reported"
fi
if must_fail "$B/top_typo.log" "Unknown dhmath option DH_MAX_JOINT " \
     cmake -S "$SRC" -B "$B/top-typo" -DDH_BUILD_TESTS=OFF -DDH_BUILD_TOOLS=OFF -DDH_MAX_JOINT=6; then
  ok "misspelled -DDH_MAX_JOINT at the top level: configuration stops"
else
  bad "misspelled option at the top level not rejected"
fi

# ---- 5b. strict warnings as errors on the whole build, GCC and Clang
for cc in gcc clang; do
  if ! command -v $cc >/dev/null 2>&1; then bad "strict parent: no $cc"; continue; fi
  if quiet "$B/strict_$cc.log" bash -c "cmake -S '$T/strict' -B '$B/strict-$cc' -DCMAKE_C_COMPILER=$cc \
        -DCMAKE_BUILD_TYPE=Release -DDHMATH_SRC='$SRC' && cmake --build '$B/strict-$cc' -j$JOBS && '$B/strict-$cc/consumer'"; then
    ok "$cc, -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wundef -Wfloat-equal -Wcast-qual -Wstrict-prototypes -Wmissing-prototypes -Wdouble-promotion -Werror on library and program: builds and runs"
  else
    bad "$cc: strict warnings on the library or program"
  fi
done

# ---- 6. cross builds with minimal toolchain files
for cpu in m0plus m4f; do
  extra=""
  [ $cpu = m0plus ] && extra=-DDH_SMALL=ON
  d=$B/cross-$cpu
  if quiet "$B/cross_$cpu.log" bash -c "cmake -S '$T/cross' -B '$d' -DCMAKE_TOOLCHAIN_FILE='$T/cross/$cpu.cmake' \
        -DCMAKE_BUILD_TYPE=MinSizeRel -DDHMATH_SRC='$SRC' $extra && cmake --build '$d' -j$JOBS --target fw"; then
    ok "cortex-$cpu firmware through add_subdirectory links without libm${extra:+ ($extra)}"
  else
    bad "cortex-$cpu firmware does not link"
  fi
  if must_fail "$B/cross_${cpu}_mismatch.log" dhmath_config_mismatch_DH_MAX_JOINTS_is_6 \
       cmake --build "$d" --target fw_mismatch; then
    ok "cortex-$cpu firmware with DH_MAX_JOINTS 6: link fails naming the setting"
  else
    bad "cortex-$cpu mismatched firmware linked"
  fi
done

# ---- 6b. installed cross package, dhmath_add_robot, orphan sections
XP=$B/prefix-m4f
if quiet "$B/install_m4f.log" bash -c "cmake -S '$SRC' -B '$B/lib-m4f' -DCMAKE_TOOLCHAIN_FILE='$SRC/port/cortex-m4f.cmake' \
      -DDH_BUILD_TESTS=OFF -DCMAKE_INSTALL_PREFIX='$XP' && cmake --build '$B/lib-m4f' -j$JOBS && cmake --install '$B/lib-m4f'"; then
  ok "cortex-m4f build installed to a prefix"
else
  bad "cortex-m4f build/install"
fi
if quiet "$B/robot_m4f.log" bash -c "cmake -S '$T/robot' -B '$B/robot-m4f' -DCMAKE_TOOLCHAIN_FILE='$SRC/port/cortex-m4f.cmake' \
      '-DCMAKE_PREFIX_PATH=$XP;$P' -DCONSUMER_PORT='$SRC/port' -DCONSUMER_LINK_OPTIONS=-Wl,--orphan-handling=error && \
      cmake --build '$B/robot-m4f' && grep -qx 'dhmath_DIR:PATH=$XP/lib/cmake/dhmath' '$B/robot-m4f/CMakeCache.txt' && \
      grep -qx 'DHMATH_EXECUTABLE:FILEPATH=$P/bin/dhmath' '$B/robot-m4f/CMakeCache.txt' && \
      grep -q 'licence Apache-2.0 ($XP/share/doc/dhmath/LICENSE)' '$B/robot_m4f.log' && \
      timeout 120 qemu-system-arm -machine mps2-an386 -cpu cortex-m4 -nographic -monitor none -serial none \
        -semihosting-config enable=on,target=native -kernel '$B/robot-m4f/robot_app'"; then
  ok "cortex-m4f consumer: find_package through CMAKE_PREFIX_PATH, dhmath_add_robot with the host bin/dhmath, --orphan-handling=error, QEMU: $(tail -1 "$B/robot_m4f.log")"
else
  bad "installed cortex-m4f consumer with dhmath_add_robot"
fi
if quiet "$B/robot_host.log" bash -c "cmake -S '$T/robot' -B '$B/robot-host' -DCMAKE_PREFIX_PATH='$P' \
      -DCONSUMER_LINK_OPTIONS=-Wl,--orphan-handling=warn && cmake --build '$B/robot-host' && '$B/robot-host/robot_app'"; then
  orph=$(grep "orphan section" "$B/robot_host.log" | grep -Ev "from \`[^']*/(Scrt1|crt1|crti|crtn|crtbeginS|crtendS|crtbegin|crtend)\.o'" || true)
  if [ -z "$orph" ]; then
    ok "host consumer with dhmath_add_robot: runs, no orphan section of its own or dhmath's (--orphan-handling=warn): $(tail -1 "$B/robot_host.log")"
  else
    bad "host consumer has orphan sections: $orph"
  fi
else
  bad "installed host consumer with dhmath_add_robot"
fi

if quiet "$B/robot_vendored.log" bash -c "cmake -S '$T/robot' -B '$B/robot-vendored' -DDHMATH_SRC='$SRC' && \
      cmake --build '$B/robot-vendored' -j$JOBS && '$B/robot-vendored/robot_app'" &&
   grep -q "dhmath gen planar.dh consumer_arm" "$B/robot_vendored.log" && [ -x "$B/robot-vendored/dhmath/cli/dhmath" ]; then
  ok "host consumer vendoring dhmath: dhmath_add_robot with the CLI target built on demand: $(tail -1 "$B/robot_vendored.log")"
else
  bad "vendored host consumer with dhmath_add_robot"
fi

if must_fail "$B/robot_nohost.log" "no host .dhmath. program" \
     cmake -S "$T/robot" -B "$B/robot-nohost" -DCMAKE_TOOLCHAIN_FILE="$SRC/port/cortex-m4f.cmake" -DDHMATH_SRC="$SRC"; then
  ok "cross consumer vendoring dhmath, no host dhmath anywhere: configuration stops saying how to get one"
else
  bad "cross consumer without a host dhmath: no clear error"
fi

# ---- 7. no libm symbol among the undefined symbols of the library
nolibm() { # name lib nm libm-symbol-list-command...
  local name=$1 lib=$2 nm=$3; shift 3
  local und libm hit
  [ -f "$lib" ] || { bad "$name: $lib not built"; return; }
  und=$("$nm" -u "$lib" | awk 'NF == 2 && $1 == "U" { print $2 }' | sort -u)
  libm=$("$@" | sort -u)
  [ -n "$libm" ] || { bad "$name: could not list libm's symbols"; return; }
  hit=$(comm -12 <(echo "$und") <(echo "$libm") | tr '\n' ' ')
  if [ -z "$hit" ]; then
    ok "$name: no libm symbol undefined in libdhmath.a (outside the library: $(comm -23 <(echo "$und") \
      <("$nm" --defined-only "$lib" | awk 'NF == 3 { print $3 }' | sort -u) | tr '\n' ' '))"
  else
    bad "$name: libdhmath.a needs libm: $hit"
  fi
}
host_libm=$(cc -print-file-name=libm.so.6)
nolibm host "$B/lib/libdhmath.a" nm bash -c "nm -D --defined-only '$host_libm' | awk '{ print \$3 }' | sed 's/@.*//'"
for cpu in m0plus m4f; do
  case $cpu in
    m0plus) fl="-mcpu=cortex-m0plus -mthumb" ;;
    m4f) fl="-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard" ;;
  esac
  # shellcheck disable=SC2086
  arm_libm=$(arm-none-eabi-gcc $fl -print-file-name=libm.a)
  nolibm "cortex-$cpu" "$B/cross-$cpu/dhmath/libdhmath.a" arm-none-eabi-nm \
    bash -c "arm-none-eabi-nm --defined-only '$arm_libm' 2>/dev/null | awk 'NF == 3 && \$2 ~ /[TW]/ { print \$3 }'"
done

# ---- 8. ecosystem metadata
if python3 "$T/check_metadata.py" "$SRC"; then ok "zephyr module, Kconfig and library.json"; else bad "ecosystem metadata"; fi

if [ $fail -ne 0 ]; then
  echo "consumer/run.sh: FAILED (logs in $B)"
  exit 1
fi
echo "consumer/run.sh: dhmath installs, packages and links as a dependency"

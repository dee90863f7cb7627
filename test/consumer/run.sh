#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# test/consumer/run.sh - the "package" stage of tools/check.sh: dhmath as a
# dependency of an external project (test/consumer/app.c).
#   1. install: cmake --install puts headers, libdhmath.a, the CMake package
#      (dhmathConfig.cmake + version file) and dhmath.pc under a prefix;
#   2. find_package(dhmath 0.2 CONFIG REQUIRED) -> dhmath::dhmath, built and run;
#   3. a plain Makefile with pkg-config, built and run (no -lm);
#   4. configuration guard: the same program compiled with DH_MAX_JOINTS 6
#      or DH_QPOS_FRAC 12 against the installed library must FAIL to link,
#      naming the setting;
#   5. parent project (subdir/): set(DH_MAX_JOINTS 6) before add_subdirectory
#      reaches library and program, the parent's own option(DH_APP_FEATURE)
#      is accepted, a misspelled dhmath option on the command line is
#      reported (warning under a parent, error at the top level);
#   6. cross builds through add_subdirectory with minimal toolchain files
#      (cross/m0plus.cmake with DH_SMALL, cross/m4f.cmake with
#      -ffreestanding and --gc-sections): the firmware links without libm;
#      the mismatched firmware fails to link, also with --gc-sections;
#   7. no libm: no undefined symbol of the host, M0+ or M4F library is one
#      that libm defines (nm against the toolchain's own libm);
#   8. ecosystem metadata: zephyr/module.yml, zephyr/Kconfig (every DH_*
#      setting), zephyr/CMakeLists.txt and library.json parse, and every
#      version equals DH_VERSION_STRING.
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
if quiet "$B/install.log" bash -c "cmake -S '$SRC' -B '$B/lib' -DCMAKE_BUILD_TYPE=Release -DDH_BUILD_TESTS=OFF \
      -DDH_BUILD_TOOLS=OFF -DCMAKE_INSTALL_PREFIX='$P' && cmake --build '$B/lib' -j$JOBS && cmake --install '$B/lib'"; then
  missing=""
  for f in include/dhmath/dhmath.h include/dhmath/dh_config.h lib/libdhmath.a lib/cmake/dhmath/dhmathConfig.cmake \
           lib/cmake/dhmath/dhmathConfigVersion.cmake lib/cmake/dhmath/dhmathTargets.cmake lib/pkgconfig/dhmath.pc; do
    [ -f "$P/$f" ] || missing="$missing $f"
  done
  if [ -z "$missing" ]; then ok "cmake --install: headers, library, CMake package, dhmath.pc"; else bad "not installed:$missing"; fi
else
  bad "library build/install"
fi

# ---- 2. find_package
if quiet "$B/find_package.log" bash -c "cmake -S '$T/installed' -B '$B/installed' -DCMAKE_PREFIX_PATH='$P' && \
      cmake --build '$B/installed' && '$B/installed/consumer'"; then
  ok "find_package(dhmath 0.2 CONFIG REQUIRED): $(tail -1 "$B/find_package.log")"
else
  bad "installed find_package consumer"
fi

# ---- 3. pkg-config + plain Makefile
export PKG_CONFIG_PATH=$P/lib/pkgconfig
ver=$(pkg-config --modversion dhmath 2>/dev/null)
hver=$(sed -n 's/^#define DH_VERSION_STRING "\([^"]*\)".*/\1/p' "$SRC/include/dhmath/dh_config.h")
if [ -n "$ver" ] && [ "$ver" = "$hver" ] &&
   quiet "$B/pkgconfig.log" bash -c "make -f '$T/Makefile' O='$B' && '$B/consumer_pc'"; then
  ok "pkg-config dhmath $ver + Makefile: $(tail -1 "$B/pkgconfig.log")"
else
  bad "pkg-config consumer (modversion '$ver', header '$hver')"
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

# ---- 5. parent project: set(), its own DH_* option, misspelled options
if quiet "$B/subdir.log" bash -c "cmake -S '$T/subdir' -B '$B/subdir' -DDHMATH_SRC='$SRC' && \
      cmake --build '$B/subdir' -j$JOBS && '$B/subdir/consumer'"; then
  ok "add_subdirectory with set(DH_MAX_JOINTS 6) and option(DH_APP_FEATURE): $(tail -1 "$B/subdir.log")"
else
  bad "add_subdirectory consumer (parent set()/option())"
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

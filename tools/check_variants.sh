#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Configuration variants: every option that changes code builds and runs the
# host suite. A misspelled option must be rejected at configure time.
# DHT_DIFF_DIV (default 10) divides test_builds_agree's input counts.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
JOBS=${JOBS:-$(nproc)}
rc=0
# test_builds_agree (this variant against its DH_SMALL twin) at a tenth of its
# 10^6 inputs per function: the host stage runs them all in the default
# configuration, here each configuration is checked and the stage stays short
export DHT_DIFF_DIV=${DHT_DIFF_DIV:-10}

variant() { # name, cmake args...
  local name=$1; shift
  local dir=build/var-$name
  echo "--- variant $name: $*"
  if cmake -S "$ROOT" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DDH_BUILD_TOOLS=OFF "$@" >/dev/null &&
     cmake --build "$dir" -j"$JOBS" >/dev/null &&
     ctest --test-dir "$dir" -j"$JOBS" --output-on-failure -LE regression; then
    echo "--- variant $name: passed"
  else
    echo "--- variant $name: FAILED"; rc=1
  fi
}

variant qpos12 -DDH_QPOS_FRAC=12
variant qpos20-j16 -DDH_QPOS_FRAC=20 -DDH_MAX_JOINTS=16
variant nochecks-plainc -DDH_CHECK_ARGS=OFF -DDH_USE_INTRINSICS=OFF
variant small -DDH_SMALL=ON
variant small-plainc -DDH_SMALL=ON -DDH_USE_INTRINSICS=OFF -DDH_QPOS_FRAC=12
variant confighdr -DDH_CONFIG_HEADER="$ROOT/test/config/dh_test_config.h"

# misspelled option: configure must fail and name the option
echo "--- variant misspelled option"
out=$(cmake -S "$ROOT" -B build/var-misspelled -DDH_QPOS_FRAK=12 2>&1 || true)
if echo "$out" | grep -q "Unknown dhmath option DH_QPOS_FRAK"; then
  echo "--- variant misspelled option: rejected as expected"
else
  echo "$out" | tail -5; echo "--- variant misspelled option: NOT rejected"; rc=1
fi
rm -rf build/var-misspelled
exit $rc

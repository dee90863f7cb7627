#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# demo.sh - the dhmath CLI's main job on real robots: forward kinematics,
# the Jacobian and an inverse-kinematics round trip on the Puma 560 and the
# Franka Panda, and every closed-form IK solution of a Puma 560 and a UR5
# target, of examples/robots/. Builds nothing.
#
#   tools/demo.sh [BUILD_DIR]    default BUILD_DIR: build
#
# The binary is BUILD_DIR/cli/dhmath (or BUILD_DIR/dhmath). Exit status 0
# when every step worked, both round trips converged and reproduce the
# joint values' end frame, and every closed-form solution reproduces its
# target.
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
B=${1:-build}
case $B in /*) ;; *) B=$ROOT/$B ;; esac
if [ -x "$B/cli/dhmath" ]; then D=$B/cli/dhmath
elif [ -x "$B/dhmath" ]; then D=$B/dhmath
else
  echo "demo.sh: no dhmath binary in $B (build first: cmake -S . -B build && cmake --build build)" >&2
  exit 2
fi
R=$ROOT/examples/robots

show() { echo "\$ dhmath $*"; "$D" "$@"; echo; }

for robot in puma560 panda; do
  f=$R/$robot.dh
  case $robot in
    puma560) q=10,-30,45,20,35,-60;        q0=15,-25,40,25,30,-55 ;;
    *)       q=10,-30,20,-120,15,90,30;    q0=15,-25,25,-115,20,85,35 ;;
  esac
  echo "=== $robot: forward kinematics at q = $q (degrees) ==="
  show fk "$f" "$q"
  echo "=== $robot: geometric Jacobian (base frame, per radian) ==="
  show jacobian "$f" "$q"
  echo "=== $robot: inverse kinematics round trip ==="
  target=$("$D" fk --expr "$f" "$q")
  echo "target (dhmath fk --expr): $target"
  echo "\$ dhmath ik $f \"$target\" --q0 $q0"
  qs=$("$D" ik "$f" "$target" --q0 "$q0")
  echo "$qs"
  qs=$(echo "$qs" | tr ' ' ',')
  echo "fk of the solution:"
  "$D" fk "$f" "$qs"
  # the solution's end frame must match the target within 1e-5 (metres)
  "$D" fk "$f" "$qs" > "${TMPDIR:-/tmp}/dhmath_demo_a.$$"
  "$D" fk "$f" "$q" > "${TMPDIR:-/tmp}/dhmath_demo_b.$$"
  paste -d' ' "${TMPDIR:-/tmp}/dhmath_demo_a.$$" "${TMPDIR:-/tmp}/dhmath_demo_b.$$" | awk '
    { for (i = 1; i <= 4; i++) { d = $i - $(i + 4); if (d < 0) d = -d; if (d > m) m = d } }
    END { printf "largest difference to the target frame: %.3g\n", m; exit (m <= 1e-5) ? 0 : 1 }'
  rm -f "${TMPDIR:-/tmp}/dhmath_demo_a.$$" "${TMPDIR:-/tmp}/dhmath_demo_b.$$"
  echo
done
# closed-form IK: every solution of one target; each one's end frame must
# match the target within 1e-5 (metres)
for robot in puma560 ur5; do
  f=$R/$robot.dh
  q=10,-30,45,20,35,-60
  echo "=== $robot: every closed-form IK solution of the end frame at q = $q ==="
  target=$("$D" fk --expr "$f" "$q")
  echo "\$ dhmath ik --all $f \"$target\""
  sols=$("$D" ik --all "$f" "$target")
  echo "$sols"
  "$D" fk "$f" "$q" > "${TMPDIR:-/tmp}/dhmath_demo_b.$$"
  echo "$sols" | while read -r line; do
    "$D" fk "$f" "$(echo "$line" | tr ' ' ',')" > "${TMPDIR:-/tmp}/dhmath_demo_a.$$"
    paste -d' ' "${TMPDIR:-/tmp}/dhmath_demo_a.$$" "${TMPDIR:-/tmp}/dhmath_demo_b.$$" | awk '
      { for (i = 1; i <= 4; i++) { d = $i - $(i + 4); if (d < 0) d = -d; if (d > m) m = d } }
      END { exit (m <= 1e-5) ? 0 : 1 }' || { echo "demo: solution $line misses the target" >&2; exit 1; }
  done
  echo "every solution reproduces the target within 1e-5"
  rm -f "${TMPDIR:-/tmp}/dhmath_demo_a.$$" "${TMPDIR:-/tmp}/dhmath_demo_b.$$"
  echo
done
echo "demo: all steps passed"

# SPDX-License-Identifier: Apache-2.0
# opw_dir.sh - sourced by tools/bench.sh and tools/target_bench.sh: checks
# OPW_DIR (the user's clone of opw_kinematics, never copied into this
# repository) and makes it absolute, or says that the opw rows are skipped
# and how to get it. $1: the calling script's name.
opw_dir_check() {
  OPW_DIR=${OPW_DIR:-}
  if [ -n "$OPW_DIR" ]; then
    OPW_DIR=$(cd "$OPW_DIR" && pwd)
    if [ ! -f "$OPW_DIR/include/opw_kinematics/opw_kinematics.h" ]; then
      echo "$1: OPW_DIR=$OPW_DIR holds no include/opw_kinematics/opw_kinematics.h" >&2
      exit 2
    fi
  else
    echo "$1: OPW_DIR not set, the opw_kinematics rows are skipped (git clone --branch 0.5.5 https://github.com/Jmeyer1292/opw_kinematics, then OPW_DIR=<clone> tools/$1)"
  fi
}

#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# gen_docs.sh - regenerates the pages of docs/generated/ at one commit.
#
#   tools/gen_docs.sh            every page
#   tools/gen_docs.sh host plots only the named ones
#
# Pages (each stamped by tools/stamp.sh with commit, date and machine):
#   host      performance_host.md      tools/bench.sh
#   target    performance_target.md    TBENCH_LIB=HEAD tools/target_bench.sh
#   footprint footprint.md             tools/footprint.sh --rev HEAD
#   plots     accuracy_plots.md, img/  tools/plot_accuracy.py
#   motion    motion_plots.md, img/move_*.png  tools/plot_move.py --docs
#   coverage  coverage.md              tools/coverage.sh build/coverage
# Refuses to start when the tree has uncommitted changes outside
# docs/generated/, and fails when HEAD moved or the tree changed during the
# run, so every page it writes names the same commit (that of HEAD); commit
# the pages afterwards. Runs the generators one after the other under nice,
# JOBS (default 2) compile jobs each. Needs what each generator needs
# (tools/README.md). OPW_DIR (a clone of opw_kinematics, never copied into
# this repository) is passed on to bench.sh and target_bench.sh, which then
# measure opw beside dh_ikc_* (docs/performance.md).
set -euo pipefail
cd "$(dirname "$0")/.."
PAGES=${*:-"host target footprint plots motion coverage"}
JOBS=${JOBS:-2}

dirty() { git status --porcelain -- . ':(exclude)docs/generated'; }

if [ -n "$(dirty)" ]; then
  echo "gen_docs.sh: uncommitted changes outside docs/generated/; commit or stash them first:" >&2
  dirty >&2
  exit 1
fi
commit=$(git rev-parse --short HEAD)
echo "== gen_docs.sh: $PAGES at $commit"

for p in $PAGES; do
  case $p in
    host|target|footprint|coverage|plots|motion) ;;
    *) echo "gen_docs.sh: unknown page $p (host target footprint plots motion coverage)" >&2; exit 2 ;;
  esac
done

written=""
for p in $PAGES; do
  echo "== gen_docs.sh: $p"
  case $p in
    host) nice tools/bench.sh; written="$written performance_host.md" ;;
    target) JOBS=$JOBS TBENCH_LIB=HEAD nice tools/target_bench.sh; written="$written performance_target.md" ;;
    footprint) JOBS=$JOBS nice tools/footprint.sh --rev HEAD; written="$written footprint.md" ;;
    coverage) DH_COV_JOBS=$JOBS nice tools/coverage.sh build/coverage; written="$written coverage.md" ;;
    plots) nice /usr/bin/python3 tools/plot_accuracy.py; written="$written accuracy_plots.md" ;;
    motion) nice /usr/bin/python3 tools/plot_move.py --docs; written="$written motion_plots.md" ;;
  esac
done

if [ "$(git rev-parse --short HEAD)" != "$commit" ] || [ -n "$(dirty)" ]; then
  echo "gen_docs.sh: HEAD or the tree changed during the run: the pages do not belong to $commit" >&2
  exit 1
fi
for f in $written; do
  head -1 "docs/generated/$f" | grep -q "^Stamp: commit $commit, " ||
    { echo "gen_docs.sh: docs/generated/$f is not stamped with $commit" >&2; exit 1; }
done
echo "== gen_docs.sh: docs/generated/ ($written ) regenerated at $commit"

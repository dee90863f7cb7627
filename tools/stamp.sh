#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# stamp.sh - the stamp line every page of docs/generated/ starts with: the
# commit it was measured at, the date and the machine.
#
#   tools/stamp.sh WRITER          prints the line
#   tools/stamp.sh WRITER PAGE     puts the line (and a blank line) on top of PAGE
#
# WRITER names the script that writes the page (e.g. tools/bench.sh). The
# commit is `git rev-parse --short HEAD`, with "+dirty" when the tree has
# uncommitted changes outside docs/generated/ (the pages being written);
# outside a git checkout it is DH_STAMP_REV, or "unknown". The machine is
# the CPU model of /proc/cpuinfo, the cores (nproc) and the kernel (uname).
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
writer=${1:?usage: tools/stamp.sh WRITER [PAGE]}

if rev=$(git -C "$here" rev-parse --short HEAD 2>/dev/null); then
    if [ -n "$(git -C "$here" status --porcelain -- . ':(exclude)docs/generated' 2>/dev/null)" ]; then
        rev="$rev+dirty"
    fi
else
    rev=${DH_STAMP_REV:-unknown}
fi
cpu=$(sed -n 's/^model name[[:space:]]*:[[:space:]]*//p' /proc/cpuinfo 2>/dev/null | head -1)
line="Stamp: commit $rev, $(date -u '+%Y-%m-%d %H:%M UTC'), ${cpu:-unknown CPU} ($(nproc) cores, $(uname -sr)); written by $writer."

if [ $# -lt 2 ]; then
    printf '%s\n' "$line"
    exit 0
fi
page=$2
{ printf '%s\n\n' "$line"; cat "$page"; } > "$page.stamp.tmp"
mv "$page.stamp.tmp" "$page"

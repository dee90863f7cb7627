#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# tools/static.sh - static-analysis gate of the library (src/, the public
# headers and src/internal/dh_port.h):
#   1. cppcheck with the MISRA C:2012 addon plus cppcheck's warning, style,
#      performance and portability checks;
#   2. clang-tidy with .clang-tidy (bugprone, CERT, clang static analyzer,
#      misc, readability subset, compiler warnings + -Wcomma).
# Both run on the flags of a host configure (compile_commands.json in
# build/static). Deviations are read from the table in docs/misra.md
# (rule id | scope | reason); any other finding fails the gate, and so
# does a deviation that no longer matches anything.
# Exit status 0 = clean; prints one summary line.
# Environment: CPPCHECK, CLANG_TIDY (tool names), STATIC_BUILD (build dir),
# JOBS (parallel clang-tidy processes, default nproc), STATIC_CMAKE_ARGS
# (extra configure options, e.g. -DDH_SMALL=ON to analyse the size-first
# code; in such a run a deviation that matches nothing is not an error,
# since it may belong to code that configuration compiles out).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
B=${STATIC_BUILD:-$ROOT/build/static}
CPPCHECK=${CPPCHECK:-cppcheck}
CLANG_TIDY=${CLANG_TIDY:-clang-tidy}
JOBS=${JOBS:-$(nproc)}
t0=$(date +%s)
mkdir -p "$B"

for tool in "$CPPCHECK" "$CLANG_TIDY"; do
  command -v "$tool" >/dev/null 2>&1 ||
    { echo "static.sh: FAILED: $tool not found (apt-get install cppcheck clang-tidy)"; exit 1; }
done

# ---- compile database of the library (default options, host compiler)
EXTRA_ARGS=${STATIC_CMAKE_ARGS:-}
# shellcheck disable=SC2086
cmake -S "$ROOT" -B "$B" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DCMAKE_BUILD_TYPE=Release \
  -DDH_BUILD_TESTS=OFF -DDH_BUILD_TOOLS=OFF $EXTRA_ARGS >"$B/configure.log" 2>&1 ||
  { cat "$B/configure.log"; echo "static.sh: FAILED: cmake configure"; exit 1; }

# ---- deviations from docs/misra.md -> cppcheck suppressions
supp="$B/suppressions.txt"
: >"$supp"
ndev=0
while IFS='|' read -r _ id scope _; do
  id=$(echo "$id" | tr -d ' ')
  case $id in misra-c2012-*|[a-zA-Z]*) ;; *) continue ;; esac
  [ "$id" = "Rule" ] && continue
  ndev=$((ndev + 1))
  set -f   # the scope "*" must not be expanded by the shell
  for s in $scope; do
    if [ "$s" = "*" ]; then echo "$id" >>"$supp"; else echo "$id:*$s" >>"$supp"; fi
  done
  set +f
done < <(grep -E '^\| *(misra-c2012-[0-9.]+|[a-zA-Z]+) *\|' docs/misra.md)
[ "$ndev" -gt 0 ] || { echo "static.sh: FAILED: no deviation table found in docs/misra.md"; exit 1; }

# cppcheck does not know that DH_ASSERT's trap does not return unless it
# sees the GCC form of the macro (__builtin_trap, known through gnu.cfg);
# the default for other compilers is an endless loop, which cppcheck
# treats as returning and then reports every asserted pointer as
# "possibly NULL".
cpp_log="$B/cppcheck.txt"
mkdir -p "$B/cppcheck"   # work files (ctu-info) stay out of src/
"$CPPCHECK" --project="$B/compile_commands.json" -D__GNUC__=12 --library=gnu \
  --addon=misra --enable=warning,style,performance,portability,information \
  --suppressions-list="$supp" --inline-suppr -q -j "$JOBS" --cppcheck-build-dir="$B/cppcheck" \
  --template='{file}:{line}:{column}: {severity}: {id}: {message}' 2>"$cpp_log" >/dev/null || true
# unmatched deviations are reported as "unmatchedSuppression" (an error
# in the default configuration only, see STATIC_CMAKE_ARGS)
if [ -n "$EXTRA_ARGS" ]; then
  grep -v ': unmatchedSuppression: ' "$cpp_log" >"$cpp_log.tmp" || true
  mv "$cpp_log.tmp" "$cpp_log"
fi
ncpp=$(grep -c -E '^[^ ].*:-?[0-9]+:[0-9]+: ' "$cpp_log" || true)
if [ "$ncpp" -gt 0 ]; then
  echo "--- cppcheck: $ncpp finding(s) not covered by docs/misra.md ---"
  grep -E '^[^ ].*:-?[0-9]+:[0-9]+: ' "$cpp_log" | sed 's/ (use --rule-texts=<file> to get proper output)//' | head -50
fi
t1=$(date +%s)

# ---- clang-tidy (configuration: .clang-tidy)
tidy_log="$B/clang-tidy.txt"
: >"$tidy_log"
ls src/*/*.c | xargs -P "$JOBS" -n 2 "$CLANG_TIDY" -p "$B" --quiet --extra-arg=-Wcomma \
  >>"$tidy_log" 2>"$B/clang-tidy.err" || true
ntidy=$(grep -c -E '^/.*:[0-9]+:[0-9]+: (warning|error): ' "$tidy_log" || true)
if [ "$ntidy" -gt 0 ]; then
  echo "--- clang-tidy: $ntidy finding(s) ---"
  grep -E '^/.*:[0-9]+:[0-9]+: (warning|error): ' "$tidy_log" | sed "s|^$ROOT/||" | head -50
fi
if grep -q -E "error: (unable to|unknown|no such)|Error while processing" "$B/clang-tidy.err"; then
  echo "--- clang-tidy did not run cleanly ---"
  grep -E "error|Error" "$B/clang-tidy.err" | head -10
  ntidy=$((ntidy + 1))
fi
t2=$(date +%s)

if [ "$ncpp" -gt 0 ] || [ "$ntidy" -gt 0 ]; then
  echo "static.sh: FAILED: cppcheck+misra $ncpp, clang-tidy $ntidy finding(s) ($ndev deviations in docs/misra.md; cppcheck $((t1 - t0)) s, clang-tidy $((t2 - t1)) s)"
  exit 1
fi
echo "static.sh: passed (cppcheck+misra and clang-tidy clean over src/; $ndev deviations in docs/misra.md; cppcheck $((t1 - t0)) s, clang-tidy $((t2 - t1)) s)"

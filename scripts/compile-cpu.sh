#!/usr/bin/env bash
# A compiler launcher that logs the CPU seconds (user + system) and peak
# memory of each compile, one line per object file, to $COMPILE_CPU_LOG
# (default compile-cpu.log in the build directory):
#
#   cmake -S . -B build-measure -DCMAKE_CXX_COMPILER_LAUNCHER=$PWD/scripts/compile-cpu.sh ...
#   cmake --build build-measure -j1
#   sort -rn build-measure/compile-cpu.log | head      # the costliest files
#
# CPU time, not wall time, so that a shared machine skews it less.
set -uo pipefail
if [[ ! -x /usr/bin/time ]]; then
  echo "compile-cpu: /usr/bin/time is missing (apt-get install time)" >&2
  exit 2
fi
out=""
previous=""
for arg in "$@"; do
  [[ "$previous" == "-o" ]] && out="$arg"
  previous="$arg"
done
times="$(mktemp)"
/usr/bin/time -f "%U %S %M" -o "$times" "$@"
status=$?
read -r user system kilobytes < "$times"
rm -f "$times"
awk -v u="$user" -v s="$system" -v k="$kilobytes" -v o="$out" \
  'BEGIN { printf "%.2f %d %s\n", u + s, k, o }' >> "${COMPILE_CPU_LOG:-compile-cpu.log}"
exit "$status"

#!/usr/bin/env bash
# Times world, plan (one object's goal) and experiment on the tidy kitchen
# scaled to 30*M items (scripts/scaled-kitchen.sh), for each M given
# (default: 34 334 3334 33334, about 10^3 .. 10^6 objects). Prints one line
# per command: objects, command, wall seconds, user and system CPU seconds
# (robust to load on a shared machine) and peak memory. Figures and how to
# read them: docs/benchmarks.md, "Commands against world size".
#
#   scripts/bench-scale.sh [M ...]
#   APPRENTICE=build/apprentice CONDITIONS=instruction,inst+search4 scripts/bench-scale.sh 34
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${APPRENTICE:-$root/build/apprentice}"
conditions="${CONDITIONS:-instruction,inst+search4}"
[[ -x "$bin" ]] || { echo "bench-scale.sh: no $bin; build it first" >&2; exit 2; }
[[ -x /usr/bin/time ]] || { echo "bench-scale.sh: needs /usr/bin/time (GNU time)" >&2; exit 2; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
sizes=("$@")
[[ ${#sizes[@]} -gt 0 ]] || sizes=(34 334 3334 33334)
printf '%-10s %-11s %9s %9s %8s %9s\n' objects command wall_s user_s sys_s max_MB
for m in "${sizes[@]}"; do
  "$root/scripts/scaled-kitchen.sh" "$m" "$tmp/k.yaml"
  objects=$((30 * m + 11))
  run() {
    local name="$1"; shift
    /usr/bin/time -o "$tmp/time" -f "%e %U %S %M" "$@" > "$tmp/out" 2>&1 || {
      echo "bench-scale.sh: $name failed at M=$m:" >&2; tail -5 "$tmp/out" >&2; exit 1; }
    read -r wall user sys kb < "$tmp/time"
    printf '%-10s %-11s %9s %9s %8s %9d\n' "$objects" "$name" "$wall" "$user" "$sys" "$((kb / 1024))"
  }
  run world "$bin" world --scenario "$tmp/k.yaml"
  run plan "$bin" plan --scenario "$tmp/k.yaml" --goal "(and (in ketchup1 fridge1) (closed fridge1))"
  run experiment "$bin" experiment --scenario "$tmp/k.yaml" --conditions "$conditions" -q
  # The experiment's figures must not depend on the size (same instructions and words).
  grep -E '^(instruction|inst\+search4) +ours' "$tmp/out" | awk -v n="$objects" '{print "           " $1 ": " $6 " instructions, " $7 " words (" n " objects)"}'
done

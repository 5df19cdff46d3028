#!/usr/bin/env bash
# Writes the tidy kitchen (data/scenarios/tidy-kitchen.yaml) with every
# object line's count multiplied by M, so that the world holds 30*M items
# (11 places and the same intent). Used by scripts/bench-scale.sh.
#
#   scripts/scaled-kitchen.sh M OUT.yaml
set -euo pipefail
if [[ $# -ne 2 || ! "$1" =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: scripts/scaled-kitchen.sh M OUT.yaml   (M: a whole number >= 1)" >&2
  exit 2
fi
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
m="$1"
out="$2"
# The domain is named relative to the scenario file: name it absolutely.
awk -v m="$m" -v domain="$root/data/domains/kitchen.pddl" '
  /^domain:/ { print "domain: " domain; next }
  /^ *- \{category: .*, at: / {
    count = 1
    if (match($0, /count: [0-9]+/)) { count = substr($0, RSTART + 7, RLENGTH - 7); sub(/, count: [0-9]+/, "") }
    sub(/\}$/, ", count: " count * m "}")
  }
  { print }
' "$root/data/scenarios/tidy-kitchen.yaml" > "$out"

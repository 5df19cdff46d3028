#!/usr/bin/env bash
# Prints the tables of docs/experiment.md for the worlds beyond the kitchen:
# each scenario's instruction and inst+search4 rows from empty knowledge, and
# the transfer table: the same conditions starting from the knowledge that
# inst+search4 learned in the paper's kitchen (experiment --knowledge-in).
# Needs build/apprentice (or $APPRENTICE) and /usr/bin/python3.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${APPRENTICE:-build/apprentice}
scenarios=(laundry-room party-cleanup playroom tidy-garage unpack-groceries tidy-kitchen-renamed)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$bin" experiment --scenario data/scenarios/tidy-kitchen.yaml --conditions inst+search4 --quiet \
  --knowledge-out "$work/kitchen" >/dev/null
kitchen=$work/kitchen/inst+search4.sqlite

for scenario in "${scenarios[@]}"; do
  echo "### $scenario"
  echo '```'
  "$bin" experiment --scenario "data/scenarios/$scenario.yaml" --conditions instruction,inst+search4 --quiet
  echo '```'
done

echo "### From the kitchen's knowledge, against from scratch"
echo
echo "| scenario | condition | from scratch: instructions / words | from the kitchen: instructions / words | of which yes/no | analogies confirmed | objects done | categories renamed |"
echo "|---|---|---|---|---|---|---|---|"
for scenario in "${scenarios[@]}"; do
  "$bin" experiment --scenario "data/scenarios/$scenario.yaml" --conditions instruction,inst+search4 --json \
    >"$work/scratch.json"
  "$bin" experiment --scenario "data/scenarios/$scenario.yaml" --conditions instruction,inst+search4 --json \
    --knowledge-in "$kitchen" >"$work/carried.json"
  /usr/bin/python3 - "$scenario" "$work/scratch.json" "$work/carried.json" <<'PY'
import json, sys
scenario, scratch, carried = sys.argv[1], json.load(open(sys.argv[2])), json.load(open(sys.argv[3]))
for s, c in zip(scratch, carried):
    t = c["transfer"]
    print(f"| {scenario} | {c['condition']} | {s['instructions']} / {s['words']} | {c['instructions']} / {c['words']} "
          f"| {c['yes_no']} | {len(t['analogies'])} | {c['objects_done']}/{c['objects_total']} | {len(t['renamed'])} |")
PY
done

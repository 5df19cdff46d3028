#!/usr/bin/env bash
# Prints the table of docs/experiment.md on what each step of the LLM goal
# analysis and repair (src/agent/goal_repair.h) adds: every step on, then
# each turned off in turn, then none, then the paper's agent; on
# tidy-kitchen-35 with the recorded GPT-3 responses of ../shared, for the
# TBP condition (GPT-3's own order, the default) and for the ensemble of
# all conditions (pool=all). Needs build/apprentice and /usr/bin/python3.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${APPRENTICE:-build/apprentice}
corpus=../shared/data/stars-tidy-kitchen/goal_responses.jsonl
[[ -f "$corpus" ]] || { echo "no $corpus (../shared)" >&2; exit 2; }
variants=(
  "all|"
  "without drop|--goal-repair=-drop"
  "without close|--goal-repair=-close"
  "without check|--goal-repair=-check"
  "without choose|--goal-repair=-choose"
  "3 responses, not 5|--llm-goal-responses 3"
  "none|--goal-repair none"
  "the paper's agent|--goal-repair none --offer-ungrounded --llm-goal-responses 3"
)
# One table row from the two conditions' --json.
row=$(cat <<'PY'
import json, sys
name = sys.argv[1]
alone, taught = json.load(sys.stdin)
def percent(value):
    return "--" if value is None else "%.1f%%" % value
print("| %s | %s | %d/%d | %s | %d | %d | %d | %d + %d |" % (
    name, percent(alone["completion_rate"]), alone["objects_done"], alone["objects_total"],
    percent(taught["relevance"]), taught["yes_no"], taught["instructions"], taught["words"],
    alone["llm_calls"], taught["llm_calls"]))
PY
)
for pool in "" ",pool=all"; do
  echo
  if [[ -z "$pool" ]]; then echo "#### TBP, in GPT-3's own order (the default)"; else echo "#### Ensemble (pool=all)"; fi
  echo
  echo "| steps | search4+llm completion | objects | inst+search4+llm relevance | yes/no | instructions | words | LLM calls (both) |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|"
  for variant in "${variants[@]}"; do
    name=${variant%%|*}
    read -r -a flags <<< "${variant#*|}"
    "$bin" experiment --scenario data/scenarios/tidy-kitchen-35.yaml --conditions search4+llm,inst+search4+llm \
        --llm "corpus:$corpus$pool" --json "${flags[@]}" |
      /usr/bin/python3 -c "$row" "$name"
  done
done

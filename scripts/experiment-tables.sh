#!/usr/bin/env bash
# Prints the tables of docs/experiment.md: every condition on the paper's
# kitchen and on the 35-object STARS kitchen, with rules generalized as we
# do (full) and as the paper did (paper). Needs build/apprentice and, for
# the LLM conditions, the recorded GPT-3 responses in ../shared.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${APPRENTICE:-build/apprentice}
corpus=../shared/data/stars-tidy-kitchen/goal_responses.jsonl
llm=()
if [[ -f "$corpus" ]]; then llm=(--llm "corpus:$corpus"); fi
for scenario in tidy-kitchen tidy-kitchen-35; do
  for generalization in full paper; do
    echo "### $scenario, --generalization $generalization"
    echo '```'
    "$bin" experiment --scenario "data/scenarios/$scenario.yaml" "${llm[@]}" --generalization "$generalization"
    echo '```'
  done
done
if [[ -f "$corpus" ]]; then
  echo "### tidy-kitchen-35, TBP responses only, --generalization full"
  echo '```'
  "$bin" experiment --scenario data/scenarios/tidy-kitchen-35.yaml --llm "corpus:$corpus,condition=TBP"
  echo '```'
fi

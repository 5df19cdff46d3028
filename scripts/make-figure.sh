#!/usr/bin/env bash
# Draws the README's figure, docs/experiment.svg: every condition on the
# paper's kitchen beside the paper's Table 3. The LLM conditions are answered
# from the recorded GPT-3 responses in ../shared when the checkout has them
# (as `make run` does). Needs a build with the Python module (make) and
# Debian's python3-matplotlib.
#
#   bash scripts/make-figure.sh [OUT.svg]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/experiment.svg}
corpus=../shared/data/stars-tidy-kitchen/goal_responses.jsonl
llm=()
if [[ -f "$corpus" ]]; then llm=(--llm "corpus:$corpus"); fi
build/apprentice experiment --scenario data/scenarios/tidy-kitchen.yaml "${llm[@]}" --quiet --plot "$out"

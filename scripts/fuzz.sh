#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang-19 into build-fuzz and
# runs each for FUZZ_SECONDS (default 10) with seeds from the repository.
# Exits non-zero if a build fails or a target finds an input that crashes,
# trips ASan or UBSan, breaks the target's stated contract, or takes longer
# than the per-input timeout. A finding is kept in build-fuzz/findings/.
#
#   scripts/fuzz.sh                       # every target, 10 s each (make test: FUZZ_SECONDS=5)
#   scripts/fuzz.sh goal store            # only these targets
#   FUZZ_SECONDS=600 scripts/fuzz.sh      # make fuzz-long: 10 minutes each
#
# Targets: parser scenario pddl goal llm_reply store (docs/fuzzing.md).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${FUZZ_BUILD_DIR:-$root/build-fuzz}"
seconds="${FUZZ_SECONDS:-10}"
jobs="$(nproc 2>/dev/null || echo 2)"
all_targets=(parser scenario pddl goal llm_reply store)
targets=("${@:-${all_targets[@]}}")
for t in "${targets[@]}"; do
  [[ " ${all_targets[*]} " == *" $t "* ]] || { echo "fuzz: '$t' is not a target (${all_targets[*]})" >&2; exit 2; }
done

for tool in clang-19 clang++-19; do
  command -v "$tool" >/dev/null || { echo "fuzz: $tool not found (apt-get install clang-19 libclang-rt-19-dev)" >&2; exit 2; }
done

CC=clang-19 CXX=clang++-19 cmake -S "$root/fuzz" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang-19 -DCMAKE_CXX_COMPILER=clang++-19 >/dev/null
cmake --build "$build" -j "$jobs" --target "${targets[@]/#/fuzz_}"

# New inputs go to a scratch directory; the seeds in the repository stay as
# they are. Findings (crash-*, timeout-*, oom-*) go to build-fuzz/findings.
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$build/findings"

# Seeds read at run time, never copied into the repository: the shared
# STARS sentences (parser), and a store written by a built apprentice.
seed_parser_from_shared() {
  local dir="$work/seeds-parser" n=0
  mkdir -p "$dir"
  local script="$root/../shared/data/stars-tidy-kitchen/instructor_script.txt"
  local responses="$root/../shared/data/stars-tidy-kitchen/goal_responses.jsonl"
  if [[ -r "$script" ]]; then
    while IFS= read -r line; do printf '%s' "$line" > "$dir/script-$((n++))"; done < "$script"
  fi
  if [[ -r "$responses" ]]; then
    grep -o '"response": "[^"]*"' "$responses" | sed 's/^"response": "//; s/"$//' | sort -u |
      while IFS= read -r line; do printf '%s' "$line" > "$dir/response-$((n++))"; done
  fi
  echo "$dir"
}
seed_store() {
  local dir="$work/seeds-store"
  mkdir -p "$dir"
  : > "$dir/empty"
  printf 'SQLite format 3\0' > "$dir/header-only"
  local app="$root/build/apprentice"
  if [[ -x "$app" ]]; then
    "$app" experiment --scenario "$root/data/scenarios/tidy-kitchen.yaml" --conditions instruction \
      --knowledge-out "$work/store" -q >/dev/null 2>&1 && cp "$work/store/instruction.sqlite" "$dir/kitchen.sqlite"
  fi
  echo "$dir"
}

status=0
for t in "${targets[@]}"; do
  out="$work/new-$t"
  mkdir -p "$out"
  extra=()
  case "$t" in
    parser)    seeds=("$root/fuzz/corpus" "$(seed_parser_from_shared)"); extra=(-dict="$root/fuzz/parser.dict" -max_len=4096) ;;
    scenario)  seeds=("$root/data/scenarios"); extra=(-max_len=16384) ;;
    pddl)      seeds=("$root/data/domains"); extra=(-max_len=16384) ;;
    goal)      seeds=("$root/fuzz/seeds/goal"); extra=(-max_len=4096) ;;
    llm_reply) seeds=("$root/fuzz/seeds/llm_reply"); extra=(-max_len=8192) ;;
    store)     seeds=("$(seed_store)"); extra=(-max_len=131072) ;;
  esac
  echo "fuzz: $t for $seconds s"
  if (cd "$work" && "$build/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
        -artifact_prefix="$build/findings/$t-" -print_final_stats=1 "${extra[@]}" "$out" "${seeds[@]}" \
        > "$work/log-$t" 2>&1); then
    grep -E '^stat::(number_of_executed_units|new_units_added)|^#[0-9]+ *DONE' "$work/log-$t" | sed "s/^/fuzz: $t: /" || true
  else
    status=1
    tail -n 40 "$work/log-$t" >&2
    echo "fuzz: $t FOUND AN INPUT that breaks it; see $build/findings/" >&2
  fi
done
[[ $status -eq 0 ]] && echo "fuzz: no crash, sanitizer report, broken contract or hang in ${targets[*]} (${seconds} s each)"
exit $status

#!/usr/bin/env bash
# Kills knowledge-store writers and checks that no store is lost (issue 11).
# Each trial starts two `apprentice experiment --conditions instruction
# --knowledge-out DIR` runs into the same DIR, the second a moment after the
# first, and SIGKILLs the first after a random delay spread over a run's
# length. Then:
#   - the second run exits 0 (it ran after, or alongside through SQLite's
#     locks) or 3 saying the store is "in use" (the first still held it);
#   - the store, if the first run got as far as creating it, opens and loads
#     (`apprentice knowledge --json` exits 0);
#   - if the second run exited 0, the store holds all 26 of its goals.
# A store that does not load, or a completed run whose goals are missing, is
# a lost store. A store is created whole under a temporary name
# (.instruction.sqlite.creating-PID-RANDOM) and then moved into place, so a
# kill during creation leaves no store or a complete one; the temporary
# files such kills leave are counted (the next writer of the store removes
# them). Prints one line per trial and a summary; exits 1 if any store was
# lost.
#
#   scripts/kill-test.sh [TRIALS]        # default 100; build/apprentice
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
app="${APPRENTICE:-$root/build/apprentice}"
trials="${1:-100}"
scenario="$root/data/scenarios/tidy-kitchen.yaml"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# exec: a background `run` is then the apprentice process itself, which the
# kill must reach (not a subshell waiting for it).
run() { exec "$app" experiment --scenario "$scenario" --conditions instruction --knowledge-out "$1" -q >/dev/null 2>"$2"; }
goals() { "$app" knowledge --knowledge "$1" --json 2>"$work/knowledge.err" |
  /usr/bin/python3 -c 'import json,sys; print(len(json.load(sys.stdin)["goals"]))' 2>/dev/null; }

start=$(date +%s%N)
(run "$work/reference" "$work/reference.err")
run_us=$(( ($(date +%s%N) - start) / 1000 ))
[[ "$(goals "$work/reference/instruction.sqlite")" == 26 ]] || { echo "kill-test: a complete run did not store 26 goals" >&2; exit 2; }
echo "kill-test: one run takes $((run_us / 1000)) ms; $trials trials"

lost=0 landed=0 in_use=0 second_ok=0 partial=0 leftovers=0 unfinished=0
RANDOM=11
for ((t = 1; t <= trials; ++t)); do
  dir="$work/t$t"
  delay_us=$(( (RANDOM * 32768 + RANDOM) % (run_us + 1) ))
  (run "$dir" "$work/first.err") & first=$!
  sleep 0.0$(( RANDOM % 10 ))
  (run "$dir" "$work/second.err") & second=$!
  sleep "$(printf '%d.%06d' $((delay_us / 1000000)) $((delay_us % 1000000)))"
  kill -KILL "$first" 2>/dev/null || true
  set +e
  wait "$first"; first_rc=$?
  wait "$second"; second_rc=$?
  set -e
  [[ $first_rc -eq 137 ]] && landed=$((landed + 1))
  verdict=ok
  store="$dir/instruction.sqlite"
  if [[ $second_rc -eq 3 ]]; then
    if grep -q "in use" "$work/second.err"; then in_use=$((in_use + 1)); else verdict="second run exited 3: $(cat "$work/second.err")"; fi
  elif [[ $second_rc -eq 0 ]]; then
    second_ok=$((second_ok + 1))
  else
    verdict="second run exited $second_rc: $(cat "$work/second.err")"
  fi
  n=-
  if [[ -e "$store" ]]; then
    if n=$(goals "$store"); then
      [[ $second_rc -eq 0 && $n -ne 26 ]] && verdict="the second run completed but the store holds $n goals"
      [[ $n -gt 0 && $n -lt 26 ]] && partial=$((partial + 1))
    else
      verdict="store does not load: $(cat "$work/knowledge.err")"; n=?
    fi
  elif [[ $second_rc -eq 0 ]]; then
    verdict="the second run completed but left no store"
  fi
  [[ $verdict == ok ]] || lost=$((lost + 1))
  # Temporary files of killed creations, and stores whose first run was
  # killed before it created the store (nothing to lose yet).
  left=$(find "$dir" -maxdepth 1 -name '.instruction.sqlite.creating-*' 2>/dev/null | wc -l)
  leftovers=$((leftovers + left))
  [[ -e "$store" ]] || unfinished=$((unfinished + 1))
  printf 'trial %3d: kill after %6d us: first %s, second exit %d, %s goals, %d temporary files: %s\n' "$t" "$delay_us" \
    "$([[ $first_rc -eq 137 ]] && echo killed || echo "exit $first_rc")" "$second_rc" "$n" "$left" "$verdict"
  rm -rf "$dir"
done
echo "kill-test: $trials trials, $landed kills landed, second run: $second_ok completed, $in_use told 'in use'; $partial stores held part of a run; $unfinished trials left no store; $leftovers temporary files left; $lost stores lost"
[[ $lost -eq 0 ]]

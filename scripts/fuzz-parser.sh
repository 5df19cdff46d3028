#!/usr/bin/env bash
# Builds the sentence parser's libFuzzer target (fuzz/) with clang-19 into
# build-fuzz and runs it for a short while. Exits non-zero if the build
# fails or the fuzzer finds an input that crashes the parser, trips ASan or
# UBSan, or makes one parse take longer than the per-input timeout.
#
#   scripts/fuzz-parser.sh            # about 20 s
#   FUZZ_SECONDS=300 scripts/fuzz-parser.sh
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${FUZZ_BUILD_DIR:-$root/build-fuzz}"
seconds="${FUZZ_SECONDS:-20}"
jobs="$(nproc 2>/dev/null || echo 2)"

for tool in clang-19 clang++-19; do
  command -v "$tool" >/dev/null || { echo "fuzz-parser: $tool not found (apt-get install clang-19 libclang-rt-19-dev)" >&2; exit 2; }
done

CC=clang-19 CXX=clang++-19 cmake -S "$root/fuzz" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang-19 -DCMAKE_CXX_COMPILER=clang++-19 >/dev/null
cmake --build "$build" -j "$jobs" --target fuzz_parser

# New inputs go to a scratch directory; the seeds in fuzz/corpus stay as
# they are. When the shared STARS data is next to the repository, its
# sentences seed the run too (read at run time, never copied in).
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/new" "$work/shared"
script="$root/../shared/data/stars-tidy-kitchen/instructor_script.txt"
responses="$root/../shared/data/stars-tidy-kitchen/goal_responses.jsonl"
n=0
if [[ -r "$script" ]]; then
  while IFS= read -r line; do
    printf '%s' "$line" > "$work/shared/script-$((n++))"
  done < "$script"
fi
if [[ -r "$responses" ]]; then
  grep -o '"response": "[^"]*"' "$responses" | sed 's/^"response": "//; s/"$//' | sort -u |
    while IFS= read -r line; do
      printf '%s' "$line" > "$work/shared/response-$((n++))"
    done
fi

cd "$work"
"$build/fuzz_parser" \
  -max_total_time="$seconds" \
  -timeout=5 \
  -rss_limit_mb=2048 \
  -max_len=4096 \
  -dict="$root/fuzz/parser.dict" \
  -print_final_stats=1 \
  "$work/new" "$root/fuzz/corpus" "$work/shared"
echo "fuzz-parser: no crash, leak or hang in ${seconds} s"

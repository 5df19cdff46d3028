#!/usr/bin/env bash
# The sentence parser's libFuzzer target alone (kept for those who call it
# by this name): scripts/fuzz.sh parser, 20 s unless FUZZ_SECONDS says.
#
#   scripts/fuzz-parser.sh            # about 20 s
#   FUZZ_SECONDS=300 scripts/fuzz-parser.sh
set -euo pipefail
FUZZ_SECONDS="${FUZZ_SECONDS:-20}" exec bash "$(dirname "${BASH_SOURCE[0]}")/fuzz.sh" parser

#!/bin/bash
# Runs apprentice against a real llama-server, as docs/llm.md ("A real
# llama-server") reports it: the experiment in each HTTP dialect, and the
# fault table. llama-server and the model are the user's own, given by
# LLAMA_SERVER (the binary) and MODEL (a GGUF file); nothing is built or
# downloaded here. Only loopback is used.
#
#   scripts/real-llm-server.sh dialects              # openai:, openai-chat:, llama:
#   scripts/real-llm-server.sh fault NAME            # one row of the fault table
#
# Fault rows: kill, kill-optional, stop-default, stop-2s, stopped-before,
# no-server, wrong-url, wrong-key, pause35-60s, pause35-default.
# Environment: CONDITIONS (search4+llm,inst+search4+llm), OUT (a directory
# for the JSON, the logs and summary.txt; /tmp/real-llm-server), PORT (18091),
# THREADS (llama-server's -t; 1: on a loaded machine two threads spin and
# were 30 times slower), APPRENTICE (build/apprentice).
set -u
cd "$(dirname "$0")/.."
: "${LLAMA_SERVER:?set LLAMA_SERVER to a llama-server binary}"
: "${MODEL:?set MODEL to a GGUF model file}"
APPRENTICE=${APPRENTICE:-build/apprentice}
CONDITIONS=${CONDITIONS:-search4+llm,inst+search4+llm}
OUT=${OUT:-/tmp/real-llm-server}
PORT=${PORT:-18091}
THREADS=${THREADS:-1}
SCENARIO=data/scenarios/tidy-kitchen.yaml
BASE=http://127.0.0.1:$PORT
mkdir -p "$OUT"
SPID=
SIGPID=

server() {  # starts llama-server with any extra flags, waits until it is ready
  "$LLAMA_SERVER" -m "$MODEL" --host 127.0.0.1 --port "$PORT" -c 4096 -t "$THREADS" "$@" > "$OUT/server.log" 2>&1 &
  SPID=$!
  for _ in $(seq 100); do
    curl -s "$BASE/health" | grep -q ok && return 0
    sleep 0.2
  done
  echo "llama-server did not come up (see $OUT/server.log)" >&2
  exit 1
}

stop_server() {
  [ -n "$SPID" ] || return 0
  kill -CONT "$SPID" 2>/dev/null
  kill "$SPID" 2>/dev/null
  wait "$SPID" 2>/dev/null
  SPID=
}
trap stop_server EXIT

run() {  # NAME, then apprentice's flags: one experiment, its exit code and time in summary.txt
  local name=$1
  shift
  local start end rc
  start=$(date +%s.%N)
  "$APPRENTICE" experiment --scenario "$SCENARIO" --conditions "$CONDITIONS" --json "$@" \
    > "$OUT/$name.json" 2> "$OUT/$name.err"
  rc=$?
  end=$(date +%s.%N)
  echo "$name exit $rc time $(echo "$end - $start" | bc) s" | tee -a "$OUT/summary.txt"
}

signal_later() {  # NAME SIGNAL: the signal goes to the server 10 s into the run
  ( sleep 10; kill "-$2" "$SPID"; echo "$1: SIG$2 at $(date +%T)" >> "$OUT/summary.txt" ) &
  SIGPID=$!
}

pause_later() {  # NAME SECONDS: SIGSTOP 10 s into the run, SIGCONT SECONDS later
  ( sleep 10; kill -STOP "$SPID"; sleep "$2"; kill -CONT "$SPID"
    echo "$1: stopped from 10 s for $2 s" >> "$OUT/summary.txt" ) &
  SIGPID=$!
}

fault() {
  local openai="openai:$BASE/v1"
  case "$1" in
    kill) server; signal_later kill KILL; run kill --llm "$openai" ;;
    kill-optional) server; signal_later kill-optional KILL; run kill-optional --llm "$openai" --llm-optional ;;
    stop-default) server; signal_later stop-default STOP; run stop-default --llm "$openai" ;;
    stop-2s) server; signal_later stop-2s STOP; run stop-2s --llm "$openai" --llm-timeout-ms 2000 ;;
    stopped-before) server; kill -STOP "$SPID"; run stopped-before --llm "$openai" ;;
    no-server) run no-server --llm "$openai" ;;
    wrong-url)
      server
      run wrong-url --llm "openai:$BASE/v2"
      run wrong-url-llama --llm "llama:$BASE/v1" ;;
    wrong-key)
      server --api-key right-key
      run wrong-key --llm "$openai" --llm-api-key wrong-key
      CONDITIONS=search4+llm run right-key --llm "$openai" --llm-api-key right-key ;;
    pause35-60s) server; pause_later pause35-60s 35; run pause35-60s --llm "$openai" --llm-timeout-ms 60000 -v ;;
    pause35-default) server; pause_later pause35-default 35; run pause35-default --llm "$openai" -v ;;
    *) echo "no such fault: $1" >&2; exit 2 ;;
  esac
  [ -z "$SIGPID" ] || wait "$SIGPID"  # the signal's subshell
  stop_server
}

case "${1:-}" in
  dialects)
    server
    for spec in "openai:$BASE/v1" "openai-chat:$BASE/v1" "llama:$BASE"; do
      run "${spec%%:*}" --llm "$spec" -v
    done ;;
  fault) fault "${2:?which fault}" ;;
  *) echo "usage: $0 dialects | fault NAME" >&2; exit 2 ;;
esac

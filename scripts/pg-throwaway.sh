#!/usr/bin/env bash
# A throwaway PostgreSQL server for the tests and benchmarks of the
# PostgreSQL knowledge store: initdb into a temporary folder, the server on
# a unix socket there and on a free port of 127.0.0.1, run as a user that
# is not root (PostgreSQL refuses root: as root, the server runs as
# `nobody`), stopped and deleted by `stop`.
#
#   scripts/pg-throwaway.sh start STATE [--durable]
#   scripts/pg-throwaway.sh restart STATE     (fast shutdown, then start again)
#   scripts/pg-throwaway.sh stop STATE
#
# `start` writes into the folder STATE (made if missing):
#   url       the superuser's URL over the socket (trust: no password),
#             postgresql://apprentice@/postgres?host=SOCKET&port=PORT
#   tcp_url   the same over TCP with its password (scram-sha-256), for the
#             tests that check a password is never printed
#   port, password, server (the temporary folder)
# Without --durable the server runs with fsync=off (quicker for tests; a
# statement still returns only once committed, and `restart` shuts down
# cleanly); --durable keeps PostgreSQL's defaults, for benchmarks.
#
# When the server binaries are missing (no `postgresql` package), `start`
# writes STATE/missing with the reason and exits 0, so that the tests skip
# saying why; under CI=true it fails instead (CI must run these tests).
set -euo pipefail

command="${1:-}"
state="${2:-}"
if [[ -z "$command" || -z "$state" ]]; then
  echo "usage: $0 start|restart|stop STATE [--durable]" >&2
  exit 2
fi

bindir="$(ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V | tail -n 1 || true)"

# Runs a server binary as the server's user.
as_server_user() {
  if [[ $(id -u) -eq 0 ]]; then
    runuser -u nobody -- "$@"
  else
    "$@"
  fi
}

start() {
  rm -rf "$state"
  mkdir -p "$state"
  if [[ -z "$bindir" || ! -x "$bindir/initdb" || ! -x "$bindir/pg_ctl" ]]; then
    echo "the PostgreSQL server binaries are not installed (no /usr/lib/postgresql/*/bin/initdb; install the Debian package postgresql)" >"$state/missing"
    if [[ "${CI:-}" == "true" ]]; then
      echo "pg-throwaway: $(cat "$state/missing")" >&2
      exit 1
    fi
    echo "pg-throwaway: skipped: $(cat "$state/missing")"
    exit 0
  fi
  local server password port
  server="$(mktemp -d /tmp/apprentice-pg.XXXXXX)"
  chmod 755 "$server"
  password="throwaway-$(od -An -N8 -tx8 /dev/urandom | tr -d ' \n')"
  printf '%s\n' "$password" >"$server/pwfile"
  if [[ $(id -u) -eq 0 ]]; then chown -R nobody "$server"; fi
  as_server_user "$bindir/initdb" -D "$server/data" -U apprentice --pwfile="$server/pwfile" \
    --auth-local=trust --auth-host=scram-sha-256 -E UTF8 --locale=C.UTF-8 --no-sync >"$server/initdb.log" 2>&1 || {
    cat "$server/initdb.log" >&2
    exit 1
  }
  rm -f "$server/pwfile"
  local options=(-c listen_addresses=127.0.0.1 -c "unix_socket_directories=$server" -c max_connections=200
    -c shared_buffers=32MB -c lc_messages=C)
  if [[ "${3:-}" != "--durable" ]]; then options+=(-c fsync=off -c full_page_writes=off); fi
  printf '%s\n' "${options[@]}" >"$server/options"
  for attempt in 1 2 3 4 5 6 7 8; do
    port=$((20000 + RANDOM % 20000))
    if as_server_user "$bindir/pg_ctl" -D "$server/data" -l "$server/log" -w -t 30 \
      -o "-p $port ${options[*]}" start >/dev/null 2>&1; then
      break
    fi
    port=""
  done
  if [[ -z "$port" ]]; then
    echo "pg-throwaway: the server did not start; its log:" >&2
    cat "$server/log" >&2 || true
    exit 1
  fi
  echo "$server" >"$state/server"
  echo "$port" >"$state/port"
  echo "$password" >"$state/password"
  echo "postgresql://apprentice@/postgres?host=$server&port=$port" >"$state/url"
  echo "postgresql://apprentice:$password@127.0.0.1:$port/postgres" >"$state/tcp_url"
  chmod 600 "$state/password" "$state/tcp_url"
  echo "pg-throwaway: PostgreSQL $("$bindir/postgres" --version | awk '{print $3}') on port $port and socket $server"
}

restart() {
  local server port
  server="$(cat "$state/server")"
  port="$(cat "$state/port")"
  as_server_user "$bindir/pg_ctl" -D "$server/data" -m fast -w -t 30 stop >/dev/null
  as_server_user "$bindir/pg_ctl" -D "$server/data" -l "$server/log" -w -t 30 \
    -o "-p $port $(tr '\n' ' ' <"$server/options")" start >/dev/null
}

stop() {
  [[ -f "$state/server" ]] || { rm -rf "$state"; return 0; }
  local server
  server="$(cat "$state/server")"
  as_server_user "$bindir/pg_ctl" -D "$server/data" -m immediate -w -t 30 stop >/dev/null 2>&1 || true
  rm -rf "$server" "$state"
}

case "$command" in
  start) start "$@" ;;
  restart) restart ;;
  stop) stop ;;
  *)
    echo "usage: $0 start|restart|stop STATE [--durable]" >&2
    exit 2
    ;;
esac

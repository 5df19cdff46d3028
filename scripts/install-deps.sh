#!/usr/bin/env bash
# Installs the Debian packages listed in scripts/debian-packages.txt that are
# not installed yet (needs root or sudo), then the npm packages of
# package-lock.json; does nothing when all are present.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
missing=()
while read -r package; do
  [[ -z "$package" || "$package" == \#* ]] && continue
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done < "$here/debian-packages.txt"
if [[ ${#missing[@]} -eq 0 ]]; then
  echo "install-deps: all packages present"
else
  echo "install-deps: installing ${missing[*]}"
  sudo=""
  if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -q
  $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# npm packages, from package.json and its lockfile (package-lock.json):
# the word vectors the build converts, and playwright-core for the page's
# browser tests. Reinstalled only when the lockfile changed since the last
# install (node_modules/.apprentice-lock keeps a copy of it).
root="$(cd "$here/.." && pwd)"
if ! command -v npm >/dev/null 2>&1; then
  echo "install-deps: installing nodejs npm"
  sudo=""
  if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -q
  $sudo apt-get install -y -q --no-install-recommends nodejs npm
fi
if cmp -s "$root/package-lock.json" "$root/node_modules/.apprentice-lock"; then
  echo "install-deps: npm packages present"
else
  echo "install-deps: npm ci (package-lock.json)"
  (cd "$root" && npm ci --no-audit --no-fund --loglevel=error)
  cp "$root/package-lock.json" "$root/node_modules/.apprentice-lock"
fi

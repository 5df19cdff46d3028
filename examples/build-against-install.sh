#!/usr/bin/env bash
# The install test (ctest install.example): installs a build tree into a
# fresh prefix, builds examples/ against it with find_package(apprentice),
# and runs the program.
#
#   examples/build-against-install.sh BUILD_DIR WORK_DIR
set -euo pipefail
build=$1
work=$2
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" >/dev/null
# The CMake package must not point back into the source or build tree.
source_dir="$(cd "$here/.." && pwd)"
if grep -rlF -e "$source_dir" -e "$(cd "$build" && pwd)" "$work/prefix/lib/cmake"; then
  echo "build-against-install: the installed CMake package names the source or build tree" >&2
  exit 1
fi
cmake -S "$here" -B "$work/example" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix" \
  ${CMAKE_CXX_COMPILER_LAUNCHER:+-DCMAKE_CXX_COMPILER_LAUNCHER=$CMAKE_CXX_COMPILER_LAUNCHER} >/dev/null
cmake --build "$work/example" 2>&1
"$work/example/teach_kitchen"
# Only the face and what it includes: no internal header (the agent's own).
for file in include/apprentice/agent/agent.h include/apprentice/agent/session.h include/apprentice/llm/factory.h; do
  [[ ! -e "$work/prefix/$file" ]] || { echo "build-against-install: the internal header $file was installed" >&2; exit 1; }
done
# The rest of the installation: the program with its man page and bash
# completion, and the Python module when it was built.
prefix="$work/prefix"
for file in bin/apprentice share/man/man1/apprentice.1 share/bash-completion/completions/apprentice \
            share/apprentice/scenarios/tidy-kitchen.yaml include/apprentice/face/apprentice.h; do
  [[ -f "$prefix/$file" ]] || { echo "build-against-install: $file was not installed" >&2; exit 1; }
done
if [[ -d "$prefix/lib/python3/dist-packages/apprentice" ]]; then
  PYTHONPATH="$prefix/lib/python3/dist-packages" /usr/bin/python3 -c \
    "import apprentice; r = apprentice.experiment('$prefix/share/apprentice/scenarios/tidy-kitchen.yaml', conditions=['inst+search4'])[0]; print('Python:', r['instructions'], 'instructions,', r['words'], 'words')"
fi

#!/usr/bin/env python3
"""The architecture's two rules, checked on the code (docs/architecture.md):

1. No file-level #include cycle in src/. A file here is a unit: a header and
   the source of the same name (language/generation.h and .cc). A header
   without a source of its own (agent/session.h, world/goal_reader.h) is a
   module's private header: it belongs to the files that include it, so an
   include through it counts as theirs.
2. No upward module arrow: a module includes only the modules below it, as
   LAYERS says; each module's CMake DEPS name no module it may not use.
3. The agent never sees the intent: no file of the modules in BLIND reaches
   world/scenario.h (the scenario's task and intent) through its includes,
   followed through every header; they take the World of world/world.h.

Exit 0 when all hold; 1 with one line per breach otherwise.
    scripts/check-layers.py [SOURCE_DIR]
    scripts/check-layers.py --self-test   (it finds a planted cycle and arrow)
"""
import os
import re
import sys

# Each module and the modules it may include (docs/architecture.md).
LAYERS = {
    "util": set(),
    "world": {"util"},
    "search": {"util", "world"},
    "language": {"util", "world"},
    "knowledge": {"util", "world"},
    "llm": {"util"},
    "vectors": {"util"},
    "instructor": {"util", "world", "language", "search"},
    "agent": {"util", "world", "language", "search", "knowledge", "llm", "vectors", "instructor"},
    "face": {"util", "world", "language", "search", "knowledge", "llm", "vectors", "instructor", "agent"},
    "experiment": {"util", "world", "language", "search", "knowledge", "llm", "vectors", "instructor", "agent", "face"},
    "benchmark": {"util", "world", "language", "search", "knowledge", "llm", "vectors", "instructor", "agent", "face"},
}
# Modules that must not see world/scenario.h, and what they use instead.
BLIND = {"agent", "knowledge", "search"}
INTENT = ("world", "scenario")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/([A-Za-z_0-9]+)\.h"', re.M)
DEPS = re.compile(r"apprentice_([a-z_]+)")


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def self_test():
    """Plants a cycle (language/a <-> language/b, through a private header)
    and an upward arrow (world including agent) in a scratch tree: both
    must be reported, and nothing else."""
    import subprocess
    import tempfile
    with tempfile.TemporaryDirectory() as root:
        def put(path, text):
            os.makedirs(os.path.dirname(os.path.join(root, path)), exist_ok=True)
            with open(os.path.join(root, path), "w", encoding="utf-8") as f:
                f.write(text)
        put("src/language/a.h", "#pragma once\n")
        put("src/language/a.cc", '#include "language/a.h"\n#include "language/b_private.h"\n')
        put("src/language/b_private.h", '#pragma once\n#include "language/b.h"\n')
        put("src/language/b.h", "#pragma once\n")
        put("src/language/b.cc", '#include "language/b.h"\n#include "language/a.h"\n')
        put("src/world/w.h", '#pragma once\n#include "agent/agent.h"\n')
        put("src/world/w.cc", '#include "world/w.h"\n')
        put("src/agent/agent.h", '#pragma once\n#include "world/w.h"\n')
        put("src/agent/agent.cc", '#include "agent/agent.h"\n')
        put("src/agent/peek.h", '#pragma once\n#include "world/w.h"\n#include "world/scenario.h"\n')
        put("src/agent/peek.cc", '#include "agent/peek.h"\n')
        run = subprocess.run([sys.executable, __file__, root], capture_output=True, text=True)
        lines = run.stdout.splitlines()
        expected = ["check-layers: src/world/w.h: includes agent/agent.h, but world may not use agent",
                    "check-layers: include cycle: agent/agent <-> world/w",
                    "check-layers: include cycle: language/a <-> language/b",
                    "check-layers: src/agent/peek.cc: reaches world/scenario.h (through agent/peek.h), "
                    "but agent must not see the intent; include world/world.h for the World",
                    "check-layers: src/agent/peek.h: reaches world/scenario.h, "
                    "but agent must not see the intent; include world/world.h for the World"]
        if run.returncode != 1 or sorted(lines) != sorted(expected):
            print("check-layers self-test failed; got:\n" + run.stdout)
            return 1
    print("check-layers self-test: the planted cycles, arrow and look at the intent were found")
    return 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    src = os.path.join(root, "src")
    files = {}  # "module/name.ext" -> [(module, name)] it includes
    for module in sorted(os.listdir(src)):
        folder = os.path.join(src, module)
        if not os.path.isdir(folder):
            continue
        for name in sorted(os.listdir(folder)):
            if name.endswith((".h", ".cc")):
                files[f"{module}/{name}"] = INCLUDE.findall(read(os.path.join(folder, name)))
    breaches = []

    # Rule 2: module arrows, in the code and in CMake.
    for path, includes in files.items():
        module = path.split("/")[0]
        if module not in LAYERS:
            breaches.append(f"src/{path}: module {module} is not in the layers of scripts/check-layers.py")
            continue
        for other, name in includes:
            if other != module and other not in LAYERS[module]:
                breaches.append(f"src/{path}: includes {other}/{name}.h, but {module} may not use {other}")
    for module in LAYERS:
        cmake = os.path.join(src, module, "CMakeLists.txt")
        if not os.path.exists(cmake):
            continue
        text = read(cmake)
        deps = text[text.find("DEPS"):] if "DEPS" in text else ""
        for other in DEPS.findall(deps):
            if other in LAYERS and other != module and other not in LAYERS[module]:
                breaches.append(f"src/{module}/CMakeLists.txt: links apprentice_{other}, but {module} may not use {other}")

    # Rule 3: the intent, through any chain of headers.
    def first_step_to_intent(path):
        """The include of `path` through which world/scenario.h is reached
        ("" when directly), or None."""
        for start in files[path]:
            if start == INTENT:
                return ""
            seen, todo = set(), [start]
            while todo:
                m, n = todo.pop()
                key = f"{m}/{n}.h"
                if key in seen or key not in files:
                    continue
                seen.add(key)
                for inc in files[key]:
                    if inc == INTENT:
                        return f"{start[0]}/{start[1]}.h"
                    todo.append(inc)
        return None
    for path in files:
        module = path.split("/")[0]
        if module not in BLIND:
            continue
        step = first_step_to_intent(path)
        if step is not None:
            through = f" (through {step})" if step else ""
            breaches.append(f"src/{path}: reaches world/scenario.h{through}, but {module} must not see the intent; "
                            "include world/world.h for the World")

    # Rule 1: cycles among units.
    units = {p.rsplit(".", 1)[0] for p in files if p.endswith(".cc")}
    def expand(module, name, seen):
        """The units an include of module/name.h reaches: itself if it is a
        unit, else (a private header) what it includes, followed."""
        key = f"{module}/{name}"
        if key in units:
            return {key}
        if key in seen or f"{key}.h" not in files:
            return set()
        seen.add(key)
        out = set()
        for m, n in files[f"{key}.h"]:
            out |= expand(m, n, seen)
        return out
    graph = {u: set() for u in units}
    for path, includes in files.items():
        unit = path.rsplit(".", 1)[0]
        if unit not in units:
            continue
        for m, n in includes:
            graph[unit] |= expand(m, n, set()) - {unit}
    index, low, stack, on, cycles, counter = {}, {}, [], set(), [], [0]
    sys.setrecursionlimit(100000)
    def connect(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                connect(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                cycles.append(sorted(component))
    for v in sorted(graph):
        if v not in index:
            connect(v)
    for cycle in cycles:
        breaches.append("include cycle: " + " <-> ".join(cycle))

    for line in breaches:
        print("check-layers: " + line)
    if not breaches:
        print(f"check-layers: {len(files)} files in {len(LAYERS)} modules; no include cycle, no upward arrow, "
              f"and {', '.join(sorted(BLIND))} never reach the intent")
    return 1 if breaches else 0


if __name__ == "__main__":
    sys.exit(main())

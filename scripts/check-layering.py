#!/usr/bin/env python3
"""Check the module layering that docs/architecture.md draws.

docs/architecture.md's "Layering" section holds a fenced block (```layering) with one
line per module of src/luxplan, lowest first: `module: the modules it uses`. A module
may include its own headers and those of every module it uses, directly or through
them; nothing above it. This fails (exit status 1) when

- a file of src/luxplan/X includes <luxplan/Y/...> for a module Y that X may not use,
- a folder of src/luxplan is not in the block, or the block names one that is not a
  folder, or a module uses one listed after it,
- CMakeLists.txt's luxplan_module(X DEPS ...) names other modules than the block.

    python3 scripts/check-layering.py [REPO]
"""

import os
import re
import sys


def read_layering(doc):
    """The block's modules in order, each with the modules it uses."""
    text = open(doc, encoding="utf-8").read()
    match = re.search(r"^```layering\n(.*?)^```", text, re.M | re.S)
    if not match:
        raise SystemExit(f"{doc}: no ```layering block")
    order, uses = [], {}
    for number, line in enumerate(match.group(1).splitlines(), 1):
        line = line.strip()
        if not line:
            continue
        name, sep, rest = line.partition(":")
        if not sep:
            raise SystemExit(f"{doc}: layering line {number} is not `module: modules it uses`: {line}")
        name = name.strip()
        order.append(name)
        uses[name] = rest.split()
    return order, uses


def closure(uses, module):
    seen, stack = set(), list(uses[module])
    while stack:
        m = stack.pop()
        if m not in seen:
            seen.add(m)
            stack.extend(uses.get(m, []))
    return seen


def cmake_deps(cmake):
    deps = {}
    text = open(cmake, encoding="utf-8").read()
    for m in re.finditer(r"^luxplan_module\((\w+)([^)]*)\)", text, re.M):
        words = m.group(2).split()
        listed = []
        if "DEPS" in words:
            for w in words[words.index("DEPS") + 1:]:
                if w == "LIBS":
                    break
                listed.append(w.removeprefix("luxplan_"))
        deps[m.group(1)] = sorted(listed)
    return deps


def main():
    repo = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    doc = os.path.join(repo, "docs", "architecture.md")
    src = os.path.join(repo, "src", "luxplan")
    order, uses = read_layering(doc)
    problems = []

    folders = sorted(d for d in os.listdir(src) if os.path.isdir(os.path.join(src, d)))
    for f in folders:
        if f not in uses:
            problems.append(f"src/luxplan/{f}: a module the layering of docs/architecture.md does not list")
    for m in order:
        if m not in folders:
            problems.append(f"docs/architecture.md: layering lists {m}, which is no folder of src/luxplan")
        for u in uses[m]:
            if u not in uses:
                problems.append(f"docs/architecture.md: {m} uses {u}, which the layering does not list")
            elif order.index(u) >= order.index(m):
                problems.append(f"docs/architecture.md: {m} uses {u}, which is listed after it (an arrow up)")

    for module, deps in sorted(cmake_deps(os.path.join(repo, "CMakeLists.txt")).items()):
        if module in uses and deps != sorted(uses[module]):
            problems.append(f"CMakeLists.txt: luxplan_module({module}) DEPS {' '.join(deps) or '(none)'}, "
                            f"but docs/architecture.md says it uses {' '.join(sorted(uses[module])) or 'nothing'}")

    include = re.compile(r'^\s*#\s*include\s*[<"]luxplan/(\w+)/([^>"]+)[>"]', re.M)
    for module in folders:
        if module not in uses:
            continue
        allowed = closure(uses, module) | {module}
        for root, _, files in os.walk(os.path.join(src, module)):
            for name in sorted(files):
                path = os.path.join(root, name)
                with open(path, encoding="utf-8", errors="replace") as f:
                    text = f.read()
                for m in include.finditer(text):
                    if m.group(1) not in allowed:
                        line = text.count("\n", 0, m.start()) + 1
                        problems.append(f"{os.path.relpath(path, repo)}:{line}: includes luxplan/{m.group(1)}/"
                                        f"{m.group(2)}, but {module} may use only "
                                        f"{', '.join(sorted(allowed - {module})) or 'nothing'}")

    for p in problems:
        print(p)
    if problems:
        print(f"{len(problems)} layering problem(s)")
        return 1
    print(f"layering: {len(order)} modules, every include within its module's reach")
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Which desktop packages depend on which, and the cycles among them.

Reads desktop/src/main/java/org/skinlab/desktop: a package depends on another when one of its
files names a class of it (an import, or a qualified name in code; comments are left out, so a
{@link} in Javadoc is no dependency). The root package org.skinlab.desktop is "root". Prints
each package's dependencies, then each cycle (a strongly connected set of packages, with the
files behind its edges); exits 1 when there is one.
Run from the repository root: python3 tools/desktop-package-cycles.py
"""
import pathlib
import re
import sys

BASE = pathlib.Path("desktop/src/main/java/org/skinlab/desktop")
COMMENT = re.compile(r"/\*.*?\*/|//[^\n]*", re.S)
STRING = re.compile(r'"(?:\\.|[^"\\])*"')
NAME = re.compile(r"\borg\.skinlab\.desktop\.(?:([a-z]\w*)\.[A-Z]|([A-Z]))")


def package_of(path):
    parts = path.relative_to(BASE).parts
    return "root" if len(parts) == 1 else parts[0]


def edges():
    """(from, to) -> the files of package 'from' that name package 'to'."""
    found = {}
    for path in sorted(BASE.rglob("*.java")):
        source = package_of(path)
        code = STRING.sub('""', COMMENT.sub("", path.read_text(encoding="utf-8")))
        for sub, root_class in NAME.findall(code):
            target = sub if sub else "root"
            if target != source:
                found.setdefault((source, target), set()).add(str(path.relative_to(BASE)))
    return found


def cycles(packages, found):
    """Tarjan's strongly connected components with more than one package."""
    graph = {p: sorted(t for (s, t) in found if s == p) for p in packages}
    index, low, stack, on, result, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
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
                result.append(sorted(component))

    for p in packages:
        if p not in index:
            visit(p)
    return result


def main():
    if not BASE.is_dir():
        sys.exit("run from the repository root (no " + str(BASE) + ")")
    found = edges()
    packages = sorted({package_of(p) for p in BASE.rglob("*.java")} | {t for (_, t) in found})
    for p in packages:
        print(f"{p:8} -> {', '.join(sorted(t for (s, t) in found if s == p)) or '(none)'}")
    loops = cycles(packages, found)
    for loop in loops:
        print("cycle: " + ", ".join(loop))
        for (s, t), files in sorted(found.items()):
            if s in loop and t in loop:
                print(f"  {s} -> {t}: {', '.join(sorted(files))}")
    if not loops:
        print("no cycle")
    return 1 if loops else 0


if __name__ == "__main__":
    sys.exit(main())

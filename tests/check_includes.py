#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The includes run one way (docs/architecture.md):
  check_includes.py SOURCE_DIR
fails (exit 1) when a header of core/, platform/, firmware/ or assets/
includes itself through others (a circle), or when the headers of the
walk's folders (firmware/walk/ and its thread folders) include each other
both ways between two folders. Prints each circle found."""
import glob
import os
import re
import sys


def headers(src):
    found = {}
    for top in ("core", "platform", "firmware", "assets"):
        for path in glob.glob(os.path.join(src, top, "**", "*.h"), recursive=True):
            found[os.path.basename(path)] = os.path.relpath(path, src)
    return found


def includes(src, found):
    graph = {}
    for name, rel in found.items():
        text = open(os.path.join(src, rel), encoding="utf-8").read()
        graph[name] = [m for m in re.findall(r'#include "([^"]+)"', text) if m in found]
    return graph


def circles(graph):
    state, out = {}, []

    def visit(node, stack):
        state[node] = 1
        stack.append(node)
        for nxt in graph.get(node, []):
            if state.get(nxt) == 1:
                out.append(stack[stack.index(nxt):] + [nxt])
            elif not state.get(nxt):
                visit(nxt, stack)
        stack.pop()
        state[node] = 2

    for node in sorted(graph):
        if not state.get(node):
            visit(node, [])
    return out


def main():
    src = sys.argv[1]
    found = headers(src)
    graph = includes(src, found)
    bad = [" -> ".join(c) for c in circles(graph)]
    walk = os.path.join("firmware", "walk")
    folders = {}
    for name, rel in found.items():
        if rel.startswith(walk + os.sep):
            for dep in graph[name]:
                a, b = os.path.dirname(rel), os.path.dirname(found[dep])
                if b.startswith(walk) and a != b:
                    folders.setdefault((a, b), (name, dep))
    for (a, b), (name, dep) in sorted(folders.items()):
        if (b, a) in folders and a < b:
            bad.append("%s and %s include each other (%s -> %s, %s -> %s)"
                       % (a, b, name, dep, *folders[(b, a)]))
    for line in bad:
        print("include circle: " + line)
    print("check_includes: %d headers, %d circles" % (len(found), len(bad)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())

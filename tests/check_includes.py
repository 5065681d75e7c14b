#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The includes run one way (docs/architecture.md):
  check_includes.py SOURCE_DIR
fails (exit 1) when a header of core/, platform/, firmware/ or assets/
includes itself through others (a circle), when the headers of the
walk's folders (firmware/walk/ and its thread folders) include each other
both ways between two folders, or when the folders of firmware/ and
platform/ include each other round a circle, counting every source file
(.c and .h): firmware's jobs (walk, kiosk, store, program, measure; the
walk's thread folders count as the walk, whose own rule is the one above)
and platform's folders (platform/, platform/input/). Prints each circle
found."""
import glob
import os
import re
import sys

TOPS = ("core", "platform", "firmware", "assets")
WALK = os.path.join("firmware", "walk")


def sources(src, pattern):
    found = {}
    for top in TOPS:
        for path in glob.glob(os.path.join(src, top, "**", pattern), recursive=True):
            found[os.path.relpath(path, src)] = os.path.basename(path)
    return found


def included(src, rel, names):
    text = open(os.path.join(src, rel), encoding="utf-8").read()
    return [m for m in re.findall(r'#include "([^"]+)"', text) if m in names]


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


def walk_folders(found, graph):
    """The walk's folders whose headers include each other both ways."""
    folders, bad = {}, []
    for name, rel in found.items():
        if rel.startswith(WALK + os.sep):
            for dep in graph[name]:
                a, b = os.path.dirname(rel), os.path.dirname(found[dep])
                if b.startswith(WALK) and a != b:
                    folders.setdefault((a, b), (name, dep))
    for (a, b), (name, dep) in sorted(folders.items()):
        if (b, a) in folders and a < b:
            bad.append("%s and %s include each other (%s -> %s, %s -> %s)"
                       % (a, b, name, dep, *folders[(b, a)]))
    return bad


def job_folder(rel):
    """The folder a source file's links count for, or None outside the check."""
    folder = os.path.dirname(rel)
    if folder.startswith(WALK + os.sep):
        return WALK
    return folder if folder.split(os.sep)[0] in ("firmware", "platform") else None


def job_folder_circles(src, found):
    """Circles between firmware's and platform's folders, each step with one
    include that makes it."""
    edges = {}
    for rel in sorted(sources(src, "*.[ch]")):
        a = job_folder(rel)
        for dep in included(src, rel, found) if a else []:
            b = job_folder(found[dep])
            if b and b != a:
                edges.setdefault(a, {}).setdefault(b, (os.path.basename(rel), dep))
    bad = []
    for circle in circles({a: sorted(bs) for a, bs in edges.items()}):
        steps = ["%s (%s includes %s)" % (b, *edges[a][b]) for a, b in zip(circle, circle[1:])]
        bad.append("folders: %s -> %s" % (circle[0], " -> ".join(steps)))
    return bad


def main():
    src = sys.argv[1]
    found = {name: rel for rel, name in sources(src, "*.h").items()}
    graph = {name: included(src, rel, found) for name, rel in found.items()}
    bad = [" -> ".join(c) for c in circles(graph)]
    bad += walk_folders(found, graph)
    bad += job_folder_circles(src, found)
    for line in bad:
        print("include circle: " + line)
    print("check_includes: %d headers, %d circles" % (len(found), len(bad)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())

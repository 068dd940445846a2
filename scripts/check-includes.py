#!/usr/bin/env python3
"""check-includes.py [ROOT] [FOLDER...] — lists every include circle in ROOT/src (default: the
checkout this script lies in); exit 0 when there is none, 1 when there is one, 2 on a usage error.

A unit is a .c (or .cpp) file with the header of the same name beside it; a circle is a set of
units each of which reaches every other through quoted #include lines (unit A includes B's
header, and B, its source or its header, includes A's, directly or through other units). A
quoted include is looked up beside the including file, then under src/core, src/plugins and
src/plugins/common, as the build's include paths find it; system and public headers
(<...>, include/sylva/) are not units of src/.

FOLDERs (paths under src/, such as core/render) restrict the verdict to the circles that have a
unit inside one of them; the others are still listed, as not counted.
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
BASES = ('core', 'plugins', 'plugins/common')


def read_includes(src):
    """Every source and header under src (paths relative to it) with its quoted includes."""
    includes = {}
    for folder, _, files in os.walk(src):
        for name in files:
            if not name.endswith(('.c', '.h', '.cpp')):
                continue
            path = os.path.join(folder, name)
            with open(path, errors='replace') as f:
                includes[os.path.relpath(path, src)] = INCLUDE.findall(f.read())
    return includes


def resolve(includes, frm, name):
    for base in (os.path.dirname(frm),) + BASES:
        candidate = os.path.normpath(os.path.join(base, name))
        if candidate in includes:
            return candidate
    return None


def unit(path):
    return re.sub(r'\.(c|h|cpp)$', '', path)


def unit_graph(includes):
    graph = {}
    for frm, names in includes.items():
        edges = graph.setdefault(unit(frm), set())
        for name in names:
            to = resolve(includes, frm, name)
            if to and unit(to) != unit(frm):
                edges.add(unit(to))
    return graph


def circles(graph):
    """The strongly connected components of more than one unit (Tarjan), each sorted."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        # iterative: a deep include chain does not reach Python's recursion limit
        work = [(v, iter(sorted(graph.get(v, ()))))]
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on_stack.add(v)
        while work:
            node, children = work[-1]
            advanced = False
            for w in children:
                if w not in index:
                    index[w] = low[w] = counter[0]
                    counter[0] += 1
                    stack.append(w)
                    on_stack.add(w)
                    work.append((w, iter(sorted(graph.get(w, ())))))
                    advanced = True
                    break
                if w in on_stack:
                    low[node] = min(low[node], index[w])
            if advanced:
                continue
            work.pop()
            if work:
                parent = work[-1][0]
                low[parent] = min(low[parent], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    w = stack.pop()
                    on_stack.discard(w)
                    component.append(w)
                    if w == node:
                        break
                if len(component) > 1:
                    found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return sorted(found)


def inside(u, folders):
    return any(u == f or u.startswith(f.rstrip('/') + '/') for f in folders)


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    root = argv[1] if len(argv) > 1 else os.path.join(here, '..')
    folders = argv[2:]
    src = os.path.join(root, 'src')
    if not os.path.isdir(src):
        print(f'check-includes: {src} is not a folder; give the checkout root', file=sys.stderr)
        return 2
    counted = 0
    for c in circles(unit_graph(read_includes(src))):
        if folders and not any(inside(u, folders) for u in c):
            print('not counted: ' + ' <-> '.join(c))
        else:
            print('CIRCLE: ' + ' <-> '.join(c))
            counted += 1
    if counted:
        print(f'includes: {counted} circle(s) among the units of src/'
              + (' in ' + ', '.join(folders) if folders else ''))
        return 1
    print('includes: no circle among the units of src/' + (' in ' + ', '.join(folders) if folders else ''))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))

#!/usr/bin/env python3
"""List import cycles among sibling modules of each crate (issue 29).

Edge A -> B between two sibling modules (children of the same parent module)
when any file under A names B: `crate::<path to B>`, `super::B` from A's top
file, or a `use` of B's items. References between a module and its parent or
children do not count. Usage: scripts/module-cycles.py [crate_src_dir ...]
(default: every crates/*/src). Prints each cycle; exits 1 when any exists.
"""
import os
import re
import sys


def modules(src):
    """Map module path tuple -> list of files belonging to it (not to children)."""
    out = {}
    for root, _, files in os.walk(src):
        for f in files:
            if not f.endswith(".rs"):
                continue
            rel = os.path.relpath(os.path.join(root, f), src)[:-3].split(os.sep)
            if rel[-1] in ("mod", "lib", "main"):
                rel = rel[:-1]
            out.setdefault(tuple(rel), []).append(os.path.join(root, f))
    return out


def strip(text):
    text = re.sub(r"//[^\n]*", "", text)
    return re.sub(r"/\*.*?\*/", "", text, flags=re.S)


def references(mod, text, known):
    """Absolute module paths a file of `mod` refers to."""
    refs = set()
    for m in re.finditer(r"\b((?:crate|super|self)(?:::\w+)+)", text):
        parts = m.group(1).split("::")
        if parts[0] == "crate":
            base, rest = (), parts[1:]
        else:
            base = list(mod)
            rest = parts
            while rest and rest[0] in ("super", "self"):
                if rest[0] == "super":
                    base = base[:-1]
                rest = rest[1:]
            base = tuple(base)
        path = base
        for p in rest:
            if path + (p,) in known:
                path = path + (p,)
            else:
                break
        refs.add(path)
    # grouped imports: use crate::{a::X, b::Y} / use super::{a, b}
    for m in re.finditer(r"\buse\s+(crate|super)::\{([^;]*)\}", text):
        base = () if m.group(1) == "crate" else tuple(mod[:-1])
        for item in re.findall(r"(?:^|[,{\s])(\w+)::", m.group(2)) + re.findall(
            r"(?:^|[,{\s])(\w+)\s*(?=[,}]|$)", m.group(2)
        ):
            if base + (item,) in known:
                refs.add(base + (item,))
    return refs


def cycles(src):
    mods = modules(src)
    known = set(mods)
    edges = {}
    for mod, files in mods.items():
        for f in files:
            for ref in references(mod, strip(open(f).read()), known):
                # lift both to the children of their common parent
                k = 0
                while k < min(len(mod), len(ref)) and mod[k] == ref[k]:
                    k += 1
                if k >= len(mod) or k >= len(ref):
                    continue  # parent-child or self
                a, b = mod[: k + 1], ref[: k + 1]
                edges.setdefault(a, set()).add(b)
    # strongly connected components (Tarjan)
    index, low, stack, on, comps, n = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = n[0]
        n[0] += 1
        stack.append(v)
        on.add(v)
        for w in edges.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                comps.append(sorted(comp))

    sys.setrecursionlimit(10000)
    for v in sorted(edges):
        if v not in index:
            visit(v)
    return comps, edges


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    srcs = sys.argv[1:] or sorted(
        os.path.join(here, "..", "crates", c, "src")
        for c in os.listdir(os.path.join(here, "..", "crates"))
        if os.path.isdir(os.path.join(here, "..", "crates", c, "src"))
    )
    found = False
    for src in srcs:
        name = os.path.basename(os.path.dirname(os.path.normpath(src)))
        comps, edges = cycles(src)
        for comp in comps:
            found = True
            names = ["::".join(c) for c in comp]
            print(f"{name}: cycle among {', '.join(names)}")
            for a in comp:
                for b in sorted(edges[a]):
                    if b in comp:
                        print(f"    {'::'.join(a)} -> {'::'.join(b)}")
        if not comps:
            print(f"{name}: no cycles")
    sys.exit(1 if found else 0)


if __name__ == "__main__":
    main()

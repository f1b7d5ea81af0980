#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""DESIGN.md's layer rule, checked: a layer uses only the layers before it in the list.

Two checks, both failing with every violation named:
  - includes: each file in src/<layer>/ includes headers of its own layer or earlier ones
    (src/<other>/... and the public include/sparsedyn/... headers, mapped to their layers);
  - links: each layer's object files (the per-layer OBJECT libraries the build makes) leave
    undefined only symbols that an earlier layer, the layer itself, or no layer at all (the
    system and third-party libraries) defines.

usage: check_layers.py SOURCE_DIR MANIFEST [NM]
MANIFEST has one line per layer, in order: "layer=object;object;..." (src/CMakeLists.txt).
"""
import os
import re
import subprocess
import sys

# Public headers by layer (include/sparsedyn/...); a folder stands for every header in it.
PUBLIC_LAYERS = {
    "assert.hpp": "base", "result.hpp": "base", "types.hpp": "base",
    "geometry/": "geometry", "narrow/": "narrow",
    "statistics.hpp": "world", "world.hpp": "world",
    "conventional.hpp": "conventional", "io/": "io",
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def public_layer(header):
    for prefix, layer in PUBLIC_LAYERS.items():
        if header == prefix or (prefix.endswith("/") and header.startswith(prefix)):
            return layer
    return None


def included_layer(header, layers):
    if header.startswith("sparsedyn/"):
        return public_layer(header[len("sparsedyn/"):])
    first = header.split("/", 1)[0]
    return first if first in layers else None


def check_includes(source_dir, order):
    rank = {layer: k for k, layer in enumerate(order)}
    problems = []
    roots = [(os.path.join(source_dir, "src", layer), layer) for layer in order]
    include_root = os.path.join(source_dir, "include", "sparsedyn")
    for dirpath, _, files in os.walk(include_root):
        for name in files:
            path = os.path.join(dirpath, name)
            layer = public_layer(os.path.relpath(path, include_root))
            if layer:
                roots.append((path, layer))
    for root, layer in roots:
        paths = [root] if os.path.isfile(root) else [
            os.path.join(d, f) for d, _, fs in os.walk(root) for f in fs]
        for path in sorted(paths):
            if not path.endswith((".hpp", ".cpp", ".h")):
                continue
            with open(path, encoding="utf-8") as text:
                for header in INCLUDE.findall(text.read()):
                    used = included_layer(header, rank)
                    if used and rank[used] > rank[layer]:
                        problems.append(f"{os.path.relpath(path, source_dir)} ({layer}) includes "
                                        f'"{header}" ({used}, a later layer)')
    return problems


def symbols(nm, objects):
    """(defined, undefined) global symbol sets of some object files."""
    defined, undefined = set(), set()
    if not objects:
        return defined, undefined
    out = subprocess.run([nm, "-P", "-A"] + objects, check=True, capture_output=True,
                         text=True).stdout
    for line in out.splitlines():
        parts = line.split()
        if len(parts) < 3:
            continue
        name, kind = parts[1], parts[2]
        if kind == "U":
            undefined.add(name)
        elif kind in "TWVDBRCGSu" or kind == "i":
            defined.add(name)
    return defined, undefined


def read_manifest(manifest):
    order, objects = [], {}
    with open(manifest, encoding="utf-8") as text:
        for line in text:
            line = line.strip()
            if not line:
                continue
            layer, _, files = line.partition("=")
            order.append(layer)
            objects[layer] = [f for f in files.split(";") if f]
    return order, objects


def link_violations(order, defined, undefined):
    problems = []
    for k, layer in enumerate(order):
        allowed = set().union(*(defined[l] for l in order[:k + 1]))
        for later in order[k + 1:]:
            used = sorted((undefined[layer] & defined[later]) - allowed)
            for name in used[:10]:
                problems.append(f"layer {layer} links against {later}: {name}")
            if len(used) > 10:
                problems.append(f"layer {layer} links against {later}: {len(used) - 10} more")
    return problems


def main():
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    source_dir, manifest = sys.argv[1], sys.argv[2]
    nm = sys.argv[3] if len(sys.argv) > 3 else "nm"
    order, objects = read_manifest(manifest)
    defined, undefined = {}, {}
    for layer in order:
        defined[layer], undefined[layer] = symbols(nm, objects[layer])
    problems = link_violations(order, defined, undefined)
    # The check checks itself: in reverse order every layer that asserts links against base.
    if not link_violations(order[::-1], defined, undefined):
        problems.append("the link check finds nothing even in reverse order: is nm's output "
                        "understood?")
    problems += check_includes(source_dir, order)
    for problem in problems:
        print(problem)
    print(f"layers {' -> '.join(order)}: {len(problems)} violations")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

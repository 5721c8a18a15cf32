#!/usr/bin/env python3
"""Fails when a #include "..." runs from a folder to one above it.

The layering, lowest first (docs/design.md, "Layout", draws it). A folder may
include its own files and those of any folder on a lower line; folders on one
line may not include each other. tests/ may include anything. A source file
in a folder missing here fails too, so that a new folder is placed on purpose.
Includes resolve as the compiler's do: beside the file, then src/, then the
repository root (the include directories the targets declare).
"""
import os
import re
import sys

LAYERS = [
    ["shaders"],          # the GLSL, and the binding table C++ shares
    ["src/util"],         # file descriptors, mapped arrays, number text
    ["src/tensor"],       # eigen-solver, glyph records, superquadrics
    ["src/view"],         # GL-free camera, frame image, underlay plane
    ["src/ref"],          # the CPU reference renderer
    ["io"],               # fields, readers, writers, format modules
    ["data-synthetic"],   # synthetic fields and their stream writer
    ["src/gl"],           # the GL loader, programs, contexts
    ["src/render"],       # the renderer and its passes
    ["src/app"],          # the commands of the one binary
    ["python", "plugins/paraview"],  # the two other front ends
]
SKIP = {".git", ".ci", "tests", "docs"}
SOURCE = (".h", ".hpp", ".cpp", ".inc", ".cxx")
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)


def folder_of(rel):
    for rank, names in enumerate(LAYERS):
        for name in names:
            if rel == name or rel.startswith(name + "/"):
                return name, rank
    return None, None


def main(root):
    root = os.path.abspath(root)
    errors = []
    for d, dirs, files in os.walk(root):
        reld = os.path.relpath(d, root)
        dirs[:] = sorted(x for x in dirs if x not in SKIP and not x.startswith("build")
                         and not os.path.exists(os.path.join(d, x, "CMakeCache.txt")))
        for f in sorted(files):
            if not f.endswith(SOURCE):
                continue
            rel = os.path.normpath(os.path.join(reld, f))
            src, rank = folder_of(rel)
            if src is None:
                errors.append(f"{rel}: its folder is in no layer (tests/include_order.py)")
                continue
            with open(os.path.join(root, rel), errors="replace") as fh:
                text = fh.read()
            for m in INCLUDE.finditer(text):
                for base in (reld, "src", "."):
                    target = os.path.normpath(os.path.join(base, m.group(1)))
                    if os.path.isfile(os.path.join(root, target)):
                        break
                else:
                    continue  # generated or a dependency's header
                dst, drank = folder_of(target)
                if dst is None or dst == src:
                    continue
                if drank >= rank:
                    line = text.count("\n", 0, m.start()) + 1
                    errors.append(f"{rel}:{line}: includes {target}, but {src} lies below {dst}")
    for e in errors:
        print("include_order: " + e)
    if errors:
        print(f"include_order: {len(errors)} include(s) cross the layering")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))

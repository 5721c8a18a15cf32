#!/usr/bin/env python3
"""Fails when a #include "..." runs from a folder to one above it, or when a
folder's sources are not one CMake target.

The layering, lowest first (docs/design.md, "Source layout", draws it). A
folder may include its own files and those of any folder on a lower line;
folders on one line may not include each other. A folder is one directory:
io/core is not io/modules/vtk. tests/ may include anything. A source file in
a folder missing here fails too, so that a new folder is placed on purpose.
Includes resolve as the compiler's do: beside the file, then src/, then the
repository root (the include directories the targets declare).

One target per folder: a folder that holds compiled sources has a
CMakeLists.txt that declares exactly one target with sources, every compiled
file of the folder is among them, and a CMakeLists.txt names only files of
its own folder (by their plain names). tests/ holds test tiers, many
executables each, and is exempt.

`include_order.py --self-test` checks that both rules catch what they must.
"""
import os
import re
import sys
import tempfile

LAYERS = [
    ["shaders", "shaders/lib"],  # the GLSL, and the binding table C++ shares
    ["src/util"],                # file descriptors, mapped arrays, number text
    ["src/tensor"],              # eigen-solver, glyph records, superquadrics
    ["src/view"],                # GL-free camera, frame image, underlay plane
    ["src/ref"],                 # the CPU reference renderer
    ["io/field"],                # fields in memory, atomic files
    ["io/core"],                 # readers, writers, the reader sandbox, module interfaces
    ["io/modules/vtk", "io/modules/teem", "io/modules/nifti", "io/modules/oiio"],  # format modules
    ["data-synthetic"],          # synthetic fields and their stream writer
    ["src/gl"],                  # the GL loader, programs, the context interface
    ["src/gl/backends/osmesa", "src/gl/backends/egl", "src/gl/backends/glfw"],  # one context each
    ["src/render"],              # the renderer and its passes
    ["src/render/legend"],       # the legend and orientation passes (Dear ImGui)
    ["src/app/scale"],           # the option table, the scale benchmark
    ["src/app", "src/app/gpubench"],  # the commands of the one binary; the GPU benchmark
    ["src/app/main", "python", "plugins/paraview/plugin/Representations"],  # the binary, Python, ParaView
]
SKIP = {".git", ".ci", "tests", "docs"}
SOURCE = (".h", ".hpp", ".cpp", ".inc", ".cxx", ".c")
COMPILED = (".cpp", ".cxx", ".c")
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)
TARGET_CALL = re.compile(r"\b(add_library|add_executable|pybind11_add_module|vtk_module_add_module)\s*\(")


def folder_of(rel):
    folder = os.path.dirname(rel)
    for rank, names in enumerate(LAYERS):
        if folder in names:
            return folder, rank
    return None, None


def walk(root):
    """(folder relative to root, its file names), for the folders checked."""
    for d, dirs, files in os.walk(root):
        dirs[:] = sorted(x for x in dirs if x not in SKIP and not x.startswith("build")
                         and not os.path.exists(os.path.join(d, x, "CMakeCache.txt")))
        yield os.path.normpath(os.path.relpath(d, root)), sorted(files)


def include_errors(root):
    errors = []
    for reld, files in walk(root):
        for f in files:
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
    return errors


def strip_comments(text):
    out, quoted = [], False
    for line in text.splitlines():
        kept = []
        for i, c in enumerate(line):
            if c == '"' and (i == 0 or line[i - 1] != "\\"):
                quoted = not quoted
            if c == "#" and not quoted:
                break
            kept.append(c)
        out.append("".join(kept))
    return "\n".join(out)


def targets_in(cmake_text):
    """(name, [source tokens]) for each target a CMakeLists.txt declares."""
    text = strip_comments(cmake_text)
    found = []
    for m in TARGET_CALL.finditer(text):
        depth, i = 1, m.end()
        while i < len(text) and depth:
            depth += {"(": 1, ")": -1}.get(text[i], 0)
            i += 1
        args = text[m.end():i - 1].split()
        if not args:
            continue
        sources = [a for a in args[1:] if a.endswith(COMPILED)]
        if m.group(1) == "vtk_module_add_module":  # CLASSES X: X.cxx and X.h
            section = None
            for a in args[1:]:
                section = a if a.isupper() else section
                if section == "CLASSES" and a != section:
                    sources.append(a + ".cxx")
        found.append((args[0], sources))
    return found


def target_errors(root):
    errors = []
    for reld, files in walk(root):
        compiled = [f for f in files if f.endswith(COMPILED)]
        cmake = os.path.join(reld, "CMakeLists.txt")
        if "CMakeLists.txt" not in files:
            if compiled:
                errors.append(f"{reld}: holds {compiled[0]} but no CMakeLists.txt (one target per folder)")
            continue
        with open(os.path.join(root, cmake), errors="replace") as fh:
            declared = [(n, s) for n, s in targets_in(fh.read()) if s]
        for name, sources in declared:
            for s in sources:
                if "/" in s or s not in files:
                    errors.append(f"{cmake}: {name} names {s}, which is not a file of {reld} (one target per folder)")
        if len(declared) > 1:
            names = ", ".join(n for n, _ in declared)
            errors.append(f"{cmake}: {len(declared)} targets with sources ({names}): one target per folder")
        listed = {s for _, sources in declared for s in sources}
        for f in compiled:
            if f not in listed:
                errors.append(f"{reld}/{f}: in no target of {cmake}")
    return errors


def check(root):
    root = os.path.abspath(root)
    errors = include_errors(root) + target_errors(root)
    for e in errors:
        print("include_order: " + e)
    if errors:
        print(f"include_order: {len(errors)} problem(s) with the layering or the targets")
        return 1
    return 0


def self_test():
    """Each rule, broken once in a small tree, must be reported."""
    cases = {
        "include upward": ({"src/util/a.h": '#include "render/b.h"\n', "src/render/b.h": ""}, "lies below"),
        "include sideways": ({"io/modules/vtk/a.h": '#include "io/modules/teem/b.h"\n',
                              "io/modules/teem/b.h": ""}, "lies below"),
        "folder without layer": ({"src/other/a.h": ""}, "in no layer"),
        "two targets": ({"src/util/a.cpp": "", "src/util/b.cpp": "",
                         "src/util/CMakeLists.txt": "add_library(x a.cpp)\nadd_library(y STATIC b.cpp)\n"},
                        "2 targets with sources"),
        "source from another folder": ({"src/util/a.cpp": "", "src/view/b.cpp": "",
                                        "src/util/CMakeLists.txt": "add_library(x a.cpp ../view/b.cpp)\n",
                                        "src/view/CMakeLists.txt": "add_library(y b.cpp)\n"},
                                       "not a file of src/util"),
        "source in no target": ({"src/util/a.cpp": "", "src/util/b.cpp": "",
                                 "src/util/CMakeLists.txt": "add_library(x a.cpp)  # b.cpp\n"}, "in no target"),
        "no CMakeLists.txt": ({"src/util/a.cpp": ""}, "no CMakeLists.txt"),
    }
    good = {"src/util/a.h": "", "src/render/b.h": '#include "util/a.h"\n#include "render/c.h"\n',
            "src/render/c.h": "", "src/render/c.cpp": '#include "render/c.h"\n',
            "src/render/CMakeLists.txt": 'add_library(r STATIC c.cpp ${GEN})\nadd_library(i INTERFACE)\n'}
    failures = []
    import contextlib
    import io
    for name, (tree, words) in list(cases.items()) + [("a sound tree", (good, None))]:
        with tempfile.TemporaryDirectory() as d:
            for rel, text in tree.items():
                os.makedirs(os.path.join(d, os.path.dirname(rel)), exist_ok=True)
                with open(os.path.join(d, rel), "w") as fh:
                    fh.write(text)
            out = io.StringIO()
            with contextlib.redirect_stdout(out):
                rc = check(d)
            if (words is None) != (rc == 0) or (words is not None and words not in out.getvalue()):
                failures.append(f"{name}: rc {rc}, said {out.getvalue().strip()!r}")
    for f in failures:
        print("include_order --self-test: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] == "--self-test":
        sys.exit(self_test())
    sys.exit(check(sys.argv[1] if len(sys.argv) > 1 else "."))

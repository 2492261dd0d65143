#!/usr/bin/env python3
"""Checks every #include of airis's own sources against DESIGN.md's layers.

    check_layers.py SOURCE_DIR

Prints `file:line: problem` for each include against an arrow and exits 1; exits 0 when every include
is within its layer. The build runs it on the repository (target `check_layers`, part of `all`);
tests/layers runs it on a tree with deliberate violations to show that they are caught.
"""
import pathlib
import re
import sys

# A folder may include its own files and those of the folders listed for it (DESIGN.md, "Layers").
ENGINE = ["engine/core", "engine/scene", "engine/environment", "engine/physics", "engine/world",
          "engine/render", "engine/mission", "engine/dataset", "engine/mavlink"]
ALLOWED = {
    "engine/core": [],
    "engine/scene": ["engine/core"],
    "engine/environment": ["engine/core"],
    "engine/physics": ["engine/core", "engine/scene", "engine/environment"],
    "engine/world": ["engine/core", "engine/scene", "engine/environment", "engine/physics"],
    "engine/render": ["engine/core", "engine/scene"],
    "engine/mission": ["engine/core", "engine/scene", "engine/environment", "engine/physics",
                       "engine/world"],
    "engine/dataset": ["engine/core", "engine/scene", "engine/environment", "engine/physics",
                       "engine/world", "engine/render"],
    "engine/mavlink": ["engine/core", "engine/scene", "engine/environment", "engine/physics",
                       "engine/world", "engine/mission"],
    "vehicles": ENGINE,
    "sensors": ENGINE,
    "scenes": ENGINE + ["vehicles", "sensors"],
    "tools/jobs": ENGINE + ["scenes"],
    # Benchmark scenarios shared by `airis bench` and tests/bench: they build concrete vehicles and
    # sensors on purpose (to time them alone) and Bullet's own dynamics world (the baseline).
    "tools/bench": ENGINE + ["vehicles", "sensors", "scenes", "tools/jobs"],
    "tools/cli": ENGINE + ["scenes", "tools/jobs", "tools/bench"],
    "tools/python": ENGINE + ["scenes", "tools/jobs"],
}
# Most specific prefix first.
LAYERS = sorted(ALLOWED, key=len, reverse=True)

# Third-party headers that are an implementation detail of one part: only it may include them.
PRIVATE_HEADERS = {
    "yaml-cpp/": ["scenes"],
    "assimp/": ["scenes"],
    "gdal": ["scenes"],  # gdal.h, gdal_priv.h, ...
    "ogr_": ["scenes"],
    "cpl_": ["scenes"],
    "btBulletCollisionCommon.h": ["engine/physics"],
    "btBulletDynamicsCommon.h": ["tools/bench"],
    "BulletCollision/": ["engine/physics"],
    "LinearMath/": ["engine/physics"],
    "embree3/": ["engine/world"],
    "opencv2/": ["engine/render", "engine/dataset"],
    "png.h": ["engine/core"],
    "jpeglib.h": ["engine/core"],
    "libdeflate.h": ["engine/core"],
    "EGL/": ["engine/render"],
    "GLES3/": ["engine/render"],
    "CLI/": ["tools/cli"],
    "pybind11/": ["tools/python"],
}

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')
ROOTS = ["engine", "vehicles", "sensors", "scenes", "tools"]
SUFFIXES = {".h", ".cc", ".in"}


def layer_of(path):
    for layer in LAYERS:
        if path.startswith(layer + "/"):
            return layer
    return None


def check(root):
    problems = []
    files = 0
    for top in ROOTS:
        for file in sorted((root / top).rglob("*")):
            if not file.is_file() or file.suffix not in SUFFIXES:
                continue
            rel = file.relative_to(root).as_posix()
            own = layer_of(rel)
            if own is None:
                problems.append(f"{rel}: in no layer of DESIGN.md (see ALLOWED in cmake/check_layers.py)")
                continue
            files += 1
            for number, line in enumerate(file.read_text(errors="replace").splitlines(), 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                kind, header = m.groups()
                if kind == '"':
                    target = layer_of(header)
                    if target is None or target == own or target in ALLOWED[own]:
                        continue
                    rule = (f"may include only {', '.join(ALLOWED[own])}" if ALLOWED[own]
                            else "may include nothing outside itself")
                    problems.append(f'{rel}:{number}: includes "{header}" ({target}), but {own} '
                                    f"{rule} (DESIGN.md layers)")
                else:
                    for prefix, owners in PRIVATE_HEADERS.items():
                        if header.startswith(prefix) and own not in owners:
                            problems.append(f"{rel}:{number}: includes <{header}>, an implementation "
                                            f"detail that only {', '.join(owners)} may use")
    return files, problems


def main():
    if len(sys.argv) != 2:
        print("usage: check_layers.py SOURCE_DIR", file=sys.stderr)
        return 2
    files, problems = check(pathlib.Path(sys.argv[1]))
    for p in problems:
        print(p, file=sys.stderr)
    if problems:
        print(f"check_layers: {len(problems)} include(s) against DESIGN.md's layers", file=sys.stderr)
        return 1
    print(f"check_layers: {files} files, every include within its layer")
    return 0


if __name__ == "__main__":
    sys.exit(main())

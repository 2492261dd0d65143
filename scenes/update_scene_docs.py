#!/usr/bin/env python3
"""Refreshes the key tables of docs/scene-format.md and docs/vehicles.md (the airframe keys) from `airis scene
schema` (the config structs' Visit lists). Each table in the pages whose first key matches a generated table's
is replaced; prose is kept.
Usage, from the repository root: build/airis scene schema | python3 scenes/update_scene_docs.py"""
import re
import sys

DOCS = ["docs/scene-format.md", "docs/vehicles.md"]
schema = sys.stdin.read()
tables = [m.group(1).rstrip("\n") + "\n"
          for m in re.finditer(r"### `[^`]+`\n\n(\| key \|.*?)(?=\n### |\Z)", schema, re.S)]
docs = {path: open(path).read() for path in DOCS}
TABLE = re.compile(r"\| key \| type \| default \| meaning \|\n\|---\|---\|---\|---\|\n(?:\|.*\n)*")


def first_key(table):
    rows = table.splitlines()
    return rows[2].split("|")[1].strip() if len(rows) > 2 else ""


replaced = 0
for table in tables:
    key = first_key(table)
    for path, doc in docs.items():
        match = next((m for m in TABLE.finditer(doc) if first_key(m.group(0)) == key), None)
        if match:
            docs[path] = doc[:match.start()] + table + doc[match.end():]
            replaced += 1
            break
    else:
        sys.exit(f"no table starting with {key} in {' or '.join(DOCS)}: add the section by hand first")
for path, doc in docs.items():
    open(path, "w").write(doc)
print(f"{', '.join(DOCS)}: {replaced} tables refreshed")

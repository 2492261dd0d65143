#!/usr/bin/env python3
"""Refreshes the key tables of docs/scene-format.md from `airis scene schema` (the config structs' Visit
lists). Each table in the page whose first key matches a generated table's is replaced; prose is kept.
Usage, from the repository root: build/airis scene schema | python3 scenes/update_scene_docs.py"""
import re
import sys

DOC = "docs/scene-format.md"
schema = sys.stdin.read()
tables = [m.group(1).rstrip("\n") + "\n"
          for m in re.finditer(r"### `[^`]+`\n\n(\| key \|.*?)(?=\n### |\Z)", schema, re.S)]
doc = open(DOC).read()
TABLE = re.compile(r"\| key \| type \| default \| meaning \|\n\|---\|---\|---\|---\|\n(?:\|.*\n)*")


def first_key(table):
    rows = table.splitlines()
    return rows[2].split("|")[1].strip() if len(rows) > 2 else ""


replaced = 0
for table in tables:
    key = first_key(table)
    for m in TABLE.finditer(doc):
        if first_key(m.group(0)) == key:
            doc = doc[:m.start()] + table + doc[m.end():]
            replaced += 1
            break
    else:
        sys.exit(f"no table starting with {key} in {DOC}: add the section by hand first")
open(DOC, "w").write(doc)
print(f"{DOC}: {replaced} tables refreshed")

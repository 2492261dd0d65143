#!/usr/bin/env python3
"""Refreshes the column tables of docs/dataset-format.md from `airis dataset schema` (the column lists the
code writes). Each table in the page under a heading naming the same file is replaced; prose is kept.
Usage, from the repository root: build/airis dataset schema | python3 tools/jobs/update_dataset_docs.py"""
import re
import sys

DOC = "docs/dataset-format.md"
schema = sys.stdin.read()
tables = re.findall(r"### (`[^`]+`)\n\n(\| column \|.*?)(?=\n### |\Z)", schema, re.S)
doc = open(DOC).read()
for title, table in tables:
    table = table.rstrip("\n") + "\n"
    pattern = re.compile(r"(#### " + re.escape(title) + r"\n\n)\| column \| type \| meaning \|\n(?:\|.*\n)*")
    doc, n = pattern.subn(lambda m: m.group(1) + table, doc)
    if n != 1:
        sys.exit(f"{DOC}: expected one '#### {title}' section with a column table, found {n}: add it first")
open(DOC, "w").write(doc)
print(f"{DOC}: {len(tables)} tables refreshed")

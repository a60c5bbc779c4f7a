#!/usr/bin/env python3
"""Regenerate src/eval/catalogue.tsv: every name of Cast3M's catalogue.

    scripts/dev/gen-catalogue.py NOTICE_DIR [PROCEDUR_DIR] > src/eval/catalogue.tsv

Reads only facts from each notice's header: the `$$$$ NAME` line, the
kind word of the title line (Operateur, Directive, Procedure, Methode,
Foncteur) with the full name after it, and the first word of its
`Section :` line. Never the notices' text. A name that has a file in
PROCEDUR_DIR is a procedure whatever its header says (a few notices call
their procedure an operator). Notices without a kind (overviews such as
NOUV or MEC1) are not names and are left out.

Columns: kind (operator|procedure), key (what a word is matched on: the
4-letter key of an operator, the full name of a procedure), full name,
section.
"""
import os
import re
import sys

KINDS = [
    (r"op[eé]rat\w*|foncteur|directive", "operator"),
    (r"proc[eé]dure|m[eé]thode", "procedure"),
]


def header(path):
    text = open(path, "rb").read().decode("latin-1")
    lines = text.split("\n")
    m = re.match(r"\$\$\$\$ (\S+)", lines[0])
    if not m:
        return None
    name = m.group(1)
    kind = full = None
    section = ""
    for line in lines[:40]:
        if line.startswith("ANGL="):
            break
        s = re.match(r"Section\s*:\s*(\S+)", line)
        if s and not section:
            section = s.group(1)
            continue
        if kind:
            continue
        x = re.match(r"\$X\s+(\S+)", line)
        if x:
            kind, full = "operator", x.group(1).upper()
            continue
        for pat, k in KINDS:
            t = re.match(r"\s*(?:\d+\.\s*)?(?:L')?(" + pat + r")\s+'?([^\s':]+)", line, re.I)
            if t:
                kind, full = k, t.group(2).upper()
                break
    if kind is None:
        return None, name, None, section
    # The header's full name, when it is a form of the notice's name.
    if not full.startswith(name[:4]) or kind == "procedure":
        full = name
    return kind, name, full, section


def main():
    notices, procs = sys.argv[1], (sys.argv[2] if len(sys.argv) > 2 else None)
    in_library = set()
    if procs:
        in_library = {f[: -len(".procedur")].upper() for f in os.listdir(procs) if f.endswith(".procedur")}
    rows = {}
    for f in sorted(os.listdir(notices)):
        if not f.endswith(".notice"):
            continue
        h = header(os.path.join(notices, f))
        if h is None:
            continue
        kind, name, full, section = h
        if name in in_library:
            kind, full = "procedure", name
        if kind is None:
            continue
        key = name if kind == "procedure" else name[:4]
        rows.setdefault((kind, key), (full, section))
    for (kind, key), (full, section) in sorted(rows.items(), key=lambda r: (r[0][1], r[0][0])):
        print(f"{kind}\t{key}\t{full}\t{section}")


main()

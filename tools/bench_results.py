#!/usr/bin/env python3
"""Assembles verif/bench/RESULTS.md from its parts, so that each mode of tools/bench.sh rewrites its
own part and keeps the others (prints the new text):

    python3 tools/bench_results.py RESULTS.md [--head FILE] [--section NAME=FILE ...]

The file is a head (tools/bench_table.py's tables: everything before the first section) and then
sections, each between markers:

    <!-- bench: begin NAME (written by tools/bench.sh; do not edit) -->
    ...
    <!-- bench: end NAME -->

--head FILE replaces the head; --section NAME=FILE replaces section NAME, or appends it when the
file has none; every other part stays as it is. RESULTS.md may be missing when --head is given."""
import argparse
import os
import re
import sys

BEGIN = "<!-- bench: begin %s (written by tools/bench.sh; do not edit) -->"
END = "<!-- bench: end %s -->"
SECTION = re.compile(r"<!-- bench: begin (\S+) .*?-->\n(.*?)<!-- bench: end \1 -->\n?", re.S)


def split(text):
    """The head and the sections [(name, body)] of a RESULTS.md."""
    first = SECTION.search(text)
    head = text[:first.start()] if first else text
    return head, [(m.group(1), m.group(2)) for m in SECTION.finditer(text)]


def join(head, sections):
    parts = [head.rstrip("\n") + "\n"]
    for name, body in sections:
        parts.append("\n" + BEGIN % name + "\n" + body.rstrip("\n") + "\n" + END % name + "\n")
    return "".join(parts)


def read(path):
    with open(path) as f:
        return f.read()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("results")
    ap.add_argument("--head")
    ap.add_argument("--section", action="append", default=[], metavar="NAME=FILE")
    a = ap.parse_args()
    if not os.path.exists(a.results) and not a.head:
        sys.exit("bench_results: %s does not exist and no --head is given" % a.results)
    head, sections = split(read(a.results)) if os.path.exists(a.results) else ("", [])
    if a.head:
        head = read(a.head)
    for item in a.section:
        name, _, path = item.partition("=")
        if not re.fullmatch(r"[\w-]+", name) or not path:
            sys.exit("bench_results: --section %s is not NAME=FILE" % item)
        body = read(path)
        names = [n for n, _ in sections]
        if name in names:
            sections[names.index(name)] = (name, body)
        else:
            sections.append((name, body))
    sys.stdout.write(join(head, sections))


if __name__ == "__main__":
    main()

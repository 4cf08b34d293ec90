#!/usr/bin/env python3
"""Every HLS top has its hand-off bundle, and hls/README.md says so (ctest hls_export.tops).

    check_tops.py ROOT TOPS     TOPS: the bundles' list (CIG_HLS_TOPS, ';'-separated)
    check_tops.py --self-test   the check finds planted drift

The tops are the `inline ... NAME_top(` and `inline CIG_HLS_TOP(NAME_top)` definitions under
ROOT/hls/. Each must be in TOPS and have its port table (`#define CIG_HLS_PORTS_NAME_top(`, the
signature the synthesis top and the testbench are expanded from: hls/types/top_ports.hpp), its
testbench case (verif/hls_export/tb/NAME_top.hpp) and its golden vectors
(verif/golden/hls/NAME_top.vec), and nothing else may name a bundle. hls/README.md's "`tools/hls_export.sh all OUTDIR` writes all N" must give the count, and
its bundle table (rows "| `NAME` | stage | vectors | ...") must list every top once with the
number of vectors its file holds.
"""
import os
import re
import sys
import tempfile

TOP_DEF = re.compile(r"^\s*inline\b[^;{}()]*?\b(?:CIG_HLS_TOP\(\s*)?([A-Za-z_]\w*_top)\s*[()]", re.MULTILINE)
PORT_TABLE = re.compile(r"^#define CIG_HLS_PORTS_([A-Za-z_]\w*_top)\(", re.MULTILINE)
FIGURE = re.compile(r"`tools/hls_export\.sh all OUTDIR` writes all (\S+?)[ ,.;]")
TABLE_ROW = re.compile(r"^\|\s*`([A-Za-z_]\w*_top)`\s*\|[^|]*\|\s*(\d+)\s*\|", re.MULTILINE)


def hls_definitions(root, pattern):
    found = {}
    for folder, _, files in os.walk(os.path.join(root, "hls")):
        for name in sorted(files):
            if name.endswith(".hpp"):
                path = os.path.join(folder, name)
                with open(path, encoding="utf-8") as f:
                    for top in pattern.findall(f.read()):
                        found.setdefault(top, os.path.relpath(path, root))
    return found


def hls_tops(root):
    return hls_definitions(root, TOP_DEF)


def stems(folder, prefix, suffix):
    if not os.path.isdir(folder):
        return set()
    return {n[len(prefix):-len(suffix)] for n in os.listdir(folder) if n.startswith(prefix) and n.endswith(suffix)}


def vector_count(path):
    with open(path, encoding="utf-8") as f:
        return sum(1 for line in f if line.startswith(">"))


def compare(what, have, want, problems):
    for top in sorted(want - have):
        problems.append(f"{top}: no {what}")
    for top in sorted(have - want):
        problems.append(f"{top}: {what} of a top that hls/ does not define")


def readme_problems(root, tops, problems):
    with open(os.path.join(root, "hls", "README.md"), encoding="utf-8") as f:
        text = f.read()
    figure = FIGURE.search(text)
    if not figure:
        problems.append("hls/README.md: no sentence '`tools/hls_export.sh all OUTDIR` writes all N'")
    elif figure.group(1) != str(len(tops)):
        problems.append(f"hls/README.md: 'writes all {figure.group(1)}', but hls/ has {len(tops)} tops")
    rows = TABLE_ROW.findall(text)
    listed = [top for top, _ in rows]
    for top in sorted({t for t in listed if listed.count(t) > 1}):
        problems.append(f"{top}: listed more than once in hls/README.md's bundle table")
    compare("row in hls/README.md's bundle table", set(listed), set(tops), problems)
    for top, count in rows:
        vec = os.path.join(root, "verif", "golden", "hls", top + ".vec")
        if os.path.isfile(vec) and int(count) != vector_count(vec):
            problems.append(f"{top}: hls/README.md says {count} vectors, {vec} holds {vector_count(vec)}")


def check(root, bundle_list):
    """The problems found, one line each ([] when the tops, the bundles and the README agree)."""
    tops = hls_tops(root)
    problems = []
    if not tops:
        return [f"{root}/hls: no *_top function found"]
    want = set(tops)
    export = os.path.join(root, "verif", "hls_export")
    compare("entry in CIG_HLS_TOPS (verif/hls_export/CMakeLists.txt)", set(bundle_list), want, problems)
    compare("port table CIG_HLS_PORTS_TOP in hls/", set(hls_definitions(root, PORT_TABLE)), want, problems)
    cases = {t + "_top" for t in stems(os.path.join(export, "tb"), "", "_top.hpp")}
    compare("testbench case verif/hls_export/tb/TOP.hpp", cases, want, problems)
    golden = os.path.join(root, "verif", "golden", "hls")
    compare("golden vectors verif/golden/hls/TOP.vec", stems(golden, "", ".vec"), want, problems)
    readme_problems(root, tops, problems)
    return problems


# ---- Self-test: a small tree that agrees, then one planted drift at a time --------------------------
def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def make_tree(root, readme_count="2", table=None):
    write(f"{root}/hls/a/one.hpp", "#define CIG_HLS_PORTS_one_top(PORT, ARRAY, RESULT) RESULT(void)\n"
          "inline CIG_HLS_TOP(one_top) {}\n")
    write(f"{root}/hls/b/two.hpp", "template <int W>\nvoid helper();\n#define CIG_HLS_PORTS_two_top(P, A, R) R(int)\n"
          "inline int\ntwo_top(const int& y) { return y; }\n")
    for top, n in (("one_top", 2), ("two_top", 1)):
        write(f"{root}/verif/hls_export/tb/{top}.hpp", "")
        write(f"{root}/verif/golden/hls/{top}.vec", f"top {top}\n" + "> 1\n< 2\n" * n)
    rows = table if table is not None else "| `one_top` | A | 2 | x |\n| `two_top` | B | 1 | y |\n"
    write(f"{root}/hls/README.md",
          f"`tools/hls_export.sh all OUTDIR` writes all {readme_count}.\n\n| top | stage | vectors | from |\n"
          f"|---|---|---|---|\n{rows}")


def self_test():
    tops = ["one_top", "two_top"]
    plants = [
        ("a top without a bundle", lambda r: write(f"{r}/hls/c/three.hpp", "inline void three_top() {}\n"), tops,
         "three_top: no entry in CIG_HLS_TOPS"),
        ("a bundle of no top", lambda r: None, tops + ["gone_top"], "gone_top: entry in CIG_HLS_TOPS"),
        ("a top without its port table", lambda r: write(f"{r}/hls/b/two.hpp", "inline int two_top(int y) {}\n"),
         tops, "two_top: no port table"),
        ("a port table of no top", lambda r: write(f"{r}/hls/c/t.hpp", "#define CIG_HLS_PORTS_six_top(P, A, R)\n"),
         tops, "six_top: port table CIG_HLS_PORTS_TOP in hls/ of a top"),
        ("a missing testbench case", lambda r: os.remove(f"{r}/verif/hls_export/tb/one_top.hpp"), tops,
         "one_top: no testbench case"),
        ("missing vectors", lambda r: os.remove(f"{r}/verif/golden/hls/one_top.vec"), tops,
         "one_top: no golden vectors"),
        ("a stale figure", lambda r: make_tree(r, readme_count="fifteen"), tops, "'writes all fifteen'"),
        ("no figure", lambda r: write(f"{r}/hls/README.md", "nothing\n"), tops, "no sentence"),
        ("a top missing from the table", lambda r: make_tree(r, table="| `one_top` | A | 2 | x |\n"), tops,
         "two_top: no row in hls/README.md"),
        ("a stale vector count", lambda r: make_tree(r, table="| `one_top` | A | 3 | x |\n| `two_top` | B | 1 | y |\n"),
         tops, "one_top: hls/README.md says 3 vectors"),
    ]
    failures = 0
    with tempfile.TemporaryDirectory() as tmp:
        clean = os.path.join(tmp, "clean")
        make_tree(clean)
        found = check(clean, tops)
        if found:
            print(f"FAIL: the agreeing tree is rejected: {found}")
            failures += 1
        for k, (what, plant, bundle_list, expected) in enumerate(plants):
            root = os.path.join(tmp, f"plant{k}")
            make_tree(root)
            plant(root)
            found = check(root, bundle_list)
            if not any(expected in p for p in found):
                print(f"FAIL: {what}: expected a problem containing {expected!r}, found {found}")
                failures += 1
            else:
                print(f"ok: {what}: {found}")
    return 1 if failures else 0


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    root, bundle_list = argv[1], [t for t in argv[2].split(";") if t]
    problems = check(root, bundle_list)
    for p in problems:
        print(p)
    if problems:
        print(f"{len(problems)} problem(s): every *_top in hls/ needs its bundle and its line in hls/README.md")
        return 1
    print(f"{len(hls_tops(root))} tops, each with its bundle, its vectors and its row in hls/README.md")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/env python3
"""Regenerates the tables of the results pages (docs/results/*.md) from the cig CLI's output.

usage: tools/results.py [--only NAME[,NAME..]] [--long] [--check] [--out DIR] BUILD_DIR

Each page is hand-written prose around blocks this tool owns, one per command:

    <!-- results: begin NAME.BLOCK (written by tools/results.py; edit the prose outside) -->
    ```text
    $ cig COMMAND...
    what the command printed on stdout
    ```
    Printed by cig VERSION (commit C) on DATE in T s.
    <!-- results: end NAME.BLOCK -->

The tool runs BUILD_DIR/bin/cig from the repository root with the command STUDIES names for the
block and replaces what lies between the markers; everything outside them stays as written. It
never creates a page and never writes any other file: a page without the markers of every block
STUDIES gives it is refused (exit 2), and so is a file in --out DIR that is not such a page.

  --only NAME    only these studies (default: all)
  --long         also the blocks that take minutes (word_length.l2048, 4 to 12 min; the four
                 run_time_vs_error sweeps, estimated at 10 min or more); without it they are left as they are
  --check        write nothing: compare each block's output with the page (times, which vary from
                 run to run, are masked) and exit 1 on any difference
  --out DIR      write the regenerated pages into DIR instead of docs/results/

Exit status: 0 done (or, with --check, no difference), 1 a difference or a failed command,
2 bad input (usage, an unknown study, a page or file without the markers).
"""
import datetime
import difflib
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PAGES = "docs/results"
# (pattern, replacement) pairs for what varies from run to run: times
TIME_S = (r"in [0-9.]+ s\b", "in … s")                     # "cig: arch analysis in 4.2 s"
TIME_MS4 = (r"\b[0-9]+\.[0-9]{4}\b", "…")                  # cig cull's time column (4 decimals)
SWEEP_MS = (r"(?m)^((?:\S+=\S+ ?)+?)\s+[0-9.]+", r"\1 …")  # a sweep row's ms/frame, after its options


class Block:
    def __init__(self, name, args, volatile=(), long=False):
        self.name, self.args, self.volatile, self.long = name, args, volatile, long


# study -> (page, blocks). The commands run from the repository root; `volatile` masks what varies
# between runs (times) for --check; `long` blocks run only with --long.
STUDIES = {
    "operation_counts": ("operation_counts.md", [Block("capacity", ["manager", "--capacity"])]),
    "architecture": ("architecture.md", [
        Block("all", ["arch", "--table", "all"], [TIME_S]),
        Block("performance", ["arch", "--table", "performance", "--areas", "1,3,10,30,100,300,1000"], [TIME_S]),
        Block("fifo16", ["arch", "--table", "performance", "--areas", "1,3,10,30,100,300,1000", "--fifo", "16"],
              [TIME_S])]),
    "invparam_timing": ("invparam_timing.md", [Block("seed", ["arch", "--processor", "invparam"])]),
    "culling": ("culling.md", [Block("world", ["cull", "scenes/world.json", "--frames", "0:239"], [TIME_MS4])]),
    "word_length": ("word_length.md", [
        Block("l256", ["wordlength"]),
        Block("l2048", ["wordlength", "--views", "2", "--lattice", "2048", "--bits", "50:68"], long=True)]),
    "run_time_vs_error": ("run_time_vs_error.md", [
        Block("segment", ["sweep", "scenes/airfield.json", "--frames", "0:4", "--engine", "segment", "--vary",
                          "spp=1,4,16,64", "--vary", "interp=plane,seed", "--reference-spp", "64", "--repeat", "2"],
              [SWEEP_MS], long=True),
        Block("quadtree", ["sweep", "scenes/airfield.json", "--frames", "0:4", "--engine", "quadtree", "--vary",
                           "spp=1,4,16,64", "--vary", "arch=9p,7p2t", "--reference-spp", "64", "--repeat", "1"],
              [SWEEP_MS], long=True),
        Block("subpixel", ["sweep", "scenes/airfield.json", "--frames", "0:4", "--engine", "segment", "--vary",
                           "subpixel=1,2,3", "--vary", "spp=4,16", "--reference-spp", "64", "--repeat", "1"],
              [SWEEP_MS], long=True),
        Block("snapped", ["sweep", "scenes/airfield.json", "--frames", "0:4", "--engine", "float", "--snap",
                          "--engine-opt", "visibility=priority", "--vary", "subpixel=2,3,4,5", "--reference-spp",
                          "64", "--repeat", "1"],
              [SWEEP_MS], long=True)]),
}


def rel(path):
    """A path as the messages show it: from the repository root when it lies inside."""
    r = os.path.relpath(os.path.abspath(path), ROOT)
    return path if r.startswith("..") else r


class BadInput(Exception):
    """Exit status 2: the message names the file (or option) and the rule."""


def begin_marker(study, block):
    return f"<!-- results: begin {study}.{block.name} (written by tools/results.py; edit the prose outside) -->"


def end_marker(study, block):
    return f"<!-- results: end {study}.{block.name} -->"


def command_line(block):
    return "$ cig " + " ".join(block.args)


def find_block(text, path, study, block):
    """(start, end) of the lines strictly between the block's markers; BadInput without them."""
    lines = text.split("\n")
    begins = [i for i, l in enumerate(lines) if l == begin_marker(study, block)]
    ends = [i for i, l in enumerate(lines) if l == end_marker(study, block)]
    if len(begins) != 1 or len(ends) != 1 or ends[0] < begins[0]:
        raise BadInput(f"{rel(path)}: markers: needs exactly one '{begin_marker(study, block)}' and, after it, one "
                       f"'{end_marker(study, block)}' (found {len(begins)} and {len(ends)}); this tool "
                       "writes only between its own markers")
    return begins[0] + 1, ends[0]


def block_body(output, block, provenance):
    return ["```text", command_line(block)] + output.rstrip("\n").split("\n") + ["```", provenance]


def marked_output(text, path, study, block):
    """The command line and output recorded in the page's block (between the fences)."""
    start, end = find_block(text, path, study, block)
    body = text.split("\n")[start:end]
    if len(body) < 3 or body[0] != "```text" or "```" not in body[1:]:
        raise BadInput(f"{rel(path)}: block {study}.{block.name}: the markers must enclose a ```text fence")
    close = body.index("```", 1)
    return body[1], "\n".join(body[2:close])


def replace_block(text, path, study, block, body):
    start, end = find_block(text, path, study, block)
    lines = text.split("\n")
    return "\n".join(lines[:start] + body + lines[end:])


def run_cig(cig, block):
    """The command's stdout and its run time; RuntimeError (exit 1) when it fails."""
    t0 = time.monotonic()
    p = subprocess.run([cig] + block.args, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"{command_line(block)} failed with exit status {p.returncode}:\n{p.stderr}")
    return p.stdout, time.monotonic() - t0


def masked(text, block):
    for pattern, replacement in block.volatile:
        text = re.sub(pattern, replacement, text)
    return text


def check_block(cig, text, path, study, block):
    """Differences between the page's block and a fresh run, as a list of lines (empty: none)."""
    recorded_cmd, recorded = marked_output(text, path, study, block)
    if recorded_cmd != command_line(block):
        return [f"{rel(path)}: {study}.{block.name}: the page shows '{recorded_cmd}', the tool runs "
                f"'{command_line(block)}'"]
    output, _ = run_cig(cig, block)
    want, got = masked(recorded, block).split("\n"), masked(output.rstrip("\n"), block).split("\n")
    return list(difflib.unified_diff(want, got, f"{rel(path)} ({study}.{block.name})", command_line(block), lineterm=""))


def provenance(cig, seconds):
    version = subprocess.run([cig, "--version"], stdout=subprocess.PIPE, text=True, check=True).stdout.strip()
    m = re.fullmatch(r"cig (\S+) \(commit (\S+)\)", version)
    name = f"cig {m.group(1)} (commit {m.group(2)})" if m else version
    return f"Printed by {name} on {datetime.date.today().isoformat()} in {seconds:.1f} s (`tools/results.py`)."


def read_page(path):
    if not os.path.isfile(path):
        raise BadInput(f"{rel(path)}: page: no such file; this tool fills pages, it never creates one")
    with open(path, encoding="utf-8") as f:
        return f.read()


def regenerate(cig, study, blocks, src, dst, check):
    """One page: each selected block rerun and replaced (or compared). Returns the differences."""
    text = read_page(src)
    for block in STUDIES[study][1]:
        find_block(text, src, study, block)  # every marker first: refuse before running anything
    if dst != src and os.path.exists(dst):
        other = read_page(dst)  # a file in --out DIR is overwritten only if it is one of our pages
        for block in STUDIES[study][1]:
            find_block(other, dst, study, block)
    diffs = []
    for block in blocks:
        if check:
            diffs += check_block(cig, text, src, study, block)
            continue
        output, seconds = run_cig(cig, block)
        text = replace_block(text, src, study, block, block_body(output, block, provenance(cig, seconds)))
        print(f"results: {study}.{block.name}: {seconds:.1f} s", file=sys.stderr)
    if not check:
        with open(dst, "w", encoding="utf-8") as f:
            f.write(text)
    return diffs


def parse_args(argv):
    opts = {"only": list(STUDIES), "long": False, "check": False, "out": None}
    rest = []
    it = iter(argv)
    for a in it:
        if a in ("--long", "--check"):
            opts[a[2:]] = True
        elif a in ("--only", "--out"):
            value = next(it, None)
            if value is None:
                raise BadInput(f"{a}: needs a value")
            opts[a[2:]] = value.split(",") if a == "--only" else value
        elif a in ("-h", "--help"):
            print(__doc__)
            sys.exit(0)
        elif a.startswith("-"):
            raise BadInput(f"{a}: unknown option (tools/results.py --help)")
        else:
            rest.append(a)
    if len(rest) != 1:
        raise BadInput("usage: tools/results.py [--only NAME[,NAME..]] [--long] [--check] [--out DIR] BUILD_DIR")
    unknown = [n for n in opts["only"] if n not in STUDIES]
    if unknown:
        raise BadInput(f"--only: unknown study {', '.join(unknown)} (studies: {', '.join(STUDIES)})")
    if opts["out"] is not None and not os.path.isdir(opts["out"]):
        raise BadInput(f"{opts['out']}: --out: not a folder")
    cig = os.path.abspath(os.path.join(rest[0], "bin", "cig"))
    if not os.access(cig, os.X_OK):
        raise BadInput(f"{rest[0]}: BUILD_DIR: holds no bin/cig (build it: cmake --build {rest[0]} --target cig)")
    return opts, cig


def main(argv):
    try:
        opts, cig = parse_args(argv)
        diffs = []
        for study in opts["only"]:
            page, blocks = STUDIES[study]
            src = os.path.join(ROOT, PAGES, page)
            dst = os.path.join(opts["out"], page) if opts["out"] else src
            chosen = [b for b in blocks if opts["long"] or not b.long]
            for b in blocks:
                if b not in chosen:
                    print(f"results: {study}.{b.name}: left as it is (takes minutes: --long)", file=sys.stderr)
            diffs += regenerate(cig, study, chosen, src, dst, opts["check"])
    except BadInput as e:
        print(f"tools/results.py: error: {e}", file=sys.stderr)
        return 2
    except RuntimeError as e:
        print(f"tools/results.py: error: {e}", file=sys.stderr)
        return 1
    for line in diffs:
        print(line)
    if opts["check"]:
        print("results: " + ("the pages differ from the commands' output" if diffs else "pages up to date"))
    return 1 if diffs else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

#!/usr/bin/env python3
"""The benchmark's regression guard (tools/bench.sh --check): compares the engine / llvmpipe ratios
of a new bench_llvmpipe run with those committed in verif/bench/RESULTS.md and fails when one has
worsened by more than the tolerance. Writes nothing.

    python3 tools/bench_check.py RESULTS.md NEW.json [--tolerance 0.15]

RESULTS.md's table "CPU time of each engine over llvmpipe's" gives the committed ratio of every
list and engine; the new ratio is the engine's median CPU time over llvmpipe's in NEW.json (tools/
bench_table.py's load_cases). Only the lists and engines of both are compared (a filtered run
compares its few lists). A ratio worse than committed x (1 + tolerance), or an engine that now
refuses a list it drew, is named with both ratios.

Exit status: 0 no ratio worsened beyond the tolerance, 1 one did, 2 bad input (no committed table,
nothing to compare)."""
import argparse
import sys

from bench_table import ENGINES, load_cases

RATIO_TABLE = "## CPU time of each engine over llvmpipe's"


def committed_ratios(path):
    """{(list, engine): ratio or None (refused, missing)} from RESULTS.md's ratio table."""
    with open(path) as f:
        lines = f.read().splitlines()
    start = next((i for i, line in enumerate(lines) if line.startswith(RATIO_TABLE)), None)
    if start is None:
        raise ValueError("%s: no section '%s'" % (path, RATIO_TABLE))
    rows = []
    for line in lines[start + 1:]:
        if line.startswith("#"):
            break
        if line.startswith("|"):
            rows.append([c.strip() for c in line.strip().strip("|").split("|")])
    if len(rows) < 2:
        raise ValueError("%s: the section '%s' holds no table" % (path, RATIO_TABLE))
    header, ratios = rows[0], {}
    for row in rows[2:]:  # after the header and its rule
        if row[0].startswith("**"):
            continue  # the geometric mean
        for engine in ENGINES:
            if engine in header:
                ratios[(row[0], engine)] = number(row[header.index(engine)])
    return ratios


def number(text):
    try:
        return float(text)
    except ValueError:
        return None  # "refused", "-"


def new_ratios(path):
    """{(list, engine): ratio or "refused"} of a bench_llvmpipe run (one-worker cases)."""
    _, lists, cases = load_cases(path)
    ratios = {}
    for name in lists:
        peer = cases.get((name, "llvmpipe"), {}).get("ms")
        for engine in ENGINES:
            case = cases.get((name, engine))
            if case is None or not peer:
                continue
            ratios[(name, engine)] = case["ms"] / peer if case.get("ms") else "refused"
    return ratios


def compare(committed, new, tolerance):
    """The lines of the verdict and whether a ratio worsened beyond the tolerance."""
    worse, compared = [], 0
    for key, now in sorted(new.items()):
        before = committed.get(key)
        if before is None:
            continue  # not in the committed table, or refused there
        compared += 1
        name, engine = key
        if now == "refused":
            worse.append("%s %s: committed ratio %.2f, now refused" % (name, engine, before))
        elif now > before * (1 + tolerance):
            worse.append("%s %s: committed ratio %.2f, new ratio %.2f (+%.0f %%)" %
                         (name, engine, before, now, 100 * (now / before - 1)))
    return worse, compared


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("results", help="the committed verif/bench/RESULTS.md")
    ap.add_argument("json", help="bench_llvmpipe's JSON output of the new run")
    ap.add_argument("--tolerance", type=float, default=0.15, help="the worsening allowed (0.15: 15 %%)")
    ap.add_argument("--label", help="what the messages call RESULTS.md (default: its path)")
    a = ap.parse_args()
    label = a.label or a.results
    try:
        committed = committed_ratios(a.results)
    except (OSError, ValueError) as e:
        print("bench check: %s" % e, file=sys.stderr)
        return 2
    worse, compared = compare(committed, new_ratios(a.json), a.tolerance)
    if compared == 0:
        print("bench check: no list and engine of %s is in %s's ratio table" % (a.json, label), file=sys.stderr)
        return 2
    for line in worse:
        print("bench check: worse by more than %.0f %%: %s" % (100 * a.tolerance, line))
    print("bench check: %d ratio(s) compared with %s, %d worse by more than %.0f %%" %
          (compared, label, len(worse), 100 * a.tolerance))
    return 1 if worse else 0


if __name__ == "__main__":
    sys.exit(main())

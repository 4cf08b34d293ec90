#!/usr/bin/env python3
"""Mutation testing of the RTL and of the architecture model against the co-simulation.

Applies each mutant of the lists (rtl_mutants.tsv, model_mutants.tsv) to a copy of its file in
BUILD/mutation (never to the source tree: other tests read rtl/ while they run), rebuilds only
what the copy feeds (groups.tsv: the file's group names the executable of CMakeLists.txt here and
the co-simulation tests to run), runs those tests and prints a table: mutant, file, category,
caught or not, by which test (the first failing GoogleTest), the first mismatch (the harness's
"first:" line). Exit status 1 if a mutant not listed as equivalent survives or does not build,
2 if the list does not apply (a file missing, an original text not found exactly once: the list
went stale after an edit of the file).

List line (tab-separated; # comments): id, file, original text, mutated text, category,
configurations (6p, 4p2t; stage F: w64n8, w57n16, w64n64; space-separated; - for the model), what
it breaks. Category `equivalent`: a mutant that cannot change what the co-simulation sees; the last column says why.
"""
import argparse
import fcntl
import fnmatch
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))
# The list's configuration names: the quadtree's (N_LOG2 _ TREE_LEVELS) and stage F's (W _ N_PP).
CONFIG_NAMES = {"6p": "6_1", "4p2t": "6_2", "w64n8": "64_8", "w57n16": "57_16", "w64n64": "64_64"}


def read_tsv(path, columns):
    rows = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if not line.strip() or line.lstrip().startswith("#"):
                continue
            cells = line.split("\t")
            if len(cells) != len(columns):
                sys.exit(f"{path}:{number}: {len(cells)} tab-separated columns, expected {len(columns)} "
                         f"({', '.join(columns)})")
            rows.append(dict(zip(columns, cells), where=f"{os.path.relpath(path, SOURCE)}:{number}"))
    return rows


def group_of(groups, file):
    for g in groups:
        if fnmatch.fnmatch(file, g["pattern"]):
            return g
    return None


def validate(mutants, groups):
    """Every mutant applies: its file exists and its original text occurs exactly once."""
    errors = []
    for m in mutants:
        path = os.path.join(SOURCE, m["file"])
        if group_of(groups, m["file"]) is None:
            errors.append(f"{m['where']}: {m['id']}: no group of groups.tsv takes {m['file']}")
        elif not os.path.isfile(path):
            errors.append(f"{m['where']}: {m['id']}: {m['file']} does not exist")
        else:
            n = open(path).read().count(m["original"])
            if n != 1:
                errors.append(f"{m['where']}: {m['id']}: the original text occurs {n} times in {m['file']} "
                              f"(must be once): {m['original']!r}")
        if m["original"] == m["mutated"]:
            errors.append(f"{m['where']}: {m['id']}: the mutated text is the original")
        for c in m["configs"].split():
            if c != "-" and c not in CONFIG_NAMES:
                errors.append(f"{m['where']}: {m['id']}: unknown configuration {c} ({', '.join(CONFIG_NAMES)}, -)")
    return errors


def copy_pristine(groups, work):
    """The mutant directory's copies of every group's files, as in the source tree."""
    for g in groups:
        for path in sorted(os.listdir(os.path.join(SOURCE, os.path.dirname(g["pattern"])))):
            rel = os.path.join(os.path.dirname(g["pattern"]), path)
            if fnmatch.fnmatch(rel, g["pattern"]):
                dest = os.path.join(work, g["copy_to"], os.path.basename(rel))
                os.makedirs(os.path.dirname(dest), exist_ok=True)
                text = open(os.path.join(SOURCE, rel)).read()
                if not os.path.exists(dest) or open(dest).read() != text:
                    with open(dest, "w") as f:
                        f.write(text)


def apply(m, g, work):
    dest = os.path.join(work, g["copy_to"], os.path.basename(m["file"]))
    text = open(os.path.join(SOURCE, m["file"])).read()
    with open(dest, "w") as f:
        f.write(text.replace(m["original"], m["mutated"], 1))
    if m["configs"] != "-":
        configs = " ".join(CONFIG_NAMES[c] for c in m["configs"].split())
        # The group's configs file sits next to its copy's directory (rtl -> configs, ip/rtl -> ip/configs).
        path = os.path.join(work, os.path.dirname(g["copy_to"]), "configs")
        if not os.path.exists(path) or open(path).read().strip() != configs:
            with open(path, "w") as f:
                f.write(configs + "\n")


def first_failure(log):
    """The first failing test and the first mismatch line of a GoogleTest log."""
    test, mismatch = "", ""
    lines = log.splitlines()
    for line in lines:
        m = re.match(r"\[  FAILED  \] (\S+) \(", line)
        if m:
            test = m.group(1)
            break
    for line in lines:
        if line.startswith("first: ") and len(line) > 7:
            mismatch = line[7:]
            break
    if not mismatch:
        for k, line in enumerate(lines):
            if line.endswith(": Failure") and k + 1 < len(lines):
                mismatch = " ".join(l.strip() for l in lines[k + 1:k + 4])
                break
    return test, mismatch


def run_mutant(m, g, args, work, logs):
    apply(m, g, work)
    t0 = time.time()
    build = subprocess.run(["cmake", "--build", args.build, "--target", g["target"], "-j", str(args.jobs)],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    build_s = time.time() - t0
    with open(os.path.join(logs, m["id"] + ".build.log"), "w") as f:
        f.write(build.stdout)
    if build.returncode != 0:
        return {"status": "BUILD FAILED", "test": "", "mismatch": f"see {logs}/{m['id']}.build.log",
                "build_s": build_s, "test_s": 0.0}
    exe = os.path.join(args.build, "bin", g["target"])
    if not os.path.exists(exe):
        exe = subprocess.run(["find", args.build, "-name", g["target"], "-type", "f"], stdout=subprocess.PIPE,
                             text=True).stdout.split()[0]
    t0 = time.time()
    try:
        run = subprocess.run([exe, "--gtest_filter=" + g["filter"], "--gtest_fail_fast"], stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True, timeout=args.timeout, cwd=args.build)
        out, code = run.stdout, run.returncode
    except subprocess.TimeoutExpired as e:
        out = e.stdout.decode() if isinstance(e.stdout, bytes) else (e.stdout or "")
        code = "timeout"
    test_s = time.time() - t0
    with open(os.path.join(logs, m["id"] + ".test.log"), "w") as f:
        f.write(out)
    if code == "timeout":
        test, mismatch = first_failure(out)
        return {"status": "caught", "test": test or "(timeout)",
                "mismatch": mismatch or f"no end within {args.timeout} s", "build_s": build_s, "test_s": test_s}
    if code == 0:
        return {"status": "NOT CAUGHT", "test": "", "mismatch": "", "build_s": build_s, "test_s": test_s}
    test, mismatch = first_failure(out)
    return {"status": "caught", "test": test or f"(exit {code})", "mismatch": mismatch, "build_s": build_s,
            "test_s": test_s}


def verdict(m, r):
    if m["category"] == "equivalent":
        return "equivalent, survives" if r["status"] == "NOT CAUGHT" else r["status"] + " (listed equivalent)"
    return r["status"]


def print_table(rows, markdown, width):
    head = ["mutant", "file", "category", "result", "by test", "s", "first mismatch"]
    body = []
    for m, r in rows:
        mismatch = r["mismatch"] if m["category"] != "equivalent" or r["status"] != "NOT CAUGHT" else m["breaks"]
        if len(mismatch) > width:
            mismatch = mismatch[:width - 3] + "..."
        body.append([m["id"], os.path.basename(m["file"]), m["category"], verdict(m, r), r["test"],
                     f"{r['build_s'] + r['test_s']:.0f}", mismatch])
    if markdown:
        print("| " + " | ".join(head) + " |")
        print("|" + "---|" * len(head))
        for b in body:
            print("| " + " | ".join(c.replace("|", "\\|") if k < 6 else "`" + c.replace("`", "'") + "`" if c else ""
                                    for k, c in enumerate(b)) + " |")
        return
    widths = [max(len(h), *(len(b[k]) for b in body)) if body else len(h) for k, h in enumerate(head)]
    print("  ".join(h.ljust(w) for h, w in zip(head, widths)))
    for b in body:
        print("  ".join(c.ljust(w) for c, w in zip(b, widths)))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(SOURCE, "build"), help="the build directory (CIG_WITH_RTL=ON)")
    ap.add_argument("--list", action="append", help="mutant lists (default: rtl_mutants.tsv, model_mutants.tsv)")
    ap.add_argument("--only", help="comma-separated mutant ids")
    ap.add_argument("--check", action="store_true", help="only check that every mutant applies")
    ap.add_argument("--markdown", action="store_true", help="the table as Markdown (rtl/quadtree/README.md, rtl/invparam/README.md)")
    ap.add_argument("--timeout", type=int, default=600, help="seconds per mutant's test run (a hang is caught)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--width", type=int, default=110, help="first mismatch: characters shown")
    args = ap.parse_args()
    args.build = os.path.abspath(args.build)
    lists = args.list or [os.path.join(HERE, "rtl_mutants.tsv"), os.path.join(HERE, "model_mutants.tsv")]
    mutants = []
    for path in lists:
        mutants += read_tsv(path, ["id", "file", "original", "mutated", "category", "configs", "breaks"])
    groups = read_tsv(os.path.join(HERE, "groups.tsv"), ["pattern", "copy_to", "target", "filter"])
    ids = [m["id"] for m in mutants]
    dup = sorted({i for i in ids if ids.count(i) > 1})
    if dup:
        sys.exit(f"mutate.py: duplicate mutant ids: {', '.join(dup)}")
    if args.only:
        wanted = args.only.split(",")
        unknown = [i for i in wanted if i not in ids]
        if unknown:
            sys.exit(f"mutate.py: no mutant {', '.join(unknown)}")
        mutants = [m for m in mutants if m["id"] in wanted]
    errors = validate(mutants, groups)
    if errors:
        print("\n".join(errors), file=sys.stderr)
        sys.exit(2)
    if args.check:
        print(f"mutate.py: {len(mutants)} mutants apply")
        return 0
    work = os.path.join(args.build, "mutation")
    if not os.path.isdir(work):
        sys.exit(f"mutate.py: {work} missing: configure {args.build} with -DCIG_WITH_RTL=ON -DCIG_BUILD_TESTS=ON")
    logs = os.path.join(work, "logs")
    os.makedirs(logs, exist_ok=True)
    lock = open(os.path.join(work, "lock"), "w")
    fcntl.flock(lock, fcntl.LOCK_EX)  # one run at a time per build directory (the ctest, a full run)
    rows = []
    t_all = time.time()
    try:
        for m in mutants:
            copy_pristine(groups, work)
            g = group_of(groups, m["file"])
            print(f"mutate.py: {m['id']} ({m['file']}, {m['category']}) ...", flush=True)
            r = run_mutant(m, g, args, work, logs)
            print(f"mutate.py: {m['id']}: {verdict(m, r)} {r['test']} ({r['build_s']:.0f} s build, "
                  f"{r['test_s']:.0f} s tests) {r['mismatch'][:args.width]}", flush=True)
            rows.append((m, r))
    finally:
        copy_pristine(groups, work)
    print()
    print_table(rows, args.markdown, args.width)
    bad = [m["id"] for m, r in rows if m["category"] != "equivalent" and r["status"] != "caught"]
    print(f"\nmutate.py: {len(rows)} mutants, {sum(r['status'] == 'caught' for _, r in rows)} caught, "
          f"{sum(m['category'] == 'equivalent' for m, _ in rows)} listed equivalent, "
          f"{len(bad)} not caught or not built{': ' + ', '.join(bad) if bad else ''}; "
          f"{time.time() - t_all:.0f} s")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""CLI habits every cig command keeps (issue 28): `cig --version` names the version and the
commit; a bare `cig` prints its usage and exits 2; every report.json leads with its provenance
(version, commit, the full command line, the date).

usage: check_cli_habits.py CIG CASE WORKDIR   (CASE: version, bare, report)"""
import json
import os
import re
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from cli_check import fail, run  # noqa: E402


def case_version(cig, work):
    r = run([cig, "--version"])
    if r.returncode != 0:
        fail(f"cig --version exited {r.returncode}: {r.stderr}")
    if not re.fullmatch(r"cig \d+\.\d+\.\d+ \(commit ([0-9a-f]{40}(-dirty)?|unknown)\)\n", r.stdout):
        fail(f"cig --version printed {r.stdout!r}")
    print(r.stdout.strip())


def case_bare(cig, work):
    r = run([cig])
    if r.returncode != 2:
        fail(f"a bare cig exited {r.returncode}, expected 2")
    for word in ("render", "compare", "cosim", "--version"):
        if word not in r.stderr:
            fail(f"a bare cig's usage does not mention {word}: {r.stderr}")
    if "no command given" not in r.stderr:
        fail("a bare cig does not say that no command was given")
    print(r.stderr.splitlines()[-1])


def case_report(cig, work, source):
    os.makedirs(work, exist_ok=True)
    report = os.path.join(work, "report.json")
    if os.path.exists(report):
        os.remove(report)
    polys = os.path.join(source, "scenes", "small", "overlap.polys.json")
    cmd = [cig, "raster", polys, "--engine", "float", "--out", os.path.join(work, "image.png"), "--report", report]
    r = run(cmd)
    if r.returncode != 0:
        fail(f"{' '.join(cmd)} exited {r.returncode}: {r.stderr}")
    with open(report) as f:
        rep = json.load(f)
    if list(rep)[0] != "provenance":
        fail(f"the report does not lead with its provenance: {list(rep)[:3]}")
    p = rep["provenance"]
    for key in ("version", "commit", "command_line", "date"):
        if not p.get(key):
            fail(f"provenance has no {key}: {p}")
    if p["command_line"] != " ".join(cmd):
        fail(f"provenance command line {p['command_line']!r} is not {' '.join(cmd)!r}")
    version = run([cig, "--version"]).stdout
    if p["version"] not in version or p["commit"] not in version:
        fail(f"provenance {p} disagrees with cig --version {version!r}")
    print("provenance:", json.dumps(p))


def main():
    cig, case, work = sys.argv[1], sys.argv[2], sys.argv[3]
    source = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    if case == "version":
        case_version(cig, work)
    elif case == "bare":
        case_bare(cig, work)
    elif case == "report":
        case_report(cig, work, source)
    else:
        fail("unknown case " + case)


if __name__ == "__main__":
    main()

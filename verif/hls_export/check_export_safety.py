#!/usr/bin/env python3
"""tools/hls_export.sh never deletes or overwrites what it did not write (issue 28). One case per
ctest hls_export.safety.CASE; each refusal must exit 2, name the folder and the rule, and leave the
user's file in place with its content:

  help        --help and -h print the usage and exit 0; a wrong argument count exits 2
  not_empty   a non-empty folder without the marker .cig-hls-bundle
  repo_root   the repository root, directly and through a symlink
  repo_parent a parent of the repository root (REPO/.. and /)
  home        $HOME (a temporary folder holding a user file) and a parent of it
  file        an existing regular file as OUTDIR
  twice       two exports into one folder keep a user file added in between, remove a file the
              marker lists that the new bundle lacks, and refuse a file the marker does not list

  all         every top into KEEP (left there: the hls_export.bundle.* tests build from it), then
              a copy with a user's file and a marker that no longer lists one file: refused, unchanged

usage: check_export_safety.py EXPORT REPO WORK CASE [KEEP]   (WORK: a scratch folder outside REPO)"""
import os
import shutil
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
from cli_check import fail, run, snapshot  # noqa: E402

TOP = "overload_threshold_top"  # the smallest bundle
BUNDLE_NAMES = [".cig-hls-bundle", "README.md", "run_vitis.tcl", "run_catapult.tcl", "hls", "src", "tb", "vectors"]


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def read(path):
    with open(path, "rb") as f:
        return f.read()


def expect_refused(r, *phrases):
    if r.returncode != 2:
        fail(f"exit {r.returncode}, expected 2\nstdout: {r.stdout}\nstderr: {r.stderr}")
    for p in phrases:
        if p not in r.stderr:
            fail(f"stderr lacks {p!r}: {r.stderr}")
    print("refused:", r.stderr.strip())


def expect_untouched(folder, before, files):
    """No bundle file appeared in `folder` that was not there `before`; each user file kept."""
    for name in BUNDLE_NAMES:
        if name not in before and os.path.lexists(os.path.join(folder, name)):
            fail(f"{folder}/{name} was written")
    for path, content in files.items():
        if not os.path.exists(path) or read(path) != content:
            fail(f"{path} was changed or removed")


def case_help(export, repo, work):
    for flag in ("--help", "-h"):
        r = run([export, flag])
        if r.returncode != 0 or not r.stdout.startswith("usage: tools/hls_export.sh TOP|all OUTDIR"):
            fail(f"{flag}: exit {r.returncode}, stdout {r.stdout!r}")
    for args in ([], [TOP], [TOP, work, "extra"]):
        r = run([export] + args)
        if r.returncode != 2 or not r.stderr.startswith("usage:") or r.stdout:
            fail(f"{args}: exit {r.returncode}, stderr {r.stderr!r}, expected the usage on stderr and 2")
    print("help: exit 0; wrong argument counts: usage on stderr, exit 2")


def case_not_empty(export, repo, work):
    user = os.path.join(work, "user")
    notes = os.path.join(user, "notes.txt")
    write(notes, "my notes\n")
    expect_refused(run([export, TOP, user]), user, "is not empty and holds no .cig-hls-bundle marker",
                   "name a new or empty folder")
    expect_untouched(user, ["notes.txt"], {notes: b"my notes\n"})
    if sorted(os.listdir(user)) != ["notes.txt"]:
        fail(f"{user} holds {os.listdir(user)}")


def case_repo_root(export, repo, work):
    before = os.listdir(repo)
    readme = {os.path.join(repo, "README.md"): read(os.path.join(repo, "README.md"))}
    expect_refused(run([export, TOP, repo]), repo + ": is the source tree's root")
    link = os.path.join(work, "link")
    os.symlink(repo, link)
    expect_refused(run([export, TOP, link]), f"{link} (= {repo}): is the source tree's root")
    expect_refused(run([export, "all", link]), f"{link} (= {repo}): is the source tree's root")
    expect_untouched(repo, before, readme)


def case_repo_parent(export, repo, work):
    parent = os.path.dirname(repo)
    before = os.listdir(parent)
    readme = {os.path.join(repo, "README.md"): read(os.path.join(repo, "README.md"))}
    expect_refused(run([export, TOP, repo + "/.."]), f"{repo}/.. (= {parent}): is a parent of the source tree {repo}")
    expect_refused(run([export, "all", "/"]), "/: is a parent of the source tree")
    expect_untouched(parent, before, readme)


def case_home(export, repo, work):
    home = os.path.join(work, "home")
    notes = os.path.join(home, "notes.txt")
    write(notes, "home notes\n")
    env = dict(os.environ, HOME=home)
    expect_refused(run([export, TOP, home], env=env), home + ": is your home folder")
    expect_refused(run([export, TOP, work], env=env), f"{work}: is a parent of your home folder {home}")
    expect_untouched(home, ["notes.txt"], {notes: b"home notes\n"})
    expect_untouched(work, ["home"], {})


def case_file(export, repo, work):
    path = os.path.join(work, "notes.txt")
    write(path, "a file\n")
    expect_refused(run([export, TOP, path]), path + ": exists and is not a folder")
    expect_untouched(work, ["notes.txt"], {path: b"a file\n"})


def manifest(folder):
    with open(os.path.join(folder, ".cig-hls-bundle")) as f:
        lines = f.read().splitlines()
    if lines[0] != "cig-hls-bundle 1" or f"top {TOP}" not in lines:
        fail(f"marker header {lines[:3]}")
    return sorted(line[5:] for line in lines if line.startswith("file "))


def files_in(folder):
    found = []
    for root, _, names in os.walk(folder):
        found += [os.path.relpath(os.path.join(root, n), folder) for n in names]
    return sorted(found)


def case_twice(export, repo, work):
    out = os.path.join(work, "bundle")
    r = run([export, TOP, out])
    if r.returncode != 0:
        fail(f"first export: exit {r.returncode}: {r.stderr}")
    first = manifest(out)
    if first != [f for f in files_in(out) if f != ".cig-hls-bundle"] or "README.md" not in first:
        fail(f"the manifest {first} is not the bundle's files {files_in(out)}")
    user = {os.path.join(out, "notes.txt"): b"mine\n", os.path.join(out, "hls", "notes.txt"): b"mine too\n"}
    for path, content in user.items():
        write(path, content.decode())
    # A file an earlier export wrote (listed in the marker) that the new bundle lacks goes.
    stale = os.path.join(out, "hls", "old", "stale.hpp")
    write(stale, "// stale\n")
    with open(os.path.join(out, ".cig-hls-bundle"), "a") as f:
        f.write("file hls/old/stale.hpp\n")
    r = run([export, TOP, out])
    if r.returncode != 0:
        fail(f"second export: exit {r.returncode}: {r.stderr}")
    expect_untouched(out, BUNDLE_NAMES, user)
    if os.path.lexists(stale) or os.path.lexists(os.path.dirname(stale)):
        fail("the stale file the marker listed (or its emptied folder) is still there")
    if manifest(out) != first:
        fail(f"second manifest {manifest(out)} differs from the first {first}")
    # A file of the new bundle that the marker does not list is not overwritten.
    marker = os.path.join(out, ".cig-hls-bundle")
    with open(marker) as f:
        text = f.read()
    with open(marker, "w") as f:
        f.write(text.replace("file README.md\n", ""))
    readme = os.path.join(out, "README.md")
    write(readme, "the user's README\n")
    expect_refused(run([export, TOP, out]), readme + ": exists and is not part of what this script wrote")
    expect_untouched(out, BUNDLE_NAMES, dict(user, **{readme: b"the user's README\n"}))
    print("twice: user files kept, the stale file removed, an unlisted file refused")


def case_all(export, repo, work, keep):
    # The export of every top stays in KEEP for the hls_export.bundle.* tests (their fixture); the
    # refused second run works on a copy.
    shutil.rmtree(keep, ignore_errors=True)  # the fixture's own folder, written by this test
    r = run([export, "all", keep])
    if r.returncode != 0:
        fail(f"all: exit {r.returncode}: {r.stderr}")
    out = os.path.join(work, "bundles")
    shutil.copytree(keep, out, symlinks=True)
    with open(os.path.join(out, ".cig-hls-bundle")) as f:
        outer = f.read().splitlines()
    tops = sorted(line[7:] for line in outer if line.startswith("bundle "))
    if outer[:2] != ["cig-hls-bundle 1", "top all"] or TOP not in tops or any(line.startswith("file ") for line in outer):
        fail(f"OUTDIR's marker: {outer}")
    for t in tops:
        with open(os.path.join(out, t, ".cig-hls-bundle")) as f:
            if f"top {t}" not in f.read().splitlines():
                fail(f"{t}'s marker does not name it")
    write(os.path.join(out, "notes.txt"), "mine\n")
    marker = os.path.join(out, TOP, ".cig-hls-bundle")
    with open(marker) as f:
        text = f.read()
    with open(marker, "w") as f:
        f.write(text.replace("file README.md\n", ""))
    before = snapshot(out)
    expect_refused(run([export, "all", out]), os.path.join(out, TOP, "README.md") + ": exists and is not part of")
    if snapshot(out) != before or any(n.startswith(".cig-incoming") for n in os.listdir(out)):
        fail("the refused run changed OUTDIR")
    print(f"all: {len(tops)} bundles, each marked; a refused second run changed nothing")


def main():
    export, repo, work, case = sys.argv[1:5]
    keep = os.path.realpath(sys.argv[5]) if len(sys.argv) > 5 else os.path.join(os.path.realpath(work), "all")
    repo, work = os.path.realpath(repo), os.path.realpath(work)
    if work == repo or work.startswith(repo + os.sep):
        fail(f"WORK {work} must lie outside the repository {repo}")
    shutil.rmtree(work, ignore_errors=True)  # this test's own scratch folder
    os.makedirs(work)
    cases = {"help": case_help, "not_empty": case_not_empty, "repo_root": case_repo_root,
             "repo_parent": case_repo_parent, "home": case_home, "file": case_file, "twice": case_twice,
             "all": None}
    if case not in cases:
        fail("unknown case " + case)
    if case == "all":
        case_all(export, repo, work, keep)
    else:
        cases[case](export, repo, work)
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()

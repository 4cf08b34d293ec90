#!/usr/bin/env python3
"""The tools/ scripts that write into a folder the user names never overwrite what they did not
write (issue 28): each case runs one script on a scratch folder holding a user's file and asserts
exit status 2, the message, and that the folder is unchanged afterwards.

  configure_not_build   tools/configure.sh on a non-empty folder without CMakeCache.txt
  configure_file        tools/configure.sh on an existing file
  synth_user_file       tools/synth_report.sh on a folder holding a report.txt it did not write
  synth_home            tools/synth_report.sh on $HOME (a temporary folder)
  fetch_user_folder     tools/fetch_flightgear.sh with CIG_FLIGHTGEAR_CACHE on a folder it did not make

usage: check_tool_folders.py SOURCE WORK CASE   (WORK: a scratch folder outside SOURCE)"""
import os
import shutil
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from cli_check import fail, snapshot  # noqa: E402


def main():
    source, work, case = os.path.realpath(sys.argv[1]), os.path.realpath(sys.argv[2]), sys.argv[3]
    shutil.rmtree(work, ignore_errors=True)  # this test's own scratch folder
    user = os.path.join(work, "user")
    os.makedirs(user)
    for name in ("Makefile", "report.txt"):
        with open(os.path.join(user, name), "w") as f:
            f.write("the user's " + name + "\n")
    env = dict(os.environ)
    configure, synth = os.path.join(source, "tools", "configure.sh"), os.path.join(source, "tools", "synth_report.sh")
    if case == "configure_not_build":
        cmd, message = [configure, user], f"{user}: is not empty and holds no CMakeCache.txt"
    elif case == "configure_file":
        cmd, message = [configure, os.path.join(user, "Makefile")], "Makefile: exists and is not a folder"
    elif case == "synth_user_file":
        cmd, message = [synth, user, "pe_mid"], f"{user}/report.txt: exists and is not listed in"
    elif case == "synth_home":
        env["HOME"] = user
        cmd, message = [synth, user, "pe_mid"], f"{user}: is your home folder"
    elif case == "fetch_user_folder":
        env["CIG_FLIGHTGEAR_CACHE"] = user
        cmd, message = [os.path.join(source, "tools", "fetch_flightgear.sh")], f"{user}: not empty and not made by this script"
    else:
        fail("unknown case " + case)
    before = snapshot(work)
    r = subprocess.run(cmd, cwd=source, env=env, capture_output=True, text=True)
    if r.returncode != 2 or message not in r.stderr:
        fail(f"{' '.join(cmd)}: exit {r.returncode} (expected 2), stderr {r.stderr!r} (expected {message!r})")
    if snapshot(work) != before:
        fail(f"{' '.join(cmd)} changed {work}")
    print(r.stderr.strip())
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()

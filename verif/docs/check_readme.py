#!/usr/bin/env python3
"""The README as a user's map that cannot drift (issue 28).

  check_readme.py lines    SOURCE                  README.md has at most 250 lines
  check_readme.py links    SOURCE                  every relative link of every tracked *.md resolves
  check_readme.py figures  SOURCE BIN BUILD CONFIG the figures the README quotes: the ctest count
                                                   (CONFIG "default": tools/test.sh's build), the
                                                   engines (count and table) and the commands
  check_readme.py recipes  SOURCE BIN WORK         runs every recipe (a ```sh block followed by a
                                                   ```text block) and finds each line of the text
                                                   block, in order, in what it printed; a token
                                                   holding "…" stands for any token (times);
                                                   then every <!-- check: FILE /json/pointer = V -->
                                                   of the prose against the report the recipe wrote

Exit 0 when everything holds, 1 with one line per difference."""
import json
import os
import re
import shutil
import subprocess
import sys

NUMBER_WORDS = {"five": 5, "six": 6, "seven": 7, "eight": 8, "nine": 9, "ten": 10}
failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL: " + msg)


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def check_lines(source):
    n = read(os.path.join(source, "README.md")).count("\n")
    print(f"README.md: {n} lines")
    if n > 250:
        fail(f"README.md has {n} lines; a user's map holds at most 250")


def anchors(text):
    out = set()
    for h in re.findall(r"^#+ (.*)$", text, re.M):
        a = re.sub(r"[^\w\- ]", "", h.strip().lower()).replace(" ", "-")
        out.add(a)
    return out


def check_links(source):
    files = subprocess.run(["git", "-C", source, "ls-files", "*.md"], capture_output=True, text=True).stdout.split()
    if not files:  # not a git checkout: every *.md outside build folders
        for root, dirs, names in os.walk(source):
            dirs[:] = [d for d in dirs if not d.startswith(("build", ".git"))]
            files += [os.path.relpath(os.path.join(root, n), source) for n in names if n.endswith(".md")]
    count = 0
    for rel in files:
        path = os.path.join(source, rel)
        if not os.path.exists(path):
            continue
        text = read(path)
        text_no_code = re.sub(r"```.*?```", "", text, flags=re.S)
        for target in re.findall(r"\]\(([^)\s]+)\)", text_no_code):
            if target.startswith(("http://", "https://", "mailto:")):
                continue
            count += 1
            file_part, _, anchor = target.partition("#")
            dest = os.path.normpath(os.path.join(os.path.dirname(path), file_part)) if file_part else path
            if not os.path.exists(dest):
                fail(f"{rel}: link ({target}) names {os.path.relpath(dest, source)}, which does not exist")
            elif anchor and dest.endswith(".md") and anchor not in anchors(read(dest)):
                fail(f"{rel}: link ({target}): no heading #{anchor} in {os.path.relpath(dest, source)}")
    print(f"{len(files)} markdown files, {count} relative links checked")


def cig_lines(bin_dir, *args):
    r = subprocess.run([os.path.join(bin_dir, "cig"), *args], capture_output=True, text=True)
    return r.stdout + r.stderr


def check_figures(source, bin_dir, build, config):
    readme = read(os.path.join(source, "README.md"))
    # The ctest count of tools/test.sh's build.
    m = re.search(r"runs (\d[\d,]*) ctests", readme)
    if not m:
        fail("README.md quotes no ctest count ('runs N ctests')")
    elif config != "default":
        print(f"ctest count: README says {m.group(1)}; not checked in the '{config}' configuration")
    else:
        listed = subprocess.run(["ctest", "--test-dir", build, "-N"], capture_output=True, text=True).stdout
        total = re.search(r"Total Tests: (\d+)", listed)
        quoted = int(m.group(1).replace(",", ""))
        print(f"ctest count: README says {quoted}, ctest -N lists {total.group(1) if total else '?'}")
        if not total or int(total.group(1)) != quoted:
            fail(f"README.md says tools/test.sh runs {quoted} ctests; ctest -N lists {total.group(1) if total else 'none'}")
        for other in re.findall(r"(\d[\d,]*) ctests", readme):
            if int(other.replace(",", "")) != quoted:
                fail(f"README.md quotes {other} ctests in one place and {quoted} in another")
    # The engines: the count in words, and the table, against the engines cig knows.
    listed = subprocess.run([os.path.join(bin_dir, "cig"), "engines", "--json"], capture_output=True, text=True)
    engines = [e["name"] for e in json.loads(listed.stdout)["engines"]] if listed.returncode == 0 else []
    table = re.findall(r"^\| `([a-z0-9-]+)` \|", readme.split("## Engines", 1)[-1].split("\n## ", 1)[0], re.M)
    print(f"engines: cig has {engines}; the README's table {table}")
    if sorted(table) != sorted(engines) or not engines:
        fail(f"README.md's engine table {table} is not cig's engines {engines}")
    for word, n in NUMBER_WORDS.items():
        if re.search(rf"\b{word} raster engines\b", readme) and n != len(engines):
            fail(f"README.md says {word} raster engines; cig has {len(engines)}")
    # The commands: every one cig lists, and none it does not.
    bare = cig_lines(bin_dir)
    commands = re.findall(r"^  ([a-z]+) {2,}", bare.split("Subcommands:", 1)[-1], re.M)
    section = readme.split("## Commands", 1)[-1].split("\n## ", 1)[0]
    named = [c for row in re.findall(r"^\| (`[^|]*`) \|", section, re.M) for c in re.findall(r"`([a-z]+)`", row)]
    print(f"commands: cig has {commands}; the README's table {named}")
    if sorted(named) != sorted(commands) or not commands:
        fail(f"README.md's command table {sorted(named)} is not cig's commands {sorted(commands)}")


def recipes(readme):
    out = []
    for m in re.finditer(r"```sh\n((?:(?!```).)*?)```\n```text\n((?:(?!```).)*?)```", readme, re.S):
        out.append((m.group(1).strip().splitlines(), m.group(2).rstrip("\n").splitlines()))
    return out


def line_matches(expected, actual):
    e, a = expected.split(), actual.split()
    if len(e) != len(a):
        return False
    for x, y in zip(e, a):
        if "…" in x:
            pattern = "^" + ".*".join(re.escape(p) for p in x.split("…")) + "$"
            if not re.match(pattern, y):
                return False
        elif x != y:
            return False
    return True


def check_recipes(source, bin_dir, work):
    shutil.rmtree(work, ignore_errors=True)  # the test's own folder
    os.makedirs(work)
    found = recipes(read(os.path.join(source, "README.md")))
    print(f"{len(found)} recipes")
    if len(found) < 5:
        fail(f"README.md has {len(found)} recipes with expected output; five are promised")
    for commands, expected in found:
        # Only a recipe's own kind of command runs here (never a Quick start script).
        first_words = {w.split()[0] for c in commands for w in c.split("&&") if w.strip()}
        if not all(w in ("build/bin/cig", "tools/hls_export.sh", "cd", "g++") or w.startswith("./tb_") for w in first_words):
            fail(f"recipe {commands[0]}: runs {sorted(first_words)}; a recipe runs cig, the export and the testbench")
            continue
        script = "\n".join(commands).replace("build/bin/", bin_dir.rstrip("/") + "/").replace("/tmp/cig-demo", work)
        if "cig cosim" in script.replace(bin_dir.rstrip("/") + "/cig", "cig") and not os.path.exists(
            os.path.join(bin_dir, "cig-cosim")
        ):
            print(f"skipped (this build has no RTL): {commands[0]}")
            continue
        r = subprocess.run(["bash", "-ec", script], cwd=source, capture_output=True, text=True)
        printed = (r.stdout + r.stderr).splitlines()
        if r.returncode != 0:
            fail(f"recipe exited {r.returncode}: {commands[0]}\n" + "\n".join(printed[-5:]))
            continue
        k = 0
        for line in expected:
            want = line.replace("/tmp/cig-demo", work)
            while k < len(printed) and not line_matches(want, printed[k]):
                k += 1
            if k == len(printed):
                fail(f"recipe {commands[0]}: no line like {line!r} in order in its output:\n" + "\n".join(printed))
                break
            k += 1
        else:
            print(f"ok: {commands[0]}")
    if check_report_figures(read(os.path.join(source, "README.md")), work) == 0:
        fail("README.md quotes no report figure to check (<!-- check: FILE POINTER = VALUE -->)")


def check_report_figures(readme, work):
    """<!-- check: FILE /json/pointer = VALUE --> after the recipes: a figure the prose quotes."""
    checks = re.findall(r"<!-- check: (\S+) (\S+) = (\S+) -->", readme)
    for file, pointer, value in checks:
        path = file.replace("/tmp/cig-demo", work)
        try:
            with open(path) as f:
                node = json.load(f)
            for key in pointer.strip("/").split("/"):
                node = node[int(key)] if isinstance(node, list) else node[key]
        except (OSError, KeyError, IndexError, ValueError) as e:
            fail(f"README.md quotes {pointer} of {file}: not found ({e})")
            continue
        if str(node) != value:
            fail(f"README.md quotes {pointer} of {file} as {value}; the recipe's run gives {node}")
        else:
            print(f"ok: {file} {pointer} = {value}")
    return len(checks)


def main():
    case, source = sys.argv[1], sys.argv[2]
    if case == "lines":
        check_lines(source)
    elif case == "links":
        check_links(source)
    elif case == "figures":
        check_figures(source, sys.argv[3], sys.argv[4], sys.argv[5])
    elif case == "recipes":
        check_recipes(source, sys.argv[3], sys.argv[4])
    else:
        fail("unknown case " + case)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()

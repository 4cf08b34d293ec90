#!/usr/bin/env python3
"""Include layering of the product (cmodel/, hls/): dependencies point down the pipeline.

Every quoted #include of a file under cmodel/ or hls/ must resolve to a file under cmodel/ or hls/
(so nothing in the product includes verif/, tools/ or generated code), and the folder it names must
be one its own folder may depend on (ALLOWED below: a stage includes the stages before it, never
after; the engines do not include each other; only the CLI includes the studies, cmodel/studies/). Exit status 1 lists every violation as
FILE:LINE: rule. `--self-test` plants violations in a temporary tree and requires each to be found.
"""
import os
import re
import sys
import tempfile

# Folder -> folders it may include (besides itself). cmodel/ folders name cmodel/<folder>,
# hls folders hls/<folder>. "hls/*" allows every hls folder.
ALLOWED = {
    # bit-accurate kernels: the formatter (stage C) is the ground under D, E and F
    "hls/types": set(),
    "hls/formatter": {"hls/types"},
    "hls/pixel": {"hls/types", "hls/formatter"},
    "hls/segment": {"hls/types", "hls/formatter", "hls/pixel"},
    "hls/quadtree": {"hls/types", "hls/formatter", "hls/pixel"},
    "hls/manager": {"hls/types"},                                              # stage A (seed 000)
    "hls/invparam": {"hls/types", "hls/formatter"},  # stage F (seed 002): the sample lattice's size only
    # C model, in pipeline order
    "cmodel/common": set(),
    # the machine in time: cycle and operation models fed by the stages' counts (plain records)
    "cmodel/timing": {"cmodel/common"},
    "cmodel/scene": {"cmodel/common"},
    "cmodel/manager": {"cmodel/common", "cmodel/scene", "hls/types", "hls/manager"},  # stage A, V[i] by its kernel
    "cmodel/frame": {"cmodel/common", "cmodel/scene"},                        # B -> engines record
    "cmodel/geometry": {"cmodel/common", "cmodel/scene", "cmodel/manager", "cmodel/frame",
                        "hls/formatter"},                                      # stage B
    "cmodel/formatter": {"cmodel/common", "cmodel/scene", "cmodel/frame", "hls/types",
                         "hls/formatter"},                                     # stage C twin
    "cmodel/image": {"cmodel/common"},
    "cmodel/engine": {"cmodel/common", "cmodel/scene", "cmodel/frame", "cmodel/image", "cmodel/formatter",
                      "hls/types", "hls/formatter"},  # every engine's front: fan split, formatter grid
    "cmodel/pixel": {"hls/types", "hls/formatter", "hls/pixel"},            # D, E: shared plane twin
    "cmodel/reference": {"cmodel/common", "cmodel/scene", "cmodel/frame", "cmodel/formatter",
                         "cmodel/image", "cmodel/engine", "hls/types", "hls/formatter"},
    "cmodel/segment": {"cmodel/common", "cmodel/scene", "cmodel/frame", "cmodel/formatter",
                       "cmodel/image", "cmodel/engine", "cmodel/pixel", "hls/types", "hls/formatter",
                       "hls/pixel", "hls/segment", "cmodel/timing"},                        # stage D
    "cmodel/quadtree": {"cmodel/common", "cmodel/scene", "cmodel/frame", "cmodel/formatter",
                        "cmodel/image", "cmodel/engine", "cmodel/pixel", "hls/types", "hls/formatter",
                        "hls/pixel", "hls/quadtree"},                                       # stage E
    "cmodel/invparam": {"cmodel/common", "cmodel/scene", "cmodel/frame", "cmodel/image", "cmodel/engine",
                        "hls/types", "hls/formatter",
                        "hls/invparam"},                                                    # stage F
    "cmodel/registry": {"cmodel/common", "cmodel/frame", "cmodel/image", "cmodel/engine",
                        "cmodel/reference", "cmodel/segment", "cmodel/quadtree", "cmodel/invparam"},  # every engine
    "cmodel/generator": {"cmodel/common", "cmodel/scene", "cmodel/manager", "cmodel/geometry",
                        "cmodel/frame", "cmodel/image", "cmodel/engine", "cmodel/registry", "cmodel/timing"},
    # import of foreign airport data (`cig import`): builds scene content, uses nothing after it
    "cmodel/import": {"cmodel/common", "cmodel/scene"},
    # seed-reproduction studies: above every stage and engine, below the CLI; nothing but the CLI
    # (and verif/) includes them, so a study can change without touching the data path
    "cmodel/studies": {"cmodel/common", "cmodel/timing", "cmodel/scene", "cmodel/manager", "cmodel/frame", "cmodel/geometry",
                       "cmodel/formatter", "cmodel/image", "cmodel/engine", "cmodel/pixel", "cmodel/reference",
                       "cmodel/segment", "cmodel/quadtree", "cmodel/invparam", "hls/*"},
    "cmodel/cli": {"cmodel/*"},                                                # every command
}

STUDIES = "cmodel/studies"
MAY_INCLUDE_STUDIES = {STUDIES, "cmodel/cli"}

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def folder_of(rel):
    parts = rel.split("/")
    return "/".join(parts[:2]) if len(parts) > 2 else parts[0]


def resolve(root, rel_file, target):
    """The repository path an include names: hls/... from the root, others from cmodel/."""
    for base in ("", "cmodel/", os.path.dirname(rel_file) + "/"):
        cand = os.path.normpath(base + target)
        if os.path.isfile(os.path.join(root, cand)):
            return cand
    return None


def allowed(src, dst):
    if src == dst:
        return True
    rules = ALLOWED.get(src)
    if rules is None:
        return False
    return dst in rules or (dst.startswith("cmodel/") and "cmodel/*" in rules) or (
        dst.startswith("hls/") and ("hls/*" in rules or src.startswith("cmodel/cli")))


def check(root):
    problems = []
    for top in ("cmodel", "hls"):
        for dirpath, _, files in os.walk(os.path.join(root, top)):
            for name in sorted(files):
                if not name.endswith((".hpp", ".cpp", ".h")):
                    continue
                rel = os.path.relpath(os.path.join(dirpath, name), root)
                src = folder_of(rel)
                if src not in ALLOWED:
                    problems.append(f"{rel}:1: unknown-folder: {src} has no row in ALLOWED (check_layers.py)")
                    continue
                with open(os.path.join(root, rel), encoding="utf-8") as f:
                    for line_no, line in enumerate(f, 1):
                        m = INCLUDE.match(line)
                        if not m:
                            continue
                        target = resolve(root, rel, m.group(1))
                        if target is None or not target.startswith(("cmodel/", "hls/")):
                            problems.append(f"{rel}:{line_no}: outside-product: \"{m.group(1)}\" is not a file "
                                            "under cmodel/ or hls/")
                            continue
                        dst = folder_of(target)
                        if dst == STUDIES and src not in MAY_INCLUDE_STUDIES:
                            problems.append(f"{rel}:{line_no}: studies: {src} must not include {target} "
                                            "(studies depend on the stages, never the other way)")
                        elif not allowed(src, dst):
                            problems.append(f"{rel}:{line_no}: layer: {src} must not include {target}")
    return problems


def self_test():
    planted = {
        "cmodel/quadtree/bad.hpp": '#include "hls/segment/x.hpp"\n',   # engine -> other engine
        "cmodel/engine/bad.hpp": '#include "reference/r.hpp"\n',       # interface -> reference
        "cmodel/cli/bad.cpp": '#include "quadtree/cosim.hpp"\n',       # product -> verif
        "hls/quadtree/bad.hpp": '#include "hls/segment/x.hpp"\n',
        "hls/formatter/bad.hpp": '#include "hls/segment/x.hpp"\n',     # ground -> stage D
        "cmodel/manager/bad.cpp": '#include "studies/s.hpp"\n',       # stage -> study
        "cmodel/registry/bad.cpp": '#include "studies/s.hpp"\n',      # registry -> study
    }
    accepted = {"cmodel/cli/ok.cpp": '#include "studies/s.hpp"\n',      # the CLI runs studies
                "cmodel/studies/s.hpp": '#include "quadtree/q.hpp"\n'}   # a study uses the stages
    with tempfile.TemporaryDirectory() as root:
        for rel in ["hls/segment/x.hpp", "cmodel/reference/r.hpp", "cmodel/quadtree/q.hpp",
                    "verif/cosim/quadtree/cosim.hpp"] + list(planted) + list(accepted):
            os.makedirs(os.path.join(root, os.path.dirname(rel)), exist_ok=True)
            with open(os.path.join(root, rel), "w") as f:
                f.write(planted.get(rel, accepted.get(rel, "")))
        found = check(root)
    missed = [rel for rel in planted if not any(p.startswith(rel + ":") for p in found)]
    missed += [rel for rel in planted if '"studies/' in planted[rel] and not any(
        p.startswith(rel + ":") and ": studies: " in p for p in found)]  # named by its own rule
    if missed or len(found) != len(planted):
        print("self-test failed: planted", sorted(planted), "found", found)
        return 1
    print(f"self-test: all {len(planted)} planted violations found")
    return 0


def main():
    if len(sys.argv) == 2 and sys.argv[1] == "--self-test":
        return self_test()
    if len(sys.argv) != 2:
        print("usage: check_layers.py REPO_ROOT | --self-test", file=sys.stderr)
        return 2
    problems = check(sys.argv[1])
    for p in problems:
        print(p)
    print(f"layering: {len(problems)} violation(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

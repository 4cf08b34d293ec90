#!/usr/bin/env python3
"""Output collisions through the real CLI (issue 28): every command that writes files finds, before
any work, an output that would replace one of its inputs, an output on another output's path, a
file output that is a folder and a folder output that is a file. Each case runs one command line in
a scratch folder holding copies of the inputs and a user's file, and asserts exit status 2, the
message, and that afterwards no file was added, changed or removed there (so the inputs' bytes are
unchanged) nor in the source tree's scenes/.

usage: check_output_collisions.py CIG SOURCE WORK CASE
       check_output_collisions.py --list [rtl]     the case names, ';'-separated (rtl: with cosim's)"""
import os
import shutil
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from cli_check import fail, snapshot  # noqa: E402

# name: (command line, run in WORK; the text stderr must contain). SRC stands for the source tree,
# '' for an empty argument.
CASES = {
    # render: the report on --out's folder (the case), on the scene, on an OBJ model the
    # scene references, on an image --out receives; --out on the scene, on a file; an input among
    # the files --out receives; a report that is a folder; through a symlink and a hard link.
    "render_report_is_out": ("render SRC/scenes/airfield.json --out D --report D",
                             "--report: 'D' is the folder --out writes into"),
    "render_report_is_scene": ("render hut.json --out D --report hut.json",
                               "--report: 'hut.json' is the scene file this run reads"),
    "render_report_is_model": ("render polyhedra.json --out D --report models/../models/crate.obj",
                               "--report: 'models/../models/crate.obj' is a model file the scene references"),
    "render_report_is_image": ("render hut.json --out D --report D/frame_0000_panorama.png",
                               "--report: 'D/frame_0000_panorama.png' is one of the files --out writes"),
    "render_report_is_ids": ("render hut.json --out D --ids --frames 0:1 --report D/./frame_0001_ch0_left.ids",
                             "--report: 'D/./frame_0001_ch0_left.ids' is one of the files --out writes"),
    "render_out_is_scene": ("render hut.json --out hut.json", "--out: 'hut.json' is the scene file this run reads, "
                            "not a folder"),
    "render_out_is_file": ("render hut.json --out notes.txt", "--out: 'notes.txt' is an existing file, not a folder"),
    "render_out_receives_scene": ("render frame_0000_panorama.png --out .",
                                  "--out: '.' would receive frame_0000_panorama.png, which is the scene file"),
    "render_report_is_folder": ("render hut.json --out D --report sub", "--report: 'sub' is a folder, not a file"),
    "render_report_symlink": ("render hut.json --out D --report link.json",
                              "--report: 'link.json' is the scene file this run reads"),
    "render_report_hard_link": ("render hut.json --out D --report hard.json",
                                "--report: 'hard.json' is the scene file this run reads"),
    # raster, polys, stress, cull
    "raster_out_is_polys": ("raster overlap.polys.json --out overlap.polys.json",
                            "--out: 'overlap.polys.json' is the polygon list this run reads"),
    "raster_report_is_out": ("raster overlap.polys.json --out a.png --report a.png",
                             "--report: 'a.png' is also --out's file"),
    "raster_report_is_ids": ("raster overlap.polys.json --out a.png --ids x.ids --report ./x.ids",
                             "--report: './x.ids' is also --ids's file"),
    "polys_out_is_scene": ("polys hut.json --frame 0 --channel 0 --out hut.json",
                           "--out: 'hut.json' is the scene file this run reads"),
    "polys_out_is_folder": ("polys hut.json --frame 0 --channel 0 --out sub", "--out: 'sub' is a folder, not a file"),
    "stress_out_is_folder": ("stress slivers --out sub", "--out: 'sub' is a folder, not a file"),
    "raster_out_empty": ("raster overlap.polys.json --out ''", "--out: the output path is empty"),
    "render_out_empty": ("render hut.json --out ''", "--out: the output folder is empty"),
    "cull_report_is_scene": ("cull hut.json --report hut.json", "--report: 'hut.json' is the scene file this run reads"),
    # compare, sweep
    "compare_report_is_out": ("compare hut.json --engine segment --out D --report D",
                              "--report: 'D' is the folder --out writes into"),
    "compare_report_is_diff": ("compare hut.json --engine segment --out D --report D/frame_0000_ch1_diff.png",
                               "--report: 'D/frame_0000_ch1_diff.png' is one of the files --out writes"),
    "compare_report_is_polys": ("compare overlap.polys.json --engine segment --report overlap.polys.json",
                                "--report: 'overlap.polys.json' is the polygon list this run reads"),
    "compare_out_is_scene": ("compare hut.json --engine segment --out hut.json",
                             "--out: 'hut.json' is the scene file this run reads, not a folder"),
    "sweep_plot_is_report": ("sweep hut.json --engine segment --vary spp=1,4 --report p.png --plot p.png",
                             "--plot: 'p.png' is also --report's file"),
    "sweep_report_is_scene": ("sweep hut.json --engine segment --vary spp=1,4 --report hut.json",
                              "--report: 'hut.json' is the scene file this run reads"),
    # arch, wordlength: no inputs; a folder, or two outputs on one path
    "arch_report_is_folder": ("arch --report sub", "--report: 'sub' is a folder, not a file"),
    "wordlength_plot_is_report": ("wordlength --report w.json --plot w.json", "--plot: 'w.json' is also --report's file"),
}
# cig cosim (only when cig-cosim is built, CIG_WITH_RTL): the quadtree RTL and the invparam array.
COSIM_CASES = {
    "cosim_report_is_polys": ("cosim overlap.polys.json --arch 4p2t --report overlap.polys.json",
                              "--report: 'overlap.polys.json' is the polygon list this run reads"),
    "cosim_trace_is_report": ("cosim overlap.polys.json --arch 4p2t --report r.json --trace r.json",
                              "--trace: 'r.json' is also --report's file"),
    "cosim_invparam_trace_is_model": ("cosim polyhedra.json --processor invparam --pps 8 --channel 1 "
                                      "--trace models/crate.obj",
                                      "--trace: 'models/crate.obj' is a model file the scene references"),
}


def prepare(source, work):
    """Copies of the inputs, a user's file and folder, a symlink and a hard link to the scene."""
    shutil.rmtree(work, ignore_errors=True)  # this test's own scratch folder
    os.makedirs(os.path.join(work, "sub"))
    os.makedirs(os.path.join(work, "models"))
    for rel, name in (("scenes/small/hut.json", "hut.json"), ("scenes/small/overlap.polys.json", "overlap.polys.json"),
                      ("scenes/polyhedra.json", "polyhedra.json"), ("scenes/models/crate.obj", "models/crate.obj"),
                      ("scenes/small/hut.json", "frame_0000_panorama.png")):
        shutil.copyfile(os.path.join(source, rel), os.path.join(work, name))
    with open(os.path.join(work, "notes.txt"), "w") as f:
        f.write("a user's notes\n")
    with open(os.path.join(work, "sub", "keep.txt"), "w") as f:
        f.write("kept\n")
    os.symlink("hut.json", os.path.join(work, "link.json"))
    os.link(os.path.join(work, "hut.json"), os.path.join(work, "hard.json"))


def main():
    if sys.argv[1] == "--list":
        rtl = sys.argv[2:] == ["rtl"]
        print(";".join(sorted(CASES) + (sorted(COSIM_CASES) if rtl else [])), end="")
        return
    cig, source, work, case = sys.argv[1:5]
    cig = os.path.abspath(cig)  # the command runs in WORK
    cases = dict(CASES, **COSIM_CASES)
    if case not in cases:
        fail("unknown case " + case)
    cmdline, message = cases[case]
    source = os.path.realpath(source)
    prepare(source, work)
    before, scenes_before = snapshot(work), snapshot(os.path.join(source, "scenes"))
    args = [cig] + ["" if a == "''" else a.replace("SRC", source) for a in cmdline.split()]
    r = subprocess.run(args, cwd=work, capture_output=True, text=True)
    if r.returncode != 2:
        fail(f"{cmdline}: exit {r.returncode}, expected 2\nstdout: {r.stdout}\nstderr: {r.stderr}")
    if "cig: error: " + message not in r.stderr:
        fail(f"{cmdline}: stderr lacks {message!r}:\n{r.stderr}")
    after = snapshot(work)
    if after != before:
        added = sorted(set(after) - set(before))
        changed = sorted(p for p in before if after.get(p, "gone") != before[p])
        fail(f"{cmdline}: the folder changed: added {added}, changed or removed {changed}")
    if snapshot(os.path.join(source, "scenes")) != scenes_before:
        fail(f"{cmdline}: the source tree's scenes/ changed")
    print(f"cig {cmdline}\n  -> {r.stderr.strip()}")
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()

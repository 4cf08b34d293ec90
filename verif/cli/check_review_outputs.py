#!/usr/bin/env python3
"""Review outputs (issue 28, docs/review_outputs.md) through the real cig: `cig compare --out`
writes a side-by-side PNG per image; `--html` on render, compare and sweep writes an index.html whose
every <img src> and <a href> resolves to a file, whose tags balance, which holds the run's provenance
command line and the command's rows, and in which user strings are escaped. `cig compare --html`
without --out, sweep --html on a file and render --html where index.html is a folder are input
errors that write nothing.

usage: check_review_outputs.py CIG CASE WORKDIR   (CASE: compare, render, sweep, escape, needs_out)"""
import html.parser
import json
import os
import shutil
import struct
import subprocess
import sys
import urllib.parse

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from cli_check import fail  # noqa: E402

VOID = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source", "track", "wbr"}


def run(cmd, expect=0):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != expect:
        fail(f"{cmd} exited {r.returncode} (expected {expect}): {r.stderr}")
    return r


class Page(html.parser.HTMLParser):
    """Balanced tags (void elements aside), the link targets and the text."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.stack, self.targets, self.text, self.errors = [], [], [], []
        self.img_widths = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "img":
            self.targets.append(a.get("src"))
            self.img_widths.append(a.get("width"))
        if tag == "a":
            self.targets.append(a.get("href"))
        if tag not in VOID:
            self.stack.append(tag)

    def handle_startendtag(self, tag, attrs):
        self.handle_starttag(tag, attrs)
        if tag not in VOID:
            self.stack.pop()

    def handle_endtag(self, tag):
        if not self.stack or self.stack[-1] != tag:
            self.errors.append(f"</{tag}> closes {self.stack[-1:] or 'nothing'}")
        else:
            self.stack.pop()

    def handle_data(self, data):
        self.text.append(data)


def check_page(folder, report_file):
    """The page in `folder`: well formed, links resolving, the report's provenance and link."""
    index = os.path.join(folder, "index.html")
    if not os.path.isfile(index):
        fail(f"no {index}")
    raw = open(index, encoding="utf-8").read()
    if not raw.startswith("<!DOCTYPE html>"):
        fail("index.html does not start with <!DOCTYPE html>")
    if "<script" in raw.lower():
        fail("index.html holds a script")
    page = Page()
    page.feed(raw)
    page.close()
    if page.errors or page.stack:
        fail(f"unbalanced tags: {page.errors} open at the end: {page.stack}")
    if not page.targets:
        fail("index.html links nothing")
    for t in page.targets:
        if not t or urllib.parse.urlparse(t).scheme or t.startswith("/"):
            fail(f"link {t!r} is not a relative path")
        target = os.path.join(folder, urllib.parse.unquote(t))
        if not os.path.isfile(target):
            fail(f"link {t!r} does not resolve to a file ({target})")
    if any(not (w or "").isdigit() for w in page.img_widths):
        fail(f"a thumbnail without a width: {page.img_widths}")
    text = "".join(page.text)
    with open(report_file) as f:
        report = json.load(f)
    command_line = report["provenance"]["command_line"]
    for key in ("command_line", "version", "commit", "date"):
        if report["provenance"][key] not in text:
            fail(f"index.html does not hold the provenance {key} {report['provenance'][key]!r}")
    rel = os.path.relpath(report_file, folder)
    if urllib.parse.quote(rel) not in [urllib.parse.quote(urllib.parse.unquote(t)) for t in page.targets]:
        fail(f"index.html does not link the report {rel}")
    return raw, text, report, command_line


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n":
        fail(f"{path} is not a PNG")
    return struct.unpack(">II", head[16:24])


def fresh(work, name):
    d = os.path.join(work, name)
    shutil.rmtree(d, ignore_errors=True)
    return d


def case_compare(cig, work, source):
    out = fresh(work, "compare")
    polys = os.path.join(source, "scenes", "small", "overlap.polys.json")
    run([cig, "compare", polys, "--engine", "quadtree", "--out", out, "--html"])
    side = os.path.join(out, "frame_0000_ch0_side.png")
    # 64 x 64 panels (docs/review_outputs.md): the scale sets the width (357), the title strip
    # (26 rows) and the scale (29 rows) add to the height.
    if png_size(side) != (357, 26 + 64 + 29):
        fail(f"{side} is {png_size(side)}, expected (357, 119)")
    raw, text, report, _ = check_page(out, os.path.join(out, "report.json"))
    row = report["rows"][0]
    for number in (f"{row['psnr']:.2f}", str(row["ids_differ"]), str(row["pixels_over_2lsb"])):
        if number not in text:
            fail(f"index.html does not show the row's {number}")
    for name in ("frame_0000_ch0_side.png", "frame_0000_ch0_diff.png"):
        if f'href="{name}"' not in raw:
            fail(f"index.html does not link {name}")
    print("compare:", sorted(os.listdir(out)))


def case_render(cig, work, source):
    out = fresh(work, "render")
    hut = os.path.join(source, "scenes", "small", "hut.json")
    run([cig, "render", hut, "--out", out, "--html"])
    raw, text, report, _ = check_page(out, os.path.join(out, "report.json"))
    for ch in report["frames"][0]["channels"]:
        name = os.path.basename(ch["image"])
        if f'src="{name}"' not in raw:
            fail(f"index.html shows no thumbnail of {name}")
        if str(ch["geometry"]["polygons_out"]) not in text:
            fail("index.html does not show the channel's polygon count")
    print("render:", sorted(os.listdir(out)))


def case_sweep(cig, work, source):
    out = fresh(work, "sweep")
    polys = os.path.join(source, "scenes", "small", "overlap.polys.json")
    run([cig, "sweep", polys, "--engine", "segment", "--vary", "format=coarse,medium", "--repeat", "1", "--html", out])
    for name in ("index.html", "report.json", "plot.png"):
        if not os.path.isfile(os.path.join(out, name)):
            fail(f"sweep --html {out} wrote no {name}")
    raw, text, report, _ = check_page(out, os.path.join(out, "report.json"))
    if 'src="plot.png"' not in raw:
        fail("index.html does not show the plot")
    for r in report["rows"]:
        if r["value"] not in text or f"{r['psnr']:.2f}" not in text:
            fail(f"index.html does not show the row {r['value']}")
    print("sweep:", sorted(os.listdir(out)))


def case_escape(cig, work, source):
    # A scene and an output folder whose names need escaping, in the title, the tables and the
    # provenance: none of them may reach the page raw.
    base = fresh(work, "escape")
    os.makedirs(base)
    scene = os.path.join(base, 'hut <&>"\'.json')
    shutil.copy(os.path.join(source, "scenes", "small", "hut.json"), scene)
    out = os.path.join(base, 'out <&>"% #')
    report = os.path.join(base, 'report <&>"%#?.json')  # outside the page's folder: linked as ../report%20...
    run([cig, "render", scene, "--out", out, "--report", report, "--html"])
    raw, text, _, command_line = check_page(out, report)
    if '<&>"' in raw:
        fail("a user string reached the page unescaped")
    if "&lt;&amp;&gt;&quot;" not in raw:
        fail("the escaped scene name is not in the page")
    if 'hut <&>"\'.json' not in text:
        fail("the scene name does not read back from the page")
    print("escape: command line", command_line)


def case_needs_out(cig, work, source):
    base = fresh(work, "needs_out")
    os.makedirs(base)
    polys = os.path.join(source, "scenes", "small", "overlap.polys.json")
    r = subprocess.run([cig, "compare", polys, "--engine", "quadtree", "--html", "--report",
                        os.path.join(base, "r.json")], capture_output=True, text=True, cwd=base)
    if r.returncode != 2:
        fail(f"compare --html without --out exited {r.returncode}, expected 2")
    if not r.stderr.startswith("cig: error: --html:") or "--out" not in r.stderr:
        fail(f"unexpected message: {r.stderr!r}")
    if os.listdir(base):
        fail(f"compare --html without --out wrote {os.listdir(base)}")
    print("needs_out:", r.stderr.strip())
    # sweep --html on a file, render --html where index.html is a folder: input errors, nothing written.
    blocker = os.path.join(base, "a_file")
    open(blocker, "w").close()
    os.makedirs(os.path.join(base, "out", "index.html"))
    for cmd in ([cig, "sweep", polys, "--engine", "segment", "--vary", "format=coarse,medium", "--html", blocker],
                [cig, "render", os.path.join(source, "scenes", "small", "hut.json"), "--out",
                 os.path.join(base, "out"), "--html"]):
        r = subprocess.run(cmd, capture_output=True, text=True, cwd=base)
        if r.returncode != 2 or not r.stderr.startswith("cig: error: --html:"):
            fail(f"{cmd} exited {r.returncode}: {r.stderr!r}")
        print("bad --html:", r.stderr.strip())
    if sorted(os.listdir(base)) != ["a_file", "out"] or os.listdir(os.path.join(base, "out")) != ["index.html"]:
        fail(f"a refused --html wrote something: {os.listdir(base)}")


def main():
    cig, case, work = sys.argv[1], sys.argv[2], sys.argv[3]
    source = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    os.makedirs(work, exist_ok=True)
    cases = {"compare": case_compare, "render": case_render, "sweep": case_sweep, "escape": case_escape,
             "needs_out": case_needs_out}
    if case not in cases:
        fail("unknown case " + case)
    cases[case](os.path.abspath(cig), os.path.abspath(work), source)


if __name__ == "__main__":
    main()
